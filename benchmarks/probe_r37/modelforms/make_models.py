"""Build the model variants under /tmp/r37/modelforms/models/ from the bundled Panda scene.

Each variant is the bundled Panda pick-and-place scene composed another way (include chains,
<frame>, <replicate>, <attach>, defaults, degrees, ...) or with one feature added.
Run: PYTHONPATH=/tmp/r37/src /work/venv/bin/python make_models.py
"""
import re
import shutil
from pathlib import Path

import common  # noqa: F401  (asserts the snapshot)
import mujoco

SRC = Path("/tmp/r37/src/models/panda_pick_place")
OUT = Path("/tmp/r37/modelforms/models")
SCENE = (SRC / "scene.xml").read_text()
PANDA = (SRC / "panda.xml").read_text()
CUBE = re.search(r'    <body name="cube".*?</body>\n', SCENE, re.S).group(0)
KEY = re.search(r"  <keyframe>.*?</keyframe>\n", SCENE, re.S).group(0)


def put(rel, text):
    p = OUT / rel
    p.parent.mkdir(parents=True, exist_ok=True)
    p.write_text(text)
    return p


def scene(cube=CUBE, key=KEY, head='<include file="panda.xml"/>', extra_world="", extra="",
          compiler='<compiler angle="radian" autolimits="true"/>'):
    s = SCENE.replace(CUBE, cube).replace(KEY, key)
    s = s.replace('<include file="panda.xml"/>', head)
    s = s.replace('<compiler angle="radian" autolimits="true"/>', compiler)
    s = s.replace("  </worldbody>", extra_world + "  </worldbody>" + extra)
    return s


def main():
    if OUT.exists():
        shutil.rmtree(OUT)
    # --- 1. composition -------------------------------------------------------------
    # include chain across folders, object in an included file, a mesh object with meshdir
    obj = """<mujoco>
  <asset><mesh name="cubemesh" file="cube.obj"/></asset>
  <worldbody>
    <body name="cube" pos="0.5 -0.15 0.02">
      <freejoint name="cube_joint"/>
      <geom name="cube" type="mesh" mesh="cubemesh" mass="0.1" rgba="0.9 0.1 0.1 1"
            contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001"
            solref="0.01 1"/>
    </body>
  </worldbody>
</mujoco>
"""
    v = [f"v {x*0.02} {y*0.02} {z*0.02}" for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    f = ["f 1 3 4 2", "f 5 6 8 7", "f 1 2 6 5", "f 3 7 8 4", "f 1 5 7 3", "f 2 4 8 6"]
    cube_obj = "\n".join(v + f) + "\n"
    put("inc_chain/assets/meshes/cube.obj", cube_obj)
    put("inc_chain/robots/panda/panda.xml", PANDA)
    put("inc_chain/robots/robot.xml", '<mujoco>\n  <include file="panda/panda.xml"/>\n</mujoco>\n')
    put("inc_chain/objects/cube_obj.xml", obj)
    put("inc_chain/scenes/pick/scene.xml", scene(
        cube="", head='<include file="../../robots/robot.xml"/>\n  '
                      '<include file="../../objects/cube_obj.xml"/>',
        compiler='<compiler angle="radian" autolimits="true" meshdir="../../assets/meshes"/>'))
    # the same content flattened in one folder (reference for inc_chain)
    put("inc_flat/cube.obj", cube_obj)
    put("inc_flat/panda.xml", PANDA)
    put("inc_flat/scene.xml", scene(cube=re.search(r"    <body.*</body>\n", obj, re.S).group(0),
                                    head='<include file="panda.xml"/>\n  <asset><mesh name="cubemesh" file="cube.obj"/></asset>'))
    # assetdir instead of meshdir
    put("inc_assetdir/assets/meshes/cube.obj", cube_obj)
    put("inc_assetdir/robots/panda/panda.xml", PANDA)
    put("inc_assetdir/robots/robot.xml", '<mujoco>\n  <include file="panda/panda.xml"/>\n</mujoco>\n')
    put("inc_assetdir/objects/cube_obj.xml", obj)
    put("inc_assetdir/scenes/pick/scene.xml", scene(
        cube="", head='<include file="../../robots/robot.xml"/>\n  '
                      '<include file="../../objects/cube_obj.xml"/>',
        compiler='<compiler angle="radian" autolimits="true" assetdir="../../assets/meshes"/>'))

    # <frame>: the cube and the robot inside frames (identical compiled model expected)
    fcube = CUBE.replace('<body name="cube" pos="0.5 -0.15 0.02">',
                         '<frame pos="0.4 -0.1 0.01"><body name="cube" pos="0.1 -0.05 0.01">'
                         ).replace("    </body>\n", "    </body></frame>\n")
    put("frame/panda.xml", PANDA.replace('<body name="link0" childclass="panda">',
                                         '<frame pos="0 0 0"><body name="link0" childclass="panda">')
        .replace("  </worldbody>", "  </frame></worldbody>"))
    put("frame/scene.xml", scene(cube=fcube))

    # <replicate>: three cubes; which one is "the object"?
    rcube = ('    <replicate count="3" offset="0.12 0 0">\n' + CUBE + "    </replicate>\n")
    put("replicate/panda.xml", PANDA)
    key_r = KEY.replace("0.5 -0.15 0.02 1 0 0 0", "0.5 -0.15 0.02 1 0 0 0  0.62 -0.15 0.02 1 0 0 0  0.74 -0.15 0.02 1 0 0 0")
    put("replicate/scene.xml", scene(cube=rcube, key=key_r))
    # the same three cubes written out (reference)
    three = "".join(CUBE.replace('name="cube"', f'name="cube{i}"').replace('name="cube_joint"', f'name="cube_joint{i}"')
                    .replace('0.5 -0.15 0.02', f'{0.5 + 0.12 * i:g} -0.15 0.02') for i in range(3))
    put("replicate_flat/panda.xml", PANDA)
    put("replicate_flat/scene.xml", scene(cube=three, key=key_r))

    # <attach> the robot with a prefix
    put("attach/robot/panda.xml", PANDA)
    put("attach/scene.xml", scene(
        head='<asset><model name="panda" file="robot/panda.xml"/></asset>',
        extra_world="").replace("  <worldbody>\n", '  <worldbody>\n    <attach model="panda" body="link0" prefix="r_"/>\n', 1))

    # the object attached from an object library file, with a prefix, inside a frame
    put("attach_obj/panda.xml", PANDA)
    put("attach_obj/objects/cube.xml", "<mujoco>\n  <worldbody>\n" + CUBE.replace('pos="0.5 -0.15 0.02"', 'pos="0 0 0"') + "  </worldbody>\n</mujoco>\n")
    put("attach_obj/scene.xml", scene(cube='    <frame pos="0.5 -0.15 0.02"><attach model="cubelib" body="cube" prefix="o_"/></frame>\n',
                                      head='<include file="panda.xml"/>\n  <asset><model name="cubelib" file="objects/cube.xml"/></asset>'))

    # the object with a larger visual-only geom (contype/conaffinity 0, no mass) listed first
    vcube = CUBE.replace('      <geom name="cube"', '      <geom name="cube_visual" type="box" size="0.021 0.021 0.021" contype="0" conaffinity="0" group="2" mass="0" rgba="1 0 0 0.3"/>\n      <geom name="cube"')
    put("visual/panda.xml", PANDA)
    put("visual/scene.xml", scene(cube=vcube))

    # <default> classes carrying the cube's contact parameters (identical compiled model expected)
    dcube = CUBE.replace('contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001"\n            solref="0.01 1"',
                         'class="obj"')
    put("defaults/panda.xml", PANDA)
    put("defaults/scene.xml", scene(cube=dcube).replace(
        "  <visual>", '  <default>\n    <default class="obj">\n      <geom contype="1" conaffinity="1" condim="4" priority="2" '
        'friction="1 0.005 0.0001" solref="0.01 1"/>\n    </default>\n  </default>\n\n  <visual>', 1))

    # degrees everywhere (ranges converted), cube orientation by euler in degrees with eulerseq
    import math

    def deg(m):
        a, b = float(m.group(1)), float(m.group(2))
        return f'range="{math.degrees(a):.10g} {math.degrees(b):.10g}"'
    pdeg = re.sub(r'(?<![a-z])range="(-?[\d.]+) (-?[\d.]+)"(?! armature)', deg, PANDA)
    # a user's slip: the ctrlrange converted to degrees as well (MuJoCo never converts it)
    pbad = re.sub(r'range="(-?[\d.]+) (-?[\d.]+)"(?! armature)', deg, PANDA).replace(
        f'range="{math.degrees(0):.10g} {math.degrees(0.04):.10g}"', 'range="0 0.04"').replace(
        '<compiler angle="radian" autolimits="true"/>', '<compiler angle="degree" autolimits="true"/>')
    put("degree_ctrl/panda.xml", pbad)
    put("degree_ctrl/scene.xml", scene(compiler='<compiler angle="degree" autolimits="true"/>'))
    # the finger's slide range is in metres: keep it
    pdeg = pdeg.replace(f'range="{math.degrees(0):.10g} {math.degrees(0.04):.10g}"', 'range="0 0.04"')
    pdeg = pdeg.replace('<compiler angle="radian" autolimits="true"/>', '<compiler angle="degree" autolimits="true"/>')
    put("degree/panda.xml", pdeg)
    put("degree/scene.xml", scene(
        cube=CUBE.replace('pos="0.5 -0.15 0.02"', 'pos="0.5 -0.15 0.02" euler="0 0 90"'),
        compiler='<compiler angle="degree" autolimits="true" eulerseq="ZYX"/>'))
    # autolimits off, every range limited explicitly
    pnol = PANDA.replace('autolimits="true"', 'autolimits="false"')
    pnol = re.sub(r'(<joint name="joint\d" axis="0 0 1" range="[^"]+")', r'\1 limited="true"', pnol)
    pnol = pnol.replace('range="0 0.04" armature', 'range="0 0.04" limited="true" armature')
    pnol = re.sub(r'(forcerange="[^"]+")', r'\1 forcelimited="true"', pnol)
    pnol = re.sub(r'(ctrlrange="[^"]+")', r'\1 ctrllimited="true"', pnol)
    put("noautolimits/panda.xml", pnol)
    put("noautolimits/scene.xml", scene(compiler='<compiler angle="radian" autolimits="false"/>'))

    # --- 4. features ----------------------------------------------------------------
    # keyframes: a second keyframe first; the cube's keyframe pose differs from its body pos
    key2 = KEY.replace("  <keyframe>\n", '  <keyframe>\n    <key name="away" qpos="0.5 -0.78539816 0 -2.35619449 0 1.57079633 0.78539816 0.04 0.04 0.6 0.1 0.02 1 0 0 0"/>\n')
    put("keyframe/panda.xml", PANDA)
    put("keyframe/scene.xml", scene(key=key2))
    # a flexcomp cloth on the table far from the path (distractor) and, separately, as "object"
    flex = ('    <flexcomp name="cloth" type="grid" count="4 4 1" spacing="0.03 0.03 0.03" pos="0.75 0.3 0.05" '
            'radius="0.005" dim="2" mass="0.05">\n      <edge equality="true"/>\n    </flexcomp>\n')
    put("flex/panda.xml", PANDA)
    put("flex/scene.xml", scene(extra_world=flex))
    # a deformable "cube" (a 3-D flexcomp) where the object should be: the user's object
    soft = ('    <flexcomp name="soft" type="grid" count="3 3 3" spacing="0.02 0.02 0.02" pos="0.5 -0.15 0.025" '
            'radius="0.002" dim="3" mass="0.1">\n      <edge equality="true"/>\n      <contact condim="4" solref="0.01 1"/>\n    </flexcomp>\n')
    put("flex_object/panda.xml", PANDA)
    put("flex_object/scene.xml", scene(cube=soft, key=KEY.replace(" 0.5 -0.15 0.02 1 0 0 0", "")
                                       .replace('qpos="', 'qpos="').replace("<key name", "<!--key name").replace("/>\n  </keyframe>", "/-->\n  </keyframe>")))
    # a PID actuator plugin (mujoco.pid) drives joint7 instead of its <position> servo
    ppid = PANDA.replace(
        '<position name="joint7" joint="joint7" kp="2000" kv="200" forcerange="-12 12" ctrlrange="-2.8973 2.8973"/>',
        '<plugin name="joint7" joint="joint7" plugin="mujoco.pid" instance="pid7" forcerange="-12 12" ctrlrange="-2.8973 2.8973"/>')
    assert ppid != PANDA
    ppid = ppid.replace("  <worldbody>", '  <extension><plugin plugin="mujoco.pid"><instance name="pid7">'
                        '<config key="kp" value="2000"/><config key="kd" value="200"/></instance></plugin></extension>\n\n  <worldbody>', 1)
    put("plugin/panda.xml", ppid)
    put("plugin/scene.xml", scene())
    # a mocap body (a marker with a collision geom, off the path)
    put("mocap/panda.xml", PANDA)
    put("mocap/scene.xml", scene(extra_world='    <body name="marker" mocap="true" pos="0.8 -0.35 0.05">\n'
                                             '      <geom name="marker" type="box" size="0.02 0.02 0.05" rgba="0 0 1 1"/>\n    </body>\n'))
    # weld equality of the cube to the hand (active at start)
    put("weld/panda.xml", PANDA)
    put("weld/scene.xml", scene(extra='\n  <equality>\n    <weld name="grasp" body1="hand" body2="cube" active="true"/>\n  </equality>\n'))
    # contact exclude between the cube and both fingers
    put("exclude/panda.xml", PANDA)
    put("exclude/scene.xml", scene(extra='\n  <contact>\n    <exclude body1="cube" body2="left_finger"/>\n'
                                         '    <exclude body1="cube" body2="right_finger"/>\n  </contact>\n'))
    # the object on three slide joints + a hinge (no free joint)
    scube = CUBE.replace('<freejoint name="cube_joint"/>',
                         '<joint name="cx" type="slide" axis="1 0 0"/><joint name="cy" type="slide" axis="0 1 0"/>'
                         '<joint name="cz" type="slide" axis="0 0 1"/><joint name="cyaw" type="hinge" axis="0 0 1"/>')
    put("slides/panda.xml", PANDA)
    put("slides/scene.xml", scene(cube=scube, key=KEY.replace("0.5 -0.15 0.02 1 0 0 0", "0 0 0 0")))
    # the object fixed (no joint)
    put("fixed/panda.xml", PANDA)
    put("fixed/scene.xml", scene(cube=CUBE.replace('      <freejoint name="cube_joint"/>\n', ""),
                                 key=KEY.replace(" 0.5 -0.15 0.02 1 0 0 0", "")))
    # two free cubes sharing one mesh
    two = obj.replace('<mujoco>\n', '').replace('</mujoco>\n', '')
    tb = re.search(r"    <body.*</body>\n", obj, re.S).group(0)
    two_b = tb.replace('name="cube"', 'name="cube_a"').replace('name="cube_joint"', 'name="ja"') + \
        tb.replace('name="cube"', 'name="cube_b"').replace('name="cube_joint"', 'name="jb"').replace("0.5 -0.15 0.02", "0.7 0.2 0.02")
    put("twomesh/cube.obj", cube_obj)
    put("twomesh/panda.xml", PANDA)
    put("twomesh/scene.xml", scene(cube=two_b, head='<include file="panda.xml"/>\n  <asset><mesh name="cubemesh" file="cube.obj"/></asset>',
                                   key=KEY.replace("0.5 -0.15 0.02 1 0 0 0", "0.5 -0.15 0.02 1 0 0 0 0.7 0.2 0.02 1 0 0 0")))
    # the object nested in the robot's hand body with a free joint
    nested = PANDA.replace('                      <site name="tcp"',
                           '                      <body name="cube" pos="0 0 0.11"><freejoint name="cube_joint"/>'
                           '<geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1" contype="1" conaffinity="1"/></body>\n'
                           '                      <site name="tcp"')
    put("nested/panda.xml", nested)
    put("nested/scene.xml", scene(cube="", key=""))

    for p in sorted(OUT.glob("**/scene.xml")):
        try:
            m = mujoco.MjModel.from_xml_path(str(p))
            print(f"{p.relative_to(OUT)}: loads, nbody {m.nbody} nq {m.nq} nu {m.nu}")
        except Exception as e:  # noqa: BLE001
            print(f"{p.relative_to(OUT)}: MuJoCo refuses: {str(e).splitlines()[0][:150]}")


if __name__ == "__main__":
    main()
