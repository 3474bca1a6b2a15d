#!/bin/bash
# Rebuilds this probe's scratch folder $W (default /tmp/r37/robots/probe): the Menagerie models, the scenes,
# the scenarios and the trajectories. No third-party file is kept in this folder.
# Sources (this machine has no network; both come through the session's fetch tool):
#  * xArm7, Lite6 XMLs and all meshes: github.com/kevinzakka/mujoco_menagerie (a Menagerie fork) commit
#    75df466bb0e39d8d7fa66b556513cfc676919924, /work/.mirror/kevinzakka+mujoco_menagerie/repo. Compared with the
#    Menagerie text the search index stores (read_file google-deepmind/mujoco_menagerie):
#      ufactory_xarm7/xarm7.xml (Menagerie 4f04d622, 10682 chars): the fork's copy differs only by two line
#      wraps (the pad_box1/pad_box2 default geoms on one line); rewrapped here -> sha256 ac6b369e...da433, the
#      stored Menagerie text byte for byte (checked against a transcription of read_file's text).
#      ufactory_lite6/lite6_gripper_wide.xml, lite6_gripper_narrow.xml: taken as the fork has them (narrow: 7515
#      chars, the same length as Menagerie 15b7a2b9's, spot-checked: motor, equality, solimp, keyframe lines).
#    Meshes: the fork's ufactory_xarm7/assets/*.stl (blob ids identical to github.com/chungmanlim/Handover2's
#    copy, e.g. link_base.stl 555d6f2e...), ufactory_lite6/assets/{visual,collision}/*.stl.
#  * ARX L5 (arx_l5/arx_l5.xml + assets/*.obj): the same fork; its XML = Menagerie 0b561660's text (6848 chars, stored
#    in the index) plus one <light> line (a later Menagerie commit), sha256 5d83116b...735c.
set -e
W=${W:-/tmp/r37/robots/probe}; P=$(cd "$(dirname "$0")" && pwd)
K=${K:-/work/.mirror/kevinzakka+mujoco_menagerie/repo}; C=75df466bb0e39d8d7fa66b556513cfc676919924
PY="env PYTHONPATH=/tmp/r37/src taskset -c 1 /work/venv/bin/python"; CM=$P/cm.sh
mkdir -p $W/xarm7 $W/lite6 $W/arx
git --git-dir=$K archive $C ufactory_xarm7/assets | tar x -C $W/xarm7 --strip-components=1
git --git-dir=$K show $C:ufactory_xarm7/xarm7.xml | python3 -c "
import re, sys; s = sys.stdin.read(); s = re.sub(r'priority=\"1\" size=', 'priority=\"1\"\n            size=', s)
open('$W/xarm7/xarm7.xml', 'w').write(s)"
( cd $W/xarm7 && echo "ac6b369e0b9c5abdaca55d2c6c048102f2e1133bf550b059a8622afa4b9da433  xarm7.xml" | sha256sum -c )
git --git-dir=$K archive $C ufactory_lite6/assets ufactory_lite6/lite6_gripper_wide.xml ufactory_lite6/lite6_gripper_narrow.xml | tar x -C $W/lite6 --strip-components=1
( cd $W/lite6 && printf '%s  %s\n' c3c51416d464375378718a68809c8c9cc0e9df680d298043bb8da54966af8da3 lite6_gripper_wide.xml 9395656fb7b383f5ffa0cc8f9f8fef004d840156e671816777c85d48d0ded882 lite6_gripper_narrow.xml | sha256sum -c )
git --git-dir=$K archive $C arx_l5/assets arx_l5/arx_l5.xml | tar x -C $W/arx --strip-components=1
( cd $W/arx && echo "5d83116bda7378b6c247f3f93a0b27d6174057fcb86ce37418d1bee60bde735c  arx_l5.xml" | sha256sum -c )
cp $P/scenes/scene_xarm7*.xml $W/xarm7/; cp $P/scenes/scene_lite6*.xml $W/lite6/; cp $P/scenes/scene_arx*.xml $W/arx/
cp $P/scenarios/xarm7/*.toml $W/xarm7/; cp $P/scenarios/lite6/*.toml $W/lite6/; cp $P/scenarios/arx/*.toml $W/arx/
cd $W/xarm7
$CM init scene_xarm7.xml --object cube --task pick_place --goal-site goal --out pp_init.toml --force
$CM init scene_xarm7_ell10.xml --object cube --task pick_place --goal-site goal --out pp_ell10_init.toml --force
$CM init scene_xarm7.xml --object cube --task pick_hold --out ph_init.toml --force
$PY $P/arm_traj.py xarm7 scene_xarm7.xml pp.npz --grasp-dz 0.005 2>/dev/null
$PY $P/arm_traj.py xarm7 scene_xarm7.xml ph.npz --grasp-dz 0.005 --hold 2>/dev/null
cd $W/lite6
$CM init scene_lite6.xml --object cube --task pick_place --goal-site goal --out pp_init.toml --force
$CM init scene_lite6_ell10.xml --object cube --task pick_place --goal-site goal --out pp_ell10_init.toml --force
$PY $P/arm_traj.py lite6 scene_lite6.xml pp.npz --grasp-dz -0.003 --g0 0.5 2>/dev/null
cd $W/arx
$CM init scene_arx.xml --object cube --task pick_place --goal-site goal --out pp_init.toml --force
$CM init scene_arx_pyr1.xml --object cube --task pick_place --goal-site goal --out pp_pyr1_init.toml --force
$PY $P/arm_traj.py arx scene_arx.xml pp.npz --grasp-dz 0.015 2>/dev/null
md5sum $W/xarm7/pp.npz $W/xarm7/ph.npz $W/lite6/pp.npz $W/arx/pp.npz
S=/tmp/r37/robots/scripts $P/make_scripts.sh
echo "models, scenes, scenarios and trajectories in $W"
