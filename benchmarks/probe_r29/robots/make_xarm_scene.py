"""A table scene around sai-mujoco 0.1.30's xArm7 + xArm gripper (`assets/robots/xarm7/v1/robot.xml`,
loaded unmodified through MjSpec; only world geometry is added): torque `motor`s (±80 N·m) on all
seven arm joints, the xArm linkage gripper driven by a `general` affine actuator on the `split`
tendon (gain 0.333, bias (0, -100, -10), ctrl 0..255, ±50 N), connect + joint equalities, driver
frictionloss 1; MuJoCo's default contact model (pyramidal, impratio 1) as shipped.

Added: a 0.8 × 0.8 m table (top z = 0.0; the arm's base stands on it at the origin), a free SPHERE
(r = 3 cm, 0.2 kg, condim 4, friction 1) at (0.45, -0.1), a goal site at (0.45, 0.15) at the
sphere's resting height. Variants: shipped (pyramidal 1) and elliptic10.
The sphere rolls out of the grip at nominal (README); `box` (4 x 4 x 6 cm, same body/geom names
and centre) is the audited object.
Usage: python make_xarm_scene.py ROBOT_XML OUT_DIR [sphere|box]
"""
from __future__ import annotations

import sys
from pathlib import Path

import mujoco
import numpy as np

R = 0.03


def build(robot: Path, contact: str, shape: str = "sphere") -> mujoco.MjSpec:
    spec = mujoco.MjSpec.from_file(str(robot))
    meshdir = robot.parent / spec.meshdir if spec.meshdir else robot.parent
    for mesh in spec.meshes:
        if mesh.file and not Path(mesh.file).is_absolute():
            mesh.file = str((meshdir / mesh.file).resolve())
    spec.meshdir = ""
    w = spec.worldbody
    w.add_geom(name="table_top", type=mujoco.mjtGeom.mjGEOM_BOX, pos=[0.3, 0, -0.02],
               size=[0.6, 0.6, 0.02], friction=[1, 0.005, 0.0001])
    ball = w.add_body(name="ball", pos=[0.45, -0.1, R])
    ball.add_freejoint(name="ball_joint")
    kind, size = ((mujoco.mjtGeom.mjGEOM_SPHERE, [R, 0, 0]) if shape == "sphere"
                  else (mujoco.mjtGeom.mjGEOM_BOX, [0.02, 0.02, R]))  # box: 4 x 4 x 6 cm, same centre
    ball.add_geom(name="ball_geom", type=kind, size=size, mass=0.2,
                  condim=4, friction=[1, 0.005, 0.0001], rgba=[0.9, 0.5, 0.1, 1])
    w.add_site(name="goal", pos=[0.45, 0.15, R], size=[0.01] * 3, rgba=[0, 1, 0, .3])
    if contact == "elliptic10":
        spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
        spec.option.impratio = 10.0
    return spec


def main():
    robot, out = Path(sys.argv[1]).absolute(), Path(sys.argv[2])
    shape = sys.argv[3] if len(sys.argv) > 3 else "sphere"
    out.mkdir(parents=True, exist_ok=True)
    for contact in ("shipped", "elliptic10"):
        spec = build(robot, contact, shape)
        spec.compile()
        path = out / (f"xarm7_{contact}.xml" if shape == "sphere" else f"xarm7_{shape}_{contact}.xml")
        path.write_text(spec.to_xml())
        m = mujoco.MjModel.from_xml_path(str(path))
        print("wrote", path, "nq", m.nq, "nu", m.nu, "cone", m.opt.cone, "impratio", m.opt.impratio)


if __name__ == "__main__":
    main()
