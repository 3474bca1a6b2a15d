"""Probe: critmoment on robot MJCF shipped in genesis-world 1.4.5's wheel (Menagerie copies).

The wheel is fetched with ``pip download genesis-world==1.4.5 --no-deps`` (never installed)
into ``$CRITMOMENT_REAL_MODELS/wheels`` and only ``genesis/assets/xml/*`` is unzipped into
``$CRITMOMENT_REAL_MODELS/genesis``. The scene files of this folder are copied next to the
robot file they include (so the robot's own ``meshdir`` resolves as shipped).

Usage::

    python benchmarks/probe_menagerie/run.py traj ROBOT SCENARIO.toml OUT.npz [--contact elliptic10] [--truncate N]
    python benchmarks/probe_menagerie/run.py scene ROBOT [--contact ...]   # the MJCF path
    # then the CLI by hand: inspect, init, rollout, analyze, validate (see the report)
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

import mujoco
import numpy as np
import tomllib

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "real_models"))
import scripted  # noqa: E402

from critmoment.trajectory import save_trajectory  # noqa: E402

CACHE = Path(os.environ.get("CRITMOMENT_REAL_MODELS",
                            Path.home() / ".cache" / "critmoment-real-models"))
XML = CACHE / "genesis" / "genesis" / "assets" / "xml"

#: robot -> (scene file here, folder of the robot file, joints, hand body, finger bodies,
#:           rest pose, cube position, table top)
ROBOTS = {
    "menagerie_panda": dict(
        scene="panda_scene.xml", folder="franka_emika_panda",
        joints=tuple(f"joint{i}" for i in range(1, 8)), hand="hand",
        fingers=("left_finger", "right_finger"),
        rest=np.array([0, 0, 0, -1.57079, 0, 1.57079, -0.7853]),
        cube=(0.5, -0.1), goal=(0.5, 0.1), table_top=0.2),
    "franka_sim": dict(
        scene="franka_sim_scene.xml", folder="franka_sim",
        joints=tuple(f"panda0_joint{i}" for i in range(1, 8)), hand="panda0_gripper",
        fingers=("panda0_leftfinger", "panda0_rightfinger"),
        rest=np.array([0, -0.2, 0, -2.1, 0, 0.5, -0.8]),  # a 1.57 rad first move saturated joint7 (damping 10)
        cube=(0.5, -0.1), goal=(0.5, 0.1), table_top=0.2),
    "bifranka": dict(scene="bifranka_scene.xml", folder="franka_sim"),  # inspect/init only
    "ur5e_panda_hand": dict(
        scene="ur5e_scene.xml", folder="universal_robots_ur5e",
        joints=("shoulder_pan", "shoulder_lift", "elbow", "wrist_1", "wrist_2", "wrist_3"),
        hand="hand/hand", fingers=("hand/left_finger", "hand/right_finger"),
        rest=np.array([-1.5708, -1.5708, 1.5708, -1.5708, -1.5708, 0.0]),
        cube=(0.45, -0.1), goal=(0.45, 0.1), table_top=0.2),
}


def scene(robot: str, contact: str = "shipped") -> Path:
    """The composed scene, copied next to the robot file it includes."""
    cfg = ROBOTS[robot]
    text = (HERE / cfg["scene"]).read_text()
    name = f"critmoment_probe_{robot}_{contact}.xml"
    if contact == "elliptic10":
        text = text.replace("<worldbody>", '<option cone="elliptic" impratio="10"/>\n\n'
                            "  <worldbody>", 1)
    out = XML / cfg["folder"] / name
    out.write_text(text)
    if robot == "ur5e_panda_hand":
        out = attach_hand(out)
    return out


def attach_hand(arm_scene: Path) -> Path:
    """Menagerie's Franka hand (hand.xml as shipped) attached at the UR5e's attachment_site
    with MjSpec, written next to the scene with absolute mesh paths."""
    hand_xml = XML / "franka_emika_panda" / "hand.xml"
    spec = mujoco.MjSpec.from_file(str(arm_scene))
    hand = mujoco.MjSpec.from_file(str(hand_xml))
    for s, base in ((spec, arm_scene.parent), (hand, hand_xml.parent)):
        meshdir = base / s.meshdir if s.meshdir else base
        for mesh in s.meshes:
            if mesh.file and not Path(mesh.file).is_absolute():
                mesh.file = str((meshdir / mesh.file).resolve())
        s.meshdir = ""
    spec.site("attachment_site").attach_body(hand.body("hand"), "hand/", "")
    spec.compile()
    out = arm_scene.with_name(arm_scene.stem + "_hand.xml")
    out.write_text(spec.to_xml())
    mujoco.MjModel.from_xml_path(str(out))
    return out


def trajectory(robot: str, mjcf: Path, scenario: Path, out: Path, seed: int = 0,
               truncate: int | None = None) -> Path:
    cfg = ROBOTS[robot]
    model = mujoco.MjModel.from_xml_path(str(mjcf))
    scripted.REST[robot] = cfg["rest"]
    x, y = cfg["cube"]
    scripted.cube_pose = lambda seed, table_top, half: np.array(
        [x, y, table_top + half, 1, 0, 0, 0])
    pads = [g for g in range(model.ngeom)
            if model.body(model.geom_bodyid[g]).name in cfg["fingers"]
            and (model.geom_contype[g] or model.geom_conaffinity[g])]
    traj = scripted.pick_place(model, robot, joints=cfg["joints"], hand=cfg["hand"], pads=pads,
                               goal=np.array([*cfg["goal"], cfg["table_top"] + 0.02]),
                               seed=seed, table_top=cfg["table_top"], half=0.02)
    raw = tomllib.loads(scenario.read_text())
    mine = [model.actuator(int(a)).name for a in scripted.Arm(
        model, cfg["joints"], cfg["hand"], tuple(pads), traj.qpos0).acts]
    cols = []
    for ch in raw["actions"]["channel"]:
        cols.append(len(mine) if ch.get("normalised") else mine.index(ch["actuators"][0]))
    import dataclasses
    traj = dataclasses.replace(traj, actions=traj.actions[:truncate, cols],
                               start=traj.start[cols])
    save_trajectory(traj, out)
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser()
    sub = p.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("scene")
    s.add_argument("robot")
    s.add_argument("--contact", default="shipped")
    t = sub.add_parser("traj")
    t.add_argument("robot")
    t.add_argument("scenario", type=Path)
    t.add_argument("out", type=Path)
    t.add_argument("--contact", default="shipped")
    t.add_argument("--truncate", type=int, default=None,
                   help="keep the first N actions (330: the cube carried, a pick_hold)")
    a = p.parse_args(argv)
    if a.cmd == "scene":
        print(scene(a.robot, a.contact))
    else:
        print(trajectory(a.robot, scene(a.robot, a.contact), a.scenario, a.out,
                         truncate=a.truncate))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
