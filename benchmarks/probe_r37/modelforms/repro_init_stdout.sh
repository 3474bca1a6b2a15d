#!/bin/bash
# D6: init without --out writes mjcf relative to the CURRENT folder, but a scenario's mjcf is read
# relative to the TOML's folder: a scenario redirected into another folder does not load.
set -u
C=/work/main/benchmarks/probe_r37/modelforms/cm.sh
R=/tmp/r37/modelforms/repro_stdout; rm -rf $R; mkdir -p $R/robots $R/configs
cp /tmp/r37/src/models/panda_pick_place/*.xml $R/robots/; cd $R
$C demo --scenario panda_pick_place --seed 0 --out traj.npz > /dev/null
$C init robots/scene.xml --object cube --task pick_place --goal 0.5 0.15 0.02 > configs/scenario.toml 2>/dev/null; echo "init rc=$?"
grep "^mjcf" configs/scenario.toml
$C rollout traj.npz --scenario configs/scenario.toml; echo "rollout rc=$?"
