#!/bin/bash
# run validations one after another: queue.sh "VARIANT[:N]" ...
cd /tmp/r29/physics
for spec in "$@"; do
  v=${spec%%:*}; n=64; [[ $spec == *:* ]] && n=${spec##*:}
  PYTHONPATH=/tmp/r29/src nice -n 5 /work/venv/bin/python /work/main/benchmarks/probe_r29/physics/runval.py $v $n > v/$v/val_$n.log 2>&1 || echo "$v rc=$? $(tail -1 v/$v/val_$n.log)" >> val_errors.txt
done
