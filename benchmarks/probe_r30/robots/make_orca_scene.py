"""Compose orca-sim 0.1.0's ORCA right hand (`scene_right.xml` with its includes, unmodified:
`models/mjcf/orcahand_right.mjcf` + `assets/mjcf/options.xml`) on Menagerie's Kinova Gen3
(as in make_gen3_scene.py), by MjSpec: the hand's root body `right_tower` (0.9 kg; the
palm hangs on its `right_wrist` hinge) attached at the arm's `pinch_site` with prefix `h_`;
a floor, a free object and a goal site on the arm's x axis (joint_1 of the Gen3 as shipped
is jammed by its base/shoulder collision meshes).

ORCA hand: 17 `position` servos (kp 2, forcerange +-1 N m) on 17 hinges (wrist, 4 thumb, 3
per finger: abduction, mcp, pip), joint damping 0.1, armature 0.001, frictionloss 0.001,
margin 0.01; collision meshes; contact excludes between neighbours.
Object: a 6 cm sphere ("ball", 0.05 kg) on the floor, or on a 12 cm post (`post`: gripped from
the side, the wrist axis vertical), or a 5 cm cube.
usage: make_orca_scene.py GEN3_DIR ORCA_DIR OUT_DIR
"""
import sys
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from make_gen3_scene import absolute_assets  # noqa: E402


def build(gen3: Path, orca: Path, contact: str, obj_kind: str = "ball"):
    arm = mujoco.MjSpec.from_file(str(gen3 / "gen3.xml"))
    absolute_assets(arm, gen3)
    hand = mujoco.MjSpec.from_file(str(orca / "scene_right.xml"))
    absolute_assets(hand, orca)
    for key in list(arm.keys):
        arm.delete(key)
    arm.site("pinch_site").attach_body(hand.body("right_tower"), "h_", "")
    w = arm.worldbody
    w.add_geom(name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[2, 2, 0.05])
    if obj_kind == "postcube":   # a 5 cm cube (0.05 kg) on the post
        post = w.add_body(name="post", pos=[0.7, 0.055, 0.06])
        post.add_geom(name="post_geom", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.01, 0.01, 0.06])
        obj = w.add_body(name="ball", pos=[0.7, 0.055, 0.145])
        obj.add_freejoint(name="ball_joint")
        obj.add_geom(name="ball_geom", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.025] * 3, mass=0.05,
                     rgba=[0.9, 0.3, 0.2, 1])
        z = 0.145
    elif obj_kind == "post":   # a 6 cm ball on a 2 x 2 cm post 12 cm tall, gripped from the side
        post = w.add_body(name="post", pos=[0.7, 0.055, 0.06])
        post.add_geom(name="post_geom", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.01, 0.01, 0.06])
        obj = w.add_body(name="ball", pos=[0.7, 0.055, 0.15])
        obj.add_freejoint(name="ball_joint")
        obj.add_geom(name="ball_geom", type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[0.03, 0, 0], mass=0.05,
                     rgba=[0.9, 0.3, 0.2, 1])
        z = 0.15
    elif obj_kind == "ball":
        obj = w.add_body(name="ball", pos=[0.45, 0.0, 0.03])
        obj.add_freejoint(name="ball_joint")
        obj.add_geom(name="ball_geom", type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[0.03, 0, 0], mass=0.05,
                     rgba=[0.9, 0.3, 0.2, 1])
        z = 0.03
    else:
        obj = w.add_body(name="ball", pos=[0.45, 0.0, 0.025])
        obj.add_freejoint(name="ball_joint")
        obj.add_geom(name="ball_geom", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.025] * 3, mass=0.05,
                     rgba=[0.9, 0.3, 0.2, 1])
        z = 0.025
    w.add_site(name="goal", pos=[0.62, 0.0, z], size=[0.01] * 3, rgba=[0, 1, 0, .3])
    if contact == "elliptic10":
        arm.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
        arm.option.impratio = 10.0
    elif contact == "pyramidal1":
        arm.option.cone = mujoco.mjtCone.mjCONE_PYRAMIDAL
        arm.option.impratio = 1.0
    elif contact != "shipped":
        raise SystemExit(contact)
    return arm


if __name__ == "__main__":
    gen3, orca, out = (Path(a) for a in sys.argv[1:4])
    kind = sys.argv[4] if len(sys.argv) > 4 else "ball"
    out.mkdir(parents=True, exist_ok=True)
    for contact in ("shipped", "elliptic10"):
        spec = build(gen3, orca, contact, kind)
        spec.compile()
        p = out / f"gen3_orca_{kind}_{contact}.xml"
        p.write_text(spec.to_xml())
        m = mujoco.MjModel.from_xml_path(str(p))
        print("wrote", p, "nq", m.nq, "nu", m.nu, "cone", m.opt.cone, "impratio", m.opt.impratio, "dt", m.opt.timestep,
              "nexclude", m.nexclude)
