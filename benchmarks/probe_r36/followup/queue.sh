#!/bin/bash
# validate (library, nthread=1) + independent truth on the NEW code; run from the scene dir.
# usage: queue.sh TRAJ TAG:SCENARIO ...   results in $R/val_TAG.json, $R/tr_TAG.json
S=${S:-/tmp/r36f/followup/scripts}; R=${R:-/tmp/r36f/followup/res}; SRC=${SRC:-/tmp/r36f/src}
PY="env PYTHONPATH=$SRC taskset -c 1 /work/venv/bin/python"
traj=$1; shift
for ts in "$@"; do
  tag=${ts%%:*}; scen=${ts#*:}
  $PY $S/run_validate.py $scen $traj $R/val_$tag.json --samples 32 --seed 0 2>&1 | tail -1
  [ -z "$NOTRUTH" ] && $PY $S/truth.py --scenario $scen $traj --validate-json $R/val_$tag.json --out $R/tr_$tag.json 2>&1 | tail -4
done
