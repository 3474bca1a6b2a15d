#!/bin/bash
# Trajectory forms (make_trajs.py) through rollout --json (and analyze for a few); run from /tmp/r37/modelforms
C=/work/main/benchmarks/probe_r37/modelforms/cm.sh
T=/tmp/r37/modelforms/trajs
P=/tmp/r37/modelforms/base/scenario.toml   # the bundled Panda scenario (copy)
summ() { /work/venv/bin/python -c "
import json,sys
try:
    r=json.load(open('$1'))
    print({k: r.get(k) for k in ('steps','dt','duration','completed','max_stage','shortfalls')} if 'steps' in r else {k: r.get(k) for k in ('verdict','p_success')})
except Exception as e: print('no json', e)"; }
for f in one_row.npz extra_keys.npz f32.npz time_gap.npz longer.npz shorter.npz; do
  echo "== rollout $f"; $C rollout $T/$f --scenario $P --json > /tmp/r37/modelforms/tr_out.json 2> /tmp/r37/modelforms/tr_err.txt; echo "rc=$?"; cut -c1-400 /tmp/r37/modelforms/tr_err.txt; summ /tmp/r37/modelforms/tr_out.json
done
echo "== rollout aloha.npz (reference)"; $C rollout aloha.npz --json > tr_out.json 2> tr_err.txt; echo "rc=$?"; cut -c1-300 tr_err.txt; summ tr_out.json
for f in act_extra.hdf5 act_f32.hdf5 lr30 lr50; do
  echo "== rollout $f (bundled ALOHA)"; $C rollout $T/$f --json --object-pose $(/work/venv/bin/python -c "import numpy as np; print(*np.load('aloha.npz')['object_pose'])") > tr_out.json 2> tr_err.txt; echo "rc=$?"; cut -c1-400 tr_err.txt; summ tr_out.json
done
for f in longer.npz shorter.npz extra_keys.npz; do
  echo "== analyze $f"; $C analyze $T/$f --scenario $P --samples 32 --figures none --json > tr_out.json 2> tr_err.txt; echo "rc=$?"; cut -c1-400 tr_err.txt; summ tr_out.json
done
