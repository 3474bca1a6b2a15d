#!/bin/bash
# Rebuilds this probe's scenes, scenarios and nominal trajectory under $W (default /tmp/r36/hands).
# No third-party file is kept in this folder. Sources:
#  * Shadow Hand E3M5 (right): Menagerie shadow_hand/right_hand.xml, the version the search index stores
#    (google-deepmind/mujoco_menagerie commit 0498058ea4d85f1f7630496c61479b0ff1fabbfe, 17389 bytes:
#    <option impratio="10"/>, cone not set = pyramidal). This machine has no network; the file is rebuilt from
#    github.com/neeltron/Bipolar-Control-for-Three-Finger-Robot-Hand commit 1330e1b, shadow_hand/right_hand.xml
#    (a Menagerie copy with cone="elliptic", a root free joint, a blank line and one forearm box moved) by the
#    four edits below, which give the stored Menagerie text's length (17389) and its '</tendon>' offset;
#    result sha256 cf3acb2a0fd547716f706b8609941e1400a601846ac0a8f548462301b07df96c.
#    Meshes: that mirror's shadow_hand/assets/*.obj at 1330e1b (same blobs as mujoco-mjx's test_data copy by size).
set -e
W=${W:-/tmp/r36/hands}; P=$(cd "$(dirname "$0")" && pwd)
NEEL=${NEEL:-/work/.mirror/neeltron+Bipolar-Control-for-Three-Finger-Robot-Hand/repo}
PY="env PYTHONPATH=/tmp/r36/src /work/venv/bin/python"; CM=$P/cm.sh
mkdir -p $W/shadow/assets $W/res
cp $P/cm.sh $P/queue.sh $P/disagree.py $W/
for f in forearm_0 forearm_1 forearm_collision wrist palm f_knuckle f_proximal f_middle f_distal_pst lf_metacarpal th_proximal th_middle th_distal_pst; do
  git -C $NEEL show 1330e1b:shadow_hand/assets/$f.obj > $W/shadow/assets/$f.obj; done
git -C $NEEL show 1330e1b:shadow_hand/right_hand.xml | python3 -c "
import sys; s = sys.stdin.read()
s = s.replace('<option cone=\"elliptic\" impratio=\"10\"/>', '<option impratio=\"10\"/>', 1)
s = s.replace('    <joint name=\"rh_root_free\" type=\"free\"/>\n', '', 1).replace('<worldbody>\n  \n', '<worldbody>\n', 1)
s = s.replace('pos=\"0.01 0.0 0.181\" quat=\"0.380188 0.924909 0 0\"', 'pos=\"0 -0.01 0.181\" quat=\"0.924909 0 0.380188 0\"', 1)
open('$W/shadow/right_hand.xml', 'w').write(s)"
( cd $W/shadow && echo "cf3acb2a0fd547716f706b8609941e1400a601846ac0a8f548462301b07df96c  right_hand.xml" | sha256sum -c )
cat > $W/shadow/shadow_ball.xml <<'XML'
<mujoco model="shadow_ball">
  <!-- Menagerie shadow_hand/right_hand.xml attached unedited (forearm and wrist included, palm down) under a
       vertical slide with a position servo (probe_r36), a floor, a pedestal and a free 3.5 cm-radius ball.
       The hand's own <option impratio="10"/> (pyramidal cone) is repeated here: <attach> keeps the parent's
       option (MuJoCo warns "keeping parent value"). -->
  <compiler angle="radian"/>
  <option impratio="10"/>
  <asset><model name="shadow" file="right_hand.xml"/></asset>
  <worldbody>
    <light pos="0 0 1"/>
    <geom name="floor" type="plane" size="1 1 0.05" rgba="0.3 0.3 0.3 1"/>
    <body name="lift" pos="-0.30 0 0.40">
      <joint name="lift" type="slide" axis="0 0 1" range="-0.25 0.1" damping="100"/>
      <body name="mount" quat="0 1 0 0">
        <attach model="shadow" body="rh_forearm" prefix=""/>
      </body>
    </body>
    <geom name="pedestal" type="cylinder" size="0.012 0.04" pos="0.035 0 0.04" rgba="0.5 0.5 0.5 1"/>
    <body name="ball" pos="0.035 0 0.115">
      <freejoint name="ball_joint"/>
      <geom name="ball" type="sphere" size="0.035" mass="0.1" rgba="1 0 0 1"/>
    </body>
  </worldbody>
  <actuator>
    <position name="lift" joint="lift" kp="5000" kv="300" ctrlrange="-0.25 0.1" forcerange="-150 150"/>
  </actuator>
</mujoco>
XML
sed 's/shadow_ball"/shadow_ball_ell"/; s#<option impratio="10"/>#<option cone="elliptic" impratio="10"/>#' $W/shadow/shadow_ball.xml > $W/shadow/shadow_ball_ell.xml
cd $W/shadow
$CM init shadow_ball.xml --object ball --task pick_hold --out ph_auto.toml --force > $W/res/init_shadow_nogripper.txt 2>&1
$CM init shadow_ball.xml --object ball --task pick_hold --gripper rh_palm --out ph_init.toml --force > $W/res/init_shadow.txt 2>&1
$CM init shadow_ball_ell.xml --object ball --task pick_hold --gripper rh_palm --out ph_ell_init.toml --force > $W/res/init_shadow_ell.txt 2>&1
# The only edit: the gripper channel's closed/open poses (a grasp pose instead of init's measured extremes; the
# knuckle spreads FFJ4/RFJ4/LFJ4 get open 0.05, closed 0: closed == open is refused). Order of init's channel:
# THJ4 THJ2 THJ1 FFJ4 FFJ3 FFJ0 MFJ3 MFJ0 RFJ4 RFJ0 LFJ4 LFJ3 LFJ0
for s in ph ph_ell; do
  python3 - $( [ $s = ph ] && echo ph_init.toml || echo ph_ell_init.toml ) $s.toml <<'PY'
import sys, re
s = open(sys.argv[1]).read()
s, n1 = re.subn(r'(?m)^closed = \[0\.0, 0\.698132, 1\.5708, 0\.349066, .*\]$', 'closed = [1.2, 0.3, 0.8, 0.0, 1.1, 2.0, 1.1, 2.0, 0.0, 2.0, 0.0, 1.1, 2.0]   # probe_r36: the grasp pose', s)
s, n2 = re.subn(r'(?m)^open = \[1\.22173, -0\.698132, .*\]$', 'open = [0.0, 0.0, 0.0, 0.05, 0.0, 0.0, 0.0, 0.0, 0.05, 0.0, 0.05, 0.0, 0.0]   # probe_r36: the open pose', s)
assert n1 == n2 == 1, (n1, n2)
open(sys.argv[2], 'w').write(s)
PY
  sed 's/^range = \[0.05, 2.0\]   # \[kg\]/range = [0.05, 0.6]   # [kg] (narrow: probe_r36)/; s/^range = \[0.2, 1.5\]   # sliding/range = [0.3, 1.5]   # (narrow: probe_r36) sliding/' $s.toml > ${s}_narrow.toml
  grep -c probe_r36 ${s}_narrow.toml
done
$PY $P/gen_shadow.py ph.toml nom.npz --ball 0.035 0 0.115 --low -0.228 --set rh_A_THJ5=0.45 --follow rh_A_RFJ3=1.1
S=$W/scripts $P/make_scripts.sh
echo "scenes, scenarios and trajectory in $W/shadow"
