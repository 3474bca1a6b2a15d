"""A scripted pick-and-place for the WidowX AI scene (scene_*.xml): DLS IK of a TCP between
the finger pads (0.12 m out along link_6's x axis), the real_models 500-step timeline
(above, down, close, lift, carry, lower, open, retreat) at 50 Hz, servo targets with a
feed-forward of the arm's inertia and the servos' own damping only (the model compensates
gravity through actuatorgravcomp). Channels: joint_0..5 [rad], gripper 0 closed .. 1 open.

Usage (the critmoment venv active, from this folder):
    python traj.py SCENE.xml OUT.npz [--close C] [--transport H] [--steps N]
e.g. python traj.py scene_shipped.xml traj.npz; --steps 300 wrote traj_fast.npz.
It uses benchmarks/real_models/scripted.py of this repository (IK and the joint path);
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

JOINTS = tuple(f"joint_{i}" for i in range(6))
REST = np.array([0.0, 1.0, 1.0, 0.0, 0.0, 0.0])


def feed_forward(model, arm, q, dt, qpos0):
    m = model.__copy__()
    m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONSTRAINT)
    m.opt.gravity[:] = 0.0
    d = mujoco.MjData(m)
    qd = np.gradient(q, dt, axis=0)
    qdd = np.gradient(qd, dt, axis=0)
    tau = np.empty_like(q)
    for i in range(len(q)):
        d.qpos[:] = qpos0
        d.qpos[arm.qadr] = q[i]
        d.qvel[:] = 0
        d.qacc[:] = 0
        d.qvel[arm.dofs] = qd[i]
        d.qacc[arm.dofs] = qdd[i]
        mujoco.mj_inverse(m, d)
        tau[i] = d.qfrc_inverse[arm.dofs]
    return np.clip(q + (arm.kv * qd + tau) / arm.kp, arm.lo, arm.hi)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--close", type=float, default=0.0, help="gripper command when closed")
    p.add_argument("--transport", type=float, default=0.12)
    p.add_argument("--steps", type=int, default=500)
    p.add_argument("--grasp-height", type=float, default=0.0)
    a = p.parse_args()
    model = mujoco.MjModel.from_xml_path(a.scene)
    data = mujoco.MjData(model)
    qpos0 = data.qpos.copy()
    ids = [model.joint(j).id for j in JOINTS]
    qpos0[model.jnt_qposadr[ids]] = REST
    g = model.jnt_qposadr[model.joint("left_carriage_joint").id]
    g2 = model.jnt_qposadr[model.joint("right_carriage_joint").id]
    qpos0[g] = qpos0[g2] = 0.044
    cj = model.jnt_qposadr[model.joint("cube_joint").id]
    cube = qpos0[cj:cj + 7].copy()
    pad_geoms = [i for i in range(model.ngeom) if model.geom_bodyid[i] in
                 (model.body("carriage_left").id, model.body("carriage_right").id)
                 and model.geom_contype[i]]
    arm = scripted.Arm(model, JOINTS, "link_6", tuple(pad_geoms), qpos0,
                       offset=np.array([0.12, 0.0, 0.0]))
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    p0, r0 = arm.tcp(data)
    down = scripted._frame([0, 0, -1], [0, 1, 0])  # approach along -z, fingers along y
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
    q, grip = scripted.joint_path(arm, data, pts, a.steps, start=REST)
    fps = 50.0
    actions = np.concatenate([feed_forward(model, arm, q, 1 / fps, qpos0), grip[:, None]], 1)
    start = np.concatenate([REST, [1.0]])
    actions[0] = start
    t = Trajectory(actions=actions, fps=fps, start=start, qpos0=qpos0, object_pose=cube,
                   meta={"generator": "probe_r24 wxai traj"}, source="wxai_pick_place")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape)


if __name__ == "__main__":
    main()
