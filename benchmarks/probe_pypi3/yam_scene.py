"""i2rt YAM (mjlab 1.6.0, ``asset_zoo/robots/i2rt_yam/xmls/yam.xml``) composed as mjlab does.

``yam.xml`` ships no actuators: mjlab adds them in Python (``yam_constants.py``). This does
the same with MjSpec, with mjlab's numbers:

* arm joints 1-3: DM-4340 (effort 28 N·m, armature 0.032), joints 4-6: DM-4310 (10 N·m,
  0.0018); position servos kp = I_eff (2π·2 Hz)², kv = 2·2·I_eff·(2π·2 Hz) (damping ratio 2),
  forcerange ± effort, ctrl unlimited (``create_position_actuator``);
* gripper: one position servo on ``left_finger`` (the right finger follows by the shipped
  joint equality), kp = 2.781624 (2π·1 Hz)², kv = 2·2·2.781624·2π, forcerange ± 0.1 × the
  DM-4310's 10 N·m reflected through 0.071 m / 2.7 rad, armature 0.0018 / ratio²;
* ``GRIPPER_ONLY_COLLISION``: only link6 and finger ``*_collision`` geoms collide; the
  fingertip spheres condim 6, friction (1, 5e-3, 5e-4), solref 0.01, priority 1; others
  condim 3, friction 0.6;
* mjlab's lift-cube sim options: timestep 5 ms, iterations 10, ls_iterations 20, elliptic
  cone, impratio 10 (the "shipped" contact model here); robot base at z = 0.01;
* a floor plane, mjlab's cube (4 cm, 0.05 kg, free) at (0.3, 0, 0.02) and a goal site.

Writes ``/root/.cache/critmoment-real-models/mjlab/yam_scene{,_pyramidal1}.xml``.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import mujoco
import numpy as np

ROOT = Path("/root/.cache/critmoment-real-models/mjlab")
YAM = ROOT / "mjlab/asset_zoo/robots/i2rt_yam/xmls/yam.xml"
EFF = {"joint1": 0.123153, "joint2": 0.277411, "joint3": 0.232763, "joint4": 0.030154,
       "joint5": 0.009126, "joint6": 0.002868, "left_finger": 2.781624}
MOTOR = {"joint1": (28.0, 0.032), "joint2": (28.0, 0.032), "joint3": (28.0, 0.032),
         "joint4": (10.0, 0.0018), "joint5": (10.0, 0.0018), "joint6": (10.0, 0.0018)}
HOME = {"joint2": 1.047, "joint3": 1.05, "joint4": -0.9, "left_finger": 0.0375 / 2,
        "right_finger": -0.0375 / 2}
GOAL = (0.3, 0.15, 0.02)


def _servo(spec, joint, kp, kv, effort, armature):
    spec.joint(joint).armature = armature
    a = spec.add_actuator(name=joint, target=joint)
    a.trntype = mujoco.mjtTrn.mjTRN_JOINT
    a.dyntype = mujoco.mjtDyn.mjDYN_NONE
    a.gaintype = mujoco.mjtGain.mjGAIN_FIXED
    a.biastype = mujoco.mjtBias.mjBIAS_AFFINE
    a.gainprm[0] = kp
    a.biasprm[1] = -kp
    a.biasprm[2] = -kv
    a.ctrllimited = mujoco.mjtLimited.mjLIMITED_FALSE
    a.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
    a.forcerange = np.array([-effort, effort])


def build(cone="elliptic", impratio=10.0, finger_ctrlrange=False) -> mujoco.MjSpec:
    spec = mujoco.MjSpec.from_file(str(YAM))
    spec.meshdir = str(YAM.parent / "assets")
    w = 2 * math.pi * 2.0
    for j, (effort, arm) in MOTOR.items():
        _servo(spec, j, EFF[j] * w * w, 2 * 2.0 * EFF[j] * w, effort, arm)
    wg = 2 * math.pi * 1.0
    ratio = 0.071 / 2.7
    _servo(spec, "left_finger", EFF["left_finger"] * wg * wg, 2 * 2.0 * EFF["left_finger"] * wg,
           0.1 * 10.0 / ratio, 0.0018 / ratio ** 2)
    if finger_ctrlrange:  # workaround: critmoment init needs a gripper ctrlrange
        a = spec.actuator("left_finger")
        a.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
        a.ctrlrange = np.array([-0.00205, 0.037524])  # the joint's range
    tip = re.compile(r"[lr]f_down(6|7|8|9|10|11)_collision")
    grip = re.compile(r"(link6|[lr]f)_.*_collision")
    for g in spec.geoms:
        if not g.name.endswith("_collision"):
            continue
        on = bool(grip.fullmatch(g.name))
        g.contype = g.conaffinity = int(on)
        if tip.fullmatch(g.name):
            g.condim, g.friction, g.solref, g.priority = 6, [1, 5e-3, 5e-4], [0.01, 1], 1
        else:
            g.condim, g.friction, g.priority = 3, [0.6, 5e-3, 1e-4], 0
    spec.body("arm").pos = [0, 0, 0.01]
    spec.option.timestep = 0.005
    spec.option.iterations = 10
    spec.option.ls_iterations = 20
    spec.option.cone = (mujoco.mjtCone.mjCONE_ELLIPTIC if cone == "elliptic"
                        else mujoco.mjtCone.mjCONE_PYRAMIDAL)
    spec.option.impratio = impratio
    wb = spec.worldbody
    wb.add_geom(name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[2, 2, 0.01])
    cube = wb.add_body(name="cube", pos=[0.3, 0.0, 0.02])
    cube.add_freejoint(name="cube_joint")
    cube.add_geom(name="cube_geom", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.02] * 3, mass=0.05,
                  rgba=[0.8, 0.2, 0.2, 1])
    wb.add_site(name="goal", pos=list(GOAL), size=[0.01] * 3)
    return spec


def home_qpos(model) -> np.ndarray:
    q = model.qpos0.copy()
    for j, v in HOME.items():
        q[model.jnt_qposadr[model.joint(j).id]] = v
    return q


def main():
    for name, cone, imp, fc in (("yam_scene.xml", "elliptic", 10.0, False),
                                ("yam_scene_pyramidal1.xml", "pyramidal", 1.0, False),
                                ("yam_scene_fc.xml", "elliptic", 10.0, True),
                                ("yam_scene_fc_pyramidal1.xml", "pyramidal", 1.0, True)):
        spec = build(cone, imp, fc)
        model = spec.compile()
        out = ROOT / name
        out.write_text(spec.to_xml())
        mujoco.MjModel.from_xml_path(str(out))
        print("wrote", out, "nu", model.nu,
              [(model.actuator(i).name, round(float(model.actuator_gainprm[i, 0]), 2),
                round(float(model.actuator_forcerange[i, 1]), 2)) for i in range(model.nu)])


if __name__ == "__main__":
    main()
