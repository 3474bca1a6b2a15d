"""com_offset range check on object variants (load only): python com_shapes.py
Each variant replaces the bundled Panda cube's geom(s); prints whether the range loads or the error."""
import re, shutil, tempfile, pathlib
import critmoment as cm
SRC = pathlib.Path("/tmp/r28b/src/models/panda_pick_place")
GEOM = re.compile(r'<geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1"')
VAR = {
 # name: (geoms replacing the cube's, extra asset xml, [(range, expected_ok)])
 "cube": ('<geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1"', "", [(0.019, True), (0.021, False)]),
 "cyl_lying_x": ('<geom name="cube" type="cylinder" size="0.02 0.04" quat="0.7071068 0 0.7071068 0" mass="0.1"', "", [(0.039, True), (0.041, False)]),
 "capsule_e45rad": ('<geom name="cube" type="capsule" size="0.015 0.03" euler="0 45 0" mass="0.1"', "", [(0.028, True), (0.03, False)]),
 "two_boxes_x": ('<geom name="cube" type="box" size="0.02 0.02 0.02" pos="-0.02 0 0" mass="0.05" friction="1 0.005 0.0001"/><geom name="cube2" type="box" size="0.02 0.02 0.02" pos="0.02 0 0" mass="0.05"', "", [(0.039, True), (0.041, False)]),
 "hollow_frame": ('<geom name="cube" type="box" size="0.005 0.03 0.02" pos="-0.025 0 0" mass="0.025"/><geom name="c2" type="box" size="0.005 0.03 0.02" pos="0.025 0 0" mass="0.025"/><geom name="c3" type="box" size="0.02 0.005 0.02" pos="0 0.025 0" mass="0.025"/><geom name="c4" type="box" size="0.02 0.005 0.02" pos="0 -0.025 0" mass="0.025"', "", [(0.02, True), (0.3, False)]),
 "dumbbell_gap": ('<geom name="cube" type="sphere" size="0.015" pos="-0.03 0 0" mass="0.05"/><geom name="c2" type="sphere" size="0.015" pos="0.03 0 0" mass="0.05"', "", [(0.04, True), (0.5, False)]),
 "big_visual": ('<geom name="vis" type="box" size="0.2 0.02 0.02" contype="0" conaffinity="0" group="2" mass="0"/><geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1"', "", [(0.019, True), (0.1, False)]),
 "explicit_inertial_off": ('<inertial pos="0.015 0 0" mass="0.1" diaginertia="3e-5 3e-5 3e-5"/><geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1"', "", [(0.004, True), (0.006, False)]),
 "inertial_rotated": ('<inertial pos="0 0 0" quat="0.7071068 0 0 0.7071068" mass="0.1" diaginertia="1e-5 3e-5 3e-5"/><geom name="cube" type="box" size="0.03 0.015 0.02" mass="0.1"', "", [(0.029, True), (0.031, False)]),
 "mesh_tetra": ('<geom name="cube" type="mesh" mesh="tet" mass="0.1"', '<asset><mesh name="tet" vertex="-0.03 -0.03 -0.02  0.03 -0.03 -0.02  0 0.03 -0.02  0 0 0.03"/></asset>', [(0.005, True), (0.028, False)]),
}
def make(name, geoms, asset, rng):
    d = pathlib.Path(tempfile.mkdtemp(prefix=f"com_{name}_", dir="/tmp/r28b"))
    for f in SRC.iterdir():
        shutil.copy(f, d)
    x = (d / "scene.xml").read_text()
    assert GEOM.search(x)
    x = GEOM.sub(geoms, x, count=1)
    if asset:
        x = x.replace("</mujoco>", asset + "\n</mujoco>")
    (d / "scene.xml").write_text(x)
    s = (d / "scenario.toml").read_text()
    s = s.replace("[uncertainty.mass]", f'[uncertainty.com]\nkind = "com_offset"\nbody = "cube"\nrange = [{-rng}, {rng}]\nnominal = 0.0\n\n[uncertainty.mass]', 1)
    (d / "scenario.toml").write_text(s)
    return d
import sys
for name, (geoms, asset, cases) in VAR.items():
    if len(sys.argv) > 1 and name not in sys.argv[1:]:
        continue
    for rng, ok in cases:
        d = make(name, geoms, asset, rng)
        try:
            tw = cm.Twin(cm.load_scenario(d))
            b = tw.model.body("cube").id
            res = "LOADS"
        except Exception as e:
            res = "REFUSED: " + type(e).__name__ + ": " + str(e)[:230]
        flag = "" if (res == "LOADS") == ok else "   <-- UNEXPECTED (expected %s)" % ("load" if ok else "refusal")
        print(f"{name:22s} ±{rng:<6} {res}{flag}")
