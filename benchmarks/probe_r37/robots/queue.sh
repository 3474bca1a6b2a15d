#!/bin/bash
# One case at a time (pinned to core 1 inside each script): validate (32 samples, seed 0, nthread 1) -> independent
# truth on validate's samples -> analyze (256 samples, seed 0, nthread 1) -> truth on the stated region's points.
# usage: queue.sh ROBOTDIR SCENARIO_STEM [SCENARIO_STEM ...]     (results in /tmp/r37/robots/res)
W=/tmp/r37/robots/probe; S=/tmp/r37/robots/scripts; O=/tmp/r37/robots/res; P=$(cd "$(dirname "$0")" && pwd)
PY="env PYTHONPATH=/tmp/r37/src taskset -c 1 /work/venv/bin/python"
cd $W/$1; shift
for s in "$@"; do
  tag=$(basename $PWD)_$s
  $PY $S/run_validate.py $s.toml pp.npz $O/val_$tag.json --samples 32 > $O/val_$tag.log 2>&1
  $PY $S/truth.py --scenario $s.toml pp.npz --validate-json $O/val_$tag.json --out $O/truth_$tag.json > $O/truth_$tag.log 2>&1
  $PY $P/run_analyze.py $s.toml pp.npz $O/an_$tag > $O/an_$tag.log 2>&1
  if [ -f $O/an_${tag}_points.json ]; then
    $PY $S/truth.py --scenario $s.toml pp.npz --points $O/an_${tag}_points.json --out $O/region_$tag.json > $O/region_$tag.log 2>&1
  fi
  echo "$(date -u +%T) done $tag" >> $O/queue.log
done
