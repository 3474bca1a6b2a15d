#!/bin/bash
# F1: a free-base robot that tips over 10-15° while placing is audited as a success.
# Builds the 5 kg cart (own model), its trajectory and scenario in $W, then: critmoment's own full
# rollouts (validate on explicit points, library, nthread 1) and a plain-MuJoCo replay printing the base tilt.
set -e
P=$(cd "$(dirname "$0")" && pwd); W=${1:-/tmp/r34/floating/tip}; mkdir -p "$W"; cd "$W"
export PYTHONPATH=/tmp/r34/src; PY="taskset -c 0 /work/venv/bin/python"
$PY $P/make_robot.py free free_tip.xml --cart-mass 5 --grip-kp 1500
$PY $P/traj.py free_tip.xml free_tip.npz --slow 1.5 --grasp-dz 0.012
$P/cm.sh init free_tip.xml --object cube --task pick_place --goal 0.55 0.35 0.32 --out free_tip.toml --force 2>/dev/null
$P/boxify.sh free_tip.toml free_tip_T.toml 0.05 3.0 0.6 1.2
# 1.883 kg / mu 0.97 (sample 28 of the 32-sample validate), and 0.2 kg nominal-like for contrast
$PY ${S:-/tmp/r34/floating/scripts}/run_samples.py free_tip_T.toml free_tip.npz pts.json --mass 0.2 1.883 --friction 0.97
$PY -c "import json; [print(p['values'], p['outcome'], 'predicted_failed', p['predicted_failed']) for p in json.load(open('pts.json'))['per_sample']]"
$PY $P/look.py free_tip.xml free_tip.npz --mass 1.883 --friction 0.97 --every 0.5 | sed -n '17,25p'
