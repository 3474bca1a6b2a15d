#!/bin/bash
# independent plain-MuJoCo truth (truth.py) on samples 0..N-1 of each variant's validate run
# usage: truthq.sh N VARIANT...   -> v/VARIANT/truth.json, truth.txt; summary row in /tmp/r29/physics/truth.tsv
cd /tmp/r29/physics
N=$1; shift
for v in "$@"; do
  case $v in a_*) tr=aloha_s0.npz;; *) tr=panda_s0.npz;; esac
  [ -f v/$v/traj.npz ] && tr=v/$v/traj.npz
  PYTHONPATH=/tmp/r29/src nice -n 5 /work/venv/bin/python /work/main/benchmarks/probe_r29/physics/truth.py --scenario v/$v $tr \
     --validate-json v/$v/val_64_0.json --only $(seq 0 $((N-1))) --out v/$v/truth.json > v/$v/truth.txt 2>&1
  echo -e "$v\t$(head -1 v/$v/truth.txt | cut -c1-200)\t$(tail -1 v/$v/truth.txt)" >> truth.tsv
done
