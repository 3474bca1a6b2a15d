"""A scripted pick-and-place for the composed YAM (yam_scene.py): ``scripted.Arm`` DLS IK,
``scripted.joint_path`` and ``feed_forward``, the Panda demo's 500-step timeline (as
``scripted.pick_place``), the cube at (0.3, 0) on the floor, the goal site (0.3, 0.15).

Channels: joint1..6 targets [rad], then the gripper normalised (0 closed .. 1 open), init's
order for this scene. Usage: python yam_traj.py SCENE.xml OUT.npz [--grasp-height H]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "real_models"))
sys.path.insert(0, str(Path(__file__).resolve().parent))
import scripted  # noqa: E402
import yam_scene  # noqa: E402

from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402

JOINTS = tuple(f"joint{i}" for i in range(1, 7))


def pick_place(model, *, grasp_height=0.0, transport=0.15, closed=0.0, open_=1.0,
               n=500, fps=50.0) -> Trajectory:
    qpos0 = yam_scene.home_qpos(model)
    rest = qpos0[[model.jnt_qposadr[model.joint(j).id] for j in JOINTS]].copy()
    cj = model.jnt_qposadr[model.joint("cube_joint").id]
    cube = qpos0[cj:cj + 7].copy()
    pads = ("lf_down4_collision", "rf_down4_collision")
    arm = scripted.Arm(model, JOINTS, "link_6", pads, qpos0)
    data = mujoco.MjData(model)
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    p0, r0 = arm.tcp(data)
    down = scripted._frame([1, 0, 0], [0, 1, 0]) @ np.diag([1, -1, -1])
    if np.trace(down.T @ r0) < np.trace((down @ np.diag([-1, -1, 1])).T @ r0):
        down = down @ np.diag([-1, -1, 1])
    goal = model.site("goal").pos.copy()
    half = 0.02
    grasp = cube[:3] + [0, 0, grasp_height]
    above = np.array([cube[0], cube[1], half + transport])
    place = goal + [0, 0, grasp_height + 0.002]
    over = np.array([goal[0], goal[1], half + transport])
    s = n / 500.0
    points = [(0, p0, r0, 1.0), (75, above, down, open_), (125, grasp, down, open_),
              (140, grasp, down, open_), (165, grasp, down, closed), (180, grasp, down, closed),
              (230, above, down, closed), (305, over, down, closed), (355, place, down, closed),
              (370, place, down, closed), (395, place, down, open_), (445, over, down, open_),
              (500, over, down, open_)]
    points = [(t * s, *r) for t, *r in points]
    q, grip = scripted.joint_path(arm, data, points, n, start=rest)
    lo_hi = model.jnt_range[model.joint("left_finger").id]
    g0 = (qpos0[model.jnt_qposadr[model.joint("left_finger").id]] - lo_hi[0]) / np.ptp(lo_hi)
    grip[0] = g0
    actions = np.concatenate([arm.feed_forward(q, 1.0 / fps, qpos0), grip[:, None]], axis=1)
    start = np.concatenate([rest, [g0]])
    actions[0] = start
    return Trajectory(actions=actions, fps=fps, start=start, qpos0=qpos0, object_pose=cube,
                      meta={"generator": "benchmarks/probe_pypi3 yam_traj"},
                      source="yam_pick_place")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--grasp-height", type=float, default=0.0)
    p.add_argument("--closed", type=float, default=0.0)
    p.add_argument("--steps", type=int, default=500)
    a = p.parse_args()
    model = mujoco.MjModel.from_xml_path(a.scene)
    t = pick_place(model, grasp_height=a.grasp_height, closed=a.closed, n=a.steps)
    save_trajectory(t, a.out)
    print("wrote", a.out, t.actions.shape)


if __name__ == "__main__":
    main()
