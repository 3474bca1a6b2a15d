#!/bin/bash
# Rebuilds this probe's scratch ($W, default /tmp/r38/robots/probe; scripts into $S = /tmp/r38/robots/work):
# the Menagerie robot files (unedited), the wrapper scenes, init's scenarios, the probe's derived scenarios, the
# trajectories, and truth.py (the independent plain-MuJoCo truth of probe_r31/tasks + probe_r33/fall/truth.patch).
# No third-party file is kept in this folder. Source: github.com/kevinzakka/mujoco_menagerie (Menagerie fork) commit
# 75df466bb0e39d8d7fa66b556513cfc676919924, mirrored at /work/.mirror/kevinzakka+mujoco_menagerie/repo.
# Code under test: the snapshot /tmp/r38/robots/src (every script asserts critmoment.__file__ lies under it).
set -e
W=${W:-/tmp/r38/robots/probe}; S=${S:-/tmp/r38/robots/work}; P=$(cd "$(dirname "$0")" && pwd)
K=${K:-/work/.mirror/kevinzakka+mujoco_menagerie/repo}; C=75df466bb0e39d8d7fa66b556513cfc676919924
SRC=/tmp/r38/robots/src; PY="env PYTHONPATH=$SRC taskset -c 1 /work/venv/bin/python"; CM=$P/cm.sh
mkdir -p $W/google $W/tiago $W/tiago1 $W/aloha $S /tmp/r38/robots/res
ex() { git --git-dir=$K archive $C "${@:2}" 2>/dev/null | tar x -C $W/$1 --strip-components=1; }
ex google google_robot/assets google_robot/robot.xml
ex tiago pal_tiago_dual/assets pal_tiago_dual/tiago_dual.xml pal_tiago_dual/tiago_dual_position.xml pal_tiago_dual/tiago_dual_motor.xml
ex tiago1 pal_tiago/assets pal_tiago/tiago.xml pal_tiago/tiago_position.xml
ex aloha aloha/assets aloha/aloha.xml aloha/joint_position_actuators.xml aloha/keyframe_ctrl.xml
( cd $W && sha256sum -c <<'SUMS'
c6c69faf532e54a5326ddeb2a474021727d9e0af961138b0d7c2ec2d17f8185a  google/robot.xml
1f69335e5859a062ba12e1c8d5463e24f1aaae4473c4b9c40759d5f33f75dc04  tiago/tiago_dual.xml
79935fcae175c3aa40bbd8049893d1dd22a1cdc259c32aedfabc8b2b2bee9915  tiago/tiago_dual_position.xml
8b8d475a395479dd8cb67fb9b2731a072f1e107c82e30a8150983dede3fb7661  tiago/tiago_dual_motor.xml
db05026576e5c59af39bae4f68cb4cda4078c01177134fcd84bd8a30020d2d0b  tiago1/tiago.xml
f7c763dc9a0790cec111e8197ca2fa26663fde0d2f7283a24bca024084d0dfd8  tiago1/tiago_position.xml
e010a84a309367046ba18827a130ee2ce08b1d2217070593773cfd4fd8f3a3c8  aloha/aloha.xml
ce843cf0cfecea5ec1f117eb4257d4249dc2296e92e5f2ffb40f2e0178109bc6  aloha/joint_position_actuators.xml
b232fdc187f5660f2a35665c984e2b0634d152be8c0dce65437179025078146a  aloha/keyframe_ctrl.xml
SUMS
)
cp $P/scenes/scene_google*.xml $W/google/; cp $P/scenes/scene_tiago.xml $P/scenes/scene_tiago_motor.xml $P/scenes/scene_tiago_nocollide.xml $W/tiago/
cp $P/scenes/scene_tiago1.xml $W/tiago1/; cp $P/scenes/scene_aloha*.xml $W/aloha/
cp $P/scenarios/google/*.toml $W/google/; cp $P/scenarios/aloha/*.toml $W/aloha/; cp $P/scenarios/tiago1/*.toml $W/tiago1/
cp $P/arm_traj.py $P/aloha_traj.py $P/run_validate.py $P/run_analyze.py $P/summ.py $P/queue.sh $P/slip3d.py $P/plain_check.py $S/
B=$SRC/benchmarks
patch -s -o $S/truth.py $B/probe_r31/tasks/truth.py $B/probe_r33/fall/truth.patch
sed -i 's#/tmp/r33/src#/tmp/r38/robots/src#g; s#/tmp/r31/src#/tmp/r38/robots/src#g' $S/truth.py
python3 - $S/truth.py <<'PYEOF'
import sys
p = sys.argv[1]; s = open(p).read()
s = s.replace('import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r38/robots/src"), _cm_check.__file__  # r33 snapshot\n', '', 1)
s = s.replace('import mujoco\nimport numpy as np\n', 'import mujoco\nimport numpy as np\nimport critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r38/robots/src"), _cm_check.__file__  # r38 snapshot\n', 1)
open(p, 'w').write(s)
PYEOF
cd $W/google
$CM init scene_google.xml --object cube --task pick_place --goal-site goal --out pp_init.toml --force
$CM init scene_google_ell10.xml --object cube --task pick_place --goal-site goal --out pp_ell10_init.toml --force
$PY $S/arm_traj.py google scene_google.xml pp.npz --slow 2 --approach 250 2>/dev/null
cd $W/aloha
$CM init scene_aloha.xml --object cube --task handover --out ho_init.toml --force
$CM init scene_aloha_pyr1.xml --object cube --task handover --out ho_pyr1_init.toml --force
$PY $S/aloha_traj.py scene_aloha.xml ho.npz --slow 2 2>/dev/null
md5sum $W/google/pp.npz $W/aloha/ho.npz   # this probe: 5bf60bab... and acce71a5...
echo "models, scenes, scenarios, trajectories in $W; scripts in $S"
bash "$(dirname "$0")/make_copies.sh"   # summ.py, run_analyze.py, run_validate.py from probe_r37/robots
