#!/bin/bash
# validate (library, nthread=1, 32 samples, seed 0) + the independent truth on the same samples.
# usage (from the scene dir): queue.sh TRAJ TAG:SCENARIO ...   -> ../res/val_TAG.json, ../res/tr_TAG.json
S=${S:-/tmp/r36/hands/scripts}; PY="env PYTHONPATH=/tmp/r36/src taskset -c 1 /work/venv/bin/python"
traj=$1; shift
for ts in "$@"; do
  tag=${ts%%:*}; scen=${ts#*:}
  $PY $S/run_validate.py $scen $traj ../res/val_$tag.json --samples 32 --seed 0 2>&1 | tail -1
  $PY $S/truth.py --scenario $scen $traj --validate-json ../res/val_$tag.json --out ../res/tr_$tag.json 2>&1 | tail -3
done
