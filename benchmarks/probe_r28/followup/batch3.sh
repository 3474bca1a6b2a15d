#!/bin/bash
# gripper noise (amplitude 0.2, seeds 0-3) on the Panda default box and ALOHA mass<=1.5 box, 64 samples
P=/work/main/benchmarks/probe_r28/followup; PY=/work/venv/bin/python; export PYTHONPATH=/tmp/r28b/src
cd /tmp/r28b/w
for t in p_noise2 p_noise2s1 p_noise2s2 p_noise2s3 p_hold15 p_hold3; do
  $PY $P/runval.py panda_pick_place $t.npz val64_$t.json 64 2>&1 | tail -1
  $PY $P/cmp_rule.py panda_pick_place $t.npz cmp64_$t.json 64 2>&1 | tail -6
done
for t in a_noise2 a_noise2s1 a_noise2s2 a_noise2s3 a_hold15; do
  $PY $P/runval.py ../models_aloha_transfer_cube $t.npz val64_$t.json 64 2>&1 | tail -1
  $PY $P/cmp_rule.py ../models_aloha_transfer_cube $t.npz cmp64_$t.json 64 2>&1 | tail -6
done
