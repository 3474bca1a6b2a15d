#!/bin/bash
cd /work/main/benchmarks/probe_r28/params
while pgrep -f run_all_ana.sh >/dev/null; do sleep 5; done
R=/tmp/r28/params
for b in aloha_shoulder_narrow_nolim aloha_grip_lim_narrow_nolim panda_shoulder_narrow_nolim panda_mass_shoulder_nolim panda_mass_fric_com_grip_nolim; do
  tw=${b%%_*}
  PYTHONPATH=/tmp/r28/src /work/venv/bin/python runval.py scen/$b.toml $R/${tw}0.npz $R/val_$b.json 2>&1 | grep -v "^$" | tail -1
  PYTHONPATH=/tmp/r28/src /work/venv/bin/python runana.py scen/$b.toml $R/${tw}0.npz $R/ana_$b 2>&1 | grep -v "^$"
done
for b in panda_mass_com_outside aloha_mass_com_outside panda_com_outside panda_marker_com_mass panda_link_com_mass; do
  tw=${b%%_*}
  PYTHONPATH=/tmp/r28/src /work/venv/bin/python runval.py scen2/$b.toml $R/${tw}0.npz $R/val_$b.json 2>&1 | grep -v "^$" | tail -1
  PYTHONPATH=/tmp/r28/src /work/venv/bin/python runana.py scen2/$b.toml $R/${tw}0.npz $R/ana_$b 2>&1 | grep -v "^$"
done
echo BATCH2 DONE
