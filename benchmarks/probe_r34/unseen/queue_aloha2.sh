#!/bin/bash
# validate (library, nthread=1) + independent truth for the ALOHA 2 cases; run from the scene dir.
# usage: queue_aloha2.sh TRAJ TAG:SCENARIO ...   (results in ../res/val_TAG.json, ../res/tr_TAG.json)
S=${S:-/tmp/r34/unseen/scripts}; PY="env PYTHONPATH=/tmp/r34/src taskset -c 1 /work/venv/bin/python"
traj=$1; shift
for ts in "$@"; do
  tag=${ts%%:*}; scen=${ts#*:}
  $PY $S/run_validate.py $scen $traj ../res/val_$tag.json --samples 32 --seed 0 2>&1 | tail -1
  $PY $S/truth.py --scenario $scen $traj --validate-json ../res/val_$tag.json --out ../res/tr_$tag.json 2>&1 | tail -4
done
