"""A scripted pick-and-place for the kitchen Franka scene (franka_scene.py): ``scripted.Arm``
DLS IK (null-space pull to REST), ``joint_path``, ``feed_forward``, the Panda demo's 500-step
timeline; cube at (0.5, -0.1) on the table (top 0.3 m), goal site (0.5, 0.1).

Channels in init's order: 7 joint targets, then the two fingers as one normalised channel
(0 closed .. 1 open). Usage: python franka_traj.py SCENE.xml OUT.npz [--steps N]
"""
import argparse
import sys
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "real_models"))
import scripted  # noqa: E402

from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402

JOINTS = tuple(f"robot:panda0_joint{i}" for i in range(1, 8))
REST = np.array([0.0, -0.4, 0.0, -2.2, 0.0, 0.23, -0.785])  # hand down, 0.44 m up


def pick_place(model, *, n=500, fps=50.0, grasp_height=0.0, transport=0.15, top=0.3):
    qpos0 = model.qpos0.copy()
    ad = [model.jnt_qposadr[model.joint(j).id] for j in JOINTS]
    qpos0[ad] = REST
    for f in ("robot:panda0_finger_joint1", "robot:panda0_finger_joint2"):
        qpos0[model.jnt_qposadr[model.joint(f).id]] = 0.04
    cj = model.jnt_qposadr[model.joint("cube_joint").id]
    cube = qpos0[cj:cj + 7].copy()
    cube[2] = top + 0.02
    qpos0[cj:cj + 7] = cube

    # the fingertip capsules (unnamed): TCP offset = the end_effector site, in link7's frame
    data = mujoco.MjData(model)
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    b = model.body("panda0_link7").id
    rot = data.xmat[b].reshape(3, 3)
    site = model.site("end_effector").id
    offset = rot.T @ (data.site_xpos[site] - data.xpos[b])
    fingers = [model.body(n).id for n in ("panda0_leftfinger", "panda0_rightfinger")]
    tips = [g for g in range(model.ngeom) if model.geom_bodyid[g] in fingers
            and model.geom_contype[g]]
    mid = np.mean([data.geom_xpos[g] for g in tips], axis=0)
    offset = rot.T @ (mid - data.xpos[b])
    arm = scripted.Arm(model, JOINTS, "panda0_link7", (model.geom(tips[0]).name or "",), qpos0,
                       offset) if False else None
    arm = scripted.Arm.__new__(scripted.Arm)
    arm.model, arm.joints, arm.hand, arm.pads, arm.qpos0, arm.offset = (
        model, JOINTS, "panda0_link7", (), qpos0, offset)
    # Arm.__post_init__ needs pad names (the tips are unnamed): set its fields by hand
    ids = [model.joint(j).id for j in JOINTS]
    arm.qadr, arm.dofs = model.jnt_qposadr[ids], model.jnt_dofadr[ids]
    arm.lo, arm.hi = model.jnt_range[ids, 0], model.jnt_range[ids, 1]
    arm.body = b
    arm.acts = np.array([model.actuator(f"panda0_joint{i}").id for i in range(1, 8)])
    arm.kp = model.actuator_gainprm[arm.acts, 0]
    arm.kv = -model.actuator_biasprm[arm.acts, 2]
    p0, r0 = arm.tcp(data)
    down = scripted._frame([1, 0, 0], [0, 1, 0]) @ np.diag([1, -1, -1])
    if np.trace(down.T @ r0) < np.trace((down @ np.diag([-1, -1, 1])).T @ r0):
        down = down @ np.diag([-1, -1, 1])
    goal = model.site("goal").pos.copy()
    grasp = cube[:3] + [0, 0, grasp_height]
    above = np.array([cube[0], cube[1], top + transport])
    place = goal + [0, 0, grasp_height + 0.002]
    over = np.array([goal[0], goal[1], top + transport])
    s = n / 500.0
    pts = [(0, p0, r0, 1.0), (75, above, down, 1.0), (125, grasp, down, 1.0),
           (140, grasp, down, 1.0), (165, grasp, down, 0.0), (180, grasp, down, 0.0),
           (230, above, down, 0.0), (305, over, down, 0.0), (355, place, down, 0.0),
           (370, place, down, 0.0), (395, place, down, 1.0), (445, over, down, 1.0),
           (500, over, down, 1.0)]
    pts = [(t * s, *r) for t, *r in pts]
    q, grip = scripted.joint_path(arm, data, pts, n, start=REST, rest=REST)
    actions = np.concatenate([arm.feed_forward(q, 1.0 / fps, qpos0), grip[:, None]], axis=1)
    start = np.concatenate([REST, [1.0]])
    actions[0] = start
    return Trajectory(actions=actions, fps=fps, start=start, qpos0=qpos0, object_pose=cube,
                      meta={"generator": "benchmarks/probe_pypi3 franka_traj"},
                      source="kitchen_franka_pick_place")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--steps", type=int, default=500)
    a = p.parse_args()
    m = mujoco.MjModel.from_xml_path(a.scene)
    t = pick_place(m, n=a.steps)
    save_trajectory(t, a.out)
    print("wrote", a.out, t.actions.shape)


if __name__ == "__main__":
    main()
