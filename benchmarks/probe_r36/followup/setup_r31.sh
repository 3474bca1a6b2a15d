#!/bin/bash
# Rebuild /tmp/r31/robots (models, scenes, scenarios, trajectories) for the r31 robots probe.
# Code under test: PYTHONPATH=/tmp/r36f/src CRITMOMENT_REAL_MODELS=/work/main/benchmarks/real_models (git archive of cf9aace). Menagerie itself is over the
# fetch limit; its meshes come from two public snapshots (bring them first with the session's
# fetch tool): github:RSeto14/RL4WindowX250 (trossen_wx250s/assets, Menagerie's STL files) and
# github:dd292/manipulation_lerobot (low_cost_robot_arm/assets). Their XMLs are edited copies;
# the Menagerie XMLs are kept verbatim in models/ (wx250s_menagerie.xml = Menagerie 3ff28577,
# 7608 chars; lcra_menagerie.xml = Menagerie 464b5ae8, 8150 chars, both read with read_file).
set -e
W=/tmp/r36f/followup/r31; P=/work/main/benchmarks/probe_r31/robots; Q=/tmp/r36f/followup/r31p; PY=/work/venv/bin/python
export PYTHONPATH=/tmp/r36f/src CRITMOMENT_REAL_MODELS=/work/main/benchmarks/real_models
M1=/work/.mirror/RSeto14+RL4WindowX250/repo; M2=/work/.mirror/dd292+manipulation_lerobot/repo
mkdir -p $W && cd $W && cp $P/cm.sh .
git --git-dir=$M1 archive HEAD trossen_wx250s/assets | tar x
git --git-dir=$M2 archive HEAD low_cost_robot_arm/assets | tar x
cp $P/models/trossen_wx250s/*.xml trossen_wx250s/; cp $P/models/low_cost_robot_arm/*.xml low_cost_robot_arm/
cp $P/scenarios/wx/*.toml trossen_wx250s/; cp $P/scenarios/lc/*.toml low_cost_robot_arm/
cd $W/trossen_wx250s && $PY $Q/arm_traj.py wx scene_wx_shipped.xml traj.npz --grasp-dz 0.005 2>/dev/null
$PY $Q/arm_traj.py wx scene_wx_shipped.xml traj_hold.npz --grasp-dz 0.005 --hold 2>/dev/null
cd $W/low_cost_robot_arm && $PY $Q/arm_traj.py lc scene_lc_shipped.xml traj.npz --grasp-dz 0.004 --lift 0.06 2>/dev/null
echo "rebuilt under $W"
