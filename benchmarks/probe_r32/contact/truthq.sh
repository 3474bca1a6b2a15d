#!/bin/bash
# independent truth on each variant's validate samples -> v/VAR/truth.json, summary line in truth.tsv
cd /tmp/r32/contact
for v in "$@"; do
  t=aloha_s0.npz; [[ $v == p_* ]] && t=panda_s0.npz; [ -f v/$v/traj.npz ] && t=v/$v/traj.npz
  PYTHONPATH=/tmp/r32/src nice -n 5 /work/venv/bin/python /work/main/benchmarks/probe_r32/contact/truth.py --scenario v/$v $t --validate-json v/$v/val_32_0.json --out v/$v/truth.json > v/$v/truth.log 2>&1
  echo -e "$v\t$(grep '^nominal ' v/$v/truth.log | cut -c1-30)\t$(tail -2 v/$v/truth.log | tr '\n' ' ')" | tee -a truth.tsv
done
