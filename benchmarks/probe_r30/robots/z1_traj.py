"""Scripted pick-and-place for make_z1_scene.py's Z1 + one-jaw gripper + 3 cm cube.

DLS IK (benchmarks/real_models/scripted.py) of a TCP fixed in link06's frame at the centre
of a cube held against the fixed (stator) jaw's pads, gripper pointing down (link06 x =
world -z), jaw closing along world y. 50 Hz, 350 steps: above the cube (60), down (100),
close (110..135), wait (150), lift 0.12 m (190), carry 0.25 m along +y (250), lower (290),
open (300..315), retreat up (350). Servo targets with the unloaded arm's inverse dynamics
fed forward. Channels: motor1..motor6, gripper (0 closed .. 1 open = -1.518 rad).

usage: z1_traj.py SCENE.xml OUT.npz [--open 0.5] [--close 0.0] [--clear 0.003]
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

JOINTS = ("joint1", "joint2", "joint3", "joint4", "joint5", "joint6")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene"); p.add_argument("out")
    p.add_argument("--open", type=float, default=0.5)
    p.add_argument("--close", type=float, default=0.0)
    p.add_argument("--clear", type=float, default=0.003, help="cube-to-stator clearance on the way down [m]")
    p.add_argument("--grasp-dz", type=float, default=0.0)
    p.add_argument("--open-steps", type=int, default=40)
    p.add_argument("--close-steps", type=int, default=40, help="steps of the closing ramp")
    a = p.parse_args()
    m = mujoco.MjModel.from_xml_path(a.scene)
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, 0)
    qpos0 = d.qpos.copy()
    home = qpos0[:6].copy()
    cube = qpos0[7:14].copy()
    half = m.geom_size[m.geom("cube_geom").id][1]  # along the closing axis (world y)
    # stator pad top face in link06's frame: pad boxes at z -0.0125, half-thickness 0.004
    offset = np.array([0.186, 0.0, -0.0125 + 0.004 + half + a.clear])
    arm = scripted.Arm(m, JOINTS, "link06", ("cube_geom",), qpos0, offset=offset)
    mujoco.mj_kinematics(m, d)
    p0, r0 = arm.tcp(d)
    # columns: link06 x, y, z in world; x down, z (closing, stator->mover) along +y
    down = np.stack([[0, 0, -1], [-1, 0, 0], [0, 1, 0]], axis=1).astype(float)
    assert abs(np.linalg.det(down) - 1) < 1e-9
    grasp = cube[:3] + [0, 0, a.grasp_dz]
    grasp_c = grasp.copy()           # clearance was put into the offset; at the grasp the cube
    above = grasp + [0, 0, 0.06]     # is pushed 'clear' onto the stator by the closing jaw
    lifted = grasp + [0, 0, 0.07]
    goal = m.site("goal").id
    gpos = m.site_pos[goal].copy()
    carried = np.array([gpos[0], gpos[1], lifted[2]])
    placed = np.array([gpos[0], gpos[1], grasp[2] + 0.002])
    up = placed + [0, 0, 0.06]
    o, c = a.open, a.close
    # the jaw starts closed (keyframe ctrl 0) and is ramped open over 1 s, closed over 1 s: a
    # step command saturates the jaw servo (+-30 N m on 3.2e-4 kg m^2, kv 100) into a limit cycle
    # the jaw is opened first with the arm still (0..40), then the arm moves; closing is
    # ramped over 'close_steps'. Opened while the wrist moves, the jaw servo (kp 1000, kv 100,
    # +-30 N m on 3.2e-4 kg m^2) saturates into a limit cycle and never opens.
    cs = a.close_steps
    pts = [(40, p0, r0, o), (90, above, down, o), (130, grasp_c, down, o), (135, grasp_c, down, o),
           (135 + cs, grasp_c, down, c), (150 + cs, grasp_c, down, c), (190 + cs, lifted, down, c),
           (250 + cs, carried, down, c), (290 + cs, placed, down, c), (300 + cs, placed, down, c),
           (315 + cs, placed, down, o), (350 + cs, up, down, o)]
    N = 350 + cs
    P = a.open_steps
    pts = [(k - 40, *rest) for k, *rest in pts]
    N = N - 40 + P
    # IK seed: the best of random restarts for the first waypoint (home is far from it)
    rng = np.random.default_rng(0)
    best, best_cost, seed = np.inf, np.inf, home
    for _ in range(300):
        cand = rng.uniform(np.maximum(arm.lo, -3), np.minimum(arm.hi, 3))
        d.qpos[:] = qpos0; d.qpos[arm.qadr] = cand
        err = arm.ik(d, above, down, iters=2000)
        if err < 1e-4:
            q1 = d.qpos[arm.qadr].copy()
            cost = np.abs(q1 - home).sum()
            if cost < best_cost:
                best_cost, seed = cost, q1
            best = min(best, err)
    q, grip = scripted.joint_path(arm, d, pts, N - P, start=home, rest=None, seed=seed)
    ramp = 0.5 - 0.5 * np.cos(np.pi * np.arange(P) / P)
    q = np.concatenate([np.repeat(home[None], P, 0), q]); grip = np.concatenate([o * ramp, grip])
    fps = 50.0
    joints = arm.feed_forward(q, 1 / fps, qpos0)
    joints[0] = home
    grip[0] = 0.0
    actions = np.concatenate([joints, grip[:, None]], 1)
    t = Trajectory(actions=actions, fps=fps, start=actions[0].copy(), qpos0=qpos0, object_pose=cube,
                   meta={"generator": "probe_r30 z1_traj", "open": o, "close": c},
                   source="z1_pick_place")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape, "critmoment", critmoment.__file__)


if __name__ == "__main__":
    main()
