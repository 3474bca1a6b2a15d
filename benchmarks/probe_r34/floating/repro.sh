#!/bin/bash
# Every run of this probe, in order (from an empty scratch folder). ~17 min on one core.
# usage: repro.sh [SCRATCH]   (default /tmp/r34/floating)
set -e
P=$(cd "$(dirname "$0")" && pwd); W=${1:-/tmp/r34/floating}; mkdir -p "$W"; cd "$W"
export PYTHONPATH=/tmp/r34/src
PY="taskset -c 0 /work/venv/bin/python"; CM="$P/cm.sh"
S=$W/scripts "$P/make_scripts.sh"
# models (own MJCF, primitives)
$PY $P/make_robot.py free free.xml
$PY $P/make_robot.py free_weld free_weld.xml
$PY $P/make_robot.py planar planar.xml
$PY $P/make_robot.py planar_vel planar_vel.xml
$PY $P/make_robot.py planar_iv planar_iv.xml
$PY $P/make_robot.py planar planar_tray.xml --tray
$PY $P/make_robot.py free free_tip.xml --cart-mass 5 --grip-kp 1500
$PY $P/make_robot.py legged legged.xml --hip-force 5 --grip-kp 1500
# inspect / init as a new user would
for k in free free_weld planar planar_vel planar_iv legged; do $CM inspect $k.xml > inspect_$k.txt 2>&1 || true; done
$CM init free.xml --object cube --task pick_place --goal 0.55 0.35 0.32 --out free.toml --force 2> init_free.txt
$CM init free.xml --object base --task pick_hold > init_free_base.txt 2>&1 || true          # refused (articulated)
$CM init free_weld.xml --object cube --task pick_place --goal 0.55 0.35 0.32 --out free_weld.toml --force 2> init_free_weld.txt
$CM init planar.xml --object cube --task pick_place --goal 0.55 0.75 0.32 --out planar.toml --force 2> init_planar.txt
$CM init planar_vel.xml --object cube --task pick_place --goal 0.55 0.75 0.32 --out planar_vel.toml > init_planar_vel.txt 2>&1 || true   # refused
$CM init planar_iv.xml --object cube --task pick_place --goal 0.55 0.75 0.32 --out planar_iv.toml > init_planar_iv.txt 2>&1 || true     # refused
$CM init planar_tray.xml --object cube --task pick_place --goal 0.55 0.6 0.32 --out ptray.toml --force 2> init_ptray.txt
$CM init free_tip.xml --object cube --task pick_place --goal 0.55 0.35 0.32 --out free_tip.toml --force 2> init_free_tip.txt
$CM init legged.xml --object cube --task pick_place --goal 0.55 0.35 0.32 --out legged.toml --force 2> init_legged.txt
# scenarios: the init box, and box A / T (boxify.sh), base servo lead allowed for the fast drives
B=$P/boxify.sh
$B free.toml free_A.toml 0.05 1.5 0.2 1.2; $B free_weld.toml free_weld_A.toml 0.05 1.5 0.2 1.2; $B planar.toml planar_A.toml 0.05 1.5 0.2 1.2
(cat planar_A.toml; printf '\n[feasibility]\nlag_tolerance_slide = 0.08\n') > pdrive_A.toml
(cat planar.toml; printf '\n[feasibility]\nlag_tolerance_slide = 0.08\n') > pdrive_init.toml
$B ptray.toml ptray_A.toml 0.05 1.5 0.2 1.2
(cat ptray_A.toml; printf '\n[feasibility]\nlag_tolerance_slide = 0.08\n') > ptray_Af.toml
(cat ptray.toml; printf '\n[feasibility]\nlag_tolerance_slide = 0.08\n') > ptray_init.toml
$B free_tip.toml free_tip_T.toml 0.05 3.0 0.6 1.2; $B legged.toml legged_T.toml 0.05 3.0 0.6 1.2
# trajectories (50 Hz, DLS IK + feed-forward)
T="$PY $P/traj.py"
$T free.xml free.npz --slow 1.5 --grasp-dz 0.012
$T planar.xml planar.npz --slow 1.5 --grasp-dz 0.012 --base-dy 0.4 --goal 0.55 0.75 0.32
$T planar.xml pdrive.npz --slow 1.5 --grasp-dz 0.012 --base-dy 0.75 --goal 0.55 0.75 0.32 --yaw 90 --carry-steps 20
$T planar_tray.xml ptray.npz --slow 1.5 --grasp-dz 0.012 --pre-drive 0.4 --pre-steps 30 --goal 0.55 0.6 0.32
$T planar_tray.xml ptray_fast.npz --slow 1.5 --grasp-dz 0.012 --pre-drive 0.4 --pre-steps 14 --goal 0.55 0.6 0.32
$T free_tip.xml free_tip.npz --slow 1.5 --grasp-dz 0.012
$T legged.xml legged.npz --slow 1.5 --grasp-dz 0.012
# nominal rollouts (CLI)
for c in "free.npz free_A" "free.npz free_weld_A" "planar.npz planar_A" "pdrive.npz pdrive_A" "ptray.npz ptray_Af" "ptray_fast.npz ptray_Af" "free_tip.npz free_tip_T" "legged.npz legged_T"; do
  set -- $c; $CM rollout $1 --scenario $2.toml > rollout_${2}_${1%.npz}.txt 2>&1 || true; done
# validate (library, nthread 1, 32 samples, seed 0) + independent truth on the same samples
R=$P/run_case.sh; export S=$W/scripts
$R free_A.toml free.npz free_A; $R free.toml free.npz free_init; $R free_weld_A.toml free.npz free_weld_A
$R planar_A.toml planar.npz planar_A; $R pdrive_A.toml pdrive.npz pdrive_A; $R pdrive_init.toml pdrive.npz pdrive_init
$R ptray_Af.toml ptray.npz ptray_A; $R ptray_Af.toml ptray_fast.npz ptrayf_A; $R ptray_init.toml ptray_fast.npz ptrayf_init
$R free_tip_T.toml free_tip.npz free_tip_T; $R free_tip.toml free_tip.npz free_tip_init
$R legged_T.toml legged.npz legged_T; $R legged.toml legged.npz legged_init
# analyze (library, nthread 1, 32 samples, seed 0)
for c in "free_A free" "pdrive_A pdrive" "ptray_Af ptray_fast" "free_tip_T free_tip" "legged_T legged"; do
  set -- $c; $PY $P/run_analyze.py $1.toml $2.npz an_$1_$2.json > an_$1_$2.txt 2>&1; done
# Pinocchio (critmoment.dynamics) vs MuJoCo inverse dynamics on the free-base models
$PY $P/check_dyn.py free.xml > check_dyn_free.txt; $PY $P/check_dyn.py legged.xml > check_dyn_legged.txt
# the robot's own base dropped at the start (free_high), no keyframe, no qpos0
$PY - <<'PYEOF'
import re, numpy as np
s = open("free.xml").read(); s = re.sub(r"\s*<keyframe>.*?</keyframe>", "", s, flags=re.S)
open("free_high.xml", "w").write(s.replace('<body name="base" pos="0 0 0.17">', '<body name="base" pos="0 0 0.22">'))
z = dict(np.load("free.npz")); z.pop("qpos0"); np.savez("free_noq.npz", **z)
PYEOF
$CM init free_high.xml --object cube --task pick_place --goal 0.55 0.35 0.32 --out free_high.toml --force 2>/dev/null
$CM rollout free_noq.npz --scenario free_high.toml > rollout_free_high.txt 2>&1 || true
$PY $P/table.py "free_A:free cart 15 kg:0.05–1.5 × 0.2–1.2" "free_init:free cart 15 kg:init 0.1–4 × 0.2–1.5" \
  "free_weld_A:free cart + weld:0.05–1.5 × 0.2–1.2" "planar_A:planar base, drive 0.4 m slow:0.05–1.5 × 0.2–1.2" \
  "pdrive_A:planar base, 0.75 m drive in 0.6 s:0.05–1.5 × 0.2–1.2" "pdrive_init:same:init 0.1–4 × 0.2–1.5" \
  "ptray_A:cube on own tray, slow drive:0.05–1.5 × 0.2–1.2" "ptrayf_A:cube on own tray, fast drive:0.05–1.5 × 0.2–1.2" \
  "ptrayf_init:same:init 0.1–4 × 0.2–1.5" "free_tip_T:free cart 5 kg:0.05–3 × 0.6–1.2" "free_tip_init:same:init 0.1–4 × 0.2–1.5" \
  "legged_T:4-legged free base:0.05–3 × 0.6–1.2" "legged_init:same:init 0.1–4 × 0.2–1.5" > table.md
