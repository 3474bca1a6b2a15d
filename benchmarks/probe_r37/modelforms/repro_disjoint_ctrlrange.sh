#!/bin/bash
# D4: a ctrlrange that does not overlap its joint's range (a degree model whose ctrlrange was
# converted to degrees too: joint4 range [-3.07, -0.07] rad, ctrlrange [-176, -4.0]) passes init
# ("it loads as written"); rollout/analyze then fail with an internal bounds message naming no
# actuator, joint or cause.
set -u
C=/work/main/benchmarks/probe_r37/modelforms/cm.sh
S=/tmp/r37/src/models/panda_pick_place
R=/tmp/r37/modelforms/repro_ctrl; rm -rf $R; mkdir -p $R; cp $S/scene.xml $S/panda.xml $R/
sed -i 's/ctrlrange="-3.0718 -0.0698"/ctrlrange="-176.0011755 -3.99924541"/' $R/panda.xml
cd $R
$C demo --scenario panda_pick_place --seed 0 --out traj.npz > /dev/null
$C init scene.xml --object cube --task pick_place --goal 0.5 0.15 0.02 --out scenario.toml 2>&1 | head -1; echo "init rc=${PIPESTATUS[0]}"
$C rollout traj.npz --scenario scenario.toml; echo "rollout rc=$?"
