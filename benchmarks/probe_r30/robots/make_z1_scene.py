"""Compose Menagerie's Unitree Z1 + its one-jaw gripper (`unitree_z1/z1_gripper.xml`, Menagerie
commit 8b039d08, unmodified; meshes from a copy of that directory) with a floor, a free 3 cm cube
and a goal site, by MjSpec.

* arm: 6 `general` affine servos (kp 1000, kv 100, forcerange +-30; joint2 kp 1500, +-60),
  joint damping 1 and frictionloss 1 on every joint (gripper too), implicitfast, MuJoCo's
  default contact (pyramidal, impratio 1): the file sets no cone.
* gripper: `jointGripper` hinge (range -1.518..0, 0 = closed), a fixed stator jaw with two pad
  boxes below, a moving jaw with two pad boxes above: ONE moving jaw, not parallel.
* the file's `home` keyframe (7 qpos values) is kept as it ships (MuJoCo pads it for the cube).
* object: a 4 x 1.6 x 8 cm standing plate ("cube"), 0.1 kg, gripped 1.5 cm below its top, friction 1, standing on the floor at (0.35, -0.1); a 3 cm cube is squeezed out under the stator by the tilted moving jaw (it meets it at 0.42 rad).
Variants: shipped (pyramidal 1) and elliptic10, each at the shipped 2 ms and at 0.5 ms (`_dt05`).
usage: make_z1_scene.py Z1_DIR OUT_DIR
"""
import sys
from pathlib import Path

import mujoco
import numpy as np


def build(z1: Path, contact: str, keep_key: bool = True) -> mujoco.MjSpec:
    spec = mujoco.MjSpec.from_file(str(z1 / "z1_gripper.xml"))
    spec.meshdir = str((z1 / "assets").resolve())
    if not keep_key:
        for k in list(spec.keys):
            spec.delete(k)
    w = spec.worldbody
    w.add_geom(name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[2, 2, 0.05])
    obj = w.add_body(name="cube", pos=[0.35, -0.1, 0.04])
    obj.add_freejoint(name="cube_joint")
    obj.add_geom(name="cube_geom", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.02, 0.008, 0.04], mass=0.1,
                 rgba=[0.9, 0.3, 0.2, 1])
    w.add_site(name="goal", pos=[0.35, 0.15, 0.04], size=[0.01] * 3, rgba=[0, 1, 0, .3])
    if contact == "elliptic10":
        spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
        spec.option.impratio = 10.0
    elif contact != "shipped":
        raise SystemExit(contact)
    return spec


if __name__ == "__main__":
    z1, out = Path(sys.argv[1]), Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    for contact, dt in (("shipped", None), ("elliptic10", None), ("shipped", 0.0005), ("elliptic10", 0.0005)):
        spec = build(z1, contact)
        tag = contact
        if dt:  # the shipped jaw servo (kp 1000 on 3.2e-4 kg m^2) cannot move at 2 ms
            spec.option.timestep = dt
            tag += "_dt05"
        spec.compile()
        p = out / f"z1_{tag}.xml"
        p.write_text(spec.to_xml())
        m = mujoco.MjModel.from_xml_path(str(p))
        print("wrote", p, "nq", m.nq, "nu", m.nu, "nkey", m.nkey, "cone", m.opt.cone, "impratio", m.opt.impratio)
