"""A scripted top-down power grasp for the Adroit relocate scene (make_scene.py): the hand
(palm down) is brought over the ball by ARTx/ARTz/ARRx (solved so that a point 4.6 cm below
the palm's face sits at the ball's centre), the four fingers and the thumb close, the arm
lifts (ARTy up, ARRx back) and holds. Controls are the model's own (its arm servos are
`general` affine with gain 500, bias -200: the joint settles at 2.5 x ctrl less the
gravity sag, so ctrl = (200 q + gravity) / 500; fingers kp 1, wrist kp 10).

Channels: the 30 actuators in model order (init's explicit layout, every actuator its own
channel, ctrl units); --hand-channel puts the moving finger actuators on one normalised
channel instead. A check in plain MuJoCo follows (its last line: the ball's height).

Usage (the critmoment venv active, from this folder; assets/ is the link fetch.sh makes):
    python traj.py SCENE.xml OUT.npz [--flex F] [--lift L] [--lift-by ARTy|ARRx] [--hand-channel]
e.g. python traj.py assets/critmoment_r24_adroit_shipped.xml traj_hand.npz --along 0.11 --flex 1.0 --hand-channel
     python traj.py assets/critmoment_r24_adroit_shipped.xml traj_artylift.npz --along 0.11 --flex 1.0 --lift-by ARTy --y0 0.01 --t-approach 1.5
Also writes OUT_ctrl30.npy (the 30 controls per sample, for check_artz.py).
"""
from __future__ import annotations

import argparse

import mujoco
import numpy as np
from scipy.optimize import least_squares

from critmoment.trajectory import Trajectory, save_trajectory

ARM = ["ARTx", "ARTy", "ARTz", "ARRx", "ARRy", "ARRz"]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--flex", type=float, default=1.3, help="finger flexion target [rad]")
    p.add_argument("--thumb", type=float, nargs=5, default=[0.4, 1.2, 0.2, 0.3, -0.6],
                   help="THJ4..THJ0 targets when closed")
    p.add_argument("--lift", type=float, default=0.12, help="ARTy rise [m]")
    p.add_argument("--lift-by", choices=["ARTy", "ARRx"], default="ARRx",
                   help="ARTy: the arm's vertical slide (critmoment clipped its control before 87d8b31,"
                        " finding 3);"
                        " ARRx: tilt the arm back, ARTy resting on its lower limit")
    p.add_argument("--y0", type=float, default=0.0, help="ARTy target while not lifting")
    p.add_argument("--t-approach", type=float, default=2.5)
    p.add_argument("--hand-channel", action="store_true",
                   help="the 22 finger actuators as one normalised channel (0 closed, 1 open)")
    p.add_argument("--above", type=float, default=0.08)
    p.add_argument("--below", type=float, default=0.046)
    p.add_argument("--along", type=float, default=0.075)
    a = p.parse_args()
    m = mujoco.MjModel.from_xml_path(a.scene)
    d = mujoco.MjData(m)
    jq = {m.joint(i).name: m.jnt_qposadr[i] for i in range(m.njnt)}
    palm = m.body("palm").id
    ball = np.array([0.0, 0.0, 0.035])
    local = np.array([0.0, -a.below, a.along])

    def point(x):
        d.qpos[:] = 0
        d.qpos[[jq["ARTx"], jq["ARTz"], jq["ARRx"]]] = x
        d.qpos[jq["ARTy"]] = a.y0
        mujoco.mj_kinematics(m, d)
        return d.xpos[palm] + d.xmat[palm].reshape(3, 3) @ local

    sol = least_squares(lambda x: point(x) - ball, np.zeros(3))
    qgrasp = np.zeros(m.nu)  # joint targets per actuator (each on its own joint)
    names = [m.actuator(i).name[2:] for i in range(m.nu)]
    idx = {n: i for i, n in enumerate(names)}
    qgrasp[[idx["ARTx"], idx["ARTz"], idx["ARRx"]]] = sol.x
    qgrasp[idx["ARTy"]] = a.y0
    print("grasp arm pose", sol.x.round(3), "residual", np.abs(sol.fun).max())
    qapp = qgrasp.copy()
    qapp[idx["ARTy"]] += a.above  # approach from above
    if a.lift_by == "ARRx":
        qapp[idx["ARTy"]] = a.y0
        qapp[idx["ARRx"]] -= a.above / 0.5
    qclose = qgrasp.copy()
    for f in ("FF", "MF", "RF", "LF"):
        for k in (2, 1, 0):
            qclose[idx[f"{f}J{k}"]] = a.flex if k else a.flex * 0.6
    for k, v in zip((4, 3, 2, 1, 0), a.thumb, strict=True):
        qclose[idx[f"THJ{k}"]] = v
    qlift = qclose.copy()
    if a.lift_by == "ARTy":
        qlift[idx["ARTy"]] = qgrasp[idx["ARTy"]] + a.lift
    else:  # tilt the arm back: the hand rises about 0.5 m x sin(angle)
        qlift[idx["ARRx"]] = qgrasp[idx["ARRx"]] - a.lift / 0.5
    # timeline [s]: approach, descend onto the ball, close, lift, hold
    T = a.t_approach
    keys = [(0.0, np.zeros(m.nu)), (T, qapp), (T + 1.5, qgrasp), (T + 1.9, qgrasp),
            (T + 2.9, qclose), (T + 3.3, qclose), (T + 4.8, qlift), (T + 6.5, qlift)]
    fps = 50.0
    t = np.arange(int(keys[-1][0] * fps) + 1) / fps
    q = np.empty((len(t), m.nu))
    for i, ti in enumerate(t):
        k = max(j for j in range(len(keys)) if keys[j][0] <= ti)
        if k == len(keys) - 1:
            q[i] = keys[-1][1]
            continue
        (t0, q0), (t1, q1) = keys[k], keys[k + 1]
        s = (ti - t0) / (t1 - t0)
        s = s ** 3 * (10 - 15 * s + 6 * s ** 2)
        q[i] = q0 + s * (q1 - q0)
    # servo ctrl from joint targets: u = (-bias1 q + gravity) / gain for the affine servos
    gain = m.actuator_gainprm[:, 0]
    kq = -m.actuator_biasprm[:, 1]
    ctrl = np.empty_like(q)
    for i in range(len(q)):
        d.qpos[:] = 0
        for n, j in idx.items():
            d.qpos[jq[n]] = q[i, j]
        d.qvel[:] = 0
        mujoco.mj_forward(m, d)
        dofs = [m.jnt_dofadr[m.joint(n).id] for n in names]
        ctrl[i] = (kq * q[i] + d.qfrc_bias[dofs]) / gain
        if q[i, idx["ARTy"]] <= 0.0:  # resting on its lower limit: no feed-forward
            ctrl[i, idx["ARTy"]] = 0.0
    lo, hi = m.actuator_ctrlrange[:, 0], m.actuator_ctrlrange[:, 1]
    ctrl = np.clip(ctrl, lo, hi)
    fingers = [i for i, n in enumerate(names) if n[:2] in ("FF", "MF", "RF", "LF", "TH")
               and qclose[i] != 0.0]
    others = [i for i in range(m.nu) if i not in fingers]
    ctrl_full = ctrl
    if a.hand_channel:  # 8 arm/wrist channels + the hand as one normalised channel
        grip = (q[:, idx["FFJ2"]] - qclose[idx["FFJ2"]]) / (0.0 - qclose[idx["FFJ2"]])
        ctrl_full = ctrl.copy()
        ctrl_full[:, fingers] = qclose[fingers] + grip[:, None] * (0.0 - qclose[fingers])
        ctrl = np.concatenate([ctrl[:, others], grip[:, None]], axis=1)
        print("hand channel closed =", [round(float(v), 4) for v in qclose[fingers]])
    qpos0 = np.zeros(m.nq)
    fj = jq["object_free"]
    qpos0[fj:fj + 7] = [*ball, 1, 0, 0, 0]
    tr = Trajectory(actions=ctrl, fps=fps, start=ctrl[0], qpos0=qpos0,
                    object_pose=qpos0[fj:fj + 7].copy(),
                    meta={"generator": "probe_r24 adroit traj"}, source="adroit_power_grasp")
    save_trajectory(tr, a.out)
    np.save(a.out.replace(".npz", "_ctrl30.npy"), ctrl_full)
    # quick check in plain MuJoCo
    d2 = mujoco.MjData(m)
    d2.qpos[:] = qpos0
    nsub = int(round(1 / fps / m.opt.timestep))
    for i in range(len(ctrl)):
        d2.ctrl[:] = ctrl_full[i]
        for _ in range(nsub):
            mujoco.mj_step(m, d2)
        if i % 25 == 0 or i == len(ctrl) - 1:
            pt = d2.xpos[palm] + d2.xmat[palm].reshape(3, 3) @ local
            print(f"t={i / fps:.1f} ball={d2.qpos[fj:fj + 3].round(3)} palm point={pt.round(3)} armq={d2.qpos[:6].round(3)} ncon={d2.ncon}")
    print("wrote", a.out, ctrl.shape)


if __name__ == "__main__":
    main()
