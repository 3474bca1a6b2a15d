"""Compose dm_control's Kinova Jaco arm + three-finger Jaco hand (dm_control 1.0.52 wheel,
dm_control/third_party/kinova, unedited) the way dm_control's composer does (the hand attached
at the arm's `wristsite`), and wrap it in a scene of ours: floor, a table, a free cube, a goal
site, and actuators (the robot XMLs ship none; dm_control adds them in Python).
usage: make_jaco.py KINOVA_DIR OUT.xml --act {velocity,motor} [--cone pyramidal --impratio 1]
  velocity: dm_control's own actuators (jaco_arm.py / jaco_hand.py: velocity kv 500, forcerange
            +-30.5 / +-6.8 N m; fingers velocity kv 10, forcerange +-1)
  motor:    torque motors with the same force limits (Kinova datasheet peak torques) as ctrlrange,
            for critmoment's [servos] (what the real arm's joint controller does)
"""
import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r33/src"), _cm_check.__file__  # r33 snapshot
import argparse
import mujoco
import numpy as np

ap = argparse.ArgumentParser()
ap.add_argument("kinova"); ap.add_argument("out")
ap.add_argument("--act", default="motor", choices=["velocity", "motor", "position"])
ap.add_argument("--cone", default=None); ap.add_argument("--impratio", type=float, default=None)
ap.add_argument("--cube-half", type=float, default=0.025)
ap.add_argument("--cube-mass", type=float, default=0.1)
a = ap.parse_args()
import os
a.kinova = os.path.abspath(a.kinova)   # a relative dir broke the mesh paths (meshdir is read relative to the XML)

arm = mujoco.MjSpec.from_file(f"{a.kinova}/jaco_arm.xml")
hand = mujoco.MjSpec.from_file(f"{a.kinova}/jaco_hand.xml")
arm.meshdir = f"{a.kinova}/meshes_decimated/"
hand.meshdir = f"{a.kinova}/meshes_decimated/"
site = arm.site("wristsite")
site.attach_body(hand.body("hand"), "hand/", "")
s = arm
s.modelname = "jaco_scene"
if a.cone:
    s.option.cone = {"pyramidal": mujoco.mjtCone.mjCONE_PYRAMIDAL, "elliptic": mujoco.mjtCone.mjCONE_ELLIPTIC}[a.cone]
if a.impratio is not None:
    s.option.impratio = a.impratio
wb = s.worldbody
wb.add_light(pos=[0, 0, 3], dir=[0, 0, -1])
wb.add_geom(name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[2, 2, 0.05], rgba=[.8, .8, .8, 1])
wb.add_geom(name="table", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.2, 0.35, 0.05], pos=[0.55, 0, 0.05],
            rgba=[.6, .4, .2, 1])
h = a.cube_half
cube = wb.add_body(name="cube", pos=[0.5, 0.15, 0.1 + h])
cube.add_freejoint(name="cube_joint")
cube.add_geom(name="cube_geom", type=mujoco.mjtGeom.mjGEOM_BOX, size=[h, h, h], mass=a.cube_mass,
              friction=[1.0, 0.005, 0.0001], rgba=[.2, .6, .9, 1])
wb.add_site(name="goal", pos=[0.5, -0.15, 0.1 + h], size=[0.01, 0, 0], rgba=[0, 1, 0, .5])
# actuators (dm_control's limits)
large = {"joint_1", "joint_2", "joint_3"}
for j in ["joint_1", "joint_2", "joint_3", "joint_4", "joint_5", "joint_6"]:
    tq = 30.5 if j in large else 6.8
    vmax = np.deg2rad(36.0 if j in large else 48.0)
    act = s.add_actuator(name=j, target=j, trntype=mujoco.mjtTrn.mjTRN_JOINT)
    if a.act == "velocity":
        act.set_to_velocity(kv=500.0)
        act.ctrlrange = [-vmax, vmax]; act.ctrllimited = 1
        act.forcerange = [-tq, tq]; act.forcelimited = 1
    else:
        act.set_to_motor()
        act.ctrlrange = [-tq, tq]; act.ctrllimited = 1
for j in ["hand/finger_1", "hand/finger_2", "hand/finger_3"]:
    act = s.add_actuator(name=j.split("/")[1], target=j, trntype=mujoco.mjtTrn.mjTRN_JOINT)
    if a.act == "velocity":
        act.set_to_velocity(kv=10.0)
        act.ctrlrange = [-5, 5]; act.ctrllimited = 1
        act.forcerange = [-1, 1]; act.forcelimited = 1
    else:
        act.set_to_motor()
        act.ctrlrange = [-1, 1]; act.ctrllimited = 1
m = s.compile()
d = mujoco.MjData(m)
# a home keyframe: elbow bent, hand above the table (dm_control's arm default is straight up)
q = np.zeros(m.nq)
mujoco.mj_resetData(m, d)
q[:] = d.qpos
for j, v in dict(joint_1=0.0, joint_2=np.pi, joint_3=np.pi, joint_4=0.0, joint_5=0.0, joint_6=0.0).items():
    q[m.jnt_qposadr[m.joint(j).id]] = v
for f in ["hand/finger_1", "hand/finger_2", "hand/finger_3"]:
    q[m.jnt_qposadr[m.joint(f).id]] = 0.2
s.add_key(name="home", qpos=q.tolist())
s.compile()
open(a.out, "w").write(s.to_xml())
print("wrote", a.out, "nq", m.nq, "nu", m.nu)
