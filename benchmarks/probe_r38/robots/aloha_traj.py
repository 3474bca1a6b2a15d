"""probe_r38: ACT's scripted transfer-cube (benchmarks/real_models/scripted.py:act_transfer of the r38 snapshot)
re-targeted to Menagerie's own ALOHA 2 (aloha/aloha.xml: joints 'left/waist'..., hands 'left/gripper_link',
arms at x = +-0.469, y = -0.019, table top z = 0): the right arm picks the cube, meets the left arm at
(0, -0.019, 0.25) and lets go once the left gripper has closed. Actions: ACT's 14 values [left 6 joints, left
gripper 0 closed..1 open, right 6, right gripper] = Menagerie's actuator order. 50 Hz, 400 rows (x --slow).
usage: aloha_traj.py SCENE.xml OUT.npz [--grasp-height H]"""
import argparse, sys
import mujoco, numpy as np
sys.path.insert(0, "/tmp/r38/robots/src/benchmarks/real_models")
import scripted  # noqa: E402
import critmoment  # noqa: E402
from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402
assert critmoment.__file__.startswith("/tmp/r38/robots/src") and scripted.__file__.startswith("/tmp/r38/robots/src")
J = scripted.ACT_JOINTS
ap = argparse.ArgumentParser(); ap.add_argument("scene"); ap.add_argument("out")
ap.add_argument("--grasp-height", type=float, default=0.005)
ap.add_argument("--slow", type=float, default=1.0, help="time scale of ACT's timeline (Menagerie's wrist servos are softer)")
ap.add_argument("--tcp", type=float, default=0.12, help="TCP along gripper_link x [m] (finger meshes end at 0.146)")
a = ap.parse_args()
model = mujoco.MjModel.from_xml_path(a.scene); data = mujoco.MjData(model)
mujoco.mj_resetDataKeyframe(model, data, 0)
qpos0 = data.qpos.copy()
cj = model.joint("cube_joint").qposadr[0]; box = qpos0[cj:cj + 7].copy()
arms = {s: scripted.Arm(model, tuple(f"{s}/{j}" for j in J), f"{s}/gripper_link", (), qpos0,
                        np.array([a.tcp, 0.0, 0.0])) for s in ("left", "right")}
mujoco.mj_kinematics(model, data)
pitch = np.deg2rad(60.0)
right_pick = scripted._frame([-np.cos(pitch), 0, -np.sin(pitch)], [0, -1, 0])
left_meet = scripted._frame([1, 0, 0], [0, 0, 1])
left_rest = scripted._frame([1, 0, 0], [0, 1, 0])
cube, meet = box[:3], np.array([0.0, -0.019, 0.25])
gh = a.grasp_height
grasp = cube + [0, 0, gh]; held = meet - [0, 0, gh]
rs, ls = arms["right"].tcp(data), arms["left"].tcp(data)
right = [(0, rs[0], rs[1], 0.0), (90, cube + [0, 0, 0.08], right_pick, 1.0),
         (130, grasp, right_pick, 1.0), (170, grasp, right_pick, 0.0),
         (200, meet + [0.05, 0, 0], right_pick, 0.0), (220, meet, right_pick, 0.0),
         (310, meet, right_pick, 1.0), (360, meet + [0.1, 0, 0], right_pick, 1.0),
         (400, meet + [0.1, 0, 0], right_pick, 1.0)]
left = [(0, ls[0], ls[1], 0.0), (100, held + [-0.1, 0, 0], left_meet, 1.0),
        (260, held + [-0.01, 0, 0], left_meet, 1.0), (300, held + [-0.01, 0, 0], left_meet, 0.0),
        (310, held + [-0.01, 0, 0], left_meet, 0.0), (360, held + [-0.1, 0, -0.02], left_rest, 0.0),
        (400, held + [-0.1, 0, -0.02], left_rest, 0.0)]
right = [(int(round(k * a.slow)), *r) for k, *r in right]; left = [(int(round(k * a.slow)), *r) for k, *r in left]
n, dt = int(round(400 * a.slow)), 0.02
start_q = qpos0[arms["left"].qadr].copy()
g0 = (qpos0[model.joint("left/left_finger").qposadr[0]] - 0.002) / (0.037 - 0.002)   # keyframe's finger opening
actions = np.zeros((n, 14))
for side, points, col in (("left", left, 0), ("right", right, 7)):
    arm = arms[side]; data.qpos[:] = qpos0
    seed = scripted._APPROACH_SEED if side == "right" else start_q
    pts = [(points[0][0], points[0][1], points[0][2], g0)] + points[1:]
    q, grip = scripted.joint_path(arm, data, pts, n, start=start_q, seed=seed)
    actions[:, col:col + 6] = arm.feed_forward(q, dt, qpos0)
    np.save(a.out[:-4] + f"_planned_{side}.npy", q)   # the IK joint path before the feed-forward
    actions[:, col + 6] = grip
start = np.concatenate([start_q, [g0], start_q, [g0]]); actions[0] = start
t = Trajectory(actions=actions, fps=50.0, start=start, qpos0=qpos0, object_pose=box,
               meta={"generator": "probe_r38 aloha_traj"}, source="menagerie_aloha_transfer")
save_trajectory(t, a.out); print("wrote", a.out, actions.shape, "g0", round(g0, 3))
