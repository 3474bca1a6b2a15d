#!/bin/bash
# D9: with a scenario keyframe that places the object, a trajectory without a pose starts the object
# at the keyframe's pose while the warnings say "the model's default object pose".
set -u
HERE=/work/main/benchmarks/probe_r37/modelforms; C=$HERE/cm.sh
S=/tmp/r37/src/models/panda_pick_place
R=/tmp/r37/modelforms/kf; rm -rf $R; mkdir -p $R; cp $S/panda.xml $R/
# keyframe 'away' first: joint1 0.5, cube at (0.6, 0.1); then the bundled 'home'
sed 's|  <keyframe>|  <keyframe>\n    <key name="away" qpos="0.5 -0.78539816 0 -2.35619449 0 1.57079633 0.78539816 0.04 0.04 0.6 0.1 0.02 1 0 0 0"/>|' $S/scene.xml > $R/scene.xml
cd $R
[ -f /tmp/r37/modelforms/panda.npz ] || $C demo --scenario panda_pick_place --seed 0 --out /tmp/r37/modelforms/panda.npz > /dev/null
$C init scene.xml --object cube --task pick_place --goal 0.5 0.15 0.02 --out init.toml 2>&1 | grep keyframe
PYTHONPATH=/tmp/r37/src /work/venv/bin/python $HERE/kf_start.py
$C rollout acts_only.npz --scenario init.toml 2>&1 | grep warning
