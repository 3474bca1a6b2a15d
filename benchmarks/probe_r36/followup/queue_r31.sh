#!/bin/bash
# probe_r31 WX250s / low-cost arm cases on the NEW code (validate + r31's truth.py)
R=/tmp/r36f/followup/res; Q=/tmp/r36f/followup/r31p; PY="env PYTHONPATH=/tmp/r36f/src taskset -c 1 /work/venv/bin/python"
for ts in "$@"; do   # dir:tag:scenario:traj:truth(0/1)
  IFS=: read d tag scen traj t <<< "$ts"; cd /tmp/r36f/followup/r31/$d
  $PY $Q/run_validate.py $scen $traj $R/val_r31_${d}_$tag.json --samples 32 --seed 0 2>&1 | tail -1
  [ "$t" = 1 ] && $PY $Q/truth.py --scenario $scen $traj --validate-json $R/val_r31_${d}_$tag.json --out $R/tr_r31_${d}_$tag.json 2>&1 | tail -3
done
