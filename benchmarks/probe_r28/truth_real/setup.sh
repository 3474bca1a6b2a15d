#!/bin/bash
# Rebuild /tmp/r28/truth_real (scenes, scenarios, trajectories) from the wheels (pip download, never installed).
set -e
W=/tmp/r28/truth_real; H=/work/main/benchmarks/probe_r28/truth_real; PY=/work/venv/bin/python
export PYTHONPATH=/tmp/r28/src
mkdir -p $W/wheels && cd $W/wheels
[ -d tas ] || { $PY -m pip download trossen-arm-sim==0.2.3 --no-deps -d tas_whl -q && mkdir -p tas && (cd tas && unzip -q -o ../tas_whl/*.whl); }
[ -d oa ] || { $PY -m pip download openarm-mujoco==2.3.0 --no-deps --no-binary :all: -d oa_sdist -q && mkdir -p oa && (cd oa && tar xzf ../oa_sdist/*.tar.gz); }
# WidowX AI (probe_r24 scenes/scenarios, unedited)
mkdir -p $W/wxai && cp /work/main/benchmarks/probe_r24/robots/wxai/{scene_shipped.xml,scene_elliptic10.xml,scenario_shipped_narrow.toml,scenario_elliptic10_narrow.toml,traj.py} $W/wxai/
ln -sfn $W/wheels/tas/trossen_arm_sim/assets $W/wxai/assets
(cd $W/wxai && CRITMOMENT_REAL_MODELS=/work/main/benchmarks/real_models $PY traj.py scene_shipped.xml traj.npz)
# OpenArm (probe_r25 scenes/scenarios; the pyramidal narrow box is the shipped narrow box on the pyramidal scene)
mkdir -p $W/openarm && cp /work/main/benchmarks/probe_r25/robots/openarm/{make_scene.py,traj.py,scenario_shipped_narrow.toml} $W/openarm/
cp $H/scenarios/openarm_scenario_pyramidal1_narrow.toml $W/openarm/scenario_pyramidal1_narrow.toml
ln -sfn $W/wheels/oa/openarm_mujoco-2.3.0/v2 $W/openarm/assets
(cd $W/openarm && $PY make_scene.py shipped && $PY make_scene.py pyramidal1 && CRITMOMENT_REAL_MODELS=/work/main/benchmarks/real_models $PY traj.py assets/pedestal/critmoment_r25_oa_shipped.xml traj.npz)
# ACT gym-aloha: init's scenarios + the real_models scripted transfer (seed 0); light-box copies
(cd $W && CRITMOMENT_REAL_MODELS=$W/rm $PY $H/make_act.py)
cp $H/scenarios/scenario_shipped_light.toml $H/scenarios/scenario_elliptic10_light.toml $W/act/
# OpenArm bimanual hand-over (probe_r27, unedited scenario and trajectory script)
mkdir -p $W/ho && cp /work/main/benchmarks/probe_r27/handover/{make_scene.py,traj.py,scenario_shipped_narrow.toml} $W/ho/
ln -sfn $W/wheels/oa/openarm_mujoco-2.3.0/v2 $W/ho/assets
(cd $W/ho && $PY make_scene.py shipped && CRITMOMENT_REAL_MODELS=/work/main/benchmarks/real_models $PY traj.py assets/pedestal/critmoment_r27_oa_ho_shipped.xml ho.npz)
