#!/bin/bash
cd /work/main/benchmarks/probe_r28/params
R=/tmp/r28/params
S=scen/panda_mass_fric_com_grip.toml
for i in 1 2; do
  ./cm.sh analyze $R/panda0.npz --scenario $S --seed 0 --out $R/det_cli_$i --figures none > $R/det_cli_$i.txt 2>&1; echo "cli run $i rc=$?"
done
PYTHONPATH=/tmp/r28/src /work/venv/bin/python runana.py $S $R/panda0.npz $R/det_py1_again 1 > /dev/null 2>&1; echo "py nthread1 again done"
for x in "scen/panda_mass_fric_com_grip.toml panda ana_panda_mass_fric_com_grip" "scen/aloha_mass_com.toml aloha ana_aloha_mass_com" "scen/panda_mass_com.toml panda ana_panda_mass_com" "scen/panda_mass_fric_grip.toml panda ana_panda_mass_fric_grip" "scen/aloha_mass_shoulder.toml aloha ana_aloha_mass_shoulder"; do
  set -- $x
  PYTHONPATH=/tmp/r28/src /work/venv/bin/python region_dense.py $1 $R/${2}0.npz $R/$3/report.json 128 2>&1 | grep -v Warn | cut -c1-900
done
echo BATCH3 DONE
