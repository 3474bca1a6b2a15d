"""Tests for critmoment.rollout: bit-exact restore, the demo rollout, completion, divergence."""

from __future__ import annotations

import dataclasses
import json
import shutil
import warnings

import mujoco
import numpy as np
import pytest

from critmoment import recording as rollout_mod
from critmoment.exceptions import InputFileError, SimulationDivergedError, TrajectoryError
from critmoment.recording import Recording, prepare_controls, rollout, simulate, task_completed
from critmoment.scenario import bundled_scenario_path, load_scenario
from critmoment.trajectory import Trajectory, load_trajectory
from critmoment.twin import Twin

G = 9.81
ARM_START = np.array([0.0, -0.96, 1.16, 0.0, -0.3, 0.0])
START = np.concatenate([ARM_START, [0.0], ARM_START, [0.0]])
BOX = np.array([0.1, 0.5, 0.02, 1.0, 0.0, 0.0, 0.0])


def _hold(n: int = 20, **kwargs) -> Trajectory:
    """Both arms holding ACT's start pose for n actions (n / 50 s)."""
    return Trajectory(np.tile(START, (n, 1)), fps=50, start=START, object_pose=BOX, **kwargs)


# ---------------------------------------------------------------------------
# bit-exact restore
# ---------------------------------------------------------------------------


def test_restore_and_step_reproduces_the_recording(twin, demo_recording):
    rec = demo_recording
    model = twin.model
    first = rec.stage_first_step()
    steps = [0, 1, 777, first[1], first[2], first[4], rec.n_steps - 1]
    for k in steps:
        data = mujoco.MjData(model)
        twin.set_state(model, data, rec.states[k])
        data.ctrl[:] = rec.controls[k]
        mujoco.mj_step(model, data)
        assert np.array_equal(twin.get_state(model, data), rec.states[k + 1]), k
        assert np.array_equal(data.sensordata, rec.sensordata[k]), k


def test_restored_step_needs_the_step_controls(twin, demo_recording):
    # the state holds the previous step's controls: stepping without setting ctrl differs,
    # so the test above really compares something
    rec = demo_recording
    k = rec.stage_first_step()[1] + 5
    assert not np.array_equal(rec.controls[k], rec.controls[k - 1])
    data = mujoco.MjData(twin.model)
    twin.set_state(twin.model, data, rec.states[k])
    mujoco.mj_step(twin.model, data)
    assert not np.array_equal(twin.get_state(twin.model, data), rec.states[k + 1])


# ---------------------------------------------------------------------------
# the demo rollout
# ---------------------------------------------------------------------------

SUMMARY_KEYS = {"steps", "dt", "max_stage", "final_stage", "stage_first_step",
                "min_fos_contact", "min_fos_motor", "max_cost"}


def test_demo_rollout_completes(twin, demo_traj, demo_recording):
    rec = demo_recording
    assert rec.dt == twin.model.opt.timestep == 0.002
    n = int(round(demo_traj.n_steps / demo_traj.fps / rec.dt))
    assert rec.n_steps == n == 4000
    assert rec.states.shape == (n + 1, mujoco.mj_stateSize(twin.model, rollout_mod.STATE_SPEC))
    assert rec.sensordata.shape == (n, twin.nsensordata)
    assert rec.controls.shape == (n, twin.model.nu)
    assert rec.completed
    summary = rec.summary()
    assert SUMMARY_KEYS <= set(summary)
    json.dumps(summary)  # the CLI prints it as JSON
    assert summary["steps"] == 4000 and summary["dt"] == 0.002
    assert summary["max_stage"] == 4 and summary["final_stage"] == 4
    assert summary["completed"] is True
    assert set(summary["stage_first_step"]) == {"1", "2", "3", "4"}
    assert summary["stage_first_step"]["4"] == int(np.argmax(rec.stage == 4))
    # an elliptic friction cone never lets a contact's λt exceed μλn: FOS ≥ 1
    assert summary["min_fos_contact"] is not None
    assert summary["min_fos_contact"] >= 1.0 - 1e-6
    assert summary["min_fos_motor"] == float(rec.fos_motor.min())
    assert summary["min_fos_motor"] > 1.0  # the nominal motion stays within the URDF limits
    assert summary["max_cost"] == float(rec.cost.max())
    assert summary["limiting_actuator"] in twin.actuator_names


def test_demo_stage_sequence(demo_recording):
    rec = demo_recording
    first = rec.stage_first_step()
    # the picker grasps, lifts, then the receiver holds the cube off the table
    assert first[1] is not None and first[2] is not None and first[4] is not None
    assert first[1] < first[2] < first[4]
    assert not rec.contact_support[first[4]:].any()
    assert rec.contact_gripper[-1].tolist() == [True, False]  # left (receiver) only at the end


def test_stage_first_step_is_monotone(demo_recording):
    # BUG: stage_first_step() looks for stage == k, so a rollout that goes 2 -> 4 directly (the
    # receiver touches the cube only once it is off the table, as in the demo) reports stage 3
    # as never reached while stage 4 is. ACT's stages are cumulative (4 means the receiver
    # touches, which is stage 3's condition): the first step at which stage >= k is meant.
    first = demo_recording.stage_first_step()
    top = int(demo_recording.stage.max())
    reached = [first[k] for k in range(1, top + 1)]
    assert None not in reached, first
    assert reached == sorted(reached)


# ---------------------------------------------------------------------------
# task completion
# ---------------------------------------------------------------------------

DT = 0.002  # debounce 0.02 s = 10 steps


def _seq(*runs):
    return np.concatenate([np.full(n, s, dtype=np.int8) for s, n in runs])


@pytest.mark.parametrize("stages, expected", [
    (_seq((0, 100), (1, 50), (2, 50), (4, 300)), True),           # held to the end
    (_seq((0, 100), (2, 50), (4, 200), (0, 100)), False),          # dropped
    (_seq((0, 50), (4, 100), (3, 3), (4, 100)), True),             # 3-step flicker ignored
    (_seq((0, 50), (4, 100), (3, 10), (4, 100)), True),            # exactly the debounce
    (_seq((0, 50), (4, 100), (3, 11), (4, 100)), False),           # one step too long
    (_seq((0, 50), (4, 100), (3, 3), (4, 50), (3, 3), (4, 5)), True),  # two flickers
    (_seq((0, 50), (4, 100), (3, 3)), False),                      # ends below 4
    (_seq((0, 400)), False),                                       # never grasped
    (_seq((0, 100), (1, 100), (2, 200)), False),                   # lifted, never handed over
])
def test_task_completed_hand_made(stages, expected):
    assert bool(task_completed(stages, dt=DT)) is expected


def test_task_completed_batched_and_debounce_in_seconds():
    held = _seq((0, 100), (4, 300))
    flicker = _seq((0, 100), (4, 100), (0, 20), (4, 180))
    dropped = _seq((0, 100), (4, 100), (0, 200))
    out = task_completed(np.stack([held, flicker, dropped]), dt=DT)
    np.testing.assert_array_equal(out, [True, False, False])
    # a 0.05 s debounce forgives the 20-step (0.04 s) drop
    out = task_completed(np.stack([held, flicker, dropped]), dt=DT, debounce=0.05)
    np.testing.assert_array_equal(out, [True, True, False])
    assert task_completed(np.stack([held, flicker])[None], dt=DT).shape == (1, 2)


# ---------------------------------------------------------------------------
# save / load
# ---------------------------------------------------------------------------


def test_recording_save_load_round_trip(tmp_path, twin, demo_recording):
    rec = demo_recording
    path = rec.save(tmp_path / "rec.npz")
    back = Recording.load(path, twin)
    for name in ("states", "sensordata", "controls", "nominal"):
        assert np.array_equal(getattr(back, name), getattr(rec, name)), name
    for name in ("fos_contact", "fos_motor", "cost", "stage", "object_acc", "contact_gripper"):
        assert np.array_equal(getattr(back, name), getattr(rec, name)), name
    assert back.dt == rec.dt
    assert (back.parameter_names, back.gripper_names, back.actuator_names) == (
        rec.parameter_names, rec.gripper_names, rec.actuator_names)
    assert (back.scenario_name, back.model_sha256, back.source) == (
        rec.scenario_name, rec.model_sha256, rec.source)
    assert back.summary() == rec.summary()


def test_recording_load_errors(tmp_path, twin, demo_recording):
    with pytest.raises(InputFileError, match="recording not found"):
        Recording.load(tmp_path / "none.npz", twin)
    bad = tmp_path / "bad.npz"
    np.savez(bad, states=np.zeros(3))
    with pytest.raises(InputFileError, match="not a critmoment recording"):
        Recording.load(bad, twin)
    # a twin with one more support sensor: another scenario
    folder = tmp_path / "other"
    shutil.copytree(bundled_scenario_path().parent, folder)
    toml = folder / "scenario.toml"
    toml.write_text(toml.read_text().replace('geoms = ["table"]', 'geoms = ["table", "left/base"]'))
    other = Twin(load_scenario(folder))
    path = demo_recording.save(tmp_path / "rec.npz")
    with pytest.raises(InputFileError, match="recorded with another scenario"):
        Recording.load(path, other)


# ---------------------------------------------------------------------------
# batched simulation with parameters
# ---------------------------------------------------------------------------


def test_object_spawned_in_the_air_settles_before_the_clock_starts(twin):
    traj = Trajectory(np.tile(START, (2, 1)), fps=50, start=START,
                      object_pose=[0.1, 0.5, 0.3, 1, 0, 0, 0])
    state0 = rollout_mod.initial_state(twin, traj)
    data = twin.initial_data(start=START, object_pose=traj.object_pose, settle=False)
    twin.set_state(twin.model, data, state0)
    mujoco.mj_forward(twin.model, data)
    assert data.time == 0.0
    # the 4 cm cube rests on the table (top at z = 0), at rest, where it was dropped in x, y
    z = data.qpos[twin.object_qposadr + 2]
    assert z == pytest.approx(0.02, abs=2e-3)
    np.testing.assert_allclose(data.qpos[twin.object_qposadr:twin.object_qposadr + 2],
                               [0.1, 0.5], atol=5e-3)
    assert np.abs(data.qvel).max() == 0.0


def test_simulate_batched_masses_fall_at_g(twin):
    traj = Trajectory(np.tile(START, (2, 1)), fps=50, start=START,
                      object_pose=[0.1, 0.5, 0.3, 1, 0, 0, 0])
    # settle=False: keep the cube in the air (initial_state would let it settle first)
    data = twin.initial_data(start=START, object_pose=traj.object_pose, settle=False)
    state0 = twin.get_state(twin.model, data)
    controls = rollout_mod.prepare_controls(twin, traj)[:3]
    samples = np.array([[0.05, 1.0], [10.0, 1.0], [2.0, 0.3]])
    out = simulate(twin, state0, controls, samples=samples, record_state=True, nthread=1)
    assert out["sensordata"].shape == (3, 3, twin.nsensordata)
    assert out["state"].shape == (3, 3, state0.size)
    assert not out["diverged"].any()
    np.testing.assert_array_equal(out["diverged_step"], -1)
    acc = twin.signals(out["sensordata"]).object_acc
    np.testing.assert_allclose(acc, np.broadcast_to([0, 0, -G], (3, 3, 3)), rtol=0, atol=1e-9)
    np.testing.assert_allclose(out["time"], np.broadcast_to([0.002, 0.004, 0.006], (3, 3)),
                               rtol=1e-12)


def test_simulate_without_state_records_time(twin):
    # BUG: simulate(record_state=False) asks batch.rollout to record "time", which is not an
    # MjData *array* field: ValueError "time is not an MjData array field". Only the
    # record_state=True path (the frequent rollout) works.
    traj = _hold(2)
    state0 = rollout_mod.initial_state(twin, traj)
    controls = rollout_mod.prepare_controls(twin, traj)[:4]
    out = simulate(twin, state0, controls, samples=[[0.05, 1.0], [1.0, 0.5]], nthread=1)
    np.testing.assert_allclose(out["time"], [[0.002, 0.004, 0.006, 0.008]] * 2, rtol=1e-12)
    assert out["sensordata"].shape == (2, 4, twin.nsensordata)
    assert "state" not in out


def test_simulate_matches_a_serial_loop_on_a_written_model(twin):
    traj = _hold(6)
    state0 = rollout_mod.initial_state(twin, traj)
    controls = rollout_mod.prepare_controls(twin, traj)
    sample = np.array([[2.0, 0.3]])
    out = simulate(twin, state0, controls, samples=sample, record_state=True, nthread=1)
    model = twin.copy_model()
    twin.write_parameters(model, sample)
    data = mujoco.MjData(model)
    twin.set_state(model, data, state0)
    for k in range(len(controls)):
        data.ctrl[:] = controls[k]
        mujoco.mj_step(model, data)
        assert np.array_equal(data.sensordata, out["sensordata"][0, k]), k
    assert np.array_equal(twin.get_state(model, data), out["state"][0, -1])


# ---------------------------------------------------------------------------
# divergence
# ---------------------------------------------------------------------------


def test_nan_targets_rejected_by_trajectory():
    actions = np.tile(START, (10, 1))
    actions[4, 2] = np.nan
    with pytest.raises(TrajectoryError, match=r"expected finite values.*step\) 4, column \(channel\) 2"):
        Trajectory(actions, fps=50)


def _first_warning_step(model, state0, controls) -> int:
    """Reference: the physics step in whose mj_step MuJoCo first raises a warning."""
    data = mujoco.MjData(model)
    mujoco.mj_setState(model, data, state0, rollout_mod.STATE_SPEC)
    for k in range(len(controls)):
        data.ctrl[:] = controls[k]
        mujoco.mj_step(model, data)
        if any(w.number for w in data.warning):
            return k
    return -1


@pytest.fixture(scope="module")
def stiff_twin(tmp_path_factory):
    """The bundled scene with an absurd elbow gain (kp 3e5, no force limit): it diverges."""
    folder = tmp_path_factory.mktemp("stiff")
    shutil.copytree(bundled_scenario_path().parent, folder, dirs_exist_ok=True)
    arm = folder / "vx300s.xml"
    old = 'name="elbow" joint="elbow" kp="200" kv="6" forcerange="-15 15"'
    assert old in arm.read_text()
    arm.write_text(arm.read_text().replace(old, 'name="elbow" joint="elbow" kp="3e5" kv="6"'))
    return Twin(load_scenario(folder))


def test_rollout_raises_on_divergence_naming_the_step(stiff_twin):
    traj = _hold(20)
    controls = rollout_mod.prepare_controls(stiff_twin, traj)
    state0 = rollout_mod.initial_state(stiff_twin, traj)
    expected = _first_warning_step(stiff_twin.model, state0, controls)
    assert expected > 0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(SimulationDivergedError, match=rf"diverged at physics step {expected} "
                                                          r"\(t = .*mjWARN_BADQACC") as info:
            rollout(traj, twin=stiff_twin)
    assert info.value.step == expected


def test_simulate_nan_control_reports_the_step(twin):
    traj = _hold(20)
    controls = rollout_mod.prepare_controls(twin, traj).copy()
    controls[50, 3] = np.nan
    state0 = rollout_mod.initial_state(twin, traj)
    expected = _first_warning_step(twin.model, state0, controls)
    assert expected == 50
    out = simulate(twin, state0, controls, record_state=True, nthread=1)
    assert bool(out["diverged"][0])
    assert "mjWARN_BADCTRL" in out["warnings"][0]
    # BUG: reported as 51. The batch stops a simulation after the step whose warning counters
    # rose and repeats that step's record, so time[50] == time[51]; simulate() takes the first
    # repeat + 1. That is right only when MuJoCo reset the data (BADQACC: time drops at the
    # warning step) and one step late when it did not (BADCTRL: ctrl zeroed, step completes).
    assert int(out["diverged_step"][0]) == expected


def test_a_reused_batch_forgets_an_earlier_divergence(twin):
    """A batch reused for the next chunk of samples (batched_rollouts) keeps its
    simulations' warning counters; the simulation that takes a diverged one's slot must not
    be marked diverged (validate's brute force called such samples DIVERGED: 1–2 per 64 on
    a Panda + Robotiq 2F-85 with an elliptic cone)."""
    import mujoco.batch

    traj = _hold(20)
    state0 = rollout_mod.initial_state(twin, traj)
    controls = rollout_mod.prepare_controls(twin, traj).copy()
    bad = controls.copy()
    bad[50, 3] = np.nan
    batch = mujoco.batch.Batch(twin.model, 1, nthread=1)
    first = simulate(twin, state0, bad, samples=[[0.05, 1.0]], nthread=1, batch=batch)
    assert bool(first["diverged"][0])
    again = simulate(twin, state0, controls, samples=[[0.05, 1.0]], nthread=1, batch=batch)
    fresh = simulate(twin, state0, controls, samples=[[0.05, 1.0]], nthread=1)
    assert not bool(again["diverged"][0]) and int(again["diverged_step"][0]) == -1
    np.testing.assert_array_equal(again["sensordata"], fresh["sensordata"])


# ---------------------------------------------------------------------------
# bad inputs
# ---------------------------------------------------------------------------


def test_rollout_wrong_action_width(twin):
    traj = Trajectory(np.zeros((10, 13)), fps=50)
    with pytest.raises(TrajectoryError, match=r"expected 14 action values per step.*got 13"):
        rollout(traj, twin=twin)


def test_rollout_target_out_of_range(twin):
    actions = np.tile(START, (10, 1))
    actions[6, 9] = 2.0  # right/elbow range is [-1.76278, 1.6057]
    with pytest.raises(TrajectoryError, match=r"'right/elbow' \(index 9\) out of range at step "
                       r"6: value 2\.0.*set \[actions\] range_policy = 'clip' or 'warn' in "
                       r"the scenario"):
        rollout(Trajectory(actions, fps=50, start=START, object_pose=BOX), twin=twin)


def test_rollout_clip_policy_override(twin):
    actions = np.tile(START, (10, 1))
    actions[6, 9] = 2.0
    traj = Trajectory(actions, fps=50, start=START, object_pose=BOX)
    with pytest.warns(UserWarning, match=r"'right/elbow' \(index 9\): 1"):
        rec = rollout(traj, twin=twin, range_policy="clip")
    elbow = twin.actuator_names.index("right/elbow")
    assert rec.controls[:, elbow].max() <= 1.6057
    assert rec.controls[:, elbow].max() > 1.16  # the clipped target was still followed


def test_a_channel_is_checked_against_its_actuators_ctrlrange(tmp_path):
    """MuJoCo clamps a limited actuator's control to its ctrlrange, whatever drives it: a
    Shadow Hand's tendon finger commanded to 3.5 of its 0..3.1415 was clamped without a
    word, and the weaker fist dropped the ball (a joint channel was refused). A channel on
    a tendon actuator is checked against the ctrlrange, as a joint channel is against its
    joint's range."""
    from inline_models import arm_scenario_toml, arm_xml

    from critmoment import Twin, load_scenario

    (tmp_path / "arm.xml").write_text(arm_xml(gripper="tendon"))
    fingers = ('actuators = ["finger_a_act", "finger_b_act"]\nnormalised = true\n'
               'scales = [0.03, 0.03]\noffsets = [0.0, 0.0]')
    text = arm_scenario_toml()
    assert fingers in text
    (tmp_path / "scenario.toml").write_text(
        text.replace(fingers, 'actuators = ["fingers"]').replace(
            'convention = "explicit"', 'convention = "explicit"\nrange_policy = "error"'))
    twin = Twin(load_scenario(tmp_path))
    assert (twin.channel_lower[2], twin.channel_upper[2]) == (0.0, 255.0)
    actions = np.zeros((10, 3))
    actions[4:, 2] = 300.0
    with pytest.raises(TrajectoryError, match=r"out of range at step 4.*outside \[0\.0, 255\.0\]"):
        prepare_controls(twin, Trajectory(actions, fps=50))
    actions[4:, 2] = 255.0
    assert prepare_controls(twin, Trajectory(actions, fps=50))[-1, -1] == 255.0


def test_a_target_the_warn_policy_keeps_is_replayed_as_recorded(tmp_path):
    """ADROIT's vertical arm slide, commanded past its joint range so that its servo holds
    the 4.9 kg hand up (the MJCF's ctrlrange allows it): the ``warn`` policy said the value
    was kept, then the upsampler clipped it to the range, and the replayed hand never rose.
    The controls are the recorded targets; only the spline's overshoot between samples
    stays clipped (to the range, or to the recorded values beyond it)."""
    import math

    from inline_models import arm_scenario_toml, arm_xml

    from critmoment import Twin, load_scenario

    (tmp_path / "arm.xml").write_text(arm_xml())  # servos without a ctrlrange
    (tmp_path / "scenario.toml").write_text(arm_scenario_toml())
    twin = Twin(load_scenario(tmp_path))
    limit = math.radians(3.0)  # the shoulder's range, MJCF's default degrees
    assert twin.channel_upper[0] == pytest.approx(limit)
    actions = np.zeros((10, 3))
    actions[:, 2] = 1.0
    actions[4:, 0] = 0.08  # past the range: the servo pulls harder at the limit
    with pytest.warns(UserWarning, match=r"out of range|outside"):
        controls = prepare_controls(twin, Trajectory(actions, fps=50), range_policy="warn")
    shoulder = twin.actuator_names.index("shoulder_act")
    assert controls[-1, shoulder] == 0.08 and controls[:, shoulder].max() == pytest.approx(0.08)
    assert controls[:, shoulder].min() >= -limit - 1e-12  # the overshoot below stays clipped


def test_a_bad_range_policy_is_a_clear_error(twin):
    """``range_policy="ignore"`` raised KeyError 'IGNORE', ``5`` an AttributeError."""
    from critmoment.exceptions import ParameterError

    traj = Trajectory(np.tile(START, (10, 1)), fps=50, start=START, object_pose=BOX)
    for bad in ("ignore", 5):
        with pytest.raises(ParameterError, match=r"range_policy: expected one of error, clip, "
                                                 r"warn .*got " + repr(bad)):
            prepare_controls(twin, traj, range_policy=bad)
    assert prepare_controls(twin, traj, range_policy="WARN").shape[1] == twin.model.nu


def test_rollout_loads_the_scenario_itself():
    rec = rollout(_hold(5), "aloha_transfer_cube")
    assert rec.scenario_name == "aloha_transfer_cube" and rec.n_steps == 50
    assert rec.source == ""
    np.testing.assert_array_equal(rec.stage, 0)  # nobody touches the cube


def test_missing_trajectory_file(tmp_path):
    with pytest.raises(InputFileError, match="does not exist"):
        load_trajectory(tmp_path / "traj.npz")


def test_a_trajectory_faster_than_the_physics_says_so(twin, demo_traj):
    """A 1 kHz trajectory (a common real-robot control rate) on a 500 Hz model: an error
    naming both rates and the fix, not the upsampler's internal parameter."""
    fast = dataclasses.replace(demo_traj, fps=1000.0, source="ep.npz")
    with pytest.raises(TrajectoryError, match=r"trajectory at 1000 Hz \(ep.npz\): expected at "
                                              r"most the physics rate, 500 Hz .*keep one row "
                                              r"in 2"):
        prepare_controls(twin, fast)


def test_a_start_outside_its_joint_range_follows_the_range_policy(twin, demo_traj):
    """A start (the robot's first positions) far outside a channel's range, 50 rad on a
    ±π waist, a gripper at 7 on its normalised [0, 1]: an error that names the channel and
    the range under the default policy (it was taken, and later blamed on a weak motor), a
    warning under "warn", clipped under "clip"; a start 1 % past a gripper's end passes."""
    import dataclasses
    import warnings

    from critmoment.exceptions import CritmomentWarning, TrajectoryError
    from critmoment.recording import checked_start

    start = np.array(demo_traj.start if demo_traj.start is not None else demo_traj.actions[0],
                     dtype=float)
    far = start.copy()
    far[0], far[6] = 50.0, 7.0
    traj = dataclasses.replace(demo_traj, start=far)
    with pytest.raises(TrajectoryError, match=r"trajectory start.*2 value\(s\) outside their "
                       r"channel's range: left/waist = 50 \(range \[-3.1415\d, 3.1415\d\]\); "
                       r"left/gripper = 7 \(range \[0, 1\]\)"):
        checked_start(twin, traj)
    with pytest.warns(CritmomentWarning, match="outside their channel's range"):
        np.testing.assert_array_equal(checked_start(twin, traj, range_policy="warn"), far)
    with pytest.warns(CritmomentWarning, match="clipped into range"):
        clipped = checked_start(twin, traj, range_policy="clip")
    assert clipped[6] == 1.0 and clipped[0] == pytest.approx(twin.channel_upper[0])
    near = start.copy()
    near[6] = 1.01
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        checked_start(twin, dataclasses.replace(demo_traj, start=near))


def test_a_chunk_cut_mid_motion_starts_moving_with_qvel0(tmp_path):
    """An action chunk cut from a running episode carried qpos0 but no velocities: it
    started at rest, the arm was jolted to its targets' speed and a motor saturated at
    t = 0 (motor FOS 1.00, where the episode itself reads 2.57), which the causes then
    blamed. With qvel0 (npz key) the chunk starts moving as the episode did."""
    import dataclasses

    import mujoco

    import critmoment as cm
    from critmoment import panda_demo
    from critmoment.trajectory import load_trajectory, save_trajectory
    from critmoment.twin import state_slice

    traj = panda_demo.make_pick_place(0)
    twin = cm.Twin(cm.load_scenario("panda_pick_place"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        full = rollout(traj, twin=twin)
        i = 250  # 5.0 s, carrying
        k = int(round(i / traj.fps / twin.model.opt.timestep))
        state = np.asarray(full.states)[k]
        qpos = state[state_slice(twin.model, mujoco.mjtState.mjSTATE_QPOS)]
        qvel = state[state_slice(twin.model, mujoco.mjtState.mjSTATE_QVEL)]
        chunk = dataclasses.replace(traj, actions=traj.actions[i:], start=None, qpos0=qpos,
                                    object_pose=None)
        save_trajectory(dataclasses.replace(chunk, qvel0=qvel), tmp_path / "chunk.npz")
        moving = load_trajectory(tmp_path / "chunk.npz")
        np.testing.assert_array_equal(moving.qvel0, qvel)
        at_rest, in_motion = rollout(chunk, twin=twin), rollout(moving, twin=twin)
    episode = full.signals.fos_motor[k:k + 50].min()
    assert at_rest.signals.fos_motor[:50].min() < 1.05 < episode
    assert in_motion.signals.fos_motor[:50].min() == pytest.approx(episode, rel=0.05)
    with pytest.raises(TrajectoryError, match="qvel0: expected it with qpos0"):
        dataclasses.replace(moving, qpos0=None)


def test_a_library_rollout_that_diverges_writes_no_mujoco_log(stiff_twin, tmp_path, monkeypatch,
                                                              capfd):
    """The command line kept MuJoCo's log off; a library call (a service auditing in its own
    folder) left MUJOCO_LOG.TXT there and MuJoCo's warning on stderr. The settings are the
    process's: back as they were after the call, also with calls in several threads."""
    import threading

    import mujoco

    monkeypatch.chdir(tmp_path)
    before = mujoco.MjLogConfig.get()
    errors = []

    def one():
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                rollout(_hold(20), twin=stiff_twin)
        except SimulationDivergedError as exc:
            errors.append(exc)

    threads = [threading.Thread(target=one) for _ in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(errors) == 3
    assert not (tmp_path / "MUJOCO_LOG.TXT").exists()
    assert "Nan, Inf or huge value" not in capfd.readouterr().err
    after = mujoco.MjLogConfig.get()
    assert (after.logto_file, after.logto_console) == (before.logto_file, before.logto_console)


def test_an_object_thrown_faster_than_any_motion_is_a_divergence(twin):
    """A solver that does not converge can fling the object with no MuJoCo warning (a
    Panda with tolerance 0.01 and 3 line-search iterations launched its cube at 21 m/s,
    on to 245 km away; the audit said UNSAFE with invented causes, exit 1). An object
    faster than MAX_OBJECT_SPEED beyond what a fall from its highest point gives it is a
    diverged simulation, from the step it got there; a fast but slower one (here 5 m/s
    down) is not, nor is a fall through the world (the rollout's checks name that)."""
    traj = _hold(4)
    state0 = rollout_mod.initial_state(twin, traj)
    controls = rollout_mod.prepare_controls(twin, traj)[:4]
    model = twin.model
    dof = int(model.jnt_dofadr[model.body_jntadr[twin.object_body_id]])
    outs = []
    for vz in (-5.0, -40.0):
        state = state0.copy()
        state[1 + model.nq + dof + 2] = vz  # (time, qpos, qvel, ...): the free joint's vz
        outs.append(simulate(twin, state, controls, nthread=1))
    assert not outs[0]["diverged"][0]
    assert outs[1]["diverged"][0] and outs[1]["diverged_step"][0] == 0
    assert outs[1]["warnings"][0].startswith("the object reached 4")
    assert rollout_mod.MAX_OBJECT_SPEED == 10.0
