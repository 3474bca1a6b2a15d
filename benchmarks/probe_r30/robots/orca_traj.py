"""Scripted pick-and-place for make_orca_scene.py's Gen3 + ORCA right hand + 6 cm ball.

DLS IK (7 DoF, null-space pull to the Gen3 `home`) of a point fixed in the palm's frame
(`--tcp`, default (0.005, 0.05, 0.055): the middle of the fingertips' cloud at half
closure), fingers pointing down and the palm facing world +x (`--pose claw`; `palmdown`: palm +y = world -z,
fingers along +x, which the Gen3 cannot reach at this distance).
The hand is driven by init's one normalised channel (16 finger servos, 0 closed .. 1 open
along the line between the measured ends); the wrist servo held at 0.
50 Hz, 500 steps: above (75), down (125), close (140..175), wait (190), lift 0.12 m (250),
carry to the goal (310), lower (360), open (370..395), retreat (430), hold.
Channels: joint_1..joint_7, h_right_wrist_actuator, h_right_palm/gripper.
usage: orca_traj.py SCENE.xml OUT.npz [--close C] [--tcp X Y Z] [--grasp-dz DZ]
"""
import argparse
import os
import sys
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, os.environ.get("CRITMOMENT_REAL_MODELS",
                                  str(Path(__file__).absolute().parents[2] / "real_models")))
import scripted  # noqa: E402

import critmoment  # noqa: E402
from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402

ALL = tuple(f"joint_{i}" for i in range(1, 8))
JOINTS = ALL[1:]   # joint_1 held at 0: as shipped it is jammed by the base/shoulder meshes
HOME = np.array([0, 0.26179939, 3.14159265, -2.26892803, 0, 0.95993109, 1.57079633])


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene"); p.add_argument("out")
    p.add_argument("--close", type=float, default=0.0)
    p.add_argument("--open", type=float, default=1.0)
    p.add_argument("--tcp", type=float, nargs=3, default=(0.005, 0.05, 0.055))
    p.add_argument("--grasp-dz", type=float, default=0.0)
    p.add_argument("--hold", action="store_true", help="pick_hold timeline")
    p.add_argument("--split", action="store_true", help="split_orca_scenario.py's channel layout")
    p.add_argument("--split-values", type=float, nargs=6, default=(0.29, -1.08, 0.0, 0.0, 0.17, 0.52),
                   help="thumb mcp, thumb abd, index/middle/ring/pinky abd targets [rad]")
    p.add_argument("--pose", default="claw", choices=["claw", "palmdown", "side"])
    p.add_argument("--scenario", help="init's scenario: the finger channel's ends, for the wrist feed-forward")
    a = p.parse_args()
    m = mujoco.MjModel.from_xml_path(a.scene)
    d = mujoco.MjData(m)
    qpos0 = m.qpos0.copy()
    qpos0[m.jnt_qposadr[[m.joint(j).id for j in ALL]]] = HOME
    oj = m.jnt_qposadr[m.joint("ball_joint").id]
    obj = qpos0[oj:oj + 7].copy()
    arm = scripted.Arm(m, JOINTS, "h_right_palm", ("ball_geom",), qpos0, offset=np.array(a.tcp))
    d.qpos[:] = qpos0
    mujoco.mj_kinematics(m, d)
    p0, r0 = arm.tcp(d)
    if a.pose == "side":   # wrist axis (palm x) vertical, fingers along +x, palm facing +y
        R = np.array([[0, 0, 1], [0, 1, 0], [-1, 0, 0]], float)
    elif a.pose == "claw":   # fingers down (palm z = world -z), palm facing +x (palm y = world +x)
        R = np.array([[0, 1, 0], [1, 0, 0], [0, 0, -1]], float)
    else:                  # palm down (palm y = world -z), fingers along world +x
        R = np.array([[0, 0, 1], [-1, 0, 0], [0, -1, 0]], float)
    grasp = obj[:3] + [0, 0, a.grasp_dz]
    above = grasp + ([0.0, -0.08, 0.0] if a.pose == "side" else [0, 0, 0.12])
    lifted = grasp + [0, 0, 0.12]
    gpos = m.site_pos[m.site("goal").id].copy()
    carried = np.array([gpos[0], gpos[1], lifted[2]])
    placed = np.array([gpos[0], gpos[1], grasp[2] + 0.003])
    up = placed + [0, 0, 0.12]
    c, o = a.close, a.open
    pts = [(0, p0, r0, o), (75, above, R, o), (125, grasp, R, o), (140, grasp, R, o),
           (175, grasp, R, c), (190, grasp, R, c), (250, lifted, R, c),
           (310, carried, R, c), (360, placed, R, c), (370, placed, R, c),
           (395, placed, R, o), (430, up, R, o), (500, up, R, o)]
    if a.hold:  # pick_hold: lift, carry 0.1 m along +x, hold closed to the end
        pts = pts[:7] + [(310, lifted + [0.10, 0, 0], R, c), (500, lifted + [0.10, 0, 0], R, c)]
    # IK seed for the first waypoint: home, else the closest to home of random restarts
    seed = HOME[1:]
    d.qpos[:] = qpos0
    if arm.ik(d, pts[1][1], pts[1][2], rest=HOME[1:], iters=3000) > 1e-4:
        rng = np.random.default_rng(0)
        best = np.inf
        for _ in range(200):
            cand = HOME[1:] + rng.uniform(-1.5, 1.5, 6)
            d.qpos[:] = qpos0; d.qpos[arm.qadr] = np.clip(cand, arm.lo, arm.hi)
            if arm.ik(d, pts[1][1], pts[1][2], rest=HOME[1:], iters=1500) < 1e-4:
                qq = d.qpos[arm.qadr].copy()
                qq -= 2 * np.pi * np.round((qq - HOME[1:]) / (2 * np.pi)) * ~np.isfinite(arm.hi)
                cost = np.abs(qq - HOME[1:]).sum()
                if cost < best:
                    best, seed = cost, qq
        print("IK seed by random restarts, |q - home|_1 =", round(float(best), 3))
    q, grip = scripted.joint_path(arm, d, pts, 500, start=HOME[1:], rest=HOME[1:], seed=seed)
    # continuous joints (no range): the DLS IK winds them by multiples of 2 pi; unwind the
    # path to the turn nearest home and redo the first, joint-space move (min-jerk)
    t1 = pts[1][0]
    free = ~np.isfinite(arm.hi)
    k = np.round((q[t1] - HOME[1:]) / (2 * np.pi)) * free
    q[t1:] -= 2 * np.pi * k
    sj = np.arange(t1 + 1) / t1
    sj = sj ** 3 * (10 - 15 * sj + 6 * sj ** 2)
    q[:t1 + 1] = HOME[1:] + sj[:, None] * (q[t1] - HOME[1:])
    fps = 50.0
    joints = arm.feed_forward(q, 1 / fps, qpos0)
    joints[0] = HOME[1:]
    # the wrist servo (kp 2, +-1 N m) holds the hand: feed its gravity and inertia load
    # forward (inverse dynamics of the planned arm path, hand at its planned closure)
    wj = m.joint("h_right_wrist").id
    wadr, wdof = m.jnt_qposadr[wj], m.jnt_dofadr[wj]
    wrist = qpos0[wadr]   # its ref, -0.15
    import tomllib
    cfg = tomllib.loads(Path(a.scenario).read_text()) if a.scenario else None
    fing = [c for c in cfg["actions"]["channel"] if c.get("normalised")][0] if cfg else None
    mff = m.__copy__(); mff.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONSTRAINT)
    dd = mujoco.MjData(mff)
    qd = np.gradient(q, 1 / 50.0, axis=0); qdd = np.gradient(qd, 1 / 50.0, axis=0)
    wtgt = np.empty(len(q))
    kpw = m.actuator_gainprm[m.actuator("h_right_wrist_actuator").id, 0]
    for i in range(len(q)):
        dd.qpos[:] = qpos0; dd.qpos[arm.qadr] = q[i]; dd.qvel[:] = 0; dd.qacc[:] = 0
        dd.qvel[arm.dofs] = qd[i]; dd.qacc[arm.dofs] = qdd[i]
        if a.split:
            for name, v in zip(("h_right_thumb_mcp_actuator", "h_right_thumb_abd_actuator", "h_right_index_abd_actuator",
                                "h_right_middle_abd_actuator", "h_right_ring_abd_actuator", "h_right_pinky_abd_actuator"), a.split_values):
                dd.qpos[m.jnt_qposadr[m.actuator_trnid[m.actuator(name).id, 0]]] = v
        if fing:
            for name, c_, o_ in zip(fing["actuators"], fing["closed"], fing["open"]):
                j = m.actuator_trnid[m.actuator(name).id, 0]
                dd.qpos[m.jnt_qposadr[j]] = c_ + grip[i] * (o_ - c_)
        mujoco.mj_inverse(mff, dd)
        wtgt[i] = wrist + dd.qfrc_inverse[wdof] / kpw
    print("wrist feed-forward torque range [N m]:", round(float((wtgt - wrist).min() * kpw), 3), round(float((wtgt - wrist).max() * kpw), 3))
    if a.split:  # split_orca_scenario.py's layout: six held joints before the flexion channel
        held = np.tile(np.array(a.split_values, float), (len(q), 1))
        actions = np.concatenate([np.zeros((len(q), 1)), joints, wtgt[:, None], held, grip[:, None]], 1)
    else:
        actions = np.concatenate([np.zeros((len(q), 1)), joints, wtgt[:, None], grip[:, None]], 1)
    t = Trajectory(actions=actions, fps=fps, start=actions[0].copy(), qpos0=qpos0, object_pose=obj,
                   meta={"generator": "probe_r30 orca_traj", "tcp": list(a.tcp)}, source="orca_pick_place")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape, "critmoment", critmoment.__file__)


if __name__ == "__main__":
    main()
