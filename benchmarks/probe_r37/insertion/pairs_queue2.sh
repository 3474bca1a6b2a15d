#!/bin/bash
# The --pairs truth for three more cases, after pairs_queue.sh (in /tmp/r37/insertion, core 1).
export PYTHONPATH=/tmp/r37/src; P=/work/venv/bin/python; D=/work/main/benchmarks/probe_r37/insertion
while ! grep -q an_peg_ship_narrow res/queue.log; do sleep 5; done
while read n t o c; do
  cc=""; [ "$c" = elliptic ] && cc="--cone elliptic --impratio 10"
  taskset -c 1 $P $D/truth.py $t --object $o $cc --pairs --samples res/val_$n.json --out res/truthpairs_$n.json > res/truthpairs_$n.txt 2>&1
  echo "truthpairs_$n done $(date -u +%T)" >> res/queue.log
done <<LIST
sock_ship_narrow sock1.npz socket x
sock_ell sock1.npz socket elliptic
peg_ell peg1.npz peg elliptic
LIST
