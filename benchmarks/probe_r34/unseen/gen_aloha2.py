"""ACT's transfer-cube timeline (real_models/scripted.py act_transfer) for Menagerie's ALOHA 2.

usage: gen_aloha2.py SCENE.xml OUT.npz [--box X Y] [--grasp-height H] [--meet X Y Z]
          [--left-dx DX] [--slow S] [--pitch DEG]

Same waypoints/timeline as benchmarks/real_models/scripted.py:act_transfer (right arm picks,
left receives), joint names 'left/waist'... of Menagerie's aloha.xml, TCP 0.125 m along
gripper_link x (the custom fingers' pad centre), the scene's 'home' keyframe as start.
The box pose: ACT's seed-0 spawn (0.127, 0.454) shifted into Menagerie's frame (arms at
y = -0.019 instead of 0.5, bases 2 cm up): (0.127, -0.065, 0.02).
Action layout = init's: [left 6 joints, left gripper 0..1, right 6 joints, right gripper].
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

JOINTS = ("waist", "shoulder", "elbow", "forearm_roll", "wrist_angle", "wrist_rotate")
START = np.array([0.0, -0.96, 1.16, 0.0, -0.3, 0.0])
SEED = np.array([0.0, -0.5, 1.0, 0.0, 0.6, 0.0])
TCP = np.array([0.125, 0.0, 0.0])

ap = argparse.ArgumentParser()
ap.add_argument("scene"); ap.add_argument("out")
ap.add_argument("--box", type=float, nargs=2, default=(0.127, -0.065))
ap.add_argument("--box-z", type=float, default=0.0191)
ap.add_argument("--grasp-height", type=float, default=0.005)
ap.add_argument("--meet", type=float, nargs=3, default=(0.0, -0.019, 0.27))
ap.add_argument("--left-dx", type=float, default=-0.01, help="receiver TCP x offset from the meet point")
ap.add_argument("--slow", type=float, default=1.0, help="stretch ACT's 400-step timeline by this factor")
ap.add_argument("--variant", default="nominal", choices=["nominal", "no_release", "no_receive", "early_open", "proper"],
                help="no_release: the picker never opens (both hold at the end); no_receive: the "
                     "receiver comes but never closes; early_open: the picker opens fully before the receiver arrives; proper: the picker holds closed until the "
                     "receiver has closed (300) and opens 300..340")
ap.add_argument("--pitch", type=float, default=60.0, help="picker's approach pitch [deg]")
a = ap.parse_args()

model = mujoco.MjModel.from_xml_path(a.scene)
data = mujoco.MjData(model)
mujoco.mj_resetDataKeyframe(model, data, model.key("home").id)
qpos0 = data.qpos.copy()
box = np.array([a.box[0], a.box[1], a.box_z, 1, 0, 0, 0])
fj = model.joint("box_joint").id
qpos0[model.jnt_qposadr[fj]:model.jnt_qposadr[fj] + 7] = box
arms = {}
for side in ("left", "right"):
    # Menagerie's pads are unnamed: build Arm without its pad-midpoint default (TCP given)
    arm = Arm.__new__(Arm)
    arm.model, arm.joints, arm.hand, arm.pads, arm.qpos0, arm.offset = (
        model, tuple(f"{side}/{j}" for j in JOINTS), f"{side}/gripper_link", (), qpos0, TCP)
    m = model
    ids = [m.joint(j).id for j in arm.joints]
    arm.qadr = m.jnt_qposadr[ids]; arm.dofs = m.jnt_dofadr[ids]
    arm.lo = m.jnt_range[ids, 0]; arm.hi = m.jnt_range[ids, 1]
    arm.body = m.body(arm.hand).id
    arm.acts = np.array([m.actuator(f"{side}/{j}").id for j in JOINTS])
    arm.kp = m.actuator_gainprm[arm.acts, 0]; arm.kv = -m.actuator_biasprm[arm.acts, 2]
    arm.offset = TCP.copy()
    arms[side] = arm

data.qpos[:] = qpos0
mujoco.mj_kinematics(model, data)
pr = np.deg2rad(a.pitch)
right_pick = _frame([-np.cos(pr), 0, -np.sin(pr)], [0, -1, 0])
left_meet = _frame([1, 0, 0], [0, 0, 1])
left_rest = _frame([1, 0, 0], [0, 1, 0])
cube, meet = box[:3], np.asarray(a.meet, float)
grasp = cube + [0, 0, a.grasp_height]
held = meet - [0, 0, a.grasp_height]
rs, ls = arms["right"].tcp(data), arms["left"].tcp(data)
right = [(0, rs[0], rs[1], 0.0), (90, cube + [0, 0, 0.08], right_pick, 1.0),
         (130, grasp, right_pick, 1.0), (170, grasp, right_pick, 0.0),
         (200, meet + [0.05, 0, 0], right_pick, 0.0), (220, meet, right_pick, 0.0),
         (310, meet, right_pick, 1.0), (360, meet + [0.1, 0, 0], right_pick, 1.0),
         (400, meet + [0.1, 0, 0], right_pick, 1.0)]
ldx = a.left_dx
if a.variant == "early_open":
    right[6] = (240,) + right[6][1:]
left = [(0, ls[0], ls[1], 0.0), (100, held + [-0.1, 0, 0], left_meet, 1.0),
        (260, held + [ldx, 0, 0], left_meet, 1.0), (300, held + [ldx, 0, 0], left_meet, 0.0),
        (310, held + [ldx, 0, 0], left_meet, 0.0), (360, held + [-0.1, 0, -0.02], left_rest, 0.0),
        (400, held + [-0.1, 0, -0.02], left_rest, 0.0)]
if a.variant == "no_release":   # both keep holding at the meet point to the end
    right = [w if w[0] <= 220 else (w[0], meet, right_pick, 0.0) for w in right]
    left = [w if w[0] <= 300 else (w[0], held + [ldx, 0, 0], left_meet, 0.0) for w in left]
if a.variant == "proper":
    right = right[:6] + [(300, meet, right_pick, 0.0), (340, meet, right_pick, 1.0),
                         (370, meet + [0.1, 0, 0], right_pick, 1.0), (400, meet + [0.1, 0, 0], right_pick, 1.0)]
    left = left[:4] + [(340, held + [ldx, 0, 0], left_meet, 0.0), (380, held + [-0.1, 0, -0.02], left_rest, 0.0),
                       (400, held + [-0.1, 0, -0.02], left_rest, 0.0)]
if a.variant == "no_receive":
    left = [w[:3] + (1.0 if w[0] >= 100 else w[3],) for w in left]
right = [(int(round(w[0] * a.slow)),) + tuple(w[1:]) for w in right]
left = [(int(round(w[0] * a.slow)),) + tuple(w[1:]) for w in left]
n, dt = int(round(400 * a.slow)), 0.02
actions = np.zeros((n, 14))
for side, points, col in (("left", left, 0), ("right", right, 7)):
    arm = arms[side]
    data.qpos[:] = qpos0
    q, grip = joint_path(arm, data, points, n, start=START, seed=SEED if side == "right" else START)
    actions[:, col:col + 6] = arm.feed_forward(q, dt, qpos0)
    actions[:, col + 6] = grip
start = np.concatenate([START, [0.0], START, [0.0]])
actions[0] = start
traj = Trajectory(actions=actions, fps=50.0, start=start, object_pose=box,
                  meta={"generator": "probe_r34/unseen gen_aloha2 (act_transfer timeline)"},
                  source="gen_aloha2")
save_trajectory(traj, a.out)
print("wrote", a.out, actions.shape)
