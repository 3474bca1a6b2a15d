"""Scripted pick-and-place for vs050-mujoco 1.1.0's DENSO VS050 + Robotiq 2F-85 scene.

The scene (`vs050_mujoco/models/pick_and_place_scene.xml`) is used AS SHIPPED (or an MjSpec
copy with another contact model, make_variants.py). DLS IK (benchmarks/real_models/scripted.py)
of a TCP at the four pad boxes' midpoint, fingers pointing down; the real_models 500-step
timeline (above, down, close, lift, carry, lower, open, retreat) at 50 Hz; servo targets with
the unloaded arm's inverse dynamics fed forward. Channels: act_joint_1..6, gripper
(0 closed .. 1 open, init's normalised channel: 255 closed, 0 open).

The trajectory carries qpos0 = the model's qpos0 with the arm at the package's own home
(0, 0, pi/2, 0, 0, 0) -- NOT the shipped keyframe "home", which was written for nq = 15 and
puts the gripper linkage and the cube in the wrong slots (see README finding on keyframes).

Usage: python vs050_traj.py SCENE.xml OUT.npz [--close C] [--grasp-z Z] [--transport H] [--steps N]
"""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

import mujoco
import numpy as np

REAL_MODELS = os.environ.get("CRITMOMENT_REAL_MODELS",
                             str(Path(__file__).absolute().parents[2] / "real_models"))
sys.path.insert(0, REAL_MODELS)
import scripted  # noqa: E402

from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402

JOINTS = tuple(f"joint_{i}" for i in range(1, 7))
HOME = np.array([0.0, 0.0, np.pi / 2, 0.0, 0.0, 0.0])
PADS = ("right_pad1", "right_pad2", "left_pad1", "left_pad2")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--close", type=float, default=0.0, help="normalised gripper command when closed")
    p.add_argument("--transport", type=float, default=0.15)
    p.add_argument("--grasp-z", type=float, default=0.03, help="TCP height at the grasp [m]")
    p.add_argument("--goal", type=float, nargs=2, default=None, help="place xy (default target_site)")
    p.add_argument("--steps", type=int, default=500)
    a = p.parse_args()
    model = mujoco.MjModel.from_xml_path(a.scene)
    data = mujoco.MjData(model)
    qpos0 = model.qpos0.copy()
    qpos0[model.jnt_qposadr[[model.joint(j).id for j in JOINTS]]] = HOME
    cj = model.jnt_qposadr[model.joint("object0_joint").id]
    cube = qpos0[cj:cj + 7].copy()
    arm = scripted.Arm(model, JOINTS, "base", PADS, qpos0)
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    p0, r0 = arm.tcp(data)
    # hand z (approach) = world -z, fingers close along hand y = world y
    down = scripted._frame([-1, 0, 0], [0, 1, 0]) @ np.diag([1, 1, 1])
    down = np.stack([down[:, 0], down[:, 1], np.cross(down[:, 0], down[:, 1])], 1)
    if down[2, 2] > 0:  # make hand z point down
        down = down @ np.diag([-1, 1, -1])
    goal = model.site("target_site").pos.copy() if a.goal is None else np.array([*a.goal, 0.0])
    grasp = np.array([cube[0], cube[1], a.grasp_z])
    above = grasp + [0, 0, a.transport]
    place = np.array([goal[0], goal[1], a.grasp_z + 0.002])
    over = place + [0, 0, a.transport]
    c, o = a.close, 1.0
    pts = [(0, p0, r0, o), (75, above, down, o), (125, grasp, down, o), (140, grasp, down, o),
           (165, grasp, down, c), (180, grasp, down, c), (230, above, down, c),
           (305, over, down, c), (355, place, down, c), (370, place, down, c),
           (395, place, down, o), (445, over, down, o), (500, over, down, o)]
    s = a.steps / 500.0
    pts = [(t * s, *r) for t, *r in pts]
    q, grip = scripted.joint_path(arm, data, pts, a.steps, start=HOME, rest=None, seed=HOME)
    fps = 50.0
    joints = arm.feed_forward(q, 1 / fps, qpos0)
    joints[0] = HOME
    actions = np.concatenate([joints, grip[:, None]], 1)
    actions[0, -1] = 1.0
    t = Trajectory(actions=actions, fps=fps, start=actions[0].copy(), qpos0=qpos0,
                   object_pose=cube, meta={"generator": "probe_r29 vs050_traj"},
                   source="vs050_pick_place")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape, "cube", cube[:3], "goal", goal)


if __name__ == "__main__":
    main()
