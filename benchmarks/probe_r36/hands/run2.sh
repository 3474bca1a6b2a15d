#!/bin/bash
cd /tmp/r36/hands/shadow
PY="env PYTHONPATH=/tmp/r36/src taskset -c 1 /work/venv/bin/python"
P=/work/main/benchmarks/probe_r36/hands
$PY $P/anchor.py ph_ell_narrow.toml nom.npz ../res/val_sh_ell_narrow.json 1500 1550 1600 1738 1800 2000 > ../res/anchor_sh_ell_narrow.txt 2>&1
$PY $P/anchor.py ph_narrow.toml nom.npz ../res/val_sh_pyr_narrow.json 1500 1550 1600 1738 1800 2000 > ../res/anchor_sh_pyr_narrow.txt 2>&1
echo '[{"mass":0.189,"friction":0.867},{"mass":0.05,"friction":0.867},{"mass":0.189,"friction":1.5},{"mass":0.05,"friction":1.5},{"mass":0.12,"friction":0.867},{"mass":0.189,"friction":1.18}]' > ../res/points_ph.json
echo '[{"mass":0.267,"friction":0.532},{"mass":0.05,"friction":0.532},{"mass":0.267,"friction":1.5},{"mass":0.05,"friction":1.5},{"mass":0.158,"friction":0.532},{"mass":0.267,"friction":1.016}]' > ../res/points_ph_ell.json
$PY /tmp/r36/hands/scripts/truth.py --scenario ph.toml nom.npz --points ../res/points_ph.json --out ../res/region_ph.json > ../res/region_ph.txt 2>&1
$PY /tmp/r36/hands/scripts/truth.py --scenario ph_ell.toml nom.npz --points ../res/points_ph_ell.json --out ../res/region_ph_ell.json > ../res/region_ph_ell.txt 2>&1
echo DONE2
