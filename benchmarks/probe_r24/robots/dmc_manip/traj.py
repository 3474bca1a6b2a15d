"""A scripted planar pick-and-place for dm_control's manipulator (make_scene.py): least-squares
IK of the pinch site (x, z) with the hand pointing down over the 4 arm joints, the
real_models 500-step timeline at 50 Hz; joint targets for init's [servos] (the arm's torque
motors driven as joint servos) with the gravity of the unloaded arm fed forward
(u = q + tau_g / kp, kp from the scenario's [servos]); gripper channel 0 closed .. 1 open.
Usage (the critmoment venv active, from this folder; assets/ is the link fetch.sh makes):
    python traj.py SCENE.xml SCENARIO.toml OUT.npz [--goal-x X] [--close C]
e.g. python traj.py assets/critmoment_r24_manip_shipped.xml scenario_shipped_gains.toml traj.npz
"""
import argparse

import mujoco
import numpy as np
import tomllib
from scipy.optimize import least_squares

from critmoment.trajectory import Trajectory, save_trajectory

JOINTS = ["arm_root", "arm_shoulder", "arm_elbow", "arm_wrist"]
ACTS = ["root", "shoulder", "elbow", "wrist"]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("scenario")
    p.add_argument("out")
    p.add_argument("--goal-x", type=float, default=0.1)
    p.add_argument("--close", type=float, default=0.0)
    p.add_argument("--transport", type=float, default=0.12)
    p.add_argument("--pinch-z", type=float, default=0.0, help="pinch site above the ball centre")
    a = p.parse_args()
    m = mujoco.MjModel.from_xml_path(a.scene)
    d = mujoco.MjData(m)
    sc = tomllib.load(open(a.scenario, "rb"))
    kp = np.array([sc["servos"][n]["kp"] for n in ACTS])
    qa = np.array([m.jnt_qposadr[m.joint(j).id] for j in JOINTS])
    lo = np.where(m.jnt_limited[[m.joint(j).id for j in JOINTS]], m.jnt_range[[m.joint(j).id for j in JOINTS], 0], -10)
    hi = np.where(m.jnt_limited[[m.joint(j).id for j in JOINTS]], m.jnt_range[[m.joint(j).id for j in JOINTS], 1], 10)
    pinch, hand = m.site("pinch").id, m.body("hand").id
    fj = m.jnt_qposadr[m.joint("ball_free").id]
    ball = m.body("ball").pos.copy()

    def res(q, target):
        d.qpos[qa] = q
        mujoco.mj_kinematics(m, d)
        zax = d.xmat[hand].reshape(3, 3)[:, 2]
        return np.array([*(d.site_xpos[pinch] - target)[[0, 2]], 0.3 * (zax[0] - 0.0), 0.3 * (zax[2] + 1.0)])

    def ik(target, q0):
        s = least_squares(res, q0, args=(np.asarray(target, float),), bounds=(lo, hi), xtol=1e-12, ftol=1e-12)
        if np.abs(s.fun).max() > 1e-3:
            raise RuntimeError(f"IK {target}: residual {np.abs(s.fun).max():.3g}")
        return s.x
    rest = np.array([3.0, 1.7, -0.1, -1.5])  # near the pose above the ball
    grasp = ball + [0, 0, a.pinch_z]
    above = grasp + [0, 0, a.transport]
    goal = np.array([a.goal_x, 0, ball[2] + a.pinch_z + 0.002])
    over = goal + [0, 0, a.transport]
    qs = {}
    q = ik(above, rest)
    rest = q.copy()  # start above the ball
    for name, tgt in (("above", above), ("grasp", grasp), ("over", over), ("goal", goal)):
        q = ik(tgt, q)
        qs[name] = q
    o, c = 1.0, a.close
    keys = [(0, rest, o), (75, qs["above"], o), (125, qs["grasp"], o), (140, qs["grasp"], o),
            (165, qs["grasp"], c), (180, qs["grasp"], c), (230, qs["above"], c),
            (305, qs["over"], c), (355, qs["goal"], c), (370, qs["goal"], c),
            (395, qs["goal"], o), (445, qs["over"], o), (500, qs["over"], o)]
    n = 500
    qt = np.empty((n, 4))
    g = np.empty(n)
    for i in range(n):
        k = max(j for j in range(len(keys)) if keys[j][0] <= i)
        if k == len(keys) - 1:
            qt[i], g[i] = keys[-1][1], keys[-1][2]
            continue
        (t0, q0, g0), (t1, q1, g1) = keys[k], keys[k + 1]
        s = (i - t0) / (t1 - t0)
        s = s ** 3 * (10 - 15 * s + 6 * s ** 2)
        qt[i] = q0 + s * (q1 - q0)
        g[i] = g0 + s * (g1 - g0)
    # gravity of the unloaded arm fed forward
    dofs = [m.jnt_dofadr[m.joint(j).id] for j in JOINTS]
    u = np.empty_like(qt)
    for i in range(n):
        d.qpos[:] = 0
        d.qpos[fj:fj + 7] = [*ball, 1, 0, 0, 0]
        d.qpos[qa] = qt[i]
        d.qvel[:] = 0
        mujoco.mj_forward(m, d)
        u[i] = qt[i] + d.qfrc_bias[dofs] / kp
    actions = np.concatenate([u, g[:, None]], axis=1)
    qpos0 = np.zeros(m.nq)
    qpos0[qa] = rest
    qpos0[fj:fj + 7] = [*ball, 1, 0, 0, 0]
    start = actions[0].copy()
    tr = Trajectory(actions=actions, fps=50.0, start=start, qpos0=qpos0, object_pose=qpos0[fj:fj + 7].copy(),
                    meta={"generator": "probe_r24 dmc manipulator traj"}, source="dmc_manip_pick_place")
    save_trajectory(tr, a.out)
    print("wrote", a.out, actions.shape, {k: v.round(3) for k, v in qs.items()})


if __name__ == "__main__":
    main()
