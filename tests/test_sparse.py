"""Tests of critmoment.sparse: physics of one restored step, exactness, sweeps, critical values.

Run with ``-s`` to see the critical values found on the demo (reported by the project).
"""

from __future__ import annotations

import dataclasses
import logging
import math
import warnings

import mujoco
import numpy as np
import pytest
from scenarios import one_actuator_toml

from critmoment import recording as rollout
from critmoment import sparse
from critmoment.exceptions import ParameterError, SimulationDivergedError
from critmoment.scenario import load_scenario
from critmoment.sparse import (
    Criterion,
    DivergencePolicy,
    FailSide,
    OthersAt,
    SparseEvaluator,
    SparseMode,
    SweepMethod,
    Term,
)
from critmoment.trajectory import Trajectory
from critmoment.twin import Twin

G = 9.81

# --------------------------------------------------------------------------
# a tiny scenario: a one-hinge "arm" with a pad, a table, and a free 4 cm box in the air
# --------------------------------------------------------------------------

TINY_MJCF = """
<mujoco model="tiny">
  <option timestep="0.002" gravity="0 0 -9.81"/>
  <worldbody>
    <geom name="table" type="plane" size="1 1 0.1"/>
    <body name="arm" pos="0 0 0.5">
      <joint name="hinge" type="hinge" axis="0 1 0"/>
      <geom name="link" type="capsule" fromto="0 0 0 0.2 0 0" size="0.02" mass="1"/>
      <geom name="pad" type="box" pos="0.2 0 0" size="0.01 0.02 0.02" mass="0.05"/>
    </body>
    <body name="box" pos="0.6 0 0.5">
      <freejoint/>
      <geom name="box" type="box" size="0.02 0.02 0.02" mass="0.05" priority="1"
            friction="1 0.005 0.0001"/>
    </body>
  </worldbody>
  <actuator>
    <position name="hinge" joint="hinge" kp="20" forcerange="-30 30"/>
  </actuator>
</mujoco>
"""

TINY_TOML = one_actuator_toml("tiny", mjcf="scene.xml", gripper="hand", gripper_geom="pad",
                              support="table", actuator="hinge", limit=5.0, task=True,
                              settle=False, uncertainty="""[uncertainty.mass]
body = "box"
range = [0.05, 10.0]
nominal = 0.05
[uncertainty.friction]
geom = "box"
range = [0.2, 1.5]
nominal = 1.0
""")

#: the same scene with the hinge's force range as the one uncertain parameter
LIMIT_TOML = TINY_TOML[:TINY_TOML.index("[uncertainty.mass]")] + """
[uncertainty.force_limit]
actuator = "hinge"
range = [1.0, 30.0]
nominal = 2.0
"""


def _make_twin(folder, toml: str) -> Twin:
    (folder / "scene.xml").write_text(TINY_MJCF)
    (folder / "scenario.toml").write_text(toml)
    return Twin(load_scenario(folder))


@pytest.fixture(scope="module")
def tiny(tmp_path_factory):
    """(twin, recording) of the tiny scenario: the box falls freely from rest."""
    twin = _make_twin(tmp_path_factory.mktemp("tiny"), TINY_TOML)
    recording = rollout.rollout(Trajectory(actions=np.zeros((2, 1)), fps=50.0), twin=twin)
    return twin, recording


@pytest.fixture(scope="module")
def pulling(tmp_path_factory):
    """(twin, recording) of the tiny scene whose hinge servo pulls 20 N·m, clamped to ±L."""
    twin = _make_twin(tmp_path_factory.mktemp("limit"), LIMIT_TOML)
    # start at q = 0 with the target at 1 rad: kp·(ctrl − q) = 20 N·m before clamping
    traj = Trajectory(actions=np.ones((2, 1)), fps=50.0, start=np.zeros(1))
    return twin, rollout.rollout(traj, twin=twin)


def _lift_step(recording) -> int:
    """First step of the last run into stage 2 (the picker holds the cube off the table) + 100."""
    two = recording.stage == 2
    starts = np.flatnonzero(two & ~np.concatenate([[False], two[:-1]]))
    assert starts.size, "the demo never lifts the cube"
    return int(starts[-1]) + 100


def _handover_step(recording) -> int:
    """First stage-4 step (the receiver holds the cube off the table) + 300."""
    first = recording.stage_first_step()[4]
    assert first is not None, "the demo never hands the cube over"
    return int(first) + 300


def _mass_samples(scenario, masses):
    samples = np.tile(scenario.box.nominal, (len(masses), 1))
    samples[:, scenario.box.index("mass")] = masses
    return samples


# --------------------------------------------------------------------------
# physics of one restored step
# --------------------------------------------------------------------------


def test_free_fall_acceleration_is_g_for_every_mass(tiny):
    twin, recording = tiny
    masses = np.geomspace(0.05, 10.0, 9)
    res = sparse.evaluate(recording, twin, [0], _mass_samples(twin.scenario, masses))
    # Without set_const after writing body_mass the derived constants keep the 0.05 kg
    # box's values, and the same step gives a_z = -9.81 * m / 0.05: -1962 m/s² at 10 kg.
    np.testing.assert_allclose(res.object_acc[0], np.tile([0.0, 0.0, -G], (9, 1)), atol=1e-9)
    assert not res.contact_gripper.any() and not res.contact_support.any()
    assert np.isinf(res.fos_grasp).all()  # nobody carries it in the nominal run


def test_held_box_heavier_mass_lowers_grip_fos_and_raises_arm_torque(scenario, twin,
                                                                      demo_recording):
    step = _lift_step(demo_recording)
    picker = scenario.gripper_names.index(scenario.task.picker)
    masses = np.array([0.05, 0.1, 0.2, 0.3, 0.5, 0.8, 1.0])
    samples = _mass_samples(scenario, masses)
    one = sparse.evaluate(demo_recording, twin, [step], samples, horizon=1)
    assert one.contact_gripper[0, :, picker].all() and not one.contact_support[0].any()
    assert (np.diff(one.fos_contact[0, :, picker]) < 0).all()
    # position servos: the force of the restored step is a function of the state alone
    np.testing.assert_array_equal(one.actuator_norm[0], np.tile(one.actuator_norm[0, :1],
                                                                (len(masses), 1)))
    # over a few steps the arm sags and the servos answer the load
    ten = sparse.evaluate(demo_recording, twin, [step], samples, horizon=10)
    for joint in ("shoulder", "elbow"):
        a = twin.actuator_names.index(f"{scenario.task.picker}/{joint}")
        load = np.abs(ten.actuator_norm[0, :, a])
        assert (np.diff(load) > 0).all(), (joint, load)
    assert (np.diff(ten.fos_motor[0]) < 0).all()


def test_object_friction_below_the_fingers_lowers_contact_friction(scenario, twin,
                                                                    demo_recording):
    step = _lift_step(demo_recording)
    obj = twin.object_geom_id
    pads = [twin.model.geom(g).id for g in scenario.grippers[1].geoms]
    low = 0.3
    assert (twin.model.geom_friction[pads, 0] > low).all()  # max-mixing would keep theirs
    for mu in (low, scenario.box.nominal[scenario.box.index("friction")]):
        model = twin.copy_model()
        values = scenario.box.nominal.copy()
        values[scenario.box.index("friction")] = mu
        twin.write_parameters(model, values[None])
        data = mujoco.MjData(model)
        twin.set_state(model, data, demo_recording.states[step])
        mujoco.mj_forward(model, data)
        contacts = data.contact
        mine = (contacts.geom[:, 0] == obj) | (contacts.geom[:, 1] == obj)
        assert mine.sum() >= 2
        np.testing.assert_array_equal(contacts.friction[mine, :2], mu)


# --------------------------------------------------------------------------
# exactness
# --------------------------------------------------------------------------


@pytest.mark.parametrize("horizon", [1, 3])
def test_batch_equals_serial_restore_and_step_bit_for_bit(scenario, twin, demo_recording,
                                                          horizon):
    steps = [_lift_step(demo_recording), _handover_step(demo_recording)]
    samples = sparse.sweep_samples(scenario.box, n=8, seed=3)
    res = sparse.evaluate(demo_recording, twin, steps, samples, horizon=horizon, nthread=2,
                          keep_raw=True)
    for j, values in enumerate(samples):
        model = twin.copy_model()
        twin.write_parameters(model, values[None])
        data = mujoco.MjData(model)
        for i, k in enumerate(steps):
            twin.set_state(model, data, demo_recording.states[k])
            for t in range(horizon):
                data.ctrl[:] = demo_recording.controls[k + t]
                mujoco.mj_step(model, data)
                assert np.array_equal(data.sensordata, res.sensordata[i, j, t])
            assert np.array_equal(twin.get_state(model, data), res.state[i, j])


def test_nominal_step_reproduces_the_recording(scenario, twin, demo_recording):
    rec = demo_recording
    steps = [0, _lift_step(rec), _handover_step(rec), rec.n_steps - 1]
    res = sparse.evaluate(rec, twin, steps, scenario.box.nominal[None], keep_raw=True, horizon=1)
    for i, k in enumerate(steps):
        assert np.array_equal(res.sensordata[i, 0, 0], rec.sensordata[k])
        assert np.array_equal(res.state[i, 0], rec.states[k + 1])
    np.testing.assert_allclose(res.cost[:, 0], rec.cost[steps], rtol=1e-12, atol=1e-15)
    np.testing.assert_array_equal(res.fos_motor[:, 0], rec.fos_motor[steps])


def test_solve_mode_equals_one_step(scenario, twin, demo_recording):
    steps = [_lift_step(demo_recording), _handover_step(demo_recording)]
    samples = sparse.sweep_samples(scenario.box, n=16, seed=1)
    step = sparse.evaluate(demo_recording, twin, steps, samples, mode=SparseMode.STEP, horizon=1)
    solve = sparse.evaluate(demo_recording, twin, steps, samples, mode=SparseMode.SOLVE,
                            horizon=1)
    for field in ("cost", "fos_contact", "fos_grasp", "fos_motor", "object_acc",
                  "actuator_norm", "contact_gripper"):
        assert np.array_equal(getattr(step, field), getattr(solve, field)), field


def test_chunks_and_threads_do_not_change_results(scenario, twin, demo_recording):
    steps = [_lift_step(demo_recording)]
    samples = sparse.sweep_samples(scenario.box, n=13, seed=2)
    whole = sparse.evaluate(demo_recording, twin, steps, samples, nthread=1, keep_raw=True)
    chunked = SparseEvaluator(demo_recording, twin, nthread=2, chunk=4)
    for _ in range(2):  # the second call reuses the batches and their parameters
        parts = chunked.evaluate(steps, samples, keep_raw=True)
        assert np.array_equal(whole.sensordata, parts.sensordata)
        assert np.array_equal(whole.state, parts.state)
        # NumPy may round a reduction over one row differently from one over many
        np.testing.assert_allclose(parts.cost, whole.cost, rtol=1e-14)
        np.testing.assert_array_equal(parts.motor_argmax, whole.motor_argmax)


def test_horizon_reduces_to_the_worst_step(scenario, twin, demo_recording):
    k = _handover_step(demo_recording)
    samples = _mass_samples(scenario, [0.05, 1.0, 5.0])
    res = sparse.evaluate(demo_recording, twin, [k], samples, horizon=4, keep_raw=True)
    mu = scenario.box.nominal[scenario.box.index("friction")]
    per_step = twin.signals(res.sensordata[0], mu=mu)  # (n, h)
    np.testing.assert_array_equal(res.cost[0], per_step.cost.max(axis=1))
    np.testing.assert_array_equal(res.fos_motor[0], per_step.fos_motor.min(axis=1))
    np.testing.assert_array_equal(res.fos_contact[0], per_step.fos_contact.min(axis=1))
    np.testing.assert_array_equal(res.worst_step[0], per_step.cost.argmax(axis=1))
    np.testing.assert_allclose(res.cost_contact[0] + res.cost_motor[0], res.cost[0], rtol=1e-12)


def test_divergence_is_marked_or_raised(tiny):
    twin, recording = tiny
    states = recording.states.copy()
    states[0, 1 + twin.model.nq] = 1e12  # a huge hinge velocity: MuJoCo warns and resets
    bad = dataclasses.replace(recording, states=states)
    samples = _mass_samples(twin.scenario, [0.05, 1.0])
    res = sparse.evaluate(bad, twin, [0, 1], samples)
    assert res.diverged[0].all() and not res.diverged[1].any()
    assert np.isinf(res.cost[0]).all() and res.failed[0].all()
    assert (res.dominant[0] == Term.DIVERGED).all()
    assert np.isnan(res.fos_motor[0]).all()
    with pytest.raises(SimulationDivergedError, match=r"moment step 0 .*sample 0 .*BADQVEL"):
        sparse.evaluate(bad, twin, [1, 0], samples, divergence=DivergencePolicy.RAISE)


# --------------------------------------------------------------------------
# the demo: sweeps, critical values, probability of success
# --------------------------------------------------------------------------


def test_liftoff_mass_sweep_and_critical_mass(scenario, twin, demo_recording):
    lift = _lift_step(demo_recording)
    picker = scenario.gripper_names.index(scenario.task.picker)
    masses = np.linspace(0.05, 10.0, 41)
    res = sparse.evaluate(demo_recording, twin, [lift], _mass_samples(scenario, masses),
                          horizon=1)
    fos = res.fos_contact[0, :, picker]
    assert fos[0] > 5 and fos[-1] < 1.01 and (fos >= 1 - 1e-9).all()
    assert (np.diff(fos) <= 1e-9).all()
    assert (res.dominant[0][res.failed[0]] == Term.CONTACT).all()

    cvs = sparse.critical_values(demo_recording, twin, [lift], rtol=1e-3, horizon=1)
    by = {(cv.parameter, cv.others_at): cv for cv in cvs}
    crit = by["mass", OthersAt.NOMINAL]
    assert crit.value is not None and 0.05 < crit.value < 10.0
    assert crit.direction == FailSide.ABOVE and crit.dominant is Term.CONTACT
    lo, hi = crit.bracket
    assert hi - lo <= 1e-3 * crit.value and lo <= crit.value <= hi
    # the refined value separates passing from failing masses
    check = sparse.evaluate(demo_recording, twin, [lift],
                            _mass_samples(scenario, [0.99 * crit.value, 1.01 * crit.value]),
                            horizon=1)
    assert check.failed[0].tolist() == [False, True]
    # with the others at the worst corner (lowest friction) the cube slips at a lower mass
    worst = by["mass", OthersAt.WORST]
    assert worst.others["friction"] == scenario.box.low[scenario.box.index("friction")]
    assert worst.value is not None and worst.value < crit.value
    print(f"\nlift-off, step {lift}, horizon 1:")
    for cv in cvs:
        print("  ", _describe(cv))


def test_handover_motor_fos_falls_with_mass_and_critical_values(scenario, twin,
                                                                  demo_recording):
    hand = _handover_step(demo_recording)
    receiver = scenario.gripper_names.index(scenario.task.receiver)
    masses = np.array([0.05, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0])
    samples = _mass_samples(scenario, masses)
    one = sparse.evaluate(demo_recording, twin, [hand], samples, horizon=1)
    assert one.contact_gripper[0, :, receiver].all() and not one.contact_support[0].any()
    assert np.ptp(one.fos_motor[0]) == 0  # explicit servos: no answer to the load in one step
    ten = sparse.evaluate(demo_recording, twin, [hand], samples, horizon=10)
    assert (np.diff(ten.fos_motor[0]) < 0).all()

    lift = _lift_step(demo_recording)
    engine = SparseEvaluator(demo_recording, twin, horizon=10)
    cvs = sparse.critical_values(demo_recording, twin, [lift, hand], evaluator=engine,
                                 others=(OthersAt.NOMINAL,))
    assert len(cvs) == 2 * scenario.box.ndim
    handover_mass = next(cv for cv in cvs if cv.step == hand and cv.parameter == "mass")
    assert handover_mass.value is not None and handover_mass.direction == FailSide.ABOVE
    print(f"\nhorizon 10, others nominal (lift-off step {lift}, hand-over step {hand}):")
    for cv in cvs:
        print("  ", _describe(cv))
    one_cvs = sparse.critical_values(demo_recording, twin, [hand], others=(OthersAt.NOMINAL,))
    print(f"hand-over step {hand}, horizon 1:")
    for cv in one_cvs:
        print("  ", _describe(cv))


def test_critical_force_limit_has_the_closed_form_value(pulling):
    twin, recording = pulling
    cost = twin.scenario.cost
    # |τ| = L (clamped) gives FOS_motor = 5 N·m / L; no contact, so C = B·exp(−β(5/L − 1))
    # crosses the threshold at L* = 5 / (1 + ln(B / threshold) / β)
    exact = 5.0 / (1.0 + math.log(cost.B / cost.threshold) / cost.beta)
    res = sparse.evaluate(recording, twin, [0], [[0.5 * exact], [2 * exact]])
    np.testing.assert_allclose(res.fos_motor[0], [2 * 5 / exact, 0.5 * 5 / exact], rtol=1e-12)
    # a motor excursion counts once it lasts the ground truth's saturation time; here the
    # cost's crossing itself is tested, as one step decides it
    engine = SparseEvaluator(recording, twin)
    engine.motor_steps = 1
    (cv,) = sparse.critical_values(recording, twin, [0], rtol=1e-4, others=[OthersAt.NOMINAL],
                                   evaluator=engine)
    assert cv.parameter == "force_limit" and cv.others == {}
    assert cv.value == pytest.approx(exact, rel=1e-4)
    assert cv.direction == FailSide.ABOVE and cv.dominant is Term.MOTOR
    # under the uniform prior on [1, 30] N·m the motion succeeds with P = (L* − 1) / 29;
    # 256 Sobol points put one point in each 1/256 of the range
    ps = sparse.probability_of_success(recording, twin, [0], n=256, seed=5, evaluator=engine)
    assert abs(ps.p - (exact - 1.0) / 29.0) <= 1 / 256
    assert ps.dominant is Term.MOTOR and ps.dominant_actuator == "hinge"
    # with the default decision, 20 N·m over the 5 N·m rating that falls under the threshold
    # within 40 ms (the joint reaching its target) is no motor failure, 10 N·m held to the
    # recording's end is
    brief = SparseEvaluator(recording, twin).evaluate([0], [[10.0], [20.0]])
    assert (brief.cost[0] > cost.threshold).all()
    assert brief.failure[0].tolist() == [sparse.Failure.MOTOR, sparse.Failure.PASS]


def _describe(cv: sparse.CriticalValue) -> str:
    others = ", ".join(f"{k} = {v:g}" for k, v in cv.others.items())
    if cv.value is None:
        verdict = "fails everywhere" if cv.fails_everywhere else "never crosses"
        return f"{cv.parameter:8s} ({cv.others_at.value:7s}: {others}): {verdict}"
    return (f"{cv.parameter:8s} ({cv.others_at.value:7s}: {others}): {cv.value:.4f}, fails "
            f"{cv.direction.value}, {cv.dominant.name.lower()} dominates")


def test_fos_criteria(scenario, twin, demo_recording):
    lift = _lift_step(demo_recording)
    res = sparse.sweep(demo_recording, twin, [lift], n=64, seed=4)
    np.testing.assert_array_equal(res.fails(), res.failed)
    np.testing.assert_array_equal(res.fails(Criterion.CONTACT, limit=1.2), res.fos_grasp < 1.2)
    np.testing.assert_array_equal(res.fails("motor", limit=7.0), res.fos_motor < 7.0)
    cvs = sparse.critical_values(demo_recording, twin, [lift], criterion=Criterion.CONTACT,
                                 others=(OthersAt.NOMINAL,))
    mass = next(cv for cv in cvs if cv.parameter == "mass")
    assert mass.criterion is Criterion.CONTACT and mass.limit == sparse.FOS_LIMIT
    assert mass.value is not None and mass.direction == FailSide.ABOVE


def test_probability_of_success(scenario, twin, demo_recording):
    steps = [_lift_step(demo_recording), _handover_step(demo_recording)]
    ps = sparse.probability_of_success(demo_recording, twin, steps, n=64, seed=0)
    fail = ps.result.failed.any(axis=0)
    assert ps.n == 64 and ps.n_fail == int(fail.sum())
    assert ps.p == pytest.approx(1 - fail.mean())
    assert ps.interval[0] <= ps.p <= ps.interval[1]
    assert ps.interval == sparse.wilson_interval(ps.n - ps.n_fail, ps.n)
    assert 0 < ps.n_fail < ps.n  # heavy, slippery cubes slip at lift-off; light ones hold
    assert ps.dominant is Term.CONTACT and sum(ps.term_counts.values()) == ps.n_fail
    again = sparse.probability_of_success(demo_recording, twin, steps, n=64, seed=0)
    assert again.p == ps.p


# --------------------------------------------------------------------------
# statistics, sampling, validation
# --------------------------------------------------------------------------


@pytest.mark.parametrize("successes, n, expected", [
    (8, 10, (0.4901625, 0.9433178)),
    (0, 10, (0.0, 0.2775328)),
    (10, 10, (0.7224672, 1.0)),
    (50, 100, (0.4038315, 0.5961685)),
])
def test_wilson_interval_known_values(successes, n, expected):
    assert sparse.wilson_interval(successes, n) == pytest.approx(expected, abs=1e-6)


def test_wilson_interval_narrows_with_confidence_and_n():
    lo90, hi90 = sparse.wilson_interval(30, 40, confidence=0.9)
    lo99, hi99 = sparse.wilson_interval(30, 40, confidence=0.99)
    assert lo99 < lo90 < 0.75 < hi90 < hi99
    lo, hi = sparse.wilson_interval(300, 400)
    assert hi - lo < hi90 - lo90
    with pytest.raises(ParameterError, match="n: expected an integer >= 1, got 0"):
        sparse.wilson_interval(0, 0)
    with pytest.raises(ParameterError, match="expected at most n = 4, got 5"):
        sparse.wilson_interval(5, 4)
    with pytest.raises(ParameterError, match=r"confidence: expected a number in \(0, 1\)"):
        sparse.wilson_interval(1, 4, confidence=95)


def test_sobol_and_grid_samples(scenario):
    box = scenario.box
    a = sparse.sweep_samples(box, n=128, seed=7)
    b = sparse.sweep_samples(box, n=128, seed=7)
    c = sparse.sweep_samples(box, n=128, seed=8)
    assert a.shape == (128, 2) and np.array_equal(a, b) and not np.array_equal(a, c)
    for bad in (-1, 1.5, "7", True):
        with pytest.raises(ParameterError, match=r"seed: expected an integer >= 0"):
            sparse.sweep_samples(box, n=8, seed=bad)
    assert (a >= box.low).all() and (a <= box.high).all()
    # balanced: every eighth of each range holds exactly 1/8 of the points
    counts = [np.histogram(box.to_unit(a)[:, j], bins=8, range=(0, 1))[0] for j in range(2)]
    assert (np.array(counts) == 16).all()
    grid = sparse.sweep_samples(box, n=25, method=SweepMethod.GRID)
    assert grid.shape == (25, 2)
    assert set(grid[:, 0]) == set(np.linspace(box.low[0], box.high[0], 5))
    assert sparse.sweep_samples(box, n=100, method="sobol", seed=1).shape == (100, 2)


def test_bad_inputs_raise_parameter_error(scenario, twin, demo_recording):
    engine = SparseEvaluator(demo_recording, twin, horizon=1)
    nominal = scenario.box.nominal
    t = demo_recording.n_steps
    with pytest.raises(ParameterError,
                       match=r"expected samples of shape \(n, 2\).*got shape \(4, 3\)"):
        engine.evaluate([10], np.ones((4, 3)))
    with pytest.raises(ParameterError, match=r"'mass': expected finite .* got \[nan\]"):
        engine.evaluate([10], [[math.nan, 1.0]])
    with pytest.raises(ParameterError, match=r"'mass': expected finite .* got \[-1.0\]"):
        engine.evaluate([10], [[-1.0, 1.0]])
    with pytest.raises(ParameterError,
                       match=rf"steps: expected physics steps in \[0, {t - 1}\].*got \[{t}\]"):
        engine.evaluate([t], nominal[None])
    with pytest.raises(ParameterError, match=r"got \[-1\]"):
        engine.evaluate([5, -1], nominal[None])
    with pytest.raises(ParameterError, match=rf"in \[0, {t - 5}\].*horizon 5"):
        SparseEvaluator(demo_recording, twin, horizon=5).evaluate([t - 3], nominal[None])
    with pytest.raises(ParameterError, match="expected integer step indices"):
        engine.evaluate([1.5], nominal[None])
    with pytest.raises(ParameterError, match="non-empty 1-D"):
        engine.evaluate([], nominal[None])
    with pytest.raises(ParameterError, match="at least one row"):
        engine.evaluate([10], np.empty((0, 2)))
    with pytest.raises(ParameterError, match="mode SOLVE .* expected horizon 1, got 3"):
        SparseEvaluator(demo_recording, twin, horizon=3, mode=SparseMode.SOLVE)
    with pytest.raises(ParameterError, match="horizon: expected an integer >= 1, got 0"):
        SparseEvaluator(demo_recording, twin, horizon=0)
    with pytest.raises(ParameterError, match=r"mode: expected one of \['step', 'solve'\]"):
        SparseEvaluator(demo_recording, twin, mode="fast")
    with pytest.raises(ParameterError, match="n_grid: expected an integer >= 2, got 1"):
        sparse.critical_values(demo_recording, twin, [10], n_grid=1, evaluator=engine)
    with pytest.raises(ParameterError, match="limit: expected a finite number"):
        sparse.critical_values(demo_recording, twin, [10], limit=math.inf, evaluator=engine)


def test_recording_of_another_scenario_is_rejected(tiny, twin):
    _, tiny_recording = tiny
    with pytest.raises(ParameterError, match=r"recording.states: expected shape \(T \+ 1, \d+\)"):
        SparseEvaluator(tiny_recording, twin)


def test_public_names_exist():
    for name in sparse.__all__:
        assert hasattr(sparse, name), name


# --------------------------------------------------------------------------
# first-failure evaluation (the audit's sweep)
# --------------------------------------------------------------------------


@pytest.mark.parametrize("horizon", [1, 5])
def test_first_failure_stops_each_sample_where_the_full_evaluation_first_fails(
        scenario, twin, demo_recording, horizon):
    lift, hand = _lift_step(demo_recording), _handover_step(demo_recording)
    steps = [hand, lift - 200, lift]  # out of time order on purpose
    samples = sparse.sweep_samples(scenario.box, n=64, seed=3)
    full = sparse.evaluate(demo_recording, twin, steps, samples, horizon=horizon)
    ff = sparse.evaluate(demo_recording, twin, steps, samples, horizon=horizon,
                         first_failure=True)
    assert full.evaluated is None and ff.evaluated.shape == (3, 64)
    assert 0 < full.failed_any.sum() < 64  # the box holds passing and failing samples
    np.testing.assert_array_equal(ff.failed_any, full.failed_any)
    time_order = np.argsort(steps)
    failed_before = np.cumsum(full.failed[time_order], axis=0) - full.failed[time_order]
    reached = np.empty_like(ff.evaluated)
    reached[time_order] = failed_before == 0
    np.testing.assert_array_equal(ff.evaluated, reached)
    # a pair that passes ran its whole horizon: identical to the full evaluation
    passed = ff.evaluated & ~ff.failed
    for name in ("cost", "fos_grasp", "fos_motor", "fos_contact", "object_acc",
                 "actuator_norm", "stage", "worst_step", "motor_argmax"):
        np.testing.assert_array_equal(getattr(ff, name)[passed], getattr(full, name)[passed],
                                      err_msg=name)
    # a pair that fails stopped at its first failing step: a cost above the threshold, at
    # most the full horizon's
    stopped = ff.evaluated & ff.failed
    np.testing.assert_array_equal(stopped, ff.evaluated & full.failed)
    np.testing.assert_array_equal(ff.failure[stopped], full.failure[stopped])
    by_cost = stopped & np.isin(ff.failure, [sparse.Failure.MOTOR, sparse.Failure.CONTACT])
    assert by_cost.any()
    assert (ff.cost[by_cost] > scenario.cost.threshold).all()
    assert (ff.cost[stopped] <= full.cost[stopped]).all()
    # the rest was not evaluated
    skipped = ~ff.evaluated
    assert skipped.any()
    assert np.isnan(ff.cost[skipped]).all() and (ff.stage[skipped] == -1).all()
    assert not ff.failed[skipped].any() and not ff.diverged[skipped].any()
    np.testing.assert_array_equal(ff.worst_cost()[~full.failed_any],
                                  full.worst_cost()[~full.failed_any])


def test_first_failure_solve_mode_equals_one_step(scenario, twin, demo_recording):
    steps = [_lift_step(demo_recording), _handover_step(demo_recording)]
    samples = sparse.sweep_samples(scenario.box, n=32, seed=4)
    step = sparse.evaluate(demo_recording, twin, steps, samples, horizon=1, first_failure=True)
    solve = sparse.evaluate(demo_recording, twin, steps, samples, horizon=1,
                            mode=SparseMode.SOLVE, first_failure=True)
    np.testing.assert_array_equal(step.evaluated, solve.evaluated)
    np.testing.assert_array_equal(step.cost, solve.cost)


def test_first_failure_skips_the_moments_after_a_divergence(tiny):
    twin, recording = tiny
    states = recording.states.copy()
    states[0, 1 + twin.model.nq] = 1e12
    bad = dataclasses.replace(recording, states=states)
    samples = _mass_samples(twin.scenario, [0.05, 1.0])
    res = sparse.evaluate(bad, twin, [1, 0], samples, first_failure=True)
    assert res.diverged[1].all() and np.isinf(res.cost[1]).all()
    assert not res.evaluated[0].any() and res.failed_any.all()


def test_unlifted_failures_are_marked_and_do_not_stop_a_sample(twin, scenario):
    """`fast` squeezes the cube off the table (it barely rises) before lifting it."""
    from critmoment import analysis, suite

    rec = rollout.rollout(suite.make("fast", seed=0, twin=twin), twin=twin)
    # every excursion counts at once: the squeeze's short excursions fail too
    engine = SparseEvaluator(rec, twin, persistence=0.0)
    squeeze = np.flatnonzero(engine._carried & ~engine._lifted)
    assert squeeze.size and not (engine._lifted & ~engine._carried).any()
    _, steps = analysis.audit_moments(rec, twin, engine, 8)
    assert np.isin(steps, squeeze).any()
    box = scenario.box.with_range("mass", 0.05, 1.5)
    samples = sparse.sweep_samples(box, n=32, seed=0)
    full = engine.evaluate(steps, samples)
    ff = engine.evaluate(steps, samples, first_failure=True)
    assert full.unlifted_failure.any() and full.failed_unlifted_only.any()
    assert (full.cost[full.unlifted_failure] > scenario.cost.threshold).all()
    np.testing.assert_array_equal(ff.failed_any, full.failed_any)
    np.testing.assert_array_equal(ff.failed_unlifted_only, full.failed_unlifted_only)
    # a sample whose only failures are unlifted ones is evaluated at every moment
    assert ff.evaluated[:, ff.failed_unlifted_only].all()


# --------------------------------------------------------------------------
# the decision: persistence of contact excursions, measured slip, creep horizon
# --------------------------------------------------------------------------


def test_without_persistence_and_slip_the_decision_is_the_cost(scenario, twin, demo_recording):
    steps = [_lift_step(demo_recording), _handover_step(demo_recording)]
    samples = sparse.sweep_samples(scenario.box, n=64, seed=5)
    res = sparse.evaluate(demo_recording, twin, steps, samples, horizon=5)
    engine = SparseEvaluator(demo_recording, twin, horizon=5, persistence=0.0,
                             slip_tolerance=math.inf)
    plain = engine.evaluate(steps, samples)
    expected = (plain.cost > scenario.cost.threshold) | plain.diverged
    np.testing.assert_array_equal(plain.failed, expected)
    assert 0 < expected.sum() < expected.size
    # the values do not depend on the decision
    np.testing.assert_array_equal(plain.cost, res.cost)
    np.testing.assert_array_equal(plain.fos_grasp, res.fos_grasp)
    # with persistence a failure is a subset: motor at once, contact once it lasts
    assert not (res.failed & ~plain.failed & (res.failure != sparse.Failure.SLIP)).any()
    contact = res.failure == sparse.Failure.CONTACT
    assert (res.excursion[contact] >= res.settings.persistence - 1e-12).all()
    brief = (plain.failure == sparse.Failure.CONTACT) & (res.failure == sparse.Failure.PASS)
    assert (res.excursion[brief] < res.settings.persistence).all()


def test_nominal_parameters_do_not_slip(scenario, twin, demo_recording):
    steps = [_lift_step(demo_recording), _handover_step(demo_recording) - 250]
    res = sparse.evaluate(demo_recording, twin, steps, scenario.box.nominal[None], horizon=20)
    # the restored run is the nominal run, bit for bit: no displacement in the grip
    np.testing.assert_array_equal(res.slip, 0.0)
    heavy = sparse.evaluate(demo_recording, twin, steps, _mass_samples(scenario, [1.0]),
                            horizon=20)
    # the picker holds the cube alone at lift-off: the heavier cube moves in its grip
    assert heavy.slip[0, 0] > 1e-6


def test_settings_come_from_the_arguments_else_the_scenario_else_the_defaults(twin,
                                                                                demo_recording):
    engine = SparseEvaluator(demo_recording, twin)
    table = getattr(twin.scenario, "sparse", None)
    assert engine.settings.persistence == getattr(table, "persistence",
                                                  sparse.DEFAULT_PERSISTENCE)
    assert engine.persistence_steps == max(1, round(engine.settings.persistence / 0.002))
    mine = SparseEvaluator(demo_recording, twin, persistence=0.05, slip_tolerance=0.01,
                           creep_horizon=30)
    assert mine.settings == sparse.DecisionSettings(0.05, 0.01, 30)
    assert mine.persistence_steps == 25
    with pytest.raises(ParameterError, match="persistence"):
        sparse.DecisionSettings(persistence=-1.0)
    with pytest.raises(ParameterError, match="slip_tolerance"):
        sparse.DecisionSettings(slip_tolerance=0.0)
    with pytest.raises(ParameterError, match="creep_horizon"):
        sparse.DecisionSettings(creep_horizon=-2)


def test_creep_horizon_fails_a_creeping_grip_the_force_ratio_passes(tmp_path, scenario,
                                                                      demo_traj):
    """A soft contact model (pyramidal cone, impratio 1): a 0.6 kg cube held with a force
    ratio of about 2 creeps; over the creep horizon its measured slip fails it."""
    from scenarios import soft_copy

    from critmoment import contactmodel

    soft = Twin(load_scenario(soft_copy(scenario, tmp_path / "soft")))
    rec = rollout.rollout(demo_traj, twin=soft)
    with pytest.warns(contactmodel.ContactModelWarning, match="creeps"):
        report = contactmodel.check_contact_model(soft, rec)
    assert report.soft and report.creep_horizon > soft.scenario.horizon
    held = rec.signals.contact_gripper[:, 1] & ~rec.signals.contact_support
    k = int(np.flatnonzero(held)[200])
    samples = _mass_samples(soft.scenario, [0.05, 0.6])
    one_step = sparse.evaluate(rec, soft, [k], samples)
    creep = SparseEvaluator(rec, soft, creep_horizon=report.creep_horizon).evaluate([k],
                                                                                   samples)
    assert one_step.fos_grasp[0, 1] > 1.8  # the force ratio calls the grip safe
    assert not one_step.failed.any()
    assert creep.failure[0, 1] == sparse.Failure.SLIP and creep.slip[0, 1] > 0.005
    assert creep.failure[0, 0] == sparse.Failure.PASS and creep.slip[0, 0] == 0.0


@pytest.mark.parametrize("persistence", [0.0, 0.004])
def test_first_failure_in_blocks_of_the_persistence_agrees_with_full_evaluation(
        scenario, twin, demo_recording, persistence):
    steps = [_handover_step(demo_recording), _lift_step(demo_recording)]
    samples = sparse.sweep_samples(scenario.box, n=64, seed=7)
    engine = SparseEvaluator(demo_recording, twin, persistence=persistence)
    assert engine.persistence_steps < engine.horizon  # stepped in several blocks
    full = engine.evaluate(steps, samples)
    ff = engine.evaluate(steps, samples, first_failure=True)
    assert 0 < full.failed_any.sum() < 64
    np.testing.assert_array_equal(ff.failed_any, full.failed_any)
    both = ff.evaluated & ff.failed
    np.testing.assert_array_equal(ff.failure[both], full.failure[both])
    passed = ff.evaluated & ~ff.failed
    np.testing.assert_array_equal(ff.cost[passed], full.cost[passed])


def test_the_contact_criterion_is_calibrated_against_the_nominal_run(scenario, twin,
                                                                     demo_traj,
                                                                     demo_recording):
    """Where the nominal grip, whose run completes the task, already crosses the contact
    criterion's threshold (here: cost constants A and alpha that put the bundled nominal grip over
    it all through the carry), the force ratio cannot tell a good grip from a slipping one:
    no moment fails by it, the nominal's cost is its motor term, and measured slip decides.
    On the bundled scene as shipped every moment trusts it."""
    from critmoment.scenario import CostParams

    steps = [_lift_step(demo_recording), _handover_step(demo_recording)]
    plain = SparseEvaluator(demo_recording, twin)
    assert plain.contact_trusted(steps).all()
    strict = Twin(scenario.replace(cost=CostParams(A=40.0, alpha=0.1)))
    rec = rollout.rollout(demo_traj, twin=strict)
    assert rec.completed
    ev = SparseEvaluator(rec, strict)
    assert not ev.contact_trusted(steps).any()
    samples = _mass_samples(strict.scenario, [0.05, 0.3, 3.0])
    res = ev.evaluate(steps, samples)
    assert not (res.failure == sparse.Failure.CONTACT).any()
    np.testing.assert_allclose(res.cost[:, 0], res.cost_motor[:, 0])
    assert (res.failure[:, 0] == sparse.Failure.PASS).all()  # the nominal passes
    # the same samples under the shipped constants: the 3 kg cube fails by contact there
    shipped = plain.evaluate(steps, samples)
    assert (shipped.failure[:, 2] == sparse.Failure.CONTACT).any()


def test_where_the_nominal_grip_touches_the_cone_a_contact_failure_needs_movement(
        twin, demo_recording):
    """The bundled Panda's nominal grip crosses the contact threshold at a few lifted steps
    while its run completes: there a force ratio on the cone without measured slip (under
    a tenth of the tolerance) is not a failure. A 2 kg cube at μ 1.1 that really succeeds
    (1.6 mm of slip in its full rollout) failed the sweep by contact before; now it passes
    and what follows is left to the chain. The bundled ALOHA grip never touches the cone:
    its decision is unchanged."""
    import critmoment as cm
    from critmoment import analysis, panda_demo

    assert not SparseEvaluator(demo_recording, twin)._nominal_touches()
    panda = Twin(cm.load_scenario("panda_pick_place"))
    rec = rollout.rollout(panda_demo.make_pick_place(seed=0), twin=panda)
    ev = SparseEvaluator(rec, panda)
    assert ev._nominal_touches() and ev.contact_trusted([rec.controls.shape[0] // 2]).all()
    _, steps = analysis.audit_moments(rec, panda, ev, 8)
    sample = np.array([[2.008, 1.125]])
    res = ev.evaluate(steps, sample)
    assert not res.failed_any[0]
    assert (res.fos_grasp[:, 0] < 1.2).any()  # the ratio does sit at the cone somewhere
    assert (res.slip[:, 0] < sparse.SLIP_FLOOR * ev.settings.slip_tolerance).all()


def test_repeated_evaluate_returns_the_same_read_only_result(scenario, twin, demo_recording):
    """An evaluator gives the same call its kept result again (read-only arrays), without
    freezing the caller's arrays; a fork computes the same result on simulations of its own."""
    ev = SparseEvaluator(demo_recording, twin)
    steps = [_lift_step(demo_recording)]
    samples = sparse.sweep_samples(scenario.box, n=6, seed=1)
    first = ev.evaluate(steps, samples)
    assert ev.evaluate(steps, samples) is first
    assert not first.cost.flags.writeable and not first.samples.flags.writeable
    assert samples.flags.writeable  # the caller's array is not frozen
    with pytest.raises(ValueError):
        first.cost[0, 0] = 0.0
    assert ev.evaluate(steps, samples, first_failure=True) is not first
    fork = ev.fork()
    assert fork._batches is not ev._batches and fork._memo is not ev._memo
    again = fork.evaluate(steps, samples)
    assert again is not first
    np.testing.assert_array_equal(again.cost, first.cost)
    np.testing.assert_array_equal(again.failure, first.failure)


def test_a_contact_failure_inside_an_elliptic_cone_is_a_sticking_one(scenario, twin):
    """On the bundled (elliptic) twin, demo seed 3: a contact failure whose grasp force
    ratio stayed at least 1 + STICKING_MARGIN (the grip's friction never at its limit) is a
    sticking failure, which does not stop the sample (it is evaluated at the later
    moments) and, alone, leaves the sample to its own rollout; a contact failure that
    reached the cone is not one. On a pyramidal cone, where a sliding contact's ratio is
    not 1, only a measured motion under SLIP_FLOOR of the tolerance makes one. (Without
    ``settle``: a contact failure on the cone whose small
    slip settles is a sticking one too, tested below.)"""
    from critmoment import analysis, demos
    from critmoment import verdict as vd

    traj = demos.scripted_transfer(3, twin=twin)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rec = rollout.rollout(traj, twin=twin)
    ev = SparseEvaluator(rec, twin)
    _, steps = analysis.audit_moments(rec, twin, ev, 8)
    samples = sparse.sweep_samples(scenario.box, n=256, seed=3)
    res = ev.evaluate(steps, samples, first_failure=True, settle=False)
    contact = res.failure == sparse.Failure.CONTACT
    stick = res.sticking_failure
    assert stick.any() and (contact & ~stick).any()
    assert not (stick & ~contact).any()
    # the horizon's lowest ratio bounds the decided steps' (which include any followed ones)
    assert (res.fos_grasp[stick] >= 1 + sparse.STICKING_MARGIN).all()
    assert not (contact & ~stick & (res.fos_grasp >= 1 + 0.2)).any()
    # a sticking failure does not stop the sample: it reaches every later moment
    order = np.argsort(steps)
    for row, j in zip(*np.nonzero(stick), strict=True):
        later = order[np.flatnonzero(order == row)[0] + 1:]
        assert res.evaluated[later, j].all()
    only = res.failed_sticking_only
    assert only.any()
    reruns = vd.samples_to_rerun(res, vd.DecisionOptions(threshold=scenario.cost.threshold),
                                 nominal_completed=rec.completed)
    np.testing.assert_array_equal(reruns.sticking, only & ~res.failed_unlifted_only)
    pyramidal = Twin(scenario)
    pyramidal.model.opt.cone = mujoco.mjtCone.mjCONE_PYRAMIDAL
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        prec = rollout.rollout(traj, twin=pyramidal)
    pres = SparseEvaluator(prec, pyramidal).evaluate(steps, samples[:64], first_failure=True,
                                                     settle=False)
    # on a pyramidal cone the ratio proves nothing (a sliding contact's lies between 1/sqrt(2)
    # and 1): only a measured motion under SLIP_FLOOR of the tolerance makes one sticking
    pstick = pres.sticking_failure
    assert (pres.failure == sparse.Failure.CONTACT).any()
    limit = sparse.SLIP_FLOOR * pres.settings.slip_tolerance
    assert (pres.slip[pstick] <= limit).all()
    assert not (pstick & (pres.slip > limit)).any()


def test_a_contact_failure_whose_object_stayed_still_is_a_sticking_one(scenario, twin,
                                                                     monkeypatch):
    """On an elliptic cone a contact failure whose object, measured in its holding gripper
    at every step decided, moved no more than STILL_SLIP is a sticking one whatever its
    force ratio; one measured at no step (two grippers hold it) is not; and on the demo,
    whose contact failures all slid 20 µm or more, the default changes nothing. (Without
    ``settle``, which makes a settling contact failure a sticking one whatever this rule
    says.)"""
    from critmoment import analysis, demos

    traj = demos.scripted_transfer(3, twin=twin)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rec = rollout.rollout(traj, twin=twin)
    _, steps = analysis.audit_moments(rec, twin, SparseEvaluator(rec, twin), 8)
    samples = sparse.sweep_samples(scenario.box, n=96, seed=3)

    def sweep(still):
        monkeypatch.setattr(sparse, "STILL_SLIP", still)
        return SparseEvaluator(rec, twin).evaluate(steps, samples, settle=False)

    default, none, every = sweep(sparse.STILL_SLIP), sweep(0.0), sweep(1.0)
    contact = none.failure == sparse.Failure.CONTACT
    ev = SparseEvaluator(rec, twin)
    alone = ev._alone.any(axis=-1)
    h = ev.horizon + ev.persistence_steps
    # inside the cone, or where two grippers hold the object in the nominal run (a
    # hand-over, whose contact failures are for the samples' own runs)
    shared = np.array([(ev._held[k:k + h].sum(axis=-1) >= 2).any() for k in steps])
    margin = contact & ((none.fos_grasp >= 1 + sparse.STICKING_MARGIN) | shared[:, None])
    np.testing.assert_array_equal(none.sticking_failure, margin & none.sticking_failure)
    np.testing.assert_array_equal(default.sticking_failure, none.sticking_failure)
    np.testing.assert_array_equal(default.failure, none.failure)
    # with any slip counting as still, every contact failure at a moment whose decided
    # steps are all measured (one gripper alone holds the object) becomes sticking
    measured = np.array([alone[k:k + h].all() for k in steps])
    unmeasured = np.array([not alone[k:k + h].any() for k in steps])
    assert (contact & measured[:, None]).any() and (contact & unmeasured[:, None]).any()
    assert every.sticking_failure[contact & measured[:, None]].all()
    np.testing.assert_array_equal(every.sticking_failure[contact & unmeasured[:, None]],
                                  none.sticking_failure[contact & unmeasured[:, None]])


def test_pairs_stepped_together_equal_each_moment_alone(scenario, twin, demo_recording):
    # evaluate (no raw readings) steps every (moment, sample) pair in one batch, each from
    # its own moment; keep_raw steps one moment at a time: the same values, to the bit,
    # including a moment whose follow-up steps the end of the recording cuts short
    rec = demo_recording
    ev = SparseEvaluator(rec, twin, nthread=2)
    last = rec.n_steps - ev.horizon
    steps = [_lift_step(rec), _handover_step(rec), last - 3, last]
    samples = sparse.sweep_samples(scenario.box, n=9, seed=5)
    together = ev.evaluate(steps, samples)
    alone = SparseEvaluator(rec, twin, nthread=1).evaluate(steps, samples, keep_raw=True)
    for f in dataclasses.fields(together):
        if f.name in ("sensordata", "state"):
            continue
        a, b = getattr(together, f.name), getattr(alone, f.name)
        if isinstance(a, np.ndarray):
            assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), f.name
    # several requests in one call: each equals its own call
    other = samples[:4] * np.array([1.0, 0.9])
    many = ev.evaluate_many([(steps[:2], other), (steps[2:], samples)])
    one = SparseEvaluator(rec, twin).evaluate(steps[:2], other)
    assert np.array_equal(many[0].cost, one.cost)
    assert np.array_equal(many[1].cost, together.cost[2:])
    assert many[1].failure.tolist() == together.failure[2:].tolist()


def test_a_samples_decision_does_not_depend_on_the_samples_beside_it(scenario, twin,
                                                                   demo_recording):
    # a pair whose contact excursion is still open at the horizon's end is followed a few
    # steps further; the others in its batch keep their first decision. Once, the re-decision
    # after a follow-up treated every pair as followed to the end, so a slip at the
    # horizon's last step became a contact failure whenever another pair of the batch (a
    # neighbour sample, or the same sample at another moment) was followed (robosuite's
    # Panda + Robotiq 2F-85, elliptic cone: 9 heavy cubes that really succeed were called
    # unsafe without their own rollout). The tolerances here make such pairs common.
    rec = demo_recording
    from critmoment.analysis import audit_evaluator, audit_moments

    _, steps = audit_moments(rec, twin, audit_evaluator(rec, twin)[0], 8)
    ev = SparseEvaluator(rec, twin, horizon=2, slip_tolerance=1e-6, nthread=1)
    samples = sparse.sweep_samples(scenario.box, n=16, seed=3)
    together = ev.evaluate(steps, samples)
    assert (together.failure == sparse.Failure.SLIP).any()
    for j in range(samples.shape[0]):
        for i, k in enumerate(steps):
            alone = ev.evaluate([k], samples[j:j + 1])
            assert alone.failure[0, 0] == together.failure[i, j], (k, j)
            assert alone.excursion[0, 0] == together.excursion[i, j], (k, j)


def test_first_failure_shared_out_between_threads_equals_one_thread(scenario, twin,
                                                                   demo_recording, tiny,
                                                                   caplog):
    # with several threads the samples of a first-failure evaluation are shared out (one
    # Python thread and one MuJoCo thread each): the same result as one thread, to the bit
    rec = demo_recording
    steps = [_lift_step(rec), _handover_step(rec)]
    samples = sparse.sweep_samples(scenario.box, n=40, seed=7)
    split = SparseEvaluator(rec, twin, nthread=2).evaluate(steps, samples, first_failure=True)
    whole = SparseEvaluator(rec, twin, nthread=1).evaluate(steps, samples, first_failure=True)
    for f in dataclasses.fields(whole):
        a, b = getattr(split, f.name), getattr(whole, f.name)
        if isinstance(a, np.ndarray):
            assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), f.name
    # a divergence in the second thread's part names the sample by its row in the call
    t, recording = tiny
    states = recording.states.copy()
    states[0, 1 + t.model.nq] = 1e12
    bad = dataclasses.replace(recording, states=states)
    caplog.set_level(logging.DEBUG, logger="critmoment")
    ev = SparseEvaluator(bad, t, nthread=2)
    res = ev.evaluate([0], _mass_samples(t.scenario, np.linspace(0.05, 1.0, 40)),
                      first_failure=True)
    assert res.diverged.all() and ev.diverged_count == 40
    said = " ".join(r.getMessage() for r in caplog.records)
    assert "sample 0 " in said and "sample 20 " in said
    # one warning per evaluator, the rest at debug level (a probe's box reaching friction
    # 1e300 printed 154 warnings); the warning says the later ones are counted as failures
    warned = [r for r in caplog.records if r.levelno >= logging.WARNING]
    assert len(warned) == 1 and "later divergences" in warned[0].getMessage()
    ev.evaluate([0], _mass_samples(t.scenario, np.array([0.5])))
    assert ev.diverged_count == 41
    assert len([r for r in caplog.records if r.levelno >= logging.WARNING]) == 1


def test_busy_batches_take_one_thread_and_bad_requests_are_refused(scenario, twin,
                                                                    demo_recording):
    # while another thread steps (``busy``), the evaluator's batches take one MuJoCo thread;
    # the values do not change. evaluate_many checks every request as evaluate does.
    rec = demo_recording
    steps = [_lift_step(rec)]
    samples = sparse.sweep_samples(scenario.box, n=6, seed=4)
    ev = SparseEvaluator(rec, twin, nthread=2)
    free = ev.evaluate(steps, samples)
    ev.busy = lambda: True
    busy = ev.evaluate(steps, samples * np.array([1.0, 0.99]))
    assert {b.nthread for b in ev._batches.values()} == {1, 2}
    again = SparseEvaluator(rec, twin, nthread=2).evaluate(steps, samples * np.array([1.0, 0.99]))
    assert np.array_equal(busy.cost, again.cost) and not np.array_equal(busy.cost, free.cost)
    with pytest.raises(ParameterError, match="steps"):
        ev.evaluate_many([(steps, samples), ([rec.n_steps + 5], samples)])
    with pytest.raises(ParameterError):
        ev.evaluate_many([(steps, np.full((1, 2), np.nan))])


def test_the_scores_read_the_signals_the_decision_computed(twin, demo_recording):
    # the decision's signals, picked per row, are those of the picked readings: scoring
    # them again from the readings (as it was done before) gives the same values to the bit
    ev = SparseEvaluator(demo_recording, twin)
    box = twin.scenario.box
    samples = np.vstack([box.low, box.nominal, box.high, sparse.sweep_samples(box, n=3)])
    h = ev.horizon
    for k in (1466, 1707, 2290):
        batch, mu = ev._batch(samples)
        sim = ev._simulate(batch, k, np.arange(batch.nsim), mu, keep_state=False,
                           stop_early=True)
        stop = np.where(sim.stop & (sim.stop_step < h), sim.stop_step, h - 1)
        last = np.minimum(np.arange(h)[None, :], stop[:, None])
        for pick in (None, last):
            rows = (np.broadcast_to(np.arange(h), (samples.shape[0], h)) if pick is None
                    else pick)
            buf = np.take_along_axis(sim.buf[:, :h], rows[:, :, None], axis=1)
            with np.errstate(over="ignore", invalid="ignore"):
                again = twin.signals(buf, mu=mu[:, None], carried=ev._carried[k + rows])
            scored = sim.scored(h, pick)
            for f in dataclasses.fields(again):
                assert np.array_equal(getattr(scored, f.name), getattr(again, f.name),
                                      equal_nan=True), (k, f.name)


def test_a_centre_of_mass_offset_on_the_bundled_cube_is_evaluated(scenario, demo_traj):
    """A ``com_offset`` parameter on a body MuJoCo compiles as simple (inertial frame = body
    frame, as the bundled cube's) used to make every batch refuse it ("sameframe no longer
    holds"); critmoment compiles that body as not simple, and the offset moves the centre of
    mass the sparse evaluation sees: the cube's nominal run is unchanged by the flag, and an
    offset of 5 mm changes the readings at the lift-off."""
    from critmoment.params import ComOffsetParameter, UncertaintyBox

    body = scenario.object_body
    box = UncertaintyBox(scenario.box.parameters
                         + (ComOffsetParameter("com", body, -0.005, 0.005, 0.0),))
    twin = Twin(scenario.replace(box=box))
    assert twin.model.body_simple[twin.object_body_id] == 0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rec = rollout.rollout(demo_traj, twin=twin)
    lift = int(np.flatnonzero(rec.stage >= 2)[0])
    ev = SparseEvaluator(rec, twin)
    samples = np.tile(box.nominal, (3, 1))
    samples[:, 2] = [0.0, -0.005, 0.005]
    res = ev.evaluate([lift], samples, keep_raw=True)
    assert np.isfinite(res.cost).all() and not res.diverged.any()
    assert not np.allclose(res.sensordata[0, 1], res.sensordata[0, 0])
    assert not np.allclose(res.sensordata[0, 2], res.sensordata[0, 0])


def test_the_nominal_cost_with_both_terms_calibrates_the_contact_criterion(tmp_path):
    """ALOHA with noslip_iterations="5" (mass ≤ 1.5 kg): at the lift the nominal grip's
    contact term (about 0.75) and the motors' (about 0.47) cross the threshold 0.9 only
    together, while the run completes. Calibrated on the contact term alone the moment
    trusted the force ratio and 4 of 16 real successes were called failing; with both terms
    it does not, and the audit agrees with brute force on every sample."""
    import shutil

    import critmoment as cm
    from critmoment import analysis, demos
    from critmoment.scenario import bundled_scenario_path

    folder = tmp_path / "noslip"
    shutil.copytree(bundled_scenario_path().parent, folder)
    scene = folder / "scene.xml"
    scene.write_text(scene.read_text().replace('impratio="10"/>',
                                               'impratio="10" noslip_iterations="5"/>'))
    toml = folder / "scenario.toml"
    toml.write_text(toml.read_text().replace("range = [0.05, 10.0]", "range = [0.05, 1.5]"))
    twin = Twin(load_scenario(folder))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        traj = demos.scripted_transfer(0, twin=twin)
        rec = rollout.rollout(traj, twin=twin)
        evaluator, _ = analysis.audit_evaluator(rec, twin)
        assert rec.completed and not evaluator.contact_trusted([2570])[0]
        check = cm.validate(traj, twin=twin, n_samples=16, seed=0)
    assert check.confusion == {"true_safe": 6, "false_safe": 0, "true_unsafe": 10,
                               "false_unsafe": 0}


def test_a_grip_that_shifts_and_settles_is_for_its_own_run_to_decide(twin, demo_traj,
                                                                      demo_recording):
    """Restored at lift-off from the nominal state with a heavier, less grippy cube, a grip
    can shift into a new equilibrium and stop: the force ratio reads a contact failure over
    the whole window while the cube moves some tens of µm and then stays. Followed a little
    further, such a failure is a sticking one (its sample's own run decides: this one
    really completes the hand-over); a cube that keeps sliding stays a failure that stops
    its sample."""
    from critmoment.analysis import audit_evaluator
    from critmoment.groundtruth import brute_force

    ev, _ = audit_evaluator(demo_recording, twin)
    lift = 1707  # the demo's lift-off moment
    samples = np.array([[0.5669, 0.7217], [3.0, 0.3]])
    res = ev.evaluate([lift], samples)
    assert res.failure[0].tolist() == [sparse.Failure.CONTACT] * 2
    assert res.sticking_failure[0].tolist() == [True, False]
    assert res.slip[0, 0] < 1e-4  # tens of µm within the window
    real = brute_force(demo_traj, twin=twin, samples=samples[:1])
    assert not real.failed[0]


def test_a_contact_failure_while_two_grippers_hold_is_for_the_own_run(scenario, tmp_path):
    """At ALOHA's hand-over both grippers hold the cube, slip is not measured (it counts in
    a gripper holding alone), and at impratio 50 the grip's force ratio sits near the cone:
    two samples of 64 (0.63 and 0.73 kg at friction 1.33-1.38) failed there at cost 0.98
    and really hold (agreement 0.969; OpenArm's hand-over on a pyramidal cone, 3 of 64).
    Such a contact failure is now a sticking one, for the sample's own run; the nominal
    run's own steps there stay passing."""
    import shutil

    from critmoment import demos

    folder = tmp_path / "impratio50"
    shutil.copytree(scenario.path.parent, folder)
    xml = (folder / "scene.xml").read_text()
    assert 'cone="elliptic" impratio="10"' in xml
    (folder / "scene.xml").write_text(xml.replace('impratio="10"', 'impratio="50"'))
    twin = Twin(load_scenario(folder))
    traj = demos.scripted_transfer(0, twin=twin)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rec = rollout.rollout(traj, twin=twin)
    ev = SparseEvaluator(rec, twin)
    step = 2936  # a change point of the hand-over, both grippers on the cube
    assert (ev._held[step:step + ev.horizon].sum(axis=-1) >= 2).all()
    samples = np.array([[0.7346601796802134, 1.3764356748200952],
                        [0.6316559219267219, 1.3297308890148998]])
    res = ev.evaluate([step], samples, settle=False)
    np.testing.assert_array_equal(res.failure[0], sparse.Failure.CONTACT)
    assert res.sticking_failure[0].all()


def test_a_motor_at_its_limit_fails_only_once_it_stays_there(demo_recording, twin):
    """A motor that touches its force limit for a few milliseconds and lets go has not
    failed (the bundled ALOHA with its shoulder limited to 5.4-5.8 N·m, unrated, touches
    it for 16-40 ms and completes the task): a motor excursion counts, as a contact one
    does, once it lasts, here as long as the ground truth's saturation (``motor_steps``,
    50 ms); one still open where no more steps can be taken counts, and one open at the
    horizon's end is followed."""
    from critmoment.groundtruth import OutcomeCriteria

    engine = SparseEvaluator(demo_recording, twin)
    p, h, pm = engine.persistence_steps, engine.horizon, engine.motor_steps
    assert pm == OutcomeCriteria().steps(0.05, 0.002) > p
    total = h + pm
    term_m = np.zeros((4, total))
    term_m[0, 2:2 + pm - 2] = 2.0  # brief: pm - 2 steps, then under the threshold
    term_m[1, 2:2 + pm] = 2.0  # lasts pm steps
    term_m[2, h - 3:h] = 2.0  # open at the end of the steps taken
    term_m[3, h - 3:h] = 2.0  # the same, where no more steps can be taken
    term_c = np.zeros_like(term_m)
    length = np.array([total, total, h, h])
    valid = np.arange(total)[None, :] < length[:, None]
    final = np.array([False, False, False, True])
    kind, step, _, follow, motor = engine._first_failure(term_c, term_m, np.zeros_like(valid),
                                                         valid, length, p, final)
    assert kind.tolist() == [sparse.Failure.PASS, sparse.Failure.MOTOR, sparse.Failure.PASS,
                             sparse.Failure.MOTOR]
    assert step[1] == 2 + pm - 1
    assert follow.tolist() == motor.tolist() == [False, False, True, False]


def test_a_motor_failure_that_never_saturates_is_a_margin_one():
    """The margin under a motor's limit that makes a motor failure a margin one (for the
    sample's own run) is the ground truth's saturation: a motor at 0.99 of its limit has not
    reached it (samples at motor FOS 1.001-1.05 had been decided failing, and really
    succeed)."""
    from critmoment.groundtruth import OutcomeCriteria

    assert sparse.MOTOR_MARGIN == pytest.approx(1.0 / OutcomeCriteria().saturation - 1.0)


def test_saturated_marks_a_motor_held_at_its_limit_for_a_failures_duration(scenario, twin,
                                                                          demo_traj,
                                                                          demo_recording):
    """``SparseResult.saturated``: a motor at the ground truth's saturation (0.999 of its
    limit) for a motor failure's duration in a row. With the right elbow limited to half its
    nominal carry's peak, it sits at the limit through the carry: its motor failures stand;
    on the bundled twin no pair is saturated."""
    sig = demo_recording.signals
    carry = np.flatnonzero((sig.contact_gripper & ~sig.contact_support[:, None]).any(axis=1))
    i = twin.actuator_names.index("right/elbow")
    peak = np.abs(np.asarray(sig.actuator_force)[carry, i]).max()
    weak = Twin(scenario.replace(limits={**scenario.limits, "right/elbow": float(0.5 * peak)}))
    rec = rollout.rollout(demo_traj, twin=weak)
    k = int(carry[len(carry) // 2])
    nominal = scenario.box.nominal[None]
    res = sparse.SparseEvaluator(rec, weak).evaluate([k], nominal)
    assert res.failure[0, 0] == sparse.Failure.MOTOR and res.saturated[0, 0]
    assert not res.margin_failure[0, 0]
    ok = sparse.SparseEvaluator(demo_recording, twin).evaluate([k], nominal)
    assert not ok.saturated.any() and not ok.failed.any()


def test_a_grip_the_restore_breaks_is_for_its_own_run(twin, demo_recording, monkeypatch):
    """Restored in the nominal state with its own mass and friction, a sample whose grasp
    holds its load with a wide margin at the restore and yet loses every gripper's touch
    within the window was pushed out of the restored grip (the low-cost robot arm's wedged
    one-jaw grasp: 8 false unsafes of 32 on a pyramidal cone, every one holding on its own
    run): a sticking failure, for its own run. A grasp outside the cone from the restore on
    (a load the grip cannot hold) that loses its touch stays a failure that stops its
    sample."""
    import dataclasses

    ev = SparseEvaluator(demo_recording, twin)
    size = ev.horizon + ev.persistence_steps
    one = ev._held.sum(axis=-1) == 1  # one gripper carries the cube, alone
    k = next(k for k in range(demo_recording.n_steps - size)
             if one[k:k + size].all() and ev._touched[k:k + size].all())
    buf = np.repeat(np.asarray(demo_recording.sensordata[k:k + size])[None], 2, axis=0)
    real = twin.signals

    def pushed_out(sd, mu=None, **kw):  # both samples lose the grip after 5 steps
        sig = real(sd, mu, **kw)
        if np.ndim(sd) != 3:  # the nominal run's own readings
            return sig
        touch, fos = sig.contact_gripper.copy(), sig.fos_grasp.copy()
        touch[:, 5:] = False
        fos[:, 5:] = 0.0
        fos[0, :5], fos[1, :5] = 10.0, 0.8  # held 10x inside the cone; outside it
        return dataclasses.replace(sig, contact_gripper=touch, fos_grasp=fos)

    monkeypatch.setattr(twin, "signals", pushed_out)
    slip = np.tile(np.linspace(0.0, 2e-3, size), (2, 1))  # moving, under the tolerance
    d = ev._decide(buf, slip, np.full(2, size), np.ones(2), k, final=True)
    assert d.failure.tolist() == [sparse.Failure.CONTACT] * 2
    assert d.sticking.tolist() == [True, False]
    assert d.stop.tolist() == [False, True]


def test_a_grip_lost_while_followed_after_a_comfortable_restore_is_for_its_own_run(
        twin, demo_recording, monkeypatch):
    """The same push out of the restored grip can come just after the window: a contact
    failure followed (the settle follow-up) whose object leaves every gripper while the
    nominal grip touches it, from a grasp that held the load twice inside the cone at the
    restore, is for its own run (the low-cost robot arm, elliptic cone: the cube held at
    force ratio 12 sags for 19 steps and drops out 5 steps after the window; 4 false
    unsafes of 32 -> 0). Without a comfortable restore (a load outside the cone from the
    start) it stays a failure that stops its sample."""
    import dataclasses

    from critmoment.analysis import audit_evaluator

    ev, _ = audit_evaluator(demo_recording, twin)
    lift, heavy = 1707, np.array([[3.0, 0.3]])  # keeps sliding: a failure
    plain = ev.evaluate([lift], heavy)
    assert plain.failure[0, 0] == sparse.Failure.CONTACT and not plain.sticking_failure[0, 0]
    real, p = twin.signals, ev.persistence_steps

    def forged(comfortable):
        def signals(sd, mu=None, **kw):
            sig = real(sd, mu, **kw)
            if np.ndim(sd) != 3:
                return sig
            if sd.shape[1] == p:  # a follow-up block: every gripper lets go
                return dataclasses.replace(
                    sig, contact_gripper=np.zeros_like(sig.contact_gripper))
            fos = sig.fos_grasp.copy()
            fos[:, 0] = 10.0 if comfortable else 0.5
            return dataclasses.replace(sig, fos_grasp=fos)
        return signals

    assert ev.horizon + ev._extension_steps() != p
    for comfortable in (True, False):
        monkeypatch.setattr(twin, "signals", forged(comfortable))
        fresh, _ = audit_evaluator(demo_recording, twin)  # nothing kept from before
        assert fresh.evaluate([lift], heavy).sticking_failure[0, 0] == comfortable


def test_releases_do_not_add_up_to_chatter(twin, demo_recording):
    """A gripper letting its object go sits on the cone as it opens: over-threshold steps
    of the nominal's releases do not make every moment distrust the force ratio (a Panda
    regrasp's two releases, 6 steps each, had; its lift-off, where 40 % of the box drops,
    was left without a cause). The same number of steps while the grip holds is chatter."""
    ev = SparseEvaluator(demo_recording, twin)
    letting = twin.letting_go(demo_recording.controls,
                              demo_recording.signals.contact_gripper).any(axis=-1)
    p = ev.persistence_steps
    release = np.flatnonzero(letting)[:p]
    hold = np.flatnonzero(ev._held.any(axis=-1) & ~letting)[:p]
    assert release.size == hold.size == p
    for steps, chatter in ((release, False), (hold, True)):
        over = np.zeros(demo_recording.n_steps, bool)
        over[steps] = True
        ev._over, ev._chatter = over, None
        assert ev._nominal_chatter() is chatter
        assert not ev._contact_trusted(int(steps[0])) and ev._nominal_touches()
