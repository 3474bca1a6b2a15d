#!/bin/bash
# D1: a scene reached through a symlink is compiled from the link's TARGET folder, so its relative
# <include>s resolve beside the target, not beside the link as MuJoCo itself does.
# Self-contained: builds everything under /tmp/r37/modelforms/repro_link (needs the bundled Panda files).
set -u
C=/work/main/benchmarks/probe_r37/modelforms/cm.sh
S=/tmp/r37/src/models/panda_pick_place
R=/tmp/r37/modelforms/repro_link; rm -rf $R; mkdir -p $R/shared $R/robotB $R/hub/blobs $R/hub/snapshots/rev1
cp $S/scene.xml $S/panda.xml $R/shared/                                  # shared scene + the 35 N hand
sed 's/forcerange="-35 35"/forcerange="-5 5"/g' $S/panda.xml > $R/robotB/panda.xml   # robot B: 5 N fingers
ln -s ../shared/scene.xml $R/robotB/scene.xml                            # robot B uses the shared scene
cd $R
echo "--- MuJoCo (link's folder):"; PYTHONPATH=/tmp/r37/src /work/venv/bin/python -c "
import mujoco; m=mujoco.MjModel.from_xml_path('robotB/scene.xml'); print('finger_left forcerange', m.actuator('finger_left').forcerange)"
echo "--- critmoment inspect robotB/scene.xml:"; $C inspect robotB/scene.xml | grep 'finger_left:'
# Hugging Face hub cache layout: every file a link to a blob without extension
cp $S/scene.xml hub/blobs/aaa111; cp $S/panda.xml hub/blobs/bbb222
ln -s ../../blobs/aaa111 hub/snapshots/rev1/scene.xml; ln -s ../../blobs/bbb222 hub/snapshots/rev1/panda.xml
echo "--- MuJoCo (hub layout):"; PYTHONPATH=/tmp/r37/src /work/venv/bin/python -c "
import mujoco; print('nbody', mujoco.MjModel.from_xml_path('hub/snapshots/rev1/scene.xml').nbody)"
echo "--- critmoment inspect hub/snapshots/rev1/scene.xml:"; $C inspect hub/snapshots/rev1/scene.xml; echo "rc=$?"
# the audit: the linked scene (critmoment compiles shared/panda.xml, 35 N) vs the same files copied
# (robot B's 5 N fingers, what MuJoCo loads from robotB/scene.xml)
mkdir -p robotB_copy; cp shared/scene.xml robotB/panda.xml robotB_copy/
$C demo --scenario panda_pick_place --seed 0 --out traj.npz > /dev/null
for d in robotB robotB_copy; do
  $C init $d/scene.xml --object cube --task pick_place --goal 0.5 0.15 0.02 --out $d/scenario.toml --force > /dev/null 2>&1
  echo "== analyze with $d/scenario.toml"; $C analyze traj.npz --scenario $d/scenario.toml --samples 32 --figures none | head -2
done
# a 1.0 kg cube, inside the safe region the linked audit states (mass <= 1.25 kg): its nominal run
for d in robotB robotB_copy; do
  sed '/^\[uncertainty.mass\]/,/^nominal/ s/^nominal = 0.1/nominal = 1.0/' $d/scenario.toml > $d/m1.toml
  echo "== $d, 1.0 kg:"; $C rollout traj.npz --scenario $d/m1.toml 2>/dev/null | head -1
done
