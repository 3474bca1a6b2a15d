"""Scripted pick-and-hold for make_ur5e_scene.py's UR5e + Robotiq 2F-85 + cylinder scene.

DLS IK (benchmarks/real_models/scripted.py) of a TCP at the four pad boxes' midpoint, fingers
pointing down, closing along world y; timeline at 50 Hz (500 steps): above the can (75), down
(125), close (140..165), wait (190), lift 0.15 m (250), carry 0.25 m along +y in `--carry`
steps, hold there to the end. Servo targets with the unloaded arm's inverse dynamics fed
forward. Channels: shoulder_pan..wrist_3, gripper (0 closed .. 1 open).

Usage: python ur5e_traj.py SCENE.xml OUT.npz [--carry STEPS] [--grasp-dz DZ]
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

JOINTS = ("shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint",
          "wrist_2_joint", "wrist_3_joint")
HOME = np.array([np.pi, -1.5708, 1.5708, -1.5708, -1.5708, 0.0])
PADS = ("g_right_pad1", "g_right_pad2", "g_left_pad1", "g_left_pad2")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--carry", type=int, default=60, help="steps of the 0.25 m carry")
    p.add_argument("--grasp-dz", type=float, default=0.01, help="TCP above the can's centre [m]")
    p.add_argument("--close", type=float, default=0.0)
    a = p.parse_args()
    model = mujoco.MjModel.from_xml_path(a.scene)
    data = mujoco.MjData(model)
    qpos0 = model.qpos0.copy()
    qpos0[model.jnt_qposadr[[model.joint(j).id for j in JOINTS]]] = HOME
    cj = model.jnt_qposadr[model.joint("can_joint").id]
    can = qpos0[cj:cj + 7].copy()
    arm = scripted.Arm(model, JOINTS, "g_base", PADS, qpos0)
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    p0, r0 = arm.tcp(data)
    down = np.array([[1, 0, 0], [0, -1, 0], [0, 0, -1]], float)  # hand z down, hand y = -world y
    if np.trace(down.T @ r0) < np.trace((down @ np.diag([-1, -1, 1])).T @ r0):
        down = down @ np.diag([-1, -1, 1])
    grasp = can[:3] + [0, 0, a.grasp_dz]
    above = grasp + [0, 0, 0.12]
    lifted = grasp + [0, 0, 0.15]
    carried = lifted + [0, 0.25, 0]
    c, o = a.close, 1.0
    t_end = 250 + a.carry
    pts = [(0, p0, r0, o), (75, above, down, o), (125, grasp, down, o), (140, grasp, down, o),
           (165, grasp, down, c), (190, grasp, down, c), (250, lifted, down, c),
           (t_end, carried, down, c), (500, carried, down, c)]
    q, grip = scripted.joint_path(arm, data, pts, 500, start=HOME, rest=None, seed=HOME)
    fps = 50.0
    joints = arm.feed_forward(q, 1 / fps, qpos0)
    joints[0] = HOME
    actions = np.concatenate([joints, grip[:, None]], 1)
    actions[0, -1] = 1.0
    t = Trajectory(actions=actions, fps=fps, start=actions[0].copy(), qpos0=qpos0, object_pose=can,
                   meta={"generator": "probe_r29 ur5e_traj", "carry": a.carry},
                   source="ur5e_pick_hold")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape)


if __name__ == "__main__":
    main()
