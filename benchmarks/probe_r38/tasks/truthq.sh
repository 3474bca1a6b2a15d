#!/bin/bash
# usage: truthq.sh LIST ("case scenario" lines; needs val_<case>.json) -> tr_<case>.json (independent plain-MuJoCo truth)
T=/work/main/benchmarks/probe_r38/tasks
export PYTHONPATH=/tmp/r38/tasks/src
while read c s; do
  [ -f tr_$c.json ] && continue
  timeout 900 taskset -c 0 /work/venv/bin/python $T/truth.py --scenario $s/scenario.toml $c.npz --validate-json val_$c.json --out tr_$c.json > log_tr_$c.txt 2>&1
  echo "$c $(tail -3 log_tr_$c.txt | tr '\n' ' ' | cut -c1-400)"
done < $1
