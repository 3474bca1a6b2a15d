#!/bin/bash
# One case after another, pinned to core 1: validate (64 samples, seed 0) -> independent truth -> analyze (256, seed 0).
# usage: queue.sh NAME SCENARIO TRAJ OBJECT [elliptic] [noanalyze]   (run in /tmp/r37/insertion)
export PYTHONPATH=/tmp/r37/src; P=/work/venv/bin/python; D=/work/main/benchmarks/probe_r37/insertion
n=$1; s=$2; t=$3; o=$4; c=""; [ "$5" = elliptic ] && c="--cone elliptic --impratio 10"
taskset -c 1 $P $D/run_validate.py $s $t res/val_$n.json --samples 64 --seed 0 > res/val_$n.txt 2>&1
taskset -c 1 $P $D/truth.py $t --object $o $c --samples res/val_$n.json --out res/truth_$n.json > res/truth_$n.txt 2>&1
[ "$6" = noanalyze ] || taskset -c 1 $P $D/run_analyze.py $s $t res/an_$n.json > res/an_$n.txt 2>&1
echo "$n done $(date -u +%T)" >> res/queue.log
