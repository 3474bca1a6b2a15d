"""Inline MJCF of a small single arm with interchangeable grippers, as models ship them.

``arm_xml(gripper=...)`` gives a 2-joint arm over a table with a 4 cm cube, and one of

* ``"slides"``: two slide fingers, one position actuator each (ALOHA, Franka hand);
* ``"tendon"``: two slide fingers coupled by a fixed tendon and driven by one ``general``
  actuator with an affine bias on a 0..255 control (the 2F-85 / Menagerie Panda pattern);
* ``"jaw"``: one hinge jaw against a fixed jaw (SO-100, Koch).

``named=False`` leaves every geom and actuator unnamed, as many shipped models do;
``motor=True`` makes the arm's actuators torque motors.
"""

from __future__ import annotations


def _fingers(gripper: str, named: bool) -> str:
    n = (lambda s: f'name="{s}"') if named else (lambda s: "")
    if gripper in ("slides", "tendon"):
        return f"""
        <body name="finger_a" pos="0 0.03 -0.06">
          <joint name="slide_a" type="slide" axis="0 -1 0" range="0 0.03" damping="5"/>
          <geom {n("pad_a")} type="box" size="0.01 0.005 0.03" mass="0.05" friction="1.0"/>
        </body>
        <body name="finger_b" pos="0 -0.03 -0.06">
          <joint name="slide_b" type="slide" axis="0 1 0" range="0 0.03" damping="5"/>
          <geom {n("pad_b")} type="box" size="0.01 0.005 0.03" mass="0.05" friction="1.0"/>
        </body>"""
    if gripper == "jaw":
        return f"""
        <geom {n("fixed_jaw")} type="box" pos="0 -0.03 -0.06" size="0.01 0.005 0.03" mass="0.05"/>
        <body name="moving_jaw" pos="0 0.03 -0.03">
          <joint name="jaw" type="hinge" axis="1 0 0" range="-0.2 1.0" damping="1"/>
          <geom {n("jaw_pad")} type="box" pos="0 0 -0.03" size="0.01 0.005 0.03" mass="0.05"/>
        </body>"""
    raise ValueError(gripper)


def _gripper_actuators(gripper: str, named: bool) -> str:
    n = (lambda s: f'name="{s}"') if named else (lambda s: "")
    if gripper == "slides":
        return f"""
    <position {n("finger_a_act")} joint="slide_a" kp="200" ctrlrange="0 0.03" forcerange="-20 20"/>
    <position {n("finger_b_act")} joint="slide_b" kp="200" ctrlrange="0 0.03" forcerange="-20 20"/>"""
    if gripper == "tendon":
        # ctrl 0 open .. 255 closed; the tendon (sum of both slides) is pulled towards
        # 0.06 * ctrl / 255 (a 2F-85-like inverted range)
        return f"""
    <general {n("fingers")} tendon="split" ctrlrange="0 255" forcerange="-40 40"
             gainprm="0.0470588 0 0" biasprm="0 -200 -10" biastype="affine"/>"""
    if gripper == "jaw":
        return f"""
    <position {n("jaw_act")} joint="jaw" kp="5" ctrlrange="-0.2 1.0" forcerange="-3 3"/>"""
    raise ValueError(gripper)


def arm_xml(*, gripper: str = "slides", named: bool = True, motor: bool = False,
            cone: str = "elliptic", impratio: float = 10.0) -> str:
    """The MJCF text (see the module docstring)."""
    n = (lambda s: f'name="{s}"') if named else (lambda s: "")
    if motor:
        arm = f"""
    <motor {n("shoulder_act")} joint="shoulder" gear="1" ctrlrange="-50 50"/>
    <motor {n("elbow_act")} joint="elbow" gear="1" ctrlrange="-50 50"/>"""
    else:
        arm = f"""
    <position {n("shoulder_act")} joint="shoulder" kp="400" kv="20" forcerange="-60 60"/>
    <position {n("elbow_act")} joint="elbow" kp="300" kv="15" forcerange="-40 40"/>"""
    tendon = """
  <tendon>
    <fixed name="split">
      <joint joint="slide_a" coef="1"/>
      <joint joint="slide_b" coef="1"/>
    </fixed>
  </tendon>
  <equality>
    <joint joint1="slide_a" joint2="slide_b" polycoef="0 1 0 0 0"/>
  </equality>""" if gripper == "tendon" else ""
    return f"""
<mujoco model="arm_{gripper}">
  <option timestep="0.002" cone="{cone}" impratio="{impratio}" integrator="implicitfast"/>
  <worldbody>
    <geom {n("table")} type="box" pos="0.3 0 -0.02" size="0.5 0.5 0.02"/>
    <site name="goal" pos="0.3 0.2 0.02" size="0.01"/>
    <body name="base" pos="0 0 0.4">
      <joint name="shoulder" type="hinge" axis="0 0 1" range="-3 3" damping="2"/>
      <geom {n("upper")} type="capsule" fromto="0 0 0 0.2 0 0" size="0.02" mass="1"
            contype="0" conaffinity="0"/>
      <body name="forearm" pos="0.2 0 0">
        <joint name="elbow" type="hinge" axis="0 0 1" range="-3 3" damping="2"/>
        <geom {n("lower")} type="capsule" fromto="0 0 0 0.1 0 0" size="0.02" mass="0.5"
              contype="0" conaffinity="0"/>
        <body name="hand" pos="0.1 0 0">
          <geom {n("palm")} type="box" size="0.02 0.04 0.01" mass="0.2"/>
          {_fingers(gripper, named)}
        </body>
      </body>
    </body>
    <body name="cube" pos="0.3 0 0.02">
      <freejoint/>
      <geom {n("cube")} type="box" size="0.02 0.02 0.02" mass="0.1" friction="0.8"/>
    </body>
  </worldbody>{tendon}
  <actuator>{arm}{_gripper_actuators(gripper, named)}
  </actuator>
  <keyframe>
    <key qpos="0 0 {'0 0' if gripper != 'jaw' else '0'} 0.3 0 0.02 1 0 0 0"/>
  </keyframe>
</mujoco>
"""


def arm_scenario_toml(mjcf: str = "arm.xml", *, shoulder: str = "", extra: str = "") -> str:
    """A pick-and-hold scenario for :func:`arm_xml`'s slide-finger arm: one channel per arm
    joint (``shoulder`` adds lines to the first, e.g. ``scales = [2.0]``), the fingers on
    one normalised channel, the cube's mass uncertain; ``extra`` is appended (``[servos]``
    tables)."""
    return f"""
[model]
mjcf = "{mjcf}"
[object]
body = "cube"
[grippers.hand]
body = "hand"
[support]
geoms = ["table"]
[actions]
convention = "explicit"
[[actions.channel]]
actuators = ["shoulder_act"]
{shoulder}
[[actions.channel]]
actuators = ["elbow_act"]
[[actions.channel]]
actuators = ["finger_a_act", "finger_b_act"]
normalised = true
scales = [0.03, 0.03]
offsets = [0.0, 0.0]
[task]
kind = "pick_hold"
[uncertainty.mass]
body = "cube"
range = [0.05, 1.0]
nominal = 0.1
{extra}
"""


#: a one-hinge arm with a pad and a free box out of its reach (a 300 kp servo, ±5 N·m)
SWING_MJCF = """
<mujoco model="swing">
  <option timestep="0.002" gravity="0 0 -9.81"/>
  <worldbody>
    <geom name="table" type="plane" size="2 2 0.1"/>
    <body name="arm" pos="0 0 0.8">
      <joint name="hinge" type="hinge" axis="0 1 0"/>
      <geom name="link" type="capsule" fromto="0 0 0 0.3 0 0" size="0.02" mass="1"/>
      <geom name="pad" type="box" pos="0.3 0 0" size="0.01 0.02 0.02" mass="0.05"/>
    </body>
    <body name="box" pos="1.2 0 0.02">
      <freejoint/>
      <geom name="box" type="box" size="0.02 0.02 0.02" mass="0.05" priority="1"/>
    </body>
  </worldbody>
  <actuator>
    <position name="hinge" joint="hinge" kp="300" forcerange="-5 5"/>
  </actuator>
</mujoco>
"""
