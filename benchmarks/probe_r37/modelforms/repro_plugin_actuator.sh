#!/bin/bash
# D3: an arm joint driven by MuJoCo's PID actuator plugin (mujoco.pid: ctrl is a position set point)
# is listed as a torque "motor", init converts it to a [servos] PD servo whose force limit is the
# set point's ctrlrange (2.8973 "N·m"), and analyze exits 2 blaming a numerical oscillation.
set -u
C=/work/main/benchmarks/probe_r37/modelforms/cm.sh
S=/tmp/r37/src/models/panda_pick_place
R=/tmp/r37/modelforms/repro_plugin; rm -rf $R; mkdir -p $R; cp $S/scene.xml $R/
/work/venv/bin/python - "$S/panda.xml" "$R/panda.xml" <<'PY'
import sys
s = open(sys.argv[1]).read()
s = s.replace('<position name="joint7" joint="joint7" kp="2000" kv="200" forcerange="-12 12" ctrlrange="-2.8973 2.8973"/>',
              '<plugin name="joint7" joint="joint7" plugin="mujoco.pid" instance="pid7" forcerange="-12 12" ctrlrange="-2.8973 2.8973"/>')
s = s.replace("  <worldbody>", '  <extension><plugin plugin="mujoco.pid"><instance name="pid7"><config key="kp" value="2000"/>'
              '<config key="kd" value="200"/></instance></plugin></extension>\n  <worldbody>', 1)
open(sys.argv[2], "w").write(s)
PY
cd $R
$C demo --scenario panda_pick_place --seed 0 --out traj.npz > /dev/null
$C inspect scene.xml | grep "joint7:"
$C init scene.xml --object cube --task pick_place --goal 0.5 0.15 0.02 --out scenario.toml 2>&1 | head -1
grep -A2 "servos.joint7\|^# joint7" scenario.toml
$C analyze traj.npz --scenario scenario.toml --samples 16 --figures none; echo "rc=$?"
