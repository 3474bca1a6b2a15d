#!/bin/bash
# usage: run_ana.sh LIST (lines "case scenario") in the gen dir -> ana_<case>.json (analyze 256 + region by full rollouts)
T=/work/main/benchmarks/probe_r38/tasks
export PYTHONPATH=/tmp/r38/tasks/src
while read c s; do
  [ -f ana_$c.json ] && continue
  echo "== $c"; timeout 900 taskset -c 0 /work/venv/bin/python $T/ana_region.py $s/scenario.toml $c.npz ana_$c.json 2>&1 | grep -v "Warning\|warn(" | tail -25
done < $1
