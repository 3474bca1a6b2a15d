"""A scripted right-to-left hand-over for the OpenArm (make_scene.py's scenes).

probe_r25's IK approach (benchmarks/real_models/scripted.py's DLS IK and min-jerk TCP
paths, inverse-dynamics feed-forward of the unloaded arm), for both arms. The TCP is the
fingertips' centre (hand frame (0, 0, -0.164): the tips curl 8 mm inward of the pads, so
they are what touches a 4 cm cube).

The OpenArm fingers are 5.5 cm wide, wider than the cube, so the two grips cannot share a
height, and with a 4 cm cube only the tips touch. Timeline (50 Hz, 550 steps = 11 s):

* right: picks from above (fingers down, spread along world x, tips ``--depth`` 6 mm above
  the cube's centre), closes 3.3 s, lifts 3.6-4.6 s, carries to the meeting point turning
  the hand ``--yaw`` 90 deg about the vertical (4.6-6.4 s; unturned, the hand cannot reach
  the middle within joint6/joint7's limits), holds, opens 8.0-8.5 s, retreats up and toward
  -y (8.8-9.8 s; straight up leaves its reach);
* left: from home to a pose below and behind the meeting point (``--lapproach``; 0-4.4 s),
  waits, rises to it (6.4-7.2 s) with fingers forward (+x, its home orientation) spread
  along y, tips ``--drop`` 30 mm below the cube's centre (their top edge 4 mm under the
  right's tips), closes 7.4-7.9 s and holds to the end. A left hand from below with
  fingers up has no IK solution; a meeting point at y = 0, or an approach from further
  behind, puts the left elbow (link4/link5) into the torso (openarm_body_link0), hence the
  meeting point (0.35, 0.04, 0.47) and the forward-pitched left seed.

Channels in init's order: left joint1..7, left gripper (0 closed .. 1 open), right
joint1..7, right gripper.

Usage (the critmoment venv active, from a folder whose assets/ links the wheel's v2):
    python traj.py SCENE.xml OUT.npz [--meet X Y Z] [--depth D] [--drop D] [--yaw DEG]
e.g. python traj.py assets/pedestal/critmoment_r27_oa_ho_shipped.xml ho.npz
CRITMOMENT_REAL_MODELS names another folder holding scripted.py.
"""
from __future__ import annotations

import argparse
import os
import sys

import mujoco
import numpy as np

REAL_MODELS = os.environ.get("CRITMOMENT_REAL_MODELS",
                             "/work/main/benchmarks/real_models")
sys.path.insert(0, REAL_MODELS)
import scripted  # noqa: E402

from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402

RIGHT = tuple(f"openarm_right_joint{i}" for i in range(1, 8))
LEFT = tuple(f"openarm_left_joint{i}" for i in range(1, 8))
HOME = np.array([0.0, 0.0, 0.0, np.pi / 2, 0.0, 0.0, 0.0])
RSEED = np.array([0.764, 1.157, -1.149, 1.569, -0.178, 0.374, 1.219])
TIP = np.array([-0.0015, 0.0, -0.164])


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--meet", type=float, nargs=3, default=[0.35, 0.04, 0.47])
    p.add_argument("--depth", type=float, default=0.006,
                   help="right tips' centre above the cube's centre [m]")
    p.add_argument("--drop", type=float, default=0.030,
                   help="left tips' centre below the cube's centre [m]")
    p.add_argument("--yaw", type=float, default=90.0,
                   help="right hand's turn about the vertical during the carry [deg]")
    p.add_argument("--close", type=float, default=0.0)
    p.add_argument("--approach", type=float, default=0.10)
    p.add_argument("--lapproach", type=float, nargs=3, default=[0.03, 0.0, 0.08])
    p.add_argument("--lseed", type=float, nargs=7,
                   default=[-0.2, -0.15, 0.85, 1.41, -0.25, 0.17, 0.8],
                   help="left IK seed and null-space rest: shoulder pitched forward, else the "
                        "left elbow (link4/link5) runs into the torso (openarm_body_link0)")
    p.add_argument("--check", action="store_true", help="also print the IK joint poses")
    a = p.parse_args()
    model = mujoco.MjModel.from_xml_path(a.scene)
    data = mujoco.MjData(model)
    qpos0 = data.qpos.copy()
    for names in (LEFT, RIGHT):
        qpos0[model.jnt_qposadr[[model.joint(j).id for j in names]]] = HOME
    cj = model.jnt_qposadr[model.joint("cube_joint").id]
    cube = qpos0[cj:cj + 7].copy()
    arms = {s: scripted.Arm(model, RIGHT if s == "right" else LEFT, f"openarm_{s}_ee_base_link",
                            (f"finger_inner_{s}_collision_00",), qpos0, TIP)
            for s in ("left", "right")}
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    down = scripted._frame([0, 1, 0], [-1, 0, 0])   # hand z up: fingers down, spread along x
    yaw = np.deg2rad(a.yaw)
    rz = np.array([[np.cos(yaw), -np.sin(yaw), 0], [np.sin(yaw), np.cos(yaw), 0], [0, 0, 1]])
    turned = rz @ down                              # the right hand turned about the vertical
    fwd = scripted._frame([0, 0, 1], [0, 1, 0])     # fingers forward (+x), spread along y
    d, ap = a.depth, a.approach
    meet = np.asarray(a.meet)
    grasp = cube[:3] + [0, 0, d]
    above = grasp + [0, 0, ap]
    rheld = meet + [0, 0, d]              # right tips over the cube's centre at the meeting
    lheld = meet - [0, 0, a.drop]         # left tips below the right ones, on the +-y faces
    lbehind = lheld - np.asarray(a.lapproach)  # below and a little behind: from further
    # back the left elbow runs into the torso
    retreat = np.array([0.0, -0.08, 0.04])  # up and back toward the right side (straight up
    # leaves the turned hand's reach)
    rs, ls = arms["right"].tcp(data), arms["left"].tcp(data)
    c, o = a.close, 1.0
    right = [(0, rs[0], rs[1], o), (75, above, down, o), (125, grasp, down, o),
             (140, grasp, down, o), (165, grasp, down, c), (180, grasp, down, c),
             (230, above, down, c), (320, rheld, turned, c), (400, rheld, turned, c),
             (425, rheld, turned, o), (440, rheld, turned, o),
             (490, rheld + retreat, turned, o), (550, rheld + retreat, turned, o)]
    left = [(0, ls[0], ls[1], o), (220, lbehind, fwd, o), (320, lbehind, fwd, o),
            (360, lheld, fwd, o), (370, lheld, fwd, o), (395, lheld, fwd, c),
            (550, lheld, fwd, c)]
    n, fps = 550, 50.0
    actions = np.zeros((n, 16))
    for side, points, col, seed in (("left", left, 0, a.lseed), ("right", right, 8, RSEED)):
        arm = arms[side]
        data.qpos[:] = qpos0
        rest = np.asarray(seed) if side == "left" else None
        q, grip = scripted.joint_path(arm, data, points, n, start=HOME, rest=rest,
                                      seed=np.asarray(seed))
        if a.check:
            for t, *_ in points:
                print(side, t, np.round(q[min(int(t), n - 1)], 3))
        actions[:, col:col + 7] = arm.feed_forward(q, 1 / fps, qpos0)
        actions[:, col + 7] = grip
        actions[0, col:col + 7] = HOME
        actions[0, col + 7] = 1.0
    start = actions[0].copy()
    t = Trajectory(actions=actions, fps=fps, start=start, qpos0=qpos0, object_pose=cube,
                   meta={"generator": "probe_r27 openarm handover traj"},
                   source="openarm_handover")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape)


if __name__ == "__main__":
    main()
