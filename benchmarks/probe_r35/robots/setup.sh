#!/bin/bash
# Rebuilds this probe's scenes, scenarios and nominal trajectories under $W (default /tmp/r35/robots).
# No third-party file is kept in this folder. Sources:
#  * Wonik Allegro (right hand): Menagerie wonik_allegro/right_hand.xml, the version the search index stores
#    (google-deepmind/mujoco_menagerie commit 28ffb48b5c1d409a37fbfbb01c023c12e61cdefd, 9941 bytes). This machine
#    has no network; the file is rebuilt from github.com/neeltron/Bipolar-Control-for-Three-Finger-Robot-Hand
#    commit 7c2c44c98fac80aaf6f7271f48fd1ca701376f96, wonik_allegro/right_hand.xml (an older Menagerie version:
#    option elliptic/impratio 10, joint damping .1, kp 1) by the three edits below that turn it into the
#    stored Menagerie text (checked: same 9941 characters, same content as read_file's text);
#    result sha256 1bf74af83cc8fc4c4cdeb1c1576cc5db4473655c620605057ce188569a1f3a7b.
#    Meshes: that mirror's wonik_allegro/assets (git blobs: base_link 56cc81b5, link_0.0 6db5cdb1, link_1.0 84e43514,
#    link_2.0 20a911a4, link_3.0 a1fffee0, link_3.0_tip b7d9be8a, link_12.0_right 7eecece5, link_13.0 3ca4ec36,
#    link_14.0 73d6f695, link_15.0 e16bff45, link_15.0_tip 9b1d8119). They are visual geoms, but they carry the
#    links' mass (density 800; the collision boxes have mass 0), so they are needed as shipped.
#  * ROBOTIS OpenMANIPULATOR-X: github.com/ROBOTIS-GIT/robotis_mujoco_menagerie commit
#    d8344c0dbe7a00208d0301111523dde65efc174a, robotis_open_manipulator_x/ (open_manipulator_x.xml sha256
#    05130a8c4b659b23c7f035371462c6d3946554854a5c9170ac83794315e8233a, scene.xml sha256
#    50297343ed38c67e2bcaf149070ee7a509ee8027fca554f24691571fa2bb137c, assets/*.stl), unedited.
set -e
W=${W:-/tmp/r35/robots}; P=$(cd "$(dirname "$0")" && pwd)
NEEL=${NEEL:-/work/.mirror/neeltron+Bipolar-Control-for-Three-Finger-Robot-Hand/repo}
ROB=${ROB:-/work/.mirror/ROBOTIS-GIT+robotis_mujoco_menagerie/repo}
PY="env PYTHONPATH=/tmp/r35/src /work/venv/bin/python"; CM=$P/cm.sh
mkdir -p $W/allegro/assets $W/omx/assets $W/res
cp $P/cm.sh $P/queue.sh $P/disagree.py $W/
# --- Allegro
for f in base_link link_0.0 link_1.0 link_2.0 link_3.0 link_3.0_tip link_12.0_right link_13.0 link_14.0 link_15.0 link_15.0_tip; do
  git -C $NEEL show 7c2c44c:wonik_allegro/assets/$f.stl > $W/allegro/assets/$f.stl; done
git -C $NEEL show 7c2c44c:wonik_allegro/right_hand.xml | python3 -c "
import sys; s = sys.stdin.read()
s = s.replace('<mujoco model=\"allegro_right\">\n', '<mujoco model=\"allegro_right\">\n\n', 1)
s = s.replace('\n  <option cone=\"elliptic\" impratio=\"10\"/>\n', '', 1).replace('damping=\".1\"', 'damping=\"1\"', 1).replace('<position kp=\"1\"/>', '<position kp=\"10\"/>', 1)
open('$W/allegro/right_hand.xml', 'w').write(s)"
( cd $W/allegro && echo "1bf74af83cc8fc4c4cdeb1c1576cc5db4473655c620605057ce188569a1f3a7b  right_hand.xml" | sha256sum -c )
cat > $W/allegro/allegro_ball.xml <<'XML'
<mujoco model="allegro_ball">
  <!-- Menagerie wonik_allegro/right_hand.xml attached unedited (palm down) under a vertical slide
       with a position servo (probe_r35), a floor, a 2 cm pedestal and a free 3 cm-radius ball -->
  <compiler angle="radian"/>
  <asset><model name="allegro" file="right_hand.xml"/></asset>
  <worldbody>
    <light pos="0 0 1"/>
    <geom name="floor" type="plane" size="1 1 0.05" rgba="0.3 0.3 0.3 1"/>
    <body name="lift" pos="0 0 0.3">
      <joint name="lift" type="slide" axis="0 0 1" range="-0.25 0.1" damping="50"/>
      <body name="mount" quat="0 1 0 0">
        <attach model="allegro" body="palm" prefix=""/>
      </body>
    </body>
    <geom name="pedestal" type="cylinder" size="0.01 0.025" pos="-0.011 0 0.025" rgba="0.5 0.5 0.5 1"/>
    <body name="ball" pos="-0.011 0 0.08">
      <freejoint name="ball_joint"/>
      <geom name="ball" type="sphere" size="0.03" mass="0.1" rgba="1 0 0 1"/>
    </body>
  </worldbody>
  <actuator>
    <position name="lift" joint="lift" kp="3000" kv="100" ctrlrange="-0.25 0.1" forcerange="-100 100"/>
  </actuator>
</mujoco>
XML
sed 's/allegro_ball"/allegro_ball_ell"/; s#<compiler angle="radian"/>#<compiler angle="radian"/>\n  <option cone="elliptic" impratio="10"/>#' $W/allegro/allegro_ball.xml > $W/allegro/allegro_ball_ell.xml
cd $W/allegro
$CM init allegro_ball.xml --object ball --task pick_hold --gripper palm --out ph_init.toml --force
$CM init allegro_ball_ell.xml --object ball --task pick_hold --gripper palm --out ph_ell_init.toml --force
for s in ph ph_ell; do   # the only edit: the gripper channel's closed/open poses (init measured ffa1/mfa1/rfa1 backwards)
  sed 's/^closed = \[-0.196, 1.709, 1.618, -0.196, 1.709, 1.618, -0.196, 1.709, 1.618, 1.396, 1.644, 1.719\]/closed = [1.3, 1.2, 1.0, 1.3, 1.2, 1.0, 1.3, 1.2, 1.0, 1.396, 1.2, 1.2]   # probe_r35: the grasp pose (init measured ffa1\/mfa1\/rfa1 backwards)/; s/^open = \[1.61, -0.174, -0.227, 1.61, -0.174, -0.227, 1.61, -0.174, -0.227, 0.263, -0.189, -0.162\]/open = [0, 0, 0, 0, 0, 0, 0, 0, 0, 1.39, 0.2, 0.2]   # probe_r35: the open pose (tha0 1.39, not 1.396: closed == open is refused)/' $( [ $s = ph ] && echo ph_init.toml || echo ph_ell_init.toml ) > $s.toml
  grep -c probe_r35 $s.toml
  sed 's/^range = \[0.05, 2.0\]   # \[kg\]/range = [0.05, 1.2]   # [kg] (narrow: probe_r35)/; s/^range = \[0.2, 1.5\]   # sliding/range = [0.4, 1.5]   # (narrow: probe_r35) sliding/' $s.toml > ${s}_narrow.toml
done
$PY $P/gen_allegro.py allegro_ball.xml nom.npz
# --- OpenMANIPULATOR-X
for f in open_manipulator_x.xml scene.xml; do git -C $ROB show d8344c0:robotis_open_manipulator_x/$f > $W/omx/$f; done
for f in Plate gripper_left_palm gripper_right_palm link1 link2 link3 link4 link5; do git -C $ROB show d8344c0:robotis_open_manipulator_x/assets/$f.stl > $W/omx/assets/$f.stl; done
( cd $W/omx && sha256sum -c <<'SUMS'
05130a8c4b659b23c7f035371462c6d3946554854a5c9170ac83794315e8233a  open_manipulator_x.xml
50297343ed38c67e2bcaf149070ee7a509ee8027fca554f24691571fa2bb137c  scene.xml
SUMS
)
cat > $W/omx/omx_cube.xml <<'XML'
<mujoco model="omx_cube">
  <!-- ROBOTIS OpenMANIPULATOR-X scene.xml (robotis_mujoco_menagerie d8344c0) included unedited, plus a free 4.4 cm cube -->
  <include file="scene.xml"/>
  <worldbody>
    <body name="cube" pos="0.2 0 0.022">
      <freejoint name="cube_joint"/>
      <geom name="cube" type="box" size="0.022 0.022 0.022" mass="0.03" rgba="1 0 0 1"/>
    </body>
  </worldbody>
</mujoco>
XML
sed 's/omx_cube"/omx_cube_pyr"/; s#<include file="scene.xml"/>#<include file="scene.xml"/>\n  <option cone="pyramidal" impratio="1"/>#' $W/omx/omx_cube.xml > $W/omx/omx_cube_pyr.xml
cd $W/omx
$CM init omx_cube.xml --object cube --task pick_place --goal 0.15 0.12 0.022 --out pp.toml --force
$CM init omx_cube_pyr.xml --object cube --task pick_place --goal 0.15 0.12 0.022 --out pp_pyr.toml --force
sed 's/^range = \[0.015, 0.6\]   # \[kg\]/range = [0.015, 0.06]   # [kg] (narrow: probe_r35)/; s/^range = \[0.2, 1.5\]   # sliding/range = [0.7, 1.5]   # (narrow: probe_r35) sliding/' pp.toml > pp_narrow.toml
$PY $P/gen_omx.py omx_cube.xml nom.npz
S=$W/scripts $P/make_scripts.sh
echo "scenes, scenarios and trajectories in $W/allegro and $W/omx"
