"""A scripted pick-and-place for the OpenArm right arm (make_scene.py's scenes).

DLS IK (benchmarks/real_models/scripted.py) of a TCP at the finger pads' midpoint, fingers
pointing down and spreading along world x; the real_models 500-step timeline (above, down,
close, lift, carry, lower, open, retreat) at 50 Hz; servo targets with the unloaded arm's
inverse dynamics fed forward (gravity and joint damping; friction loss is not). The left
arm holds the pedestal's home pose (joint4 = pi/2). Channels in init's order: left
joint1..7, left gripper (0 closed .. 1 open), right joint1..7, right gripper.

Usage (the critmoment venv active, from this folder):
    python traj.py SCENE.xml OUT.npz [--close C] [--grasp-height H] [--steps N]
e.g. python traj.py assets/pedestal/critmoment_r25_oa_shipped.xml /tmp/r25/robots/oa_traj.npz
CRITMOMENT_REAL_MODELS names another folder holding scripted.py.
"""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

import mujoco
import numpy as np

REAL_MODELS = os.environ.get("CRITMOMENT_REAL_MODELS",
                             str(Path(__file__).absolute().parents[3] / "real_models"))
sys.path.insert(0, REAL_MODELS)
import scripted  # noqa: E402

from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402

RIGHT = tuple(f"openarm_right_joint{i}" for i in range(1, 8))
LEFT = tuple(f"openarm_left_joint{i}" for i in range(1, 8))
HOME = np.array([0.0, 0.0, 0.0, np.pi / 2, 0.0, 0.0, 0.0])
SEED = np.array([0.764, 1.157, -1.149, 1.569, -0.178, 0.374, 1.219])


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--close", type=float, default=0.0, help="gripper command when closed")
    p.add_argument("--transport", type=float, default=0.10)
    p.add_argument("--steps", type=int, default=500)
    p.add_argument("--grasp-height", type=float, default=0.0)
    a = p.parse_args()
    model = mujoco.MjModel.from_xml_path(a.scene)
    data = mujoco.MjData(model)
    qpos0 = data.qpos.copy()
    for names in (LEFT, RIGHT):
        qpos0[model.jnt_qposadr[[model.joint(j).id for j in names]]] = HOME
    cj = model.jnt_qposadr[model.joint("cube_joint").id]
    cube = qpos0[cj:cj + 7].copy()
    hand = "openarm_right_ee_base_link"
    pads = tuple(model.geom(i).name for i in range(model.ngeom)
                 if model.geom(i).name.startswith(("finger_inner_right_collision",
                                                   "finger_outer_right_collision")))
    arm = scripted.Arm(model, RIGHT, hand, pads, qpos0)
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    p0, r0 = arm.tcp(data)
    down = scripted._frame([0, 1, 0], [-1, 0, 0])  # hand z up, fingers hang down, spread along x
    goal = model.site("goal").pos.copy()
    grasp = cube[:3] + [0, 0, a.grasp_height]
    above = grasp + [0, 0, a.transport]
    place = goal + [0, 0, a.grasp_height + 0.002]
    over = place + [0, 0, a.transport]
    c, o = a.close, 1.0
    pts = [(0, p0, r0, o), (75, above, down, o), (125, grasp, down, o), (140, grasp, down, o),
           (165, grasp, down, c), (180, grasp, down, c), (230, above, down, c),
           (305, over, down, c), (355, place, down, c), (370, place, down, c),
           (395, place, down, o), (445, over, down, o), (500, over, down, o)]
    s = a.steps / 500.0
    pts = [(t * s, *r) for t, *r in pts]
    q, grip = scripted.joint_path(arm, data, pts, a.steps, start=HOME, rest=None, seed=SEED)
    fps = 50.0
    right = arm.feed_forward(q, 1 / fps, qpos0)
    right[0] = HOME
    n = len(q)
    left = np.tile(HOME, (n, 1))
    actions = np.concatenate([left, np.ones((n, 1)), right, grip[:, None]], 1)
    actions[0, -1] = 1.0
    start = actions[0].copy()
    t = Trajectory(actions=actions, fps=fps, start=start, qpos0=qpos0, object_pose=cube,
                   meta={"generator": "probe_r25 openarm traj"}, source="openarm_pick_place")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape)


if __name__ == "__main__":
    main()
