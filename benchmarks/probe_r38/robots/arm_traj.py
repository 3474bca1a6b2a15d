"""Scripted pick-and-place (or pick-and-hold) for the r38 scenes (Menagerie Google Robot, PAL TIAGo),
adapted from probe_r37/robots/arm_traj.py (itself from probe_r31/robots/arm_traj.py): DLS IK
(benchmarks/real_models/scripted.py of the r37 snapshot) of a TCP fixed in the hand body's frame,
fingers down, servo targets with the unloaded arm's inverse dynamics fed forward. 50 Hz.
Timeline: open (0..P) arm still, above the cube, down, close (ramp), wait, lift, carry to the goal
site, lower, open, retreat up, hold.
usage: arm_traj.py {google,...} SCENE.xml OUT.npz [--grasp-dz DZ] [--close C] [--open O] [--lift H] [--hold]
"""
import argparse
import sys
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, "/tmp/r38/robots/src/benchmarks/real_models")
import scripted  # noqa: E402  (the r37 snapshot's own benchmark helper)
import critmoment  # noqa: E402
from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402
assert critmoment.__file__.startswith("/tmp/r38/robots/src"), critmoment.__file__
assert scripted.__file__.startswith("/tmp/r38/robots/src"), scripted.__file__

# hand x = world +y, hand y (closing) = world +x, hand z (approach) = world -z
DOWN_Z = np.stack([[0, 1, 0], [1, 0, 0], [0, 0, -1]], axis=1).astype(float)
ROBOTS = {
    "tiago": dict(hand="arm_7_link", joints=tuple(f"arm_{i}_joint" for i in range(1, 8)),
                  tcp=np.array([0.0, 0.0, 0.26]),   # between the finger tips (finger meshes reach 0.295 along z)
                  down=DOWN_Z, rest_seed=True),
    "tiago_x": dict(hand="arm_7_link", joints=tuple(f"arm_{i}_joint" for i in range(1, 8)),
                    tcp=np.array([0.0, 0.0, 0.26]),
                    down=np.stack([[1, 0, 0], [0, -1, 0], [0, 0, -1]], axis=1).astype(float), rest_seed=True),
    "google": dict(hand="link_gripper",
                   joints=("joint_torso", "joint_shoulder", "joint_bicep", "joint_elbow", "joint_forearm",
                           "joint_wrist", "joint_gripper"),
                   tcp=np.array([0.0, 0.0, 0.135]),   # between the finger tips when closed on a 3 cm cube
                   # hand x = world +x, hand y (closing) = world -y, hand z = world -z (the wrist
                   # rotation joint_gripper sits at its 1.35 limit with the closing axis along world x)
                   down=np.stack([[1, 0, 0], [0, -1, 0], [0, 0, -1]], axis=1).astype(float), rest_seed=True),  # null-space pull toward the approach pose (home is straight up)
    "xarm7": dict(hand="xarm_gripper_base_link",
                  joints=tuple(f"joint{i}" for i in range(1, 8)),
                  tcp=np.array([0.0, 0.0, 0.1455]),   # pads' centre (pad_1/pad_2 mid, finger closed on 4 cm)
                  down=DOWN_Z),
    "lite6": dict(hand="gripper_body",
                  joints=tuple(f"joint{i}" for i in range(1, 7)),
                  tcp=np.array([0.0, 0.0, 0.071]),    # the tip geoms' centre
                  down=DOWN_Z),
    "arx": dict(hand="link6",
                joints=tuple(f"joint{i}" for i in range(1, 7)),
                tcp=np.array([0.125, 0.0, 0.0]),   # between the tip and base pads, on the closing axis
                # hand x (approach) = world -z, hand y (closing) = world +y, hand z = world +x
                down=np.stack([[0, 0, -1], [0, 1, 0], [1, 0, 0]], axis=1).astype(float)),
}


def main():
    p = argparse.ArgumentParser()
    p.add_argument("robot"); p.add_argument("scene"); p.add_argument("out")
    p.add_argument("--grasp-dz", type=float, default=0.0)
    p.add_argument("--close", type=float, default=0.0)
    p.add_argument("--open", type=float, default=1.0)
    p.add_argument("--lift", type=float, default=0.10)
    p.add_argument("--slow", type=float, default=1.0, help="time scale of every segment after the opening")
    p.add_argument("--approach", type=int, default=50, help="rows of the joint-space move to the approach pose")
    p.add_argument("--hold", action="store_true", help="pick_hold: no place/release, hold at the goal")
    p.add_argument("--g0", type=float, default=1.0, help="gripper channel at the start (the keyframe's ctrl)")
    a = p.parse_args()
    R = ROBOTS[a.robot]
    assert abs(np.linalg.det(R["down"]) - 1) < 1e-9
    m = mujoco.MjModel.from_xml_path(a.scene)
    d = mujoco.MjData(m)
    if m.nkey:
        mujoco.mj_resetDataKeyframe(m, d, 0)
    else:
        mujoco.mj_resetData(m, d)   # no keyframe: the model's qpos0 (the cube at its body pos)
    qpos0 = d.qpos.copy()
    arm = scripted.Arm(m, R["joints"], R["hand"], (), qpos0, offset=R["tcp"])
    home = qpos0[arm.qadr].copy()
    cj = m.jnt_qposadr[m.joint("cube_joint").id]
    cube = qpos0[cj:cj + 7].copy()
    mujoco.mj_kinematics(m, d)
    p0, r0 = arm.tcp(d)
    down = R["down"]
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
        pts = [(0, p0, r0, a.g0), (P, p0, r0, o), (P + 50, above, down, o), (P + 100, grasp, down, o),
               (P + 110, grasp, down, o), (P + 135, grasp, down, c), (P + 160, grasp, down, c),
               (P + 220, lifted, down, c), (P + 280, carried, down, c), (P + 400, carried, down, c)]
        N = P + 400
    else:
        pts = [(0, p0, r0, a.g0), (P, p0, r0, o), (P + 50, above, down, o), (P + 100, grasp, down, o),
               (P + 110, grasp, down, o), (P + 135, grasp, down, c), (P + 160, grasp, down, c),
               (P + 220, lifted, down, c), (P + 280, carried, down, c), (P + 330, placed, down, c),
               (P + 340, placed, down, c), (P + 360, placed, down, o), (P + 400, up, down, o),
               (P + 450, up, down, o)]
        N = P + 450
    if a.slow != 1.0 or a.approach != 50:   # probe_r38: soft servos (Google Robot kp 10-40, damping 10)
        def tk(k):
            if k <= P:
                return k
            k2 = P + a.approach if k == P + 50 else None
            return k2 if k2 is not None else P + a.approach + int(round((k - P - 50) * a.slow))
        pts = [(tk(k), *r) for k, *r in pts]
        N = tk(N)
    rng = np.random.default_rng(0)
    best_cost, seed = np.inf, home
    for _ in range(200):
        cand = rng.uniform(np.maximum(arm.lo, -3), np.minimum(arm.hi, 3))
        d.qpos[:] = qpos0; d.qpos[arm.qadr] = cand
        err = arm.ik(d, above, down, iters=2000)
        if err < 1e-4:
            q1 = d.qpos[arm.qadr].copy(); cost = np.abs(q1 - home).sum()
            if cost < best_cost:
                best_cost, seed = cost, q1
    if not np.isfinite(best_cost):
        raise SystemExit("IK: approach pose unreachable")
    pts2 = [(k - P, *rest) for k, *rest in pts[1:]]
    rest = (seed if R.get("rest_seed") else home) if len(R["joints"]) > 6 else None
    q, grip = scripted.joint_path(arm, d, pts2, N - P, start=home, rest=rest, seed=seed)
    ramp = 0.5 - 0.5 * np.cos(np.pi * np.arange(P) / P)
    # the gripper starts at the keyframe's state: the grip channel ramps from its start value to open
    g0 = a.g0
    q = np.concatenate([np.repeat(home[None], P, 0), q]); grip = np.concatenate([g0 + (o - g0) * ramp, grip])
    fps = 50.0
    joints = arm.feed_forward(q, 1 / fps, qpos0)
    joints[:P] = home
    actions = np.concatenate([joints, grip[:, None]], 1)
    t = Trajectory(actions=actions, fps=fps, start=actions[0].copy(), qpos0=qpos0, object_pose=cube,
                   meta={"generator": f"probe_r38 arm_traj {a.robot}"}, source=f"{a.robot}_pick")
    save_trajectory(t, a.out)
    np.save(a.out[:-4] + "_planned_q.npy", q)   # probe_r38: the IK joint path before the feed-forward
    print("wrote", a.out, actions.shape)


if __name__ == "__main__":
    main()
