#!/bin/bash
# probe_r30 Gen3 + ORCA / Gen3 + 2F-85 cases; SRC=/tmp/r36f/src (new, + truth) or /tmp/r36/src (old, validate only)
SRC=${SRC:-/tmp/r36f/src}; R=${R:-/tmp/r36f/followup/res}; Q=/tmp/r36f/followup/r30p
PY="env PYTHONPATH=$SRC taskset -c 1 /work/venv/bin/python"
sed "s#/tmp/r36f/src#$SRC#" $Q/run_validate.py > /tmp/r36f/followup/r30p/rv_$(basename $(dirname $SRC)).py
RV=/tmp/r36f/followup/r30p/rv_$(basename $(dirname $SRC)).py
for ts in "$@"; do   # dir:tag:scenario:traj
  IFS=: read d tag scen traj <<< "$ts"; cd /tmp/r36f/followup/r30/$d
  $PY $RV $scen $traj $R/val_r30_${d}_$tag.json --samples 32 --seed 0 2>&1 | tail -1
  [ -z "$NOTRUTH" ] && $PY $Q/truth.py --scenario $scen $traj --validate-json $R/val_r30_${d}_$tag.json --out $R/tr_r30_${d}_$tag.json 2>&1 | tail -3
done
