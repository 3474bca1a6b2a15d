"""Scripted top-down pick-and-place of a cube for ROBOTIS OpenMANIPULATOR-X (probe_r35).

usage: gen_omx.py SCENE.xml OUT.npz [--check] [--goal X Y] [--grasp-z Z]

4-DoF arm: the TCP (link5 x = 0.13 m, the fingertip pads) placed by damped least squares with
link5's x axis (along the fingers) pointing down. Minimum-jerk joint interpolation between
waypoints at 50 Hz: above the cube 75, down 125, closed 175, lifted 250, over the goal 325,
down 375, open 410, up 460, end 500. Layout = init's [Joint1..4, gripper 0 closed..1 open].
"""
import argparse
import mujoco, numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r35/src"), critmoment.__file__
from critmoment.trajectory import Trajectory, save_trajectory

ap = argparse.ArgumentParser()
ap.add_argument("scene"); ap.add_argument("out")
ap.add_argument("--check", action="store_true")
ap.add_argument("--goal", type=float, nargs=2, default=(0.15, 0.12))
ap.add_argument("--grasp-z", type=float, default=0.027)
ap.add_argument("--close", type=float, default=0.0, help="gripper channel value when closed")
a = ap.parse_args()
m = mujoco.MjModel.from_xml_path(a.scene); d = mujoco.MjData(m)
mujoco.mj_resetDataKeyframe(m, d, m.key("home").id)
J = [m.joint(f"Joint{i}").id for i in range(1, 5)]; QA = m.jnt_qposadr[J]; DA = m.jnt_dofadr[J]
L5 = m.body("link5").id; TCP = np.array([0.13, 0, 0])
def ik(target, q0):
    q = q0.copy()
    for _ in range(200):
        d.qpos[QA] = q; mujoco.mj_kinematics(m, d); mujoco.mj_comPos(m, d)
        R = d.xmat[L5].reshape(3, 3); p = d.xpos[L5] + R @ TCP
        e = np.r_[target - p, 0.3 * (np.array([0, 0, -1.0]) - R[:, 0])]
        if np.linalg.norm(e) < 1e-6: break
        jp = np.zeros((3, m.nv)); jr = np.zeros((3, m.nv)); mujoco.mj_jac(m, d, jp, jr, p, L5)
        # d(R x-axis)/dq = w x xaxis
        jx = -np.cross(R[:, 0][None, :], jr.T).T
        Jm = np.r_[jp[:, DA], 0.3 * jx[:, DA]]
        q = q + np.linalg.solve(Jm.T @ Jm + 1e-6 * np.eye(4), Jm.T @ e)
        q = np.clip(q, m.jnt_range[J, 0], m.jnt_range[J, 1])
    return q, np.linalg.norm(target - p)
cube = np.array([0.2, 0.0, 0.022]); goal = np.array([*a.goal, 0.022]); gz = a.grasp_z
home = np.zeros(4)
wp = [(0, None, 1.0), (75, cube + [0, 0, 0.05], 1.0), (125, [*cube[:2], gz], 1.0), (175, [*cube[:2], gz], a.close),
      (250, [*cube[:2], 0.075], a.close), (325, [*goal[:2], 0.075], a.close), (375, [*goal[:2], gz + 0.003], a.close),
      (410, [*goal[:2], gz + 0.003], 1.0), (460, [*goal[:2], 0.075], 1.0), (500, [*goal[:2], 0.075], 1.0)]
qs, prev = [], np.array([0, 0.3, 0.3, 1.0])
for f, p, g in wp:
    if p is None: qs.append(home); continue
    q, err = ik(np.array(p, float), prev); prev = q; qs.append(q)
    assert err < 1e-3, (f, p, err)
def mj(t): t = np.clip(t, 0, 1); return t ** 3 * (10 - 15 * t + 6 * t * t)
n = 500; act = np.zeros((n, 5))
for i in range(n):
    for k in range(len(wp) - 1):
        f0, f1 = wp[k][0], wp[k + 1][0]
        if f0 <= i <= f1:
            s = mj((i - f0) / (f1 - f0))
            act[i, :4] = qs[k] + s * (qs[k + 1] - qs[k]); act[i, 4] = wp[k][2] + s * (wp[k + 1][2] - wp[k][2])
            break
box = np.array([*cube, 1, 0, 0, 0])
if a.check:
    mujoco.mj_resetDataKeyframe(m, d, m.key("home").id)
    steps = int(round(0.02 / m.opt.timestep))
    for i in range(n):
        d.ctrl[:4] = act[i, :4]; d.ctrl[4] = -0.01 + act[i, 4] * 0.029
        for _ in range(steps): mujoco.mj_step(m, d)
        if i % 25 == 0 or i == n - 1:
            R = d.xmat[L5].reshape(3, 3); print(i, "tcp", (d.xpos[L5] + R @ TCP).round(3), "lagv", (d.qpos[QA] - act[i, :4]).round(3), "cube", d.body("cube").xpos.round(3), "grip q", round(d.qpos[m.jnt_qposadr[m.joint('Gripper').id]], 4), "lag", np.abs(d.qpos[QA] - act[i, :4]).max().round(3))
save_trajectory(Trajectory(actions=act, fps=50.0, start=act[0], object_pose=box,
                           meta={"generator": "probe_r35 gen_omx"}, source="gen_omx"), a.out)
print("wrote", a.out, act.shape)
if a.check:
    print("waypoint joints", np.array(qs).round(3))
