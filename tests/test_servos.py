"""``[servos]``: a torque-controlled model's motors driven as joint-position servos."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest
from inline_models import arm_scenario_toml, arm_xml

import critmoment as cm
from critmoment import actuators as act_info
from critmoment import modelinfo
from critmoment.exceptions import ScenarioError
from critmoment.scenario import ServoGains, Servos, compile_spec, load_scenario, prepare_spec

#: a 0.5 m, 2 kg link on a horizontal hinge (angles in degrees, as some models ship), its
#: motor geared 2:1 with a control of +-5: at most 10 N·m on the joint
PENDULUM = """
<mujoco>
  <compiler angle="degree"/>
  <option timestep="0.002" integrator="implicitfast"/>
  <worldbody>
    <body name="link">
      <joint name="hinge" type="hinge" axis="0 1 0" range="-90 90" damping="0.1"/>
      <geom type="capsule" fromto="0 0 0 0.5 0 0" size="0.01" mass="0" contype="0"
            conaffinity="0"/>
      <geom type="sphere" pos="0.5 0 0" size="0.02" mass="2" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
  <actuator>
    <motor name="drive" joint="hinge" gear="2" ctrlrange="-5 5"/>
  </actuator>
</mujoco>
"""


def _pendulum(tmp_path, servos):
    path = tmp_path / "pendulum.xml"
    path.write_text(PENDULUM)
    return compile_spec(prepare_spec(path, servos=servos), path)


def test_a_motor_made_a_servo_holds_against_gravity_with_the_torque_m_g_lever(tmp_path):
    kp, kv = 400.0, 20.0
    model = _pendulum(tmp_path, Servos(default=ServoGains(kp=kp, kv=kv)))
    info = act_info.describe(model, 0)
    assert info.kind.tracks_position
    # the control is the joint's target in radians (the degrees converted), the force bound
    # the motor's: its control range (gain 1), before the 2:1 gear
    np.testing.assert_allclose(model.actuator_ctrlrange[0], [-math.pi / 2, math.pi / 2])
    np.testing.assert_allclose(model.actuator_forcerange[0], [-5.0, 5.0])
    data = mujoco.MjData(model)
    data.ctrl[0] = 0.0  # hold the link horizontal
    for _ in range(3000):
        mujoco.mj_step(model, data)
    assert abs(data.qvel[0]) < 1e-6
    # gravity turns the link down, +y: the servo answers with m g L = 9.81 N·m, under the
    # 10 N·m the motor can give
    lever_torque = 2.0 * 9.81 * 0.5
    assert data.qfrc_actuator[0] == pytest.approx(-lever_torque, rel=1e-3)
    assert data.actuator_force[0] == pytest.approx(-lever_torque / 2.0, rel=1e-3)  # the gear
    # kp acts on the joint: the sag is the torque over kp
    assert data.qpos[0] == pytest.approx(lever_torque / kp, rel=1e-2)
    # a target the motor cannot hold against gravity: the servo saturates at its bound
    data.ctrl[0] = math.radians(-60)
    heavy = _pendulum(tmp_path, Servos(gains={"drive": ServoGains(kp=kp, kv=kv)}))
    heavy.body_mass[1] = 3.0
    data = mujoco.MjData(heavy)
    for _ in range(3000):
        mujoco.mj_step(heavy, data)
    assert data.actuator_force[0] == pytest.approx(-5.0)


def test_servos_name_only_torque_motors_on_joints(tmp_path):
    with pytest.raises(ScenarioError, match=r"\[servos.wheel\].*no actuator of the model.*drive"):
        _pendulum(tmp_path, Servos(gains={"wheel": ServoGains(kp=1.0, kv=0.0)}))
    path = tmp_path / "arm.xml"
    path.write_text(arm_xml())
    with pytest.raises(ScenarioError, match=r"\[servos.shoulder_act\].*not a torque motor.*"
                                            r"\(none\)"):
        prepare_spec(path, servos=Servos(gains={"shoulder_act": ServoGains(kp=1.0, kv=0.0)}))


def _motor_scenario(tmp_path, servos: str):
    (tmp_path / "arm.xml").write_text(arm_xml(motor=True))
    (tmp_path / "scenario.toml").write_text(arm_scenario_toml(extra=servos))
    return tmp_path


def test_a_torque_controlled_arm_tracks_joint_targets_through_its_servos(tmp_path):
    sc = load_scenario(_motor_scenario(tmp_path, """
[servos]
kp = 300.0
kv = 20.0
[servos.elbow_act]
kp = 200.0
kv = 10.0
"""))
    assert sc.servos.default == ServoGains(300.0, 20.0)
    assert sc.limits == {"shoulder_act": 50.0, "elbow_act": 50.0, "finger_a_act": 20.0,
                         "finger_b_act": 20.0}
    twin = cm.Twin(sc)
    model = twin.model
    np.testing.assert_allclose(model.actuator_biasprm[:2, 1], [-300.0, -200.0])
    # a slow swing of both joints, the gripper open: the servos follow it
    t = np.linspace(0.0, 2.0, 101)
    # (the inline arm's hinges span +-3 degrees: MJCF's default unit, the servos' control
    # range in radians)
    np.testing.assert_allclose(model.actuator_ctrlrange[:2], [[-math.radians(3),
                                                                math.radians(3)]] * 2)
    target = np.stack([0.04 * np.sin(np.pi * t / 4), -0.03 * np.sin(np.pi * t / 4),
                       np.ones_like(t)], axis=1)
    rec = cm.rollout(cm.Trajectory(actions=target, fps=50.0), twin=twin)
    q = rec.states[-1, 1:3]  # (time, then qpos: shoulder, elbow)
    np.testing.assert_allclose(q, target[-1, :2], atol=2e-3)


def test_servos_table_is_checked(tmp_path):
    with pytest.raises(ScenarioError, match=r"\[servos\]: expected both kp and kv"):
        load_scenario(_motor_scenario(tmp_path, "[servos]\nkp = 300.0\n"))
    with pytest.raises(ScenarioError, match=r"\[servos.elbow_act\] kv: expected a damping"):
        load_scenario(_motor_scenario(tmp_path, "[servos.elbow_act]\nkp = 3.0\nkv = -1.0\n"))
    with pytest.raises(ScenarioError, match=r"\[servos\] kp: expected a finite number > 0"):
        load_scenario(_motor_scenario(tmp_path, "[servos]\nkp = 0.0\nkv = 1.0\n"))
    with pytest.raises(ScenarioError, match=r"unknown key.*'ki'"):
        load_scenario(_motor_scenario(tmp_path, "[servos]\nkp = 1.0\nkv = 1.0\nki = 2.0\n"))


@pytest.mark.parametrize(("ctrlrange", "forcerange", "limit"), [
    ("-2 4", None, 2.0),  # an asymmetric control range: its smaller side
    ("-5 5", "-3 8", 3.0),  # the motor's own force range cuts one side
    ("0 6", None, 6.0),  # one-sided
])
def test_inspect_init_and_the_twin_give_a_torque_motor_one_limit(tmp_path, ctrlrange,
                                                                  forcerange, limit):
    # the limit inspect prints and init writes for a motor is the one the twin's servo gets
    xml = PENDULUM.replace('ctrlrange="-5 5"', f'ctrlrange="{ctrlrange}"'
                           + (f' forcerange="{forcerange}"' if forcerange else ""))
    path = tmp_path / "pendulum.xml"
    path.write_text(xml)
    shipped = mujoco.MjModel.from_xml_path(str(path))
    servo = compile_spec(prepare_spec(path, servos=Servos(default=ServoGains(kp=100.0, kv=5.0))),
                         path)
    assert act_info.motor_limit(shipped, 0) == pytest.approx(limit)
    assert act_info.force_limit(servo, 0) == pytest.approx(limit)
    text = modelinfo.inspect_model(path).text()
    if forcerange is None:
        assert f"force at most {limit:g} (ctrl × gain; {2 * limit:g} at the joint, gear 2)" in text


def test_default_servo_gains_on_a_model_without_torque_motors_warn(tmp_path):
    path = tmp_path / "arm.xml"
    path.write_text(arm_xml())
    with pytest.warns(Warning, match=r"\[servos\]: default kp, kv given, but the "
                                                  r"model has no torque motor"):
        prepare_spec(path, servos=Servos(default=ServoGains(kp=100.0, kv=5.0)))
