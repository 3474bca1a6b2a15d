"""Scripted pick-and-place (probe_r32 robots: dm_control Jaco + 3-finger hand, Synria Alicia-D), adapted from
probe_r31/robots/arm_traj.py: DLS IK (benchmarks/real_models/scripted.py) of a TCP fixed in the hand frame, fingers
pointing down, servo targets with the unloaded arm's inverse dynamics fed forward (torque motors: the gains of the
scenario's [servos], --scenario). 50 Hz. Timeline: open (arm still), above the cube, down, close, wait, lift, carry
to the goal site, lower, open, retreat up, hold. --slow K stretches every segment, --yaw turns the grasp frame.
usage: robot_traj.py {jaco,alicia} SCENE.xml OUT.npz [--scenario S] [--slow K] [--yaw DEG] [--grasp-dz DZ] [--lift H]
"""
import argparse, os, sys
from pathlib import Path
import mujoco
import numpy as np
sys.path.insert(0, str(Path("/work/main/benchmarks/real_models")))
import scripted  # noqa: E402
import critmoment  # noqa: E402
from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402
assert critmoment.__file__.startswith("/tmp/r33/src"), critmoment.__file__

ROBOTS = {
    # dm_control Jaco + 3-finger hand: hand z = world +z (fingers, along hand -z, point down),
    # closing axis (finger 1 vs fingers 2, 3) = hand y = world y
    # Synria Alicia-D v5.6 (100 mm gripper): link6 z (wrist -> fingertips) = world -z, closing
    # axis (finger slides) = link6 y = world y; a 3x3x6 cm block held mid-pad, 0.100 m along link6 z (tips ~1 mm above the table)
    "alicia": dict(hand="link6", joints=tuple(f"Joint{i}" for i in range(1, 7)),
                   tcp=np.array([0.0, 0.0, 0.100]),
                   down=np.stack([[-1, 0, 0], [0, 1, 0], [0, 0, -1]], axis=1).astype(float)),
    "jaco": dict(hand="hand/hand", joints=tuple(f"joint_{i}" for i in range(1, 7)),
                 tcp=np.array([0.0, 0.0, -0.17]), down=np.eye(3)),
    # hand body, joints, TCP in hand frame, hand axes (cols) in world at the grasp
    "wx": dict(hand="wx250s/gripper_link",
               joints=("waist", "shoulder", "elbow", "forearm_roll", "wrist_angle", "wrist_rotate"),
               tcp=np.array([0.09, 0.0, 0.0]),
               # hand x = world -z (fingers down), hand y (closing) = world x
               down=np.stack([[0, 0, -1], [1, 0, 0], [0, -1, 0]], axis=1).astype(float)),
    "lc": dict(hand="gripper_static_finger",
               joints=("base_rotation", "pitch", "elbow", "wrist_pitch", "wrist_roll"),
               # cube centre held against the static pad (face y 0.0085), half 0.0125, 2 mm clear
               tcp=np.array([-0.058, 0.0085 - 0.0125 - 0.002, 0.0005]),
               # hand x = world +z (fingers, along -x, point down), hand y = world +x
               down=np.stack([[0, 0, 1], [1, 0, 0], [0, 1, 0]], axis=1).astype(float)),
}


def main():
    p = argparse.ArgumentParser()
    p.add_argument("robot"); p.add_argument("scene"); p.add_argument("out")
    p.add_argument("--grasp-dz", type=float, default=0.0)
    p.add_argument("--close", type=float, default=0.0)
    p.add_argument("--open", type=float, default=1.0)
    p.add_argument("--lift", type=float, default=0.10)
    p.add_argument("--slow", type=int, default=1, help="stretch every segment by this factor")
    p.add_argument("--yaw", type=float, default=0.0, help="turn the grasp frame about world z [deg]")
    p.add_argument("--scenario", default=None, help="servo gains for torque motors")
    p.add_argument("--loosen", type=float, nargs=2, default=None, metavar=("H", "G"),
                   help="r33: over the goal, stop H above the place pose, gripper to G (0 closed..1 open) for 0.3 s, close, place")
    p.add_argument("--loosen-dy", type=float, default=0.0, help="r33: the loosen hover this far along world y from the goal")
    p.add_argument("--hold", action="store_true", help="pick_hold: no place/release, hold at the goal")
    a = p.parse_args()
    R = ROBOTS[a.robot]
    assert abs(np.linalg.det(R["down"]) - 1) < 1e-9
    m = mujoco.MjModel.from_xml_path(a.scene)
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, 0)
    qpos0 = d.qpos.copy()
    arm = scripted.Arm(m, R["joints"], R["hand"], (), qpos0, offset=R["tcp"])
    if a.scenario:
        import tomllib
        sv = tomllib.load(open(a.scenario, "rb")).get("servos", {})
        if sv:
            names = [m.actuator(int(i)).name for i in arm.acts]; arm.kp = np.array([sv[n]["kp"] for n in names], float)
            arm.kv = np.array([sv[n]["kv"] for n in names], float)
    home = qpos0[arm.qadr].copy()
    cj = m.jnt_qposadr[m.joint("cube_joint").id]
    cube = qpos0[cj:cj + 7].copy()
    mujoco.mj_kinematics(m, d)
    p0, r0 = arm.tcp(d)
    cy, sy = np.cos(np.radians(a.yaw)), np.sin(np.radians(a.yaw))
    down = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1.0]]) @ R["down"]
    grasp = cube[:3] + [0, 0, a.grasp_dz]
    above = grasp + [0, 0, 0.06]
    lifted = grasp + [0, 0, a.lift]
    gpos = m.site_pos[m.site("goal").id].copy()
    carried = np.array([gpos[0], gpos[1], lifted[2]])
    placed = np.array([gpos[0], gpos[1], grasp[2] + (gpos[2] - cube[2]) + 0.003])
    up = placed + [0, 0, 0.06]
    o, c = a.open, a.close
    P = 25
    if a.hold:
        pts = [(0, p0, r0, 0.0), (P, p0, r0, o), (P + 50, above, down, o), (P + 100, grasp, down, o),
               (P + 110, grasp, down, o), (P + 135, grasp, down, c), (P + 160, grasp, down, c),
               (P + 220, lifted, down, c), (P + 280, carried, down, c), (P + 400, carried, down, c)]
        N = P + 400
    elif a.loosen:
        H, G = a.loosen; hov = placed + [0, a.loosen_dy, H]; g = c + G * (o - c)
        pts = [(0, p0, r0, 0.0), (P, p0, r0, o), (P + 50, above, down, o), (P + 100, grasp, down, o),
               (P + 110, grasp, down, o), (P + 135, grasp, down, c), (P + 160, grasp, down, c),
               (P + 220, lifted, down, c), (P + 280, carried, down, c), (P + 300, hov, down, c),
               (P + 305, hov, down, c), (P + 308, hov, down, g), (P + 323, hov, down, g),
               (P + 328, hov, down, c), (P + 340, hov, down, c), (P + 370, placed, down, c),
               (P + 380, placed, down, c), (P + 400, placed, down, o), (P + 440, up, down, o),
               (P + 490, up, down, o)]
        N = P + 490
    else:
        pts = [(0, p0, r0, 0.0), (P, p0, r0, o), (P + 50, above, down, o), (P + 100, grasp, down, o),
               (P + 110, grasp, down, o), (P + 135, grasp, down, c), (P + 160, grasp, down, c),
               (P + 220, lifted, down, c), (P + 280, carried, down, c), (P + 330, placed, down, c),
               (P + 340, placed, down, c), (P + 360, placed, down, o), (P + 400, up, down, o),
               (P + 450, up, down, o)]
        N = P + 450
    k = a.slow
    pts = [(s0 * k, *rest) for s0, *rest in pts]; N *= k; P *= k
    # seed: random restarts for the approach pose, nearest home
    rng = np.random.default_rng(0)
    best_cost, seed = np.inf, home
    for _ in range(200):
        cand = rng.uniform(np.maximum(arm.lo, -3), np.minimum(arm.hi, 3))
        d.qpos[:] = qpos0; d.qpos[arm.qadr] = cand
        err = arm.ik(d, above, down, iters=2000)
        if err < 1e-4:
            q1 = d.qpos[arm.qadr].copy()
            free = ~np.isfinite(arm.lo)   # continuous joints: the turn nearest home
            q1[free] = home[free] + (q1[free] - home[free] + np.pi) % (2 * np.pi) - np.pi
            cost = np.abs(q1 - home).sum()
            if cost < best_cost:
                best_cost, seed = cost, q1
    if not np.isfinite(best_cost):
        raise SystemExit("IK: approach pose unreachable")
    # joint_path: first segment 0..P is 'start -> first waypoint after it' in joint space; keep
    # the arm still during the opening by planning from P on
    pts2 = [(k - P, *rest) for k, *rest in pts[1:]]
    q, grip = scripted.joint_path(arm, d, pts2, N - P, start=home, rest=None, seed=seed)
    ramp = 0.5 - 0.5 * np.cos(np.pi * np.arange(P) / P)
    q = np.concatenate([np.repeat(home[None], P, 0), q]); grip = np.concatenate([o * ramp, grip])
    fps = 50.0
    joints = arm.feed_forward(q, 1 / fps, qpos0)
    joints[:P] = home
    actions = np.concatenate([joints, grip[:, None]], 1)
    t = Trajectory(actions=actions, fps=fps, start=actions[0].copy(), qpos0=qpos0, object_pose=cube,
                   meta={"generator": f"probe_r32 robot_traj {a.robot}"}, source=f"{a.robot}_pick")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape)


if __name__ == "__main__":
    main()
