#!/bin/bash
# usage: run_all_validate.sh [cases.tsv]  (in the gen dir) -> val_<case>.json, val.log
T=/work/main/benchmarks/probe_r31/tasks
export PYTHONPATH=/tmp/r31/src
while read c s; do
  [ -f val_$c.json ] && continue
  timeout 600 /work/venv/bin/python $T/run_validate.py $s $c.npz val_$c.json --samples 32 2>&1 | grep -v Warning | tail -2
done < ${1:-cases.tsv}
