#!/bin/bash
cd /tmp/r36/hands/shadow
PY="env PYTHONPATH=/tmp/r36/src taskset -c 1 /work/venv/bin/python"
for s in ph_ell_fl ph_ell_narrow ph_narrow; do
$PY /tmp/r36/hands/scripts/truth.py --scenario $s.toml nom.npz --points ../res/points_$s.json --out ../res/region_$s.json > ../res/region_$s.txt 2>&1
done
echo DONE5
