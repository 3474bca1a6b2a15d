"""Scripted pick-and-place of a sphere for make_xarm_scene.py's xArm7 scene (torque motors driven
through the scenario's [servos] gains).

DLS IK (benchmarks/real_models/scripted.py) of a TCP at the four pad boxes' midpoint, fingers
pointing down; the real_models 500-step timeline (above, down, close, lift, carry, lower, open,
retreat) at 50 Hz; joint targets with the unloaded arm's inverse dynamics fed forward through the
SCENARIO's servo gains (target = q + (kv q' + tau_id) / kp). Channels: torq_j1..7 (joint targets
[rad]), gripper (0 closed .. 1 open).
Usage: python xarm_traj.py SCENE.xml SCENARIO.toml OUT.npz [--grasp-dz DZ] [--steps N]
"""
from __future__ import annotations

import argparse
import os
import sys
import tomllib
from pathlib import Path

import mujoco
import numpy as np

REAL_MODELS = os.environ.get("CRITMOMENT_REAL_MODELS",
                             str(Path(__file__).absolute().parents[2] / "real_models"))
sys.path.insert(0, REAL_MODELS)
import scripted  # noqa: E402

from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402

JOINTS = tuple(f"joint{i}" for i in range(1, 8))
HOME = np.array([0.0, -0.3, 0.0, 1.2, 0.0, 1.5, 0.0])
PADS = ("left_finger_pad_1", "left_finger_pad_2", "right_finger_pad_1", "right_finger_pad_2")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("scenario")
    p.add_argument("out")
    p.add_argument("--grasp-dz", type=float, default=0.0)
    p.add_argument("--transport", type=float, default=0.15)
    p.add_argument("--steps", type=int, default=500)
    p.add_argument("--close", type=float, default=0.0)
    a = p.parse_args()
    cfg = tomllib.loads(Path(a.scenario).read_text())
    model = mujoco.MjModel.from_xml_path(a.scene)
    data = mujoco.MjData(model)
    qpos0 = model.qpos0.copy()
    qpos0[model.jnt_qposadr[[model.joint(j).id for j in JOINTS]]] = HOME
    bj = model.jnt_qposadr[model.joint("ball_joint").id]
    ball = qpos0[bj:bj + 7].copy()
    arm = scripted.Arm(model, JOINTS, "xarm_gripper_base_link", PADS, qpos0)
    arm.kp = np.array([cfg["servos"][f"torq_j{i}"]["kp"] for i in range(1, 8)])
    arm.kv = np.array([cfg["servos"][f"torq_j{i}"]["kv"] for i in range(1, 8)])
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    p0, r0 = arm.tcp(data)
    down = r0.copy()  # HOME already points the fingers down
    goal = model.site("goal").pos.copy()
    grasp = ball[:3] + [0, 0, a.grasp_dz]
    above = grasp + [0, 0, a.transport]
    place = goal + [0, 0, a.grasp_dz + 0.002]
    over = place + [0, 0, a.transport]
    c, o = a.close, 1.0
    pts = [(0, p0, r0, o), (75, above, down, o), (125, grasp, down, o), (140, grasp, down, o),
           (165, grasp, down, c), (180, grasp, down, c), (230, above, down, c),
           (305, over, down, c), (355, place, down, c), (370, place, down, c),
           (395, place, down, o), (445, over, down, o), (500, over, down, o)]
    s = a.steps / 500.0
    pts = [(t * s, *r) for t, *r in pts]
    q, grip = scripted.joint_path(arm, data, pts, a.steps, start=HOME, rest=HOME, seed=HOME)
    fps = 50.0
    joints = arm.feed_forward(q, 1 / fps, qpos0)
    joints[0] = HOME
    actions = np.concatenate([joints, grip[:, None]], 1)
    actions[0, -1] = 1.0
    t = Trajectory(actions=actions, fps=fps, start=actions[0].copy(), qpos0=qpos0, object_pose=ball,
                   meta={"generator": "probe_r29 xarm_traj"}, source="xarm_pick_place")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape, "max |ff offset| per joint",
          np.round(np.abs(joints - q).max(0), 3))


if __name__ == "__main__":
    main()
