#!/bin/bash
# usage: run_all_validate.sh LIST [SAMPLES]  (in the gen dir) -> val_<case>.json (validate, nthread 1, seed 0)
T=/work/main/benchmarks/probe_r38/tasks
export PYTHONPATH=/tmp/r38/tasks/src
N=${2:-32}; P=val; [ "$N" != 32 ] && P=val$N
while read c s; do
  [ -f ${P}_$c.json ] && continue
  timeout 900 taskset -c 0 /work/venv/bin/python $T/run_validate.py $s/scenario.toml $c.npz ${P}_$c.json --samples $N > log_${P}_$c.txt 2>&1
  echo "$c $(tail -1 log_${P}_$c.txt | cut -c1-300)"
done < $1
