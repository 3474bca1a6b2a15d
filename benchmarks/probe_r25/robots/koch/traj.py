"""A scripted pick-and-place for youzi-robot 0.1.0's low-cost 6-DoF arm (Koch-style,
``assets/pick_place_cube.xml`` as shipped: a 3 cm cube on the floor, target region at
(0.06, 0.135)); the cube starts at ``--cube`` (the trajectory's object_pose).

5 arm joints, so the TCP pose is met in least squares (position first, orientation weighted
``w``), jaws pointing down (link_5 rotated -90 deg about world x from the zero pose: the
moving jaw link_6 closes along world x). TCP in link_5's frame: ``--tcp`` (default a 3 cm
cube's centre 2 mm off the fixed jaw's inner face, 50 mm out along the jaw). The
real_models 500-step timeline at 50 Hz, servo targets with the unloaded arm's inverse
dynamics fed forward. Channels: joint_1..5 [rad], jaw 0 closed .. 1 open (init's layout:
closed 0.032, open -2.45 rad).

Usage (the critmoment venv active, from this folder):
    python traj.py SCENE.xml OUT.npz [--open V] [--close C] [--tcp X Y Z] [--steps N]
"""
from __future__ import annotations

import argparse

import mujoco
import numpy as np
from scipy.optimize import least_squares

from critmoment.trajectory import Trajectory, save_trajectory

JOINTS = tuple(f"joint_{i}" for i in range(1, 6))
REST = np.zeros(5)
SEED = np.array([-0.34, -0.46, -0.56, -1.67, -0.34])


def min_jerk(s):
    return s ** 3 * (10.0 - 15.0 * s + 6.0 * s ** 2)


class KochArm:
    def __init__(self, model, qpos0, tcp):
        self.model = model
        ids = [model.joint(j).id for j in JOINTS]
        self.qadr = model.jnt_qposadr[ids]
        self.dofs = model.jnt_dofadr[ids]
        self.lo, self.hi = model.jnt_range[ids, 0], model.jnt_range[ids, 1]
        self.body = model.body("link_5").id
        self.data = mujoco.MjData(model)
        self.data.qpos[:] = qpos0
        self.offset = np.asarray(tcp, float)
        acts = [model.actuator(j).id for j in JOINTS]
        self.kp = model.actuator_gainprm[acts, 0]
        self.kv = -model.actuator_biasprm[acts, 2]

    def tcp(self, q):
        self.data.qpos[self.qadr] = q
        mujoco.mj_kinematics(self.model, self.data)
        rot = self.data.xmat[self.body].reshape(3, 3)
        return self.data.xpos[self.body] + rot @ self.offset, rot

    def ik(self, q0, pos, rot, w=0.05):
        def residual(q):
            p, r = self.tcp(q)
            return np.concatenate([p - pos, w * (r - rot).ravel()])
        sol = least_squares(residual, q0, bounds=(self.lo, self.hi), xtol=1e-12, ftol=1e-12,
                            gtol=1e-12)
        return sol.x, float(np.linalg.norm(self.tcp(sol.x)[0] - pos))

    def feed_forward(self, q, dt, qpos):
        m = self.model.__copy__()
        m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONSTRAINT)
        data = mujoco.MjData(m)
        qd = np.gradient(q, dt, axis=0)
        qdd = np.gradient(qd, dt, axis=0)
        tau = np.empty_like(q)
        for i in range(len(q)):
            data.qpos[:] = qpos
            data.qpos[self.qadr] = q[i]
            data.qvel[:] = 0.0
            data.qacc[:] = 0.0
            data.qvel[self.dofs] = qd[i]
            data.qacc[self.dofs] = qdd[i]
            mujoco.mj_inverse(m, data)
            tau[i] = data.qfrc_inverse[self.dofs]
        return np.clip(q + (self.kv * qd + tau) / self.kp, self.lo, self.hi)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--open", type=float, default=0.4, help="jaw command when open (0..1)")
    p.add_argument("--close", type=float, default=0.0, help="jaw command when closed")
    p.add_argument("--tcp", type=float, nargs=3, default=(-0.05, -0.0047, 0.0011))
    p.add_argument("--goal", type=float, nargs=3, default=(0.06, 0.135, 0.015))
    p.add_argument("--lift", type=float, default=0.05)
    p.add_argument("--cube", type=float, nargs=2, default=(-0.06, 0.14),
                   help="the cube's start x y (the trajectory's object_pose; the shipped "
                        "spawn (0, 0.2) is beyond jaws-down reach)")
    p.add_argument("--steps", type=int, default=500)
    a = p.parse_args()
    model = mujoco.MjModel.from_xml_path(a.scene)
    data = mujoco.MjData(model)
    cj = model.jnt_qposadr[model.joint("red_box_joint").id]
    data.qpos[cj:cj + 2] = a.cube
    # settle the cube (it ships 5 mm above the floor)
    for _ in range(500):
        mujoco.mj_step(model, data)
    qpos0 = data.qpos.copy()
    qpos0[:6] = 0.0
    cube = qpos0[cj:cj + 7].copy()
    arm = KochArm(model, qpos0, a.tcp)
    zero = arm.tcp(REST)[1]
    rx = np.array([[1, 0, 0], [0, 0, 1], [0, -1, 0]], float)  # -90 deg about world x
    down = rx @ zero
    c, goal = cube[:3], np.asarray(a.goal, float)
    o, cl = a.open, a.close
    pts = [(0, c + [0, 0, a.lift], o), (125, c, o), (140, c, o), (165, c, cl), (180, c, cl),
           (230, c + [0, 0, a.lift], cl), (305, goal + [0, 0, a.lift], cl),
           (355, goal + [0, 0, 0.002], cl), (370, goal + [0, 0, 0.002], cl),
           (395, goal + [0, 0, 0.002], o), (445, goal + [0, 0, a.lift], o),
           (500, goal + [0, 0, a.lift], o)]
    s = a.steps / 500.0
    t1 = int(round(75 * s))
    q_above, err = arm.ik(SEED, pts[0][1], down)
    if err > 1e-3:
        raise RuntimeError(f"IK: no pose above the cube (error {err:.2g})")
    n = a.steps
    q = np.empty((n, 5))
    grip = np.empty(n)
    sj = min_jerk(np.arange(t1 + 1) / t1)
    q[:t1 + 1] = REST + sj[:, None] * (q_above - REST)
    grip[:t1 + 1] = 1.0 * (1 - sj) + o * sj
    steps = np.array([t1 + pt[0] * (n - 1 - t1) / 500.0 for pt in pts])
    qi, worst = q_above, 0.0
    for i in range(t1 + 1, n):
        k = min(np.searchsorted(steps, i, side="right") - 1, len(pts) - 2)
        u = min_jerk((i - steps[k]) / (steps[k + 1] - steps[k]))
        pos = pts[k][1] + u * (np.asarray(pts[k + 1][1]) - pts[k][1])
        grip[i] = pts[k][2] + u * (pts[k + 1][2] - pts[k][2])
        qi, err = arm.ik(qi, pos, down)
        q[i] = qi
        worst = max(worst, err)
    if worst > 2e-3:
        raise RuntimeError(f"IK: TCP path error up to {worst:.2g} m")
    fps = 50.0
    actions = np.concatenate([arm.feed_forward(q, 1 / fps, qpos0), grip[:, None]], 1)
    start = np.concatenate([REST, [1.0]])
    actions[0] = start
    t = Trajectory(actions=actions, fps=fps, start=start, qpos0=qpos0, object_pose=cube,
                   meta={"generator": "probe_r25 koch traj"}, source="koch_pick_place")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape, "IK worst", round(worst, 4))


if __name__ == "__main__":
    main()
