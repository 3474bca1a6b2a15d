#!/bin/bash
# D5: a compiled .mjb model (mujoco.mj_saveModel) is refused with MuJoCo's "could not find decoder
# for resource" instead of "critmoment needs the MJCF (XML) source"
set -u
C=/work/main/benchmarks/probe_r37/modelforms/cm.sh
R=/tmp/r37/modelforms/repro_mjb; rm -rf $R; mkdir -p $R; cp /tmp/r37/src/models/panda_pick_place/*.xml $R/; cd $R
PYTHONPATH=/tmp/r37/src /work/venv/bin/python -c "
import mujoco; mujoco.mj_saveModel(mujoco.MjModel.from_xml_path('scene.xml'), 'scene.mjb', None)"
$C inspect scene.mjb; echo "rc=$?"
$C init scene.mjb --object cube --task pick_hold; echo "rc=$?"
