#!/bin/bash
# D2: the object held by an active <equality weld> to the hand (a "magic grasp", as RL sims attach
# objects) is audited SAFE, P = 1, exit 0, over a box where the real grip slips (the same chunk
# without the weld: CONDITIONAL, P = 0.47, slip above ~0.57 kg). Nothing (inspect, init, analyze)
# mentions the constraint.
set -u
HERE=/work/main/benchmarks/probe_r37/modelforms; C=$HERE/cm.sh
R=/tmp/r37/modelforms/repro_weld; rm -rf $R; mkdir -p $R/base; cp /tmp/r37/src/models/panda_pick_place/*.xml $R/base/; cd $R
$C demo --scenario panda_pick_place --seed 0 --out panda.npz > /dev/null
$C init base/scene.xml --object cube --task pick_place --goal 0.5 0.15 0.02 --out base/init.toml > /dev/null 2>&1
PYTHONPATH=/tmp/r37/src /work/venv/bin/python $HERE/make_weld.py $R/w $R/base $R/panda.npz
cd w
for v in noweld weld; do
  $C init scene_$v.xml --object cube --task pick_hold --out $v.toml --force > /dev/null 2>&1
  echo "== $v"; $C analyze chunk.npz --scenario $v.toml --samples 32 --figures none | head -3; echo "rc=${PIPESTATUS[0]}"
done
