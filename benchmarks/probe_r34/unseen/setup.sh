#!/bin/bash
# Rebuilds this probe's scenes and scenarios under $W (default /tmp/r34/unseen). No third-party
# file is kept in this folder; they come from:
#   * Menagerie ALOHA 2 XMLs (google-deepmind/mujoco_menagerie, unedited; save them yourself
#     into $W/aloha2/ — this machine has no network, the probe read them with the read_file tool):
#       aloha/aloha.xml (commit 3ae30a74fed76e95b5e8f48babaed00f89fb91b0, 18638 bytes,
#         sha256 7439a20de30cbcb33d0abc5fe218040446b265f789af27790cc1cc8d8c76793e)
#       aloha/scene.xml (3a992d75e4129b9e843f234e8e1cf172245a2326, 5208 bytes,
#         sha256 551126e4bda31ae239bf64de721745a6db651aca57c85c6867c51d6e920c2202)
#       aloha/joint_position_actuators.xml (9982f57900376c58b8dabdb97a759262a18ff4f6, 1374 bytes,
#         sha256 668973891e1575788eed963223ae4292d7ac1d98600b4d74ee6abe0de61fee1f)
#   * ALOHA 2 meshes: Menagerie's aloha/assets as vendored by github.com/yw14218/ObAct at commit
#     18200ae81421343f92b2b1ca662813e6d3360725 (its first add of Menagerie's aloha/; its XMLs there
#     are an older, edited Menagerie version and are NOT used)
#   * Menagerie agilex_piper/piper.xml at commit cd165455b4e46c725d19a97db15c0c0eaca30100 (14538
#     bytes, sha256 597e60be295cc8116cef0562fe0bf9761d5f5e968efe826fb79ed845f4c46556) -> $W/piper/
#   * PiPER meshes: github.com/SkyLineHXY/Piper_Mujoco_Sim b1cfdc67a3ed3d2d76353a704be459caad707934,
#     manipulator_grasp/assets/agilex_piper/assets (Menagerie's, 16/02/2025 release). The mirror
#     lacks link2_31.obj (a visual-only mesh: class visual, contype 0, density 0): a 1 mm
#     tetrahedron stands in for it (no effect on the physics: every body has an explicit inertial).
set -e
W=${W:-/tmp/r34/unseen}; P=$(cd "$(dirname "$0")" && pwd)
CM=$P/cm.sh
OBACT=${OBACT:-/work/.mirror/yw14218+ObAct/repo}; SKY=${SKY:-/work/.mirror/SkyLineHXY+Piper_Mujoco_Sim/repo}
mkdir -p $W/aloha2/assets $W/piper/assets $W/res
for f in $(git -C $OBACT ls-tree --name-only 18200ae aloha/assets/ | grep -v DS_Store | grep -v "/meshes$"); do
  git -C $OBACT show 18200ae:$f > $W/aloha2/assets/$(basename $f); done
for f in $(git -C $SKY ls-tree --name-only b1cfdc6 manipulator_grasp/assets/agilex_piper/assets/); do
  git -C $SKY show b1cfdc6:$f > $W/piper/assets/$(basename $f) 2>/dev/null || true; done
printf 'v 0 0 0\nv 0.001 0 0\nv 0 0.001 0\nv 0 0 0.001\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n' > $W/piper/assets/link2_31.obj
( cd $W/aloha2 && sha256sum -c <<'SUMS'
7439a20de30cbcb33d0abc5fe218040446b265f789af27790cc1cc8d8c76793e  aloha.xml
551126e4bda31ae239bf64de721745a6db651aca57c85c6867c51d6e920c2202  scene.xml
668973891e1575788eed963223ae4292d7ac1d98600b4d74ee6abe0de61fee1f  joint_position_actuators.xml
SUMS
)
( cd $W/piper && echo "597e60be295cc8116cef0562fe0bf9761d5f5e968efe826fb79ed845f4c46556  piper.xml" | sha256sum -c )
# our wrappers: the shipped scene included unedited + ACT's transfer-cube box (4 cm, 50 g, ACT's contact params)
cat > $W/aloha2/handover.xml <<'XML'
<mujoco model="aloha2_handover">
  <!-- Menagerie ALOHA 2 scene.xml, included unedited, plus ACT's transfer-cube box (4 cm, 50 g, ACT's contact params) -->
  <include file="scene.xml"/>
  <worldbody>
    <body name="box" pos="0.1 0.0 0.02">
      <freejoint name="box_joint"/>
      <geom name="box" type="box" size="0.02 0.02 0.02" mass="0.05" condim="4" solimp="2 1 0.01" solref="0.01 1" friction="1 0.005 0.0001" rgba="1 0 0 1"/>
    </body>
  </worldbody>
</mujoco>
XML
sed 's/aloha2_handover"/aloha2_handover_pyr"/; s#<include file="scene.xml"/>#<include file="scene.xml"/>\n  <option cone="pyramidal" impratio="1"/>#' $W/aloha2/handover.xml > $W/aloha2/handover_pyr.xml
cat > $W/piper/piper_cube.xml <<'XML'
<mujoco model="piper_cube">
  <!-- Menagerie agilex_piper/piper.xml (cd165455) included unedited, plus a floor and a free 3 cm cube -->
  <include file="piper.xml"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.05" rgba="0.3 0.3 0.3 1"/>
    <body name="cube" pos="0.25 0 0.015">
      <freejoint name="cube_joint"/>
      <geom name="cube" type="box" size="0.015 0.015 0.015" mass="0.05" condim="4" friction="1 0.005 0.0001" rgba="1 0 0 1"/>
    </body>
  </worldbody>
</mujoco>
XML
sed 's/piper_cube"/piper_cube_pyr"/; s#<include file="piper.xml"/>#<include file="piper.xml"/>\n  <option cone="pyramidal" impratio="1"/>#' $W/piper/piper_cube.xml > $W/piper/piper_cube_pyr.xml
cd $W/aloha2
$CM inspect handover.xml > ../res/inspect_aloha2.txt
$CM init handover.xml --object box --task handover --out ho.toml --force > ../res/init_aloha2.txt 2>&1
$CM init handover_pyr.xml --object box --task handover --out ho_pyr.toml --force > ../res/init_aloha2_pyr.txt 2>&1
for s in ho ho_pyr; do   # the only edits: the boxes
  sed 's/^range = \[0.025, 1.0\]   # \[kg\]/range = [0.05, 0.6]   # [kg] (narrow: probe_r34)/' $s.toml > ${s}_narrow.toml
  sed 's/^range = \[0.025, 1.0\]   # \[kg\]/range = [0.05, 3.0]   # [kg] (heavy: probe_r34)/; s/^range = \[0.2, 1.5\]   # sliding/range = [0.1, 1.0]   # (heavy: probe_r34) sliding/' $s.toml > ${s}_heavy.toml
done
PY="env PYTHONPATH=/tmp/r34/src /work/venv/bin/python"
$PY $P/gen_aloha2.py handover.xml nom_s2.npz --slow 2                      # ACT's timeline, 2x slower
for v in no_release no_receive early_open proper; do $PY $P/gen_aloha2.py handover.xml v_$v.npz --slow 2 --variant $v; done
$PY $P/gen_aloha2.py handover.xml nom.npz                                  # ACT's own speed (tracking warnings)
cd $W/piper
$CM inspect piper_cube.xml > ../res/inspect_piper.txt
$CM init piper_cube.xml --object cube --task pick_hold --out ph.toml --force > ../res/init_piper.txt 2>&1
$CM init piper_cube_pyr.xml --object cube --task pick_hold --out ph_pyr.toml --force > ../res/init_piper_pyr.txt 2>&1
for s in ph ph_pyr; do
  sed 's/^range = \[0.025, 1.0\]   # \[kg\]/range = [0.025, 0.2]   # [kg] (narrow: probe_r34)/' $s.toml > ${s}_narrow.toml
  sed 's/^range = \[0.025, 1.0\]   # \[kg\]/range = [0.04, 0.12]   # [kg] (edge: probe_r34)/; s/^range = \[0.2, 1.5\]   # sliding/range = [0.3, 1.5]   # (edge: probe_r34) sliding/' $s.toml > ${s}_edge.toml
done
python3 - <<'PYEOF'   # finding 1's box: a light nominal (0.025 kg, mu 1.25), mass 0.02-0.05 x mu 1.0-1.5
s = open('ph_pyr.toml').read()
s = s.replace('range = [0.025, 1.0]   # [kg]\nnominal = 0.05', 'range = [0.02, 0.05]   # [kg] (light nominal: probe_r34)\nnominal = 0.025')
s = s.replace('range = [0.2, 1.5]   # sliding', 'range = [1.0, 1.5]   # (light nominal: probe_r34) sliding').replace('nominal = 1.0\n', 'nominal = 1.25\n')
open('ph_pyr_light.toml', 'w').write(s)
PYEOF
$PY $P/gen_piper.py piper_cube.xml nom.npz
for e in 1 5; do $PY $P/gen_piper.py piper_cube.xml nom_x$e.npz --extra $e; done
echo "scenes, scenarios and trajectories in $W/aloha2 and $W/piper"
