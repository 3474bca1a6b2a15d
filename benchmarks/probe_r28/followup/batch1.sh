#!/bin/bash
# gripper-channel variants: validate (32 samples, API nthread=1) and the ground truth with/without letting_go
P=/work/main/benchmarks/probe_r28/followup; PY=/work/venv/bin/python; export PYTHONPATH=/tmp/r28b/src
cd /tmp/r28b/w
for t in a_partial3 a_hold15 a_hold3 a_hold5 a_noise1 a_noise2 a_regrip; do
  for s in aloha_transfer_cube ../models_aloha_transfer_cube; do
    tag=$t.$(basename $s)
    $PY $P/runval.py $s $t.npz val_$tag.json 32 2>&1 | tail -1
    $PY $P/cmp_rule.py $s $t.npz cmp_$tag.json 32 2>&1 | tail -8
  done
done
for t in p_hold15 p_hold3 p_hold5 p_noise1 p_noise2 p_regrip; do
  s=panda_pick_place; tag=$t.$s
  $PY $P/runval.py $s $t.npz val_$tag.json 32 2>&1 | tail -1
  $PY $P/cmp_rule.py $s $t.npz cmp_$tag.json 32 2>&1 | tail -8
done
