#!/bin/bash
# probe_r38 (from probe_r37/robots/queue.sh): per case, pinned to core 1: validate (32 samples, seed 0, nthread 1) ->
# independent truth on validate's samples -> analyze (256 samples, seed 0, nthread 1) -> truth on the region's points.
# usage: queue.sh ROBOTDIR TRAJ SCENARIO_STEM [SCENARIO_STEM ...]     (results in /tmp/r38/robots/res)
W=/tmp/r38/robots/probe; S=/tmp/r38/robots/work; O=/tmp/r38/robots/res
PY="env PYTHONPATH=/tmp/r38/robots/src taskset -c 1 /work/venv/bin/python"
cd $W/$1; tr=$2; shift 2
for s in "$@"; do
  tag=$(basename $PWD)_$s
  echo "$(date -u +%T) start $tag" >> $O/queue.log
  $PY $S/run_validate.py $s.toml $tr $O/val_$tag.json --samples 32 > $O/val_$tag.log 2>&1
  $PY $S/truth.py --scenario $s.toml $tr --validate-json $O/val_$tag.json --out $O/truth_$tag.json > $O/truth_$tag.log 2>&1
  $PY $S/run_analyze.py $s.toml $tr $O/an_$tag > $O/an_$tag.log 2>&1
  if [ -f $O/an_${tag}_points.json ]; then
    $PY $S/truth.py --scenario $s.toml $tr --points $O/an_${tag}_points.json --out $O/region_$tag.json > $O/region_$tag.log 2>&1
  fi
  echo "$(date -u +%T) done $tag" >> $O/queue.log
done
