"""Scripted pick-and-place for the probe's robots (make_robot.py), adapted from probe_r32's
robot_traj.py: DLS IK (benchmarks/real_models/scripted.py: Arm, _path) of the TCP (pads' centre,
0.06 m along the hand's x), fingers pointing down, closing along world y; servo targets with the
unloaded robot's inverse dynamics fed forward. 50 Hz. For a planar base (KIND planar) the base
drives along y by --base-dy (and turns by --base-yaw) while the cube is carried; its targets are
the last three action channels (bx, by, byaw), fed forward too. The free base has no actuator:
its 7 qpos numbers come from qpos0 only.
usage: traj.py SCENE.xml OUT.npz [--slow K] [--base-dy DY] [--base-yaw RAD] [--grasp-dz DZ]
       [--goal X Y Z] [--tray]
"""
import argparse
import sys

import mujoco
import numpy as np

sys.path.insert(0, "/tmp/r34/src/benchmarks/real_models")
import scripted  # noqa: E402
import critmoment  # noqa: E402
from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402
assert critmoment.__file__.startswith("/tmp/r34/src"), critmoment.__file__

DOWN = np.stack([[0, 0, -1], [0, 1, 0], [1, 0, 0]], axis=1).astype(float)  # hand x -> -z, hand y -> y
TCP = np.array([0.06, 0.0, 0.0])


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene"); p.add_argument("out")
    p.add_argument("--slow", type=float, default=1.0)
    p.add_argument("--base-dy", type=float, default=0.0)
    p.add_argument("--base-yaw", type=float, default=0.0)
    p.add_argument("--grasp-dz", type=float, default=0.0)
    p.add_argument("--lift", type=float, default=0.10)
    p.add_argument("--goal", type=float, nargs=3, default=None)
    p.add_argument("--yaw", type=float, default=0.0, help="turn the grasp about world z [deg] (90: closing axis along world x)")
    p.add_argument("--carry-steps", type=int, default=80, help="50 Hz steps of the carry segment (before --slow)")
    p.add_argument("--pre-drive", type=float, default=0.0, help="planar base: drive this far along y [m] before the pick, arm at home, cube where it is (on the robot's tray)")
    p.add_argument("--pre-steps", type=int, default=25, help="50 Hz steps of that drive (before --slow)")
    p.add_argument("--no-ff", action="store_true", help="no feed-forward (plain joint targets)")
    a = p.parse_args()
    m = mujoco.MjModel.from_xml_path(a.scene)
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, 0)
    qpos0 = d.qpos.copy()
    planar = m.njnt and mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, "base_x") >= 0
    arm = scripted.Arm(m, tuple(f"j{i}" for i in range(1, 7)), "hand", (), qpos0, offset=TCP)
    base = scripted.Arm(m, ("base_x", "base_y", "base_yaw"), "base", (), qpos0,
                        offset=np.zeros(3)) if planar else None
    cj = m.jnt_qposadr[m.joint("cube_joint").id]
    cube = qpos0[cj:cj + 7].copy()
    home = qpos0[arm.qadr].copy()
    if planar:
        d.qpos[base.qadr[1]] += a.pre_drive
    mujoco.mj_kinematics(m, d)
    p0, r0 = arm.tcp(d)
    grasp = cube[:3] + [0, a.pre_drive, a.grasp_dz]
    above = grasp + [0, 0, 0.06]
    lifted = grasp + [0, 0, a.lift]
    gpos = np.array(a.goal) if a.goal else m.site_pos[m.site("goal").id].copy()
    carried = np.array([gpos[0], gpos[1], lifted[2]])
    placed = np.array([gpos[0], gpos[1], grasp[2] + (gpos[2] - cube[2]) + 0.003])
    up = placed + [0, 0, 0.06]
    o, c = 1.0, 0.0
    cy, sy = np.cos(np.radians(a.yaw)), np.sin(np.radians(a.yaw))
    down = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1.0]]) @ DOWN
    P = a.pre_steps
    C = a.carry_steps - 80
    DOWN_ = down
    pts = [(P, p0, r0, o), (P + 50, above, DOWN_, o), (P + 100, grasp, DOWN_, o),
           (P + 110, grasp, DOWN_, o), (P + 135, grasp, DOWN_, c), (P + 160, grasp, DOWN_, c),
           (P + 220, lifted, DOWN_, c), (P + 300 + C, carried, DOWN_, c), (P + 350 + C, placed, DOWN_, c),
           (P + 360 + C, placed, DOWN_, c), (P + 380 + C, placed, DOWN_, o), (P + 420 + C, up, DOWN_, o),
           (P + 470 + C, up, DOWN_, o)]
    N = P + 470 + C
    k = a.slow
    pts = [(int(round(s * k)), *r) for s, *r in pts]; N = int(round(N * k)); P = int(round(P * k))
    # base schedule: min-jerk from 0 to (dy, yaw) over the carry (lifted -> carried)
    t_lift, t_carry = pts[6][0], pts[7][0]
    s = np.clip((np.arange(N) - t_lift) / (t_carry - t_lift), 0, 1)
    s = s ** 3 * (10 - 15 * s + 6 * s ** 2)
    bq = np.zeros((N, 3))
    if planar:
        bq = qpos0[base.qadr][None] + s[:, None] * np.array([0.0, a.base_dy, a.base_yaw])
        sp = np.clip(np.arange(N) / P, 0, 1); sp = sp ** 3 * (10 - 15 * sp + 6 * sp ** 2)
        bq[:, 1] += a.pre_drive * sp
    # TCP path (world), from P on
    pts2 = [(t - P, *r) for t, *r in pts]
    pos, rot, grip = scripted._path(pts2, N - P)
    # seed: IK at 'above' from random restarts, nearest home
    rng = np.random.default_rng(0)
    best, seed = np.inf, None
    t1 = pts2[1][0]
    for _ in range(100):
        d.qpos[:] = qpos0
        d.qpos[arm.qadr] = rng.uniform(np.maximum(arm.lo, -2.5), np.minimum(arm.hi, 2.5))
        if planar:
            d.qpos[base.qadr] = bq[P + t1]
        err = arm.ik(d, pos[t1], rot[t1].as_matrix(), iters=2000)
        if err < 1e-5:
            q1 = d.qpos[arm.qadr].copy(); cost = np.abs(q1 - home).sum()
            if cost < best:
                best, seed = cost, q1
    if seed is None:
        raise SystemExit("IK: 'above' unreachable")
    q = np.empty((N, 6))
    q[:P] = home
    sj = np.arange(t1 + 1) / t1; sj = sj ** 3 * (10 - 15 * sj + 6 * sj ** 2)
    q[P:P + t1 + 1] = home + sj[:, None] * (seed - home)
    d.qpos[:] = qpos0; d.qpos[arm.qadr] = seed
    worst = 0.0
    for i in range(t1 + 1, N - P):
        if planar:
            d.qpos[base.qadr] = bq[P + i]
        worst = max(worst, arm.ik(d, pos[i], rot[i].as_matrix()))
        q[P + i] = d.qpos[arm.qadr]
    if worst > 1e-3:
        raise SystemExit(f"IK: TCP path error up to {worst:.2g}")
    ramp = 0.5 - 0.5 * np.cos(np.pi * np.arange(P) / P)
    g = np.concatenate([o * np.ones(P) if True else ramp, grip])
    fps = 50.0
    # feed-forward with the whole robot's state (base included) for each step
    if a.no_ff:
        joints = q
    else:
        qfull = np.repeat(qpos0[None], N, 0)
        qfull[:, arm.qadr] = q
        if planar:
            qfull[:, base.qadr] = bq
        joints = _feed_forward(m, arm, q, 1 / fps, qfull)
        joints[:P] = home
    cols = [joints, g[:, None]]
    if planar:
        bff = bq if a.no_ff else _feed_forward(m, base, bq, 1 / fps, qfull)
        cols.append(bff)
    hips = [i for i in range(m.nu) if m.actuator(i).name.startswith("h")]
    if hips:  # legged: the hip servos hold 0 (stance) the whole run
        cols.append(np.zeros((N, len(hips))))
    actions = np.concatenate(cols, 1)
    t = Trajectory(actions=actions, fps=fps, start=actions[0].copy(), qpos0=qpos0, object_pose=cube,
                   meta={"generator": "probe_r34 floating traj"}, source="probe_r34")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape, "IK worst", f"{worst:.2g}", file=sys.stderr)


def _feed_forward(m, arm, q, dt, qfull):
    """scripted.Arm.feed_forward with every joint's path (base and arm both move)."""
    mm = m.__copy__()
    mm.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONSTRAINT)
    data = mujoco.MjData(mm)
    qd = np.gradient(q, dt, axis=0)
    qdd = np.gradient(qd, dt, axis=0)
    tau = np.empty_like(q)
    for i in range(len(q)):
        data.qpos[:] = qfull[i]
        data.qvel[:] = 0.0
        data.qacc[:] = 0.0
        data.qvel[arm.dofs] = qd[i]
        data.qacc[arm.dofs] = qdd[i]
        mujoco.mj_inverse(mm, data)
        tau[i] = data.qfrc_inverse[arm.dofs]
    return np.clip(q + (arm.kv * qd + tau) / arm.kp, arm.lo, arm.hi)


if __name__ == "__main__":
    main()
