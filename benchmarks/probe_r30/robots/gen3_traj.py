"""Scripted pick-and-place for make_gen3_scene.py's Kinova Gen3 + Robotiq 2F-85 + 5 cm cube.

DLS IK with a null-space pull to the Menagerie `home` posture (7 DoF;
benchmarks/real_models/scripted.py) of a TCP at the four pad boxes' midpoint, fingers
pointing down, closing along world y. 50 Hz, 500 steps: above the cube (75), down (125),
close (140..165), wait (190), lift 0.15 m (250), carry to the goal (310), lower (360),
open (370..390), retreat up (430), hold. Servo targets with the unloaded arm's inverse
dynamics fed forward. Channels: joint_1..joint_7, gripper (0 closed .. 1 open).
usage: gen3_traj.py SCENE.xml OUT.npz [--grasp-dz DZ] [--close C]
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

JOINTS = tuple(f"joint_{i}" for i in range(1, 8))
HOME = np.array([0, 0.26179939, 3.14159265, -2.26892803, 0, 0.95993109, 1.57079633])
PADS = ("g_right_pad1", "g_right_pad2", "g_left_pad1", "g_left_pad2")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene"); p.add_argument("out")
    p.add_argument("--grasp-dz", type=float, default=0.0)
    p.add_argument("--close", type=float, default=0.0)
    a = p.parse_args()
    m = mujoco.MjModel.from_xml_path(a.scene)
    d = mujoco.MjData(m)
    qpos0 = m.qpos0.copy()
    qpos0[m.jnt_qposadr[[m.joint(j).id for j in JOINTS]]] = HOME
    cj = m.jnt_qposadr[m.joint("cube_joint").id]
    cube = qpos0[cj:cj + 7].copy()
    arm = scripted.Arm(m, JOINTS, "g_base", PADS, qpos0)
    d.qpos[:] = qpos0
    mujoco.mj_kinematics(m, d)
    p0, r0 = arm.tcp(d)
    # fingers down (hand z = world -z), closing axis hand y = world +-y, whichever is nearer home
    down = np.array([[1, 0, 0], [0, -1, 0], [0, 0, -1]], float)
    alt = down @ np.diag([-1, -1, 1])
    if np.trace(down.T @ r0) < np.trace(alt.T @ r0):
        down = alt
    grasp = cube[:3] + [0, 0, a.grasp_dz]
    above = grasp + [0, 0, 0.12]
    lifted = grasp + [0, 0, 0.15]
    gpos = m.site_pos[m.site("goal").id].copy()
    carried = np.array([gpos[0], gpos[1], lifted[2]])
    placed = np.array([gpos[0], gpos[1], grasp[2] + 0.003])
    up = placed + [0, 0, 0.12]
    c, o = a.close, 1.0
    pts = [(0, p0, r0, o), (75, above, down, o), (125, grasp, down, o), (140, grasp, down, o),
           (165, grasp, down, c), (190, grasp, down, c), (250, lifted, down, c),
           (310, carried, down, c), (360, placed, down, c), (370, placed, down, c),
           (390, placed, down, o), (430, up, down, o), (500, up, down, o)]
    q, grip = scripted.joint_path(arm, d, pts, 500, start=HOME, rest=HOME, seed=HOME)
    fps = 50.0
    joints = arm.feed_forward(q, 1 / fps, qpos0)
    joints[0] = HOME
    actions = np.concatenate([joints, grip[:, None]], 1)
    t = Trajectory(actions=actions, fps=fps, start=actions[0].copy(), qpos0=qpos0, object_pose=cube,
                   meta={"generator": "probe_r30 gen3_traj"}, source="gen3_pick_place")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape, "critmoment", critmoment.__file__)


if __name__ == "__main__":
    main()
