#!/bin/bash
# usage (from the generated folder): run_all_validate.sh  -> val_<case>.json for every case, one at a time
T=/work/main/benchmarks/probe_r30/tasks
export PYTHONPATH=/tmp/r30/src
for f in A_nominal A_chunk100 A_chunk50 A_chunk100_te A_fast05 A_slow2 A_carryfast A_pause3 A_overshoot A_jtilt45 A_jtiltm45 A_noise_ar A_noise_w20 A_jrot90 A_jroll60; do
  /work/venv/bin/python $T/run_validate.py aloha_m15 $f.npz val_$f.json --samples 32 2>/dev/null | cut -c1-400
done
for f in P_nominal P_chunk100 P_chunk50 P_chunk100_te P_fast05 P_slow2 P_carryfast P_overshoot P_pause4 P_pause4_lift P_j6tilt45 P_j6tiltm45 P_j5roll60 P_j7rot90 P_tiltcarry40 P_noise_ar P_noise_w20; do
  /work/venv/bin/python $T/run_validate.py panda_pick_place $f.npz val_$f.json --samples 32 2>/dev/null | cut -c1-400
done
/work/venv/bin/python $T/run_validate.py stack P_stack.npz val_P_stack.json --samples 32 2>/dev/null | cut -c1-400
/work/venv/bin/python $T/run_validate.py stack_nosup P_stack.npz val_P_stack_nosup.json --samples 32 2>/dev/null | cut -c1-400
