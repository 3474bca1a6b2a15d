#!/bin/bash
# Rebuilds the third-party files of this probe under $W (default /tmp/r37/insertion): gym-aloha's wheel
# (not installed; only its assets unzipped), as benchmarks/real_models/scenes.py fetches ACT's transfer-cube scene.
set -e
W=${W:-/tmp/r37/insertion}
mkdir -p $W/wheel
ls $W/wheel/gym_aloha-*.whl >/dev/null 2>&1 || pip download gym-aloha --no-deps --only-binary :all: -d $W/wheel
WHL=$(ls $W/wheel/gym_aloha-*.whl | tail -1)
sha256sum $WHL
( cd $W && unzip -o -q $WHL 'gym_aloha/assets/*' )
sha256sum $W/gym_aloha/assets/bimanual_viperx_insertion.xml $W/gym_aloha/assets/scene.xml
# the contact-model copy: the same file with <option cone="elliptic" impratio="10"/> (the shipped scene sets none:
# pyramidal, impratio 1)
sed 's#^<mujoco>#<mujoco>\n    <option cone="elliptic" impratio="10"/>#' $W/gym_aloha/assets/bimanual_viperx_insertion.xml \
  > $W/gym_aloha/assets/insertion_elliptic10.xml
grep -c 'cone="elliptic"' $W/gym_aloha/assets/insertion_elliptic10.xml
