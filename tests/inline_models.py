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


#: a 15 kg cart on four one-hinge legs (position servos h0-h3, 5 N·m) with a free joint,
#: carrying a 6-joint arm with two slide fingers, over a table with a 4 cm cube (probe_r34's
#: floating-base robot): the robot's own base is a free body
LEGGED_MJCF = """<mujoco model="probe_r34_legged">
  <compiler angle="radian" autolimits="true"/>
  <option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>
  <worldbody>
    <light pos="0 0 3"/>
    <geom name="floor" type="plane" size="3 3 0.1" rgba=".8 .8 .8 1"/>
    <body name="table" pos="0.65 0.3 0.15">
      <geom name="table_top" type="box" size="0.25 0.6 0.15" rgba=".6 .4 .2 1"/>
    </body>
    <body name="base" pos="0 0 0.17">
      <freejoint name="base_free"/>
      <geom name="chassis" type="box" size="0.25 0.2 0.06" mass="15.0" rgba=".2 .4 .7 1"/>
      <body name="leg0" pos="0.2 0.15 -0.06"><joint name="hip0" axis="0 1 0" range="-0.8 0.8" armature="0.01" damping="0.5"/><geom type="capsule" fromto="0 0 0 0.05 0 -0.08" size="0.015" mass="0.2" rgba=".1 .1 .1 1"/><geom name="foot0" type="sphere" size="0.03" pos="0.05 0 -0.08" mass="0.1" friction="1 0.005 0.0001" rgba=".1 .1 .1 1"/></body><body name="leg1" pos="0.2 -0.15 -0.06"><joint name="hip1" axis="0 1 0" range="-0.8 0.8" armature="0.01" damping="0.5"/><geom type="capsule" fromto="0 0 0 0.05 0 -0.08" size="0.015" mass="0.2" rgba=".1 .1 .1 1"/><geom name="foot1" type="sphere" size="0.03" pos="0.05 0 -0.08" mass="0.1" friction="1 0.005 0.0001" rgba=".1 .1 .1 1"/></body><body name="leg2" pos="-0.2 0.15 -0.06"><joint name="hip2" axis="0 1 0" range="-0.8 0.8" armature="0.01" damping="0.5"/><geom type="capsule" fromto="0 0 0 0.05 0 -0.08" size="0.015" mass="0.2" rgba=".1 .1 .1 1"/><geom name="foot2" type="sphere" size="0.03" pos="0.05 0 -0.08" mass="0.1" friction="1 0.005 0.0001" rgba=".1 .1 .1 1"/></body><body name="leg3" pos="-0.2 -0.15 -0.06"><joint name="hip3" axis="0 1 0" range="-0.8 0.8" armature="0.01" damping="0.5"/><geom type="capsule" fromto="0 0 0 0.05 0 -0.08" size="0.015" mass="0.2" rgba=".1 .1 .1 1"/><geom name="foot3" type="sphere" size="0.03" pos="0.05 0 -0.08" mass="0.1" friction="1 0.005 0.0001" rgba=".1 .1 .1 1"/></body>


      <body name="shoulder" pos="0.10 0 0.1">
        <joint name="j1" axis="0 0 1" range="-2.8 2.8" armature="0.1" damping="1"/>
        <geom type="cylinder" size="0.05 0.04" mass="1.0" rgba=".3 .3 .3 1"/>
        <body name="upper" pos="0 0 0.06">
          <joint name="j2" axis="0 1 0" range="-2 2" armature="0.1" damping="1"/>
          <geom type="capsule" fromto="0 0 0 0 0 0.30" size="0.035" mass="2.0" rgba=".5 .5 .7 1"/>
          <body name="fore" pos="0 0 0.30">
            <joint name="j3" axis="0 1 0" range="-2.6 2.6" armature="0.05" damping="0.5"/>
            <geom type="capsule" fromto="0 0 0 0.28 0 0" size="0.03" mass="1.2" rgba=".5 .5 .7 1"/>
            <body name="wrist1" pos="0.28 0 0">
              <joint name="j4" axis="1 0 0" range="-3 3" armature="0.02" damping="0.2"/>
              <geom type="cylinder" fromto="0 0 0 0.05 0 0" size="0.03" mass="0.4" rgba=".3 .3 .3 1"/>
              <body name="wrist2" pos="0.05 0 0">
                <joint name="j5" axis="0 1 0" range="-2.2 2.2" armature="0.02" damping="0.2"/>
                <geom type="sphere" size="0.03" mass="0.3" rgba=".3 .3 .3 1"/>
                <body name="hand" pos="0.05 0 0">
                  <joint name="j6" axis="1 0 0" range="-3 3" armature="0.01" damping="0.1"/>
                  <geom name="palm" type="box" size="0.02 0.05 0.025" pos="0.01 0 0" mass="0.4" rgba=".2 .2 .2 1"/>
                  <body name="finger_l" pos="0.06 0 0">
                    <joint name="fl" type="slide" axis="0 1 0" range="0 0.04" armature="0.01" damping="2"/>
                    <geom name="pad_l" type="box" size="0.03 0.005 0.012" pos="0 0.005 0" mass="0.05" friction="1 0.005 0.0001" rgba=".8 .2 .2 1"/>
                  </body>
                  <body name="finger_r" pos="0.06 0 0">
                    <joint name="fr" type="slide" axis="0 -1 0" range="0 0.04" armature="0.01" damping="2"/>
                    <geom name="pad_r" type="box" size="0.03 0.005 0.012" pos="0 -0.005 0" mass="0.05" friction="1 0.005 0.0001" rgba=".8 .2 .2 1"/>
                  </body>
                </body>
              </body>
            </body>
          </body>
        </body>
      </body>
    </body>
    <body name="cube" pos="0.55 0 0.32">
      <freejoint name="cube_joint"/>
      <geom name="cube_geom" type="box" size="0.02 0.02 0.02" mass="0.2" friction="0.8 0.005 0.0001" rgba=".9 .1 .1 1"/>
    </body>
    <site name="goal" pos="0.55 0.35 0.32" size="0.01" rgba="0 1 0 1"/>
  </worldbody>

  <contact><exclude body1="shoulder" body2="fore"/><exclude body1="upper" body2="wrist1"/><exclude body1="upper" body2="wrist2"/><exclude body1="fore" body2="wrist2"/><exclude body1="fore" body2="hand"/><exclude body1="wrist1" body2="hand"/><exclude body1="wrist1" body2="finger_l"/><exclude body1="wrist1" body2="finger_r"/><exclude body1="wrist2" body2="finger_l"/><exclude body1="wrist2" body2="finger_r"/><exclude body1="fore" body2="finger_l"/><exclude body1="fore" body2="finger_r"/><exclude body1="finger_l" body2="finger_r"/></contact>
  <actuator>
    <position name="a1" joint="j1" kp="3000" kv="150" forcerange="-150 150" ctrlrange="-2.8 2.8"/>
    <position name="a2" joint="j2" kp="3000" kv="150" forcerange="-150 150" ctrlrange="-2 2"/>
    <position name="a3" joint="j3" kp="2000" kv="100" forcerange="-80 80" ctrlrange="-2.6 2.6"/>
    <position name="a4" joint="j4" kp="300" kv="15" forcerange="-20 20" ctrlrange="-3 3"/>
    <position name="a5" joint="j5" kp="300" kv="15" forcerange="-20 20" ctrlrange="-2.2 2.2"/>
    <position name="a6" joint="j6" kp="100" kv="5" forcerange="-10 10" ctrlrange="-3 3"/>
    <position name="grip_l" joint="fl" kp="1500.0" kv="10" forcerange="-60.0 60.0" ctrlrange="0 0.04"/>
    <position name="grip_r" joint="fr" kp="1500.0" kv="10" forcerange="-60.0 60.0" ctrlrange="0 0.04"/>
    <position name="h0" joint="hip0" kp="300" kv="10" forcerange="-5.0 5.0" ctrlrange="-0.8 0.8"/>
    <position name="h1" joint="hip1" kp="300" kv="10" forcerange="-5.0 5.0" ctrlrange="-0.8 0.8"/>
    <position name="h2" joint="hip2" kp="300" kv="10" forcerange="-5.0 5.0" ctrlrange="-0.8 0.8"/>
    <position name="h3" joint="hip3" kp="300" kv="10" forcerange="-5.0 5.0" ctrlrange="-0.8 0.8"/>
  </actuator>
  <keyframe><key name="home" qpos="-0.000934898534 -1.20124599e-16 0.169123509 0.999999999 1.96697678e-16 3.16884349e-05 9.34359866e-17 -0.00864461206 -0.00864461206 -0.00859151061 -0.00859151061 0 0 0.3 0 1.2 0 0.04 0.04 0.55 5.26664484e-11 0.319892245 1 2.04484583e-11 -1.63778206e-12 3.15017675e-22" ctrl="0 0 0.3 0 1.2 0 0.04 0.04 0 0 0 0"/></keyframe>
</mujoco>
"""
