"""Scripted pick-and-hold of a cube for Menagerie's AgileX PiPER (probe_r34).

usage: gen_piper.py SCENE.xml OUT.npz [--cube X Y Z] [--slow S] [--extra FRAMES] [--frames N]

Top-down grasp (link6 z down, fingers closing along world y), TCP 0.12 m along link6 z (the
tip pads' centre), DLS IK + minimum-jerk + inverse-dynamics feed-forward from
benchmarks/real_models/scripted.py. Timeline at 50 Hz: above the cube at 100, down at 150,
closed by 200, lifted 10 cm by 260, held to 400. Layout = init's [joint1..6, gripper 0..1].
"""
import argparse
import sys

import mujoco
import numpy as np

import critmoment
assert critmoment.__file__.startswith("/tmp/r34/src"), critmoment.__file__
sys.path.insert(0, "/tmp/r34/src/benchmarks/real_models")
from scripted import Arm, joint_path, _frame  # noqa: E402
from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("scene"); ap.add_argument("out")
ap.add_argument("--cube", type=float, nargs=3, default=(0.25, 0.0, 0.015))
ap.add_argument("--slow", type=float, default=1.0)
ap.add_argument("--grasp-dz", type=float, default=0.0)
ap.add_argument("--extra", type=int, default=0, help="hold the last action this many more frames")
ap.add_argument("--frames", type=int, default=0, help="cut the trajectory after this many frames (a shorter hold)")
a = ap.parse_args()

model = mujoco.MjModel.from_xml_path(a.scene)
data = mujoco.MjData(model)
mujoco.mj_resetDataKeyframe(model, data, model.key("home").id)
qpos0 = data.qpos.copy()
box = np.array([*a.cube, 1, 0, 0, 0])
fj = model.joint("cube_joint").id
qpos0[model.jnt_qposadr[fj]:model.jnt_qposadr[fj] + 7] = box
JOINTS = tuple(f"joint{i}" for i in range(1, 7))
arm = Arm.__new__(Arm)
arm.model, arm.joints, arm.hand, arm.pads, arm.qpos0 = model, JOINTS, "link6", (), qpos0
ids = [model.joint(j).id for j in JOINTS]
arm.qadr = model.jnt_qposadr[ids]; arm.dofs = model.jnt_dofadr[ids]
arm.lo = model.jnt_range[ids, 0]; arm.hi = model.jnt_range[ids, 1]
arm.body = model.body("link6").id
arm.acts = np.array([model.actuator(j).id for j in JOINTS])
arm.kp = model.actuator_gainprm[arm.acts, 0]; arm.kv = -model.actuator_biasprm[arm.acts, 2]
arm.offset = np.array([0.0, 0.0, 0.12])
data.qpos[:] = qpos0
mujoco.mj_kinematics(model, data)
down = _frame([-1, 0, 0], [0, 1, 0])
cube = box[:3]
grasp = cube + [0, 0, a.grasp_dz]
s0 = arm.tcp(data)
pts = [(0, s0[0], s0[1], 1.0), (100, cube + [0, 0, 0.08], down, 1.0), (150, grasp, down, 1.0),
       (200, grasp, down, 0.0), (260, grasp + [0, 0, 0.10], down, 0.0), (400, grasp + [0, 0, 0.10], down, 0.0)]
pts = [(int(round(p[0] * a.slow)),) + tuple(p[1:]) for p in pts]
n, dt = int(round(400 * a.slow)), 0.02
start = qpos0[arm.qadr].copy()
q, grip = joint_path(arm, data, pts, n, start=start, seed=np.array([0, 1.2, -1.0, 0, 0.8, 0]))
actions = np.zeros((n, 7))
actions[:, :6] = arm.feed_forward(q, dt, qpos0)
actions[:, 6] = grip
if a.frames:
    actions = actions[:a.frames]
if a.extra:
    actions = np.vstack([actions, np.repeat(actions[-1:], a.extra, axis=0)])
st = np.concatenate([start, [1.0]])
actions[0] = st
save_trajectory(Trajectory(actions=actions, fps=50.0, start=st, object_pose=box,
                           meta={"generator": "probe_r34/unseen gen_piper"}, source="gen_piper"), a.out)
print("wrote", a.out, actions.shape)
