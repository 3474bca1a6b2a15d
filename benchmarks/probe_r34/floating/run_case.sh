#!/bin/bash
# run_case.sh SCENARIO TRAJ TAG : validate (library, nthread 1, 32 Sobol samples, seed 0) -> val_TAG.json,
# then the independent plain-MuJoCo truth (truth.py, rebuilt by make_scripts.sh) on the same samples -> tr_TAG.json, log_tr_TAG.txt
# run from the scratch folder (/tmp/r34/floating); S = the rebuilt scripts (default /tmp/r34/floating/scripts)
set -e
P=$(cd "$(dirname "$0")" && pwd); S=${S:-/tmp/r34/floating/scripts}
export PYTHONPATH=/tmp/r34/src
taskset -c 0 /work/venv/bin/python $S/run_validate.py "$1" "$2" val_$3.json | tail -1
taskset -c 0 /work/venv/bin/python $S/truth.py --scenario "$1" "$2" --validate-json val_$3.json --out tr_$3.json > log_tr_$3.txt 2>&1
tail -2 log_tr_$3.txt
