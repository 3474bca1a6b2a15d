"""Tests of critmoment.history: each sample's own drift from the nominal run."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import critmoment as cm
from critmoment import history, sparse
from critmoment.exceptions import ParameterError


def _carry_steps(recording):
    """Steps where the picker alone holds the cube off the table (a carry)."""
    held = recording.signals.contact_gripper & ~recording.signals.contact_support[:, None]
    alone = held & (held.sum(axis=1, keepdims=True) == 1)
    carry = np.flatnonzero(alone[:, 1])
    return [int(carry[100]), int(carry[len(carry) // 2])]


def test_nominal_sample_does_not_drift_and_heavier_ones_do(scenario, twin, demo_recording):
    ev = sparse.SparseEvaluator(demo_recording, twin)
    samples = np.tile(scenario.box.nominal, (3, 1))
    samples[:, scenario.box.index("mass")] = [0.05, 0.5, 1.5]
    est = history.estimate_drift(ev, _carry_steps(demo_recording), samples, horizon=20)
    assert est.steps.size == 2 and est.drift.shape == (2, 3)
    # the nominal sample's own run is the nominal run, bit for bit
    np.testing.assert_array_equal(est.drift[:, 0], 0.0)
    np.testing.assert_array_equal(est.lag[:, 0], 0.0)
    assert (est.drift[:, 2] > est.drift[:, 1]).all() and (est.drift[:, 1] > 0).all()
    assert (est.remaining > 0).all()
    np.testing.assert_allclose(est.predicted_drift,
                               est.drift + est.drift_rate * est.remaining[:, None])
    assert not est.escalate[0] and est.escalate[2]
    # moments where no gripper holds the cube alone are not traced
    none = history.estimate_drift(ev, [0], samples)
    assert none.steps.size == 0 and not none.escalate.any()


def test_bad_options_raise(twin, demo_recording, scenario):
    ev = sparse.SparseEvaluator(demo_recording, twin)
    with pytest.raises(ParameterError, match="horizon"):
        history.estimate_drift(ev, [100], scenario.box.nominal[None], horizon=2)
    with pytest.raises(ParameterError, match="drift_tolerance"):
        history.estimate_drift(ev, [100], scenario.box.nominal[None], drift_tolerance=0.0)
    for block in (0, -3, 2.5, True):
        with pytest.raises(ParameterError, match="block: expected an integer >= 1"):
            history.chained_failures(ev, [100], scenario.box.nominal[None], block=block)
    with pytest.raises(ParameterError, match="criteria: expected an OutcomeCriteria"):
        history.chained_failures(ev, [100], scenario.box.nominal[None], criteria={"x": 1})


def test_a_nominal_chain_is_the_nominal_run(scenario, twin, demo_recording):
    ev = sparse.SparseEvaluator(demo_recording, twin)
    steps = np.array(_carry_steps(demo_recording) + [_carry_steps(demo_recording)[0] - 400])
    samples = np.tile(scenario.box.nominal, (2, 1))
    samples[1, scenario.box.index("mass")] = 1.0
    chain = history.chained_failures(ev, steps, samples, start=None)
    np.testing.assert_array_equal(chain.steps, np.sort(steps))
    assert chain.start == steps.min()
    # the nominal sample never fails, so it runs to the end of the nominal hold
    assert chain.end == demo_recording.controls.shape[0]
    assert chain.stepped == chain.end - steps.min()
    assert chain.slip_step[0] == -1 and chain.drop_step[0] == -1 and chain.max_slip[0] == 0
    # carried on its own state, the nominal sample is the nominal run: the same decision
    # as restoring the nominal state at every moment
    plain = ev.evaluate(chain.steps, samples[:1])
    np.testing.assert_array_equal(chain.failure[:, 0], plain.failure[:, 0])
    assert chain.failure.shape == (3, 2) and chain.failed.shape == (2,)
    # the first moment starts from the nominal state for every sample: the plain decision
    first = ev.evaluate(chain.steps[:1], samples)
    np.testing.assert_array_equal(chain.failure[0], first.failure[0])
    heavy = history.chained_failures(ev, steps, _mass(scenario, 10.0))
    assert heavy.failed[0]  # a 10 kg cube fails in the carry


def _mass(scenario, mass):
    sample = scenario.box.nominal[None].copy()
    sample[0, scenario.box.index("mass")] = mass
    return sample


def test_the_chain_watches_slip_and_drops_as_the_ground_truth_does(scenario, twin, demo_traj,
                                                                    demo_recording):
    """Started before the grasp, a chain's own run is the sample's full rollout: its
    measured slip and the step its object is lost agree with the brute force's."""
    from critmoment import groundtruth

    ev = sparse.SparseEvaluator(demo_recording, twin)
    sig = demo_recording.signals
    held = sig.contact_gripper & ~sig.contact_support[:, None]
    start = int(np.flatnonzero(held.any(axis=1))[0]) - 200
    samples = np.tile(scenario.box.nominal, (4, 1))
    samples[:, scenario.box.index("mass")] = [0.05, 0.3, 1.0, 0.6]
    samples[3, scenario.box.index("friction")] = 0.5
    chain = history.chained_failures(ev, [start], samples)
    truth = groundtruth.brute_force(demo_traj, twin=twin, samples=samples).classification
    np.testing.assert_array_equal(chain.failed, truth.failed)
    # where neither fails, the same slip to a micrometre
    np.testing.assert_allclose(chain.max_slip[:2], truth.max_slip[:2], atol=1e-6)
    # a slippery 0.6 kg cube falls out of the grip: lost in mid-air in both
    assert chain.drop_step[3] >= 0 and truth.drop_step[3] >= 0
    # the 1 kg cube slips where the brute force says it does, within a few steps
    assert abs(chain.slip_step[2] - truth.slip_step[2]) <= 10


def test_on_soft_contacts_the_chain_sees_the_creep_the_force_ratio_passes(tmp_path, scenario,
                                                                         demo_traj):
    """Pyramidal cone, impratio 1: from the nominal state at a carry step, a 0.45 kg cube
    held with a force ratio of about 2.7 passes the one-step decision but creeps out of
    the grip; the chain watches its slip over the rest of the hold and fails it, as its
    full rollout does, and passes the cubes that really stay."""
    from scenarios import soft_copy

    from critmoment import groundtruth
    from critmoment.recording import rollout
    from critmoment.scenario import load_scenario
    from critmoment.twin import Twin

    soft = Twin(load_scenario(soft_copy(scenario, tmp_path / "soft")))
    rec = rollout(demo_traj, twin=soft)
    held = rec.signals.contact_gripper[:, 1] & ~rec.signals.contact_support
    k = int(np.flatnonzero(held)[200])
    ev = sparse.SparseEvaluator(rec, soft)
    samples = np.tile(soft.scenario.box.nominal, (4, 1))
    samples[:, soft.scenario.box.index("mass")] = [0.05, 0.3, 0.45, 0.8]
    one_step = ev.evaluate([k], samples)
    assert not one_step.failed.any() and one_step.fos_grasp[0, 2] > 2.5
    chain = history.chained_failures(ev, [k], samples, start=k)
    truth = groundtruth.brute_force(demo_traj, twin=soft, samples=samples).classification
    np.testing.assert_array_equal(chain.failed, [False, False, True, True])
    np.testing.assert_array_equal(chain.failed, truth.failed)
    assert chain.slip_step[2] > k and chain.max_slip[2] > 0.01


def test_the_chain_watches_motor_saturation_as_the_ground_truth_does(scenario, demo_traj,
                                                                     demo_recording):
    """With the right elbow's limit 15 % over the nominal carry's peak, cubes of 0.6 and
    1 kg saturate it for longer than the ground truth's motor time: the chain finds the
    same first step as their full rollouts; lighter cubes pass in both."""
    from critmoment import groundtruth
    from critmoment.recording import rollout
    from critmoment.twin import Twin

    sig = demo_recording.signals
    carry = np.flatnonzero((sig.contact_gripper & ~sig.contact_support[:, None]).any(axis=1))
    probe = Twin(scenario)
    i = probe.actuator_names.index("right/elbow")
    peak = np.abs(np.asarray(sig.actuator_force)[carry, i]).max()
    limits = {**scenario.limits, "right/elbow": float(1.15 * peak)}
    twin = Twin(scenario.replace(limits=limits))
    rec = rollout(demo_traj, twin=twin)
    assert rec.completed
    samples = np.tile(scenario.box.nominal, (4, 1))
    samples[:, scenario.box.index("mass")] = [0.05, 0.4, 0.6, 1.0]
    samples[:, scenario.box.index("friction")] = 1.5
    chain = history.chained_failures(sparse.SparseEvaluator(rec, twin), [int(carry[0]) - 200],
                                     samples)
    truth = groundtruth.brute_force(demo_traj, twin=twin, samples=samples).classification
    assert [o.value for o in truth.outcome] == ["success", "success", "motor", "motor"]
    np.testing.assert_array_equal(chain.motor_step, truth.motor_step)
    np.testing.assert_array_equal(chain.failed, truth.failed)


def test_a_chained_failure_is_a_moment_failure_or_a_watched_one():
    """A chained sample fails at a moment of its chain (any failure code) or by the watch
    (slip, drop, saturation, tracking, divergence). Its own rollout should decide a failure
    at a moment, a watched one at or after the nominal release, and an incomplete task; a
    slip, drop or motor failure during the hold stands."""
    F = sparse.Failure
    failure = np.array([[F.PASS, F.CONTACT, F.CONTACT, F.PASS, F.MOTOR, F.PASS],
                        [F.CONTACT, -1, -1, F.PASS, -1, F.PASS]], dtype=np.int8)
    none = np.full(6, -1)
    slip = none.copy()
    slip[2] = 1500
    result = history.ChainedResult(steps=np.array([100, 200]), samples=np.zeros((6, 2)),
                                   failure=failure, start=100, stepped=0, end=300,
                                   slip_step=slip, drop_step=none, motor_step=none,
                                   max_slip=np.zeros(6))
    np.testing.assert_array_equal(result.failed, [True, True, True, False, True, False])
    np.testing.assert_array_equal(result.watched_failed, [False, False, True, False, False,
                                                          False])
    # every failure here comes from a moment (sample 2 also slips): its rollout decides it
    np.testing.assert_array_equal(dataclasses.replace(result, release=2000).to_confirm,
                                  result.failed)
    # only watched failures: a drop in the hold that leaves the task incomplete stands, a
    # tracking loss after the release and an incomplete task without a drop go to their
    # rollouts; a drop whose run completes the task (the object caught again) fails nothing
    quiet = np.full((1, 5), F.PASS, dtype=np.int8)
    drop, motor = np.full(5, -1), np.full(5, -1)
    drop[[0, 4]], motor[1] = 150, 260
    watched = history.ChainedResult(steps=np.array([100]), samples=np.zeros((5, 2)),
                                    failure=quiet, start=100, stepped=0, end=300,
                                    slip_step=np.full(5, -1), drop_step=drop, motor_step=motor,
                                    max_slip=np.zeros(5),
                                    incomplete=np.array([True, False, True, False, False]),
                                    release=250)
    np.testing.assert_array_equal(watched.failed, [True, True, True, False, False])
    np.testing.assert_array_equal(watched.to_confirm, [False, True, True, False, False])
    # with the release before the drop, the dropped run goes to its rollout too
    np.testing.assert_array_equal(dataclasses.replace(watched, release=150).to_confirm,
                                  [True, True, True, False, False])
    # a fall onto a support fails the caught-again run 4 (its task complete), as the
    # ground truth's fall rule does; its own rollout confirms it where there is one
    fall = np.full(5, -1)
    fall[4] = 170
    fell = dataclasses.replace(watched, fall_step=fall)
    np.testing.assert_array_equal(fell.failed, [True, True, True, False, True])
    np.testing.assert_array_equal(fell.to_confirm, [False, True, True, False, True])
    assert fell.kinds()[4] == "dropped"


def test_the_chain_watches_tracking_as_the_ground_truth_does(scenario, twin):
    """Demo seed 8, a 0.196 kg cube at μ 0.78: its grip shifts, the pads collide at the
    hand-over and the right wrist lags its target, which the brute force calls a motor
    failure and no moment sees (a false safe before the chain watched tracking)."""
    from critmoment import demos, groundtruth
    from critmoment.recording import rollout

    traj = demos.scripted_transfer(8, twin=twin)
    rec = rollout(traj, twin=twin)
    held = rec.signals.contact_gripper & ~rec.signals.contact_support[:, None]
    start = int(np.flatnonzero(held.any(axis=1))[0]) - 200
    samples = np.array([[0.19594991677440704, 0.7830319359898568], scenario.box.nominal])
    chain = history.chained_failures(sparse.SparseEvaluator(rec, twin), [start], samples)
    truth = groundtruth.brute_force(traj, twin=twin, samples=samples).classification
    # the lag comes first (the cube also turns in the shifted grip 0.2 s later: a slip)
    assert truth.outcome[0].value == "motor"
    assert truth.slip_step[0] == -1 or truth.slip_step[0] > truth.motor_step[0]
    np.testing.assert_array_equal(chain.failed, [True, False])
    assert abs(chain.motor_step[0] - truth.motor_step[0]) <= 2
    # a joint lagging its target, which both name so (not a saturation)
    assert truth.motor_tracking[0] == chain.motor_tracking[0]
    assert chain.kinds()[0] == ("tracking" if truth.motor_tracking[0] else "motor")


def test_a_chain_that_goes_non_finite_between_the_moments_fails(twin, demo_recording):
    """A simulation whose readings turn NaN between the moments, without MuJoCo raising,
    has diverged: the watch fails it (it would otherwise pass every rule, NaN comparing
    false)."""
    from critmoment.groundtruth import OutcomeCriteria

    ev = sparse.SparseEvaluator(demo_recording, twin)
    watch = history._Watch(ev, 2, OutcomeCriteria())
    k, s = 1000, 5
    model = twin.model
    sd = np.zeros((2, s, model.nsensordata))
    xpos = np.zeros((2, s, model.nbody, 3))
    xmat = np.tile(np.eye(3).ravel(), (2, s, model.nbody, 1))
    qpos = np.tile(demo_recording.states[k + 1:k + s + 1, 1:1 + model.nq], (2, 1, 1))
    sd[1, 3, 0] = np.nan
    watch(k, np.array([0, 1]), sd, xpos, xmat, qpos)
    np.testing.assert_array_equal(watch.diverged_step, [-1, k + 3])
    np.testing.assert_array_equal(watch.failed(), [False, True])


@pytest.mark.parametrize("seed", range(5))
def test_streamed_run_lengths_equal_counting_step_by_step(seed):
    """The watch's vectorised run lengths (history._runs) give the run lengths and the first
    step a run reaches its length that a step-by-step count gives, across block borders."""
    rng = np.random.default_rng(seed)
    c, r, need = 4, 3, 5
    flags = rng.random((c, 40, r)) < 0.8
    count = np.zeros((c, r), np.int64)
    first_loop = np.full(c, -1)
    for j in range(40):
        count = (count + 1) * flags[:, j]
        hit = (count >= need).any(axis=1) & (first_loop < 0)
        first_loop[hit] = j
    run = np.zeros((c, r), np.int64)
    first = np.full(c, -1)
    for lo in range(0, 40, 7):  # uneven blocks
        run, f = history._runs(run, flags[:, lo:lo + 7], need)
        new = (f >= 0) & (first < 0)
        first[new] = lo + f[new]
    np.testing.assert_array_equal(run, count)
    np.testing.assert_array_equal(first, first_loop)


def test_the_chain_watches_past_the_release_to_the_end_of_the_run():
    """The ground truth watches a run to its end; so does the chain. On the bundled Panda
    the nominal run lets go of the cube 1.2 s before its end: a chain started after the
    release still steps to the last step, and a motor rule that fires there (saturation at
    1e-6 of the limit: any loaded joint) is seen after the hold."""
    import critmoment as cm
    from critmoment import panda_demo
    from critmoment.groundtruth import OutcomeCriteria

    twin = cm.Twin(cm.load_scenario("panda_pick_place"))
    rec = cm.rollout(panda_demo.make_pick_place(0), twin=twin)
    ev = sparse.SparseEvaluator(rec, twin)
    last_held = int(np.flatnonzero(ev._carried)[-1])
    assert last_held < ev.n_steps - 200
    start = last_held + 50
    chain = history.chained_failures(ev, [start], twin.scenario.box.nominal[None],
                                     start=start, criteria=OutcomeCriteria(saturation=1e-6))
    assert chain.end == ev.n_steps
    assert chain.motor_step[0] > last_held and chain.failed[0]


def test_the_chain_starts_before_the_object_is_first_touched(scenario, twin, demo_recording):
    """The cube's mass and friction act once something other than the table touches it:
    the chain starts ONSET_MARGIN (or the horizon, if longer) before the nominal run's
    first touch, not at a first moment that sits on the touch, where the restored nominal
    state is mid-way through the contact's onset. A moment before that margin starts it."""
    import math

    ev = sparse.SparseEvaluator(demo_recording, twin)
    touch = int(np.flatnonzero(demo_recording.signals.contact_gripper.any(axis=1))[0])
    margin = max(ev.horizon, math.ceil(history.ONSET_MARGIN / twin.model.opt.timestep))
    assert history.chain_start(ev, [touch, touch + 300]) == touch - margin
    assert history.chain_start(ev, [touch + 300, touch - 400]) == touch - 400
    # the cheaper start on request (start=None); by default a chain starts at step 0
    chain = history.chained_failures(ev, [touch], scenario.box.nominal[None], start=None)
    assert chain.start == touch - margin and not chain.failed[0]
    assert history.chained_failures(ev, [touch], scenario.box.nominal[None]).start == 0
    # the scan of the recorded states agrees with the touch sensors
    run = history.NominalOnsets(ev, touch + 10)
    assert run.first_contact(run.object_geoms, run.support_geoms) == touch
    # with the table itself it touches from the first steps (it settles from its spawn)
    assert run.first_contact(run.object_geoms, frozenset()) < 10


def test_parameter_onsets_on_the_nominal_run(scenario, twin, demo_recording):
    """Where each kind of parameter can first change the motion: a force limit once the
    nominal force reaches the range's low end (never if it stays below), a finger pad's
    friction at the pad's first contact with anything, the object's mass at its first touch,
    its centre of mass and the mass of a robot link from the start."""
    from critmoment.params import ForceLimitParameter, FrictionParameter, MassParameter

    ev = sparse.SparseEvaluator(demo_recording, twin)
    run = history.NominalOnsets(ev, ev.n_steps)
    model = twin.model
    i = twin.actuator_names.index("right/elbow")
    force = np.abs(np.asarray(demo_recording.signals.actuator_force)[:, i])
    low = float(np.quantile(force, 0.9))
    limit = ForceLimitParameter("elbow", "right/elbow", low, 2 * low, 1.5 * low)
    assert limit.onset(limit.resolve(model), run) == int(np.flatnonzero(force >= low)[0])
    never = ForceLimitParameter("elbow", "right/elbow", 2 * force.max(), 3 * force.max(),
                                2 * force.max())
    assert never.onset(never.resolve(model), run) == ev.n_steps
    pad = scenario.grippers[0].geoms[0]
    friction = FrictionParameter("pad", pad, 0.5, 1.5, 1.0)
    # the left gripper starts closed, its pads pressed on each other
    assert friction.onset(friction.resolve(model), run) == 0
    link = MassParameter("link", model.body(model.geom_bodyid[model.geom(pad).id]).name,
                         0.1, 1.0, 0.5)
    assert link.onset(link.resolve(model), run) == 0
    # the object's mass acts at the first touch; its centre of mass from the start (an
    # offset can tip it over on its own)
    from critmoment.params import ComOffsetParameter

    touch = int(np.flatnonzero(demo_recording.signals.contact_gripper.any(axis=1))[0])
    body = scenario.object_body
    mass = MassParameter("m", body, 0.05, 1.0, 0.1)
    assert mass.onset(mass.resolve(model), run) == touch
    com = ComOffsetParameter("c", body, -0.01, 0.01, 0.0)
    assert com.onset(com.resolve(model), run) == 0


def test_the_chain_applies_the_task_rule_at_the_end_of_the_run():
    """A sample that passes every moment and the watch to the end is still decided by the
    task's success rule over its whole run, as the ground truth's NOT_COMPLETED is: with the
    bundled Panda's goal moved 5 cm away, every sample that keeps its cube is incomplete in
    the chain and in its full rollout; at the real goal the nominal sample completes, and
    the 1.5 kg cube, dropped, is incomplete in both."""
    import dataclasses

    import critmoment as cm
    from critmoment import groundtruth, panda_demo

    sc = cm.load_scenario("panda_pick_place")
    traj = panda_demo.make_pick_place(0)
    samples = np.array([[0.1, 1.0], [0.6, 1.0], [1.5, 0.5]])
    goal = tuple(np.add(sc.task.goal, (0.05, 0.0, 0.0)))
    for moved in (False, True):
        scenario = sc.replace(task=dataclasses.replace(sc.task, goal=goal)) if moved else sc
        twin = cm.Twin(scenario)
        rec = cm.rollout(traj, twin=twin)
        assert rec.completed is not moved
        ev = sparse.SparseEvaluator(rec, twin)
        touch = int(np.flatnonzero(rec.signals.contact_gripper.any(axis=1))[0])
        chain = history.chained_failures(ev, [touch], samples)
        truth = groundtruth.brute_force(traj, twin=twin, samples=samples).classification
        # a dropped cube runs on to the end too, where it is incomplete (the ground truth's
        # DROPPED outcome is an incomplete run with a drop)
        np.testing.assert_array_equal(chain.incomplete, ~truth.completed)
        np.testing.assert_array_equal(chain.failed, truth.failed)
        assert chain.incomplete[0] is np.bool_(moved)


def test_a_drop_fails_a_chained_sample_only_where_the_task_ends_incomplete():
    """As in the ground truth, a drop alone fails nothing: with a 2 ms drop time, the
    bundled Panda's 0.2 kg cube leaves both fingers a few steps before the nominal release
    (a drop by that rule) and is still placed; the chain records the drop, steps on to the
    end and passes the sample, as its full rollout does."""
    import critmoment as cm
    from critmoment import groundtruth, panda_demo
    from critmoment.groundtruth import OutcomeCriteria

    twin = cm.Twin(cm.load_scenario("panda_pick_place"))
    traj = panda_demo.make_pick_place(0)
    rec = cm.rollout(traj, twin=twin)
    ev = sparse.SparseEvaluator(rec, twin)
    touch = int(np.flatnonzero(rec.signals.contact_gripper.any(axis=1))[0])
    samples = twin.scenario.box.nominal[None].copy()
    samples[0, twin.scenario.box.index("mass")] = 0.2
    criteria = OutcomeCriteria(drop_time=0.002)
    chain = history.chained_failures(ev, [touch], samples, criteria=criteria)
    truth = groundtruth.brute_force(traj, twin=twin, samples=samples,
                                    criteria=criteria).classification
    assert chain.drop_step[0] >= 0 and truth.drop_step[0] >= 0
    assert truth.outcome[0] is groundtruth.Outcome.SUCCESS
    assert not chain.incomplete[0] and not chain.failed[0]
    assert chain.stepped == ev.n_steps - chain.start  # it ran on to the end


@pytest.mark.parametrize("seed", range(4))
def test_streamed_sustained_level_equals_the_direct_one(seed):
    """The watch's streamed sustained level (history.SustainedLevel): the highest level a
    signal held for ``need`` consecutive steps, per sample the largest over columns, equal
    across uneven block borders to the direct max over windows of the window's min."""
    rng = np.random.default_rng(seed)
    c, t, r, need = 3, 50, 4, 6
    values = rng.normal(size=(c, t, r))
    windows = np.lib.stride_tricks.sliding_window_view(values, need, axis=1)
    direct = windows.min(axis=-1).max(axis=(1, 2))
    level = history.SustainedLevel(c, r, need)
    ids = np.arange(c)
    for lo, hi in [(0, 2), (2, 3), (3, 17), (17, 17), (17, 50)]:
        level.update(ids, values[:, lo:hi])
    np.testing.assert_allclose(level.best, direct, rtol=0, atol=0)
    # a signal shorter than the duration never held any level
    short = history.SustainedLevel(1, 1, need)
    short.update(np.array([0]), np.ones((1, need - 1, 1)))
    assert short.best[0] == -np.inf


def test_a_chained_pass_close_to_a_rule_goes_to_its_own_rollout(scenario, demo_traj,
                                                                demo_recording, monkeypatch):
    """With the right elbow's limit 15 % over the nominal carry's peak, the nominal cube's
    chain passes but holds the arm's motors at about 70 % of their limits for longer than
    the ground truth's motor time: its closest level is the one computed from the recorded
    forces (the nominal chain is the nominal run), so it is near just under that level and
    not just over it, and with verification from there the audit's chained evidence sends
    it to its own rollout; the 1 kg cube fails (a failure is never near)."""
    from critmoment import analysis
    from critmoment import verdict as vd
    from critmoment.groundtruth import OutcomeCriteria
    from critmoment.recording import rollout
    from critmoment.twin import Twin

    sig = demo_recording.signals
    carry = np.flatnonzero((sig.contact_gripper & ~sig.contact_support[:, None]).any(axis=1))
    i = Twin(scenario).actuator_names.index("right/elbow")
    peak = np.abs(np.asarray(sig.actuator_force)[carry, i]).max()
    twin = Twin(scenario.replace(limits={**scenario.limits, "right/elbow": float(1.15 * peak)}))
    rec = rollout(demo_traj, twin=twin)
    samples = np.tile(scenario.box.nominal, (2, 1))
    samples[1, scenario.box.index("mass")] = 1.0
    start = int(carry[0]) - 200
    ev = sparse.SparseEvaluator(rec, twin)
    chain = history.chained_failures(ev, [start], samples)
    np.testing.assert_array_equal(chain.failed, [False, True])
    criteria = OutcomeCriteria()
    rot = np.flatnonzero(twin.rotational)
    load = np.abs(np.asarray(rec.signals.actuator_force)[start:, rot] / twin.limits[rot])
    need = criteria.steps(criteria.motor_time, float(twin.model.opt.timestep))
    windows = np.lib.stride_tricks.sliding_window_view(load / criteria.saturation, need,
                                                       axis=0)
    expected = windows.min(axis=-1).max()
    assert 0.5 < expected < 0.95
    np.testing.assert_allclose(chain.closest[0], expected, rtol=1e-12)
    np.testing.assert_array_equal(chain.near(expected - 0.01), [True, False])
    np.testing.assert_array_equal(chain.near(expected + 0.01), [False, False])
    for bad in (0, -0.5, float("nan"), "0.8", True):
        with pytest.raises(ParameterError, match="fraction"):
            chain.near(bad)
    # the decision's chained evidence: the near pass is decided by its rollout
    sweep = ev.evaluate([start], samples)
    dopt = vd.DecisionOptions(threshold=scenario.cost.threshold, verify=expected - 0.01)
    none = np.zeros(2, bool)
    chained, failed, rolled, kinds, first = analysis.chain_samples(
        ev, np.array([start]), samples, sweep, none, dopt)
    assert chained[0] and not failed[0] and rolled[0]
    assert len(kinds) == 2 and kinds[0] is None and first[0] == -1  # a pass: no failure
    for verify in (None, expected + 0.01):
        off = dataclasses.replace(dopt, verify=verify)
        assert not analysis.chain_samples(ev, np.array([start]), samples, sweep, none,
                                          off)[2][0]
    # a point chained before (the region check's next round) keeps its result unstepped
    before: dict = {}
    first = analysis.chain_samples(ev, np.array([start]), samples, sweep, none, dopt,
                                   chained_before=before)
    assert len(before) == 2

    def no_chain(*args, **kwargs):
        raise AssertionError("chained again")

    monkeypatch.setattr(history, "chained_failures", no_chain)
    again = analysis.chain_samples(ev, np.array([start]), samples[::-1], sweep, none, dopt,
                                   chained_before=before)
    for a, b in zip(first, again, strict=True):
        assert list(a) == list(b)[::-1]


def test_a_chain_from_the_start_is_the_samples_full_rollout(twin, demo_traj, demo_recording):
    """From step 0 a chain steps the sample's own full run, bit for bit as its brute-force
    rollout does: the object's largest slip in the grip is the ground truth's to 1e-12 (the
    cheaper start before the first touch is not exact: the object's mass already sets how
    it rests, and on a chaotic model that flips outcomes)."""
    from critmoment.groundtruth import Outcome, brute_force

    ev = sparse.SparseEvaluator(demo_recording, twin)
    samples = np.array([[0.05, 1.0], [0.6, 0.3], [1.5, 1.0], [3.0, 0.5]])
    last = demo_recording.n_steps - 2 * ev.horizon
    chain = history.chained_failures(ev, [last], samples)
    assert chain.start == 0
    gt = brute_force(demo_traj, twin=twin, samples=samples).classification
    assert (gt.max_slip > 0.01).any() and (gt.max_slip > 0).sum() >= 2
    np.testing.assert_allclose(chain.max_slip, gt.max_slip, rtol=0, atol=1e-12)
    real = np.array([o is not Outcome.SUCCESS for o in gt.outcome])
    assert real.any() and not real.all()
    np.testing.assert_array_equal(chain.failed, real)
    # the same saturation, counted from the same step (the chain's index is the step after)
    both = (chain.motor_step >= 0) & (gt.motor_step >= 0)
    assert both.any()
    np.testing.assert_array_equal(np.abs(chain.motor_step - gt.motor_step)[both] <= 1, True)


def _regrasp(traj):
    """The bundled Panda's pick-and-place, then back down to the placed cube, a regrasp, a
    lift, a second placing and release (785 actions)."""
    a = np.asarray(traj.actions)

    def arm(rows, grip):
        out = np.array(rows, dtype=np.float64)
        out[:, -1] = grip
        return out

    down, up, place = a[445:395:-1], a[395:445], np.repeat(a[395][None], 15, axis=0)
    parts = [a, arm(down, 1.0), arm(place, np.linspace(1, 0, 15)), arm(place, 0.0),
             arm(up, 0.0), arm(np.repeat(a[445][None], 30, axis=0), 0.0), arm(down, 0.0),
             arm(np.repeat(a[395][None], 25, axis=0), np.linspace(0, 1, 25)), arm(up, 1.0)]
    return dataclasses.replace(traj, actions=np.concatenate(parts))


def test_a_regrasp_starts_slip_afresh_alike_in_chains_sparse_and_ground_truth():
    """Each hold of a nominal run that regrasps is measured from its own grasp
    (``Twin.hold_segments``): the chain keeps equal to the brute force to 1e-12 over a
    release and a regrasp, sparse evaluation anchors a moment of the second hold at the
    second grasp, and a contact that flickers without the command opening starts nothing."""
    from critmoment import panda_demo
    from critmoment.groundtruth import brute_force

    twin = cm.Twin(cm.load_scenario("panda_pick_place"))
    traj = _regrasp(panda_demo.make_pick_place(0))
    rec = cm.rollout(traj, twin=twin)
    assert rec.completed
    sig = rec.signals
    segments = twin.hold_segments(rec.controls, sig.contact_gripper)
    held = sig.contact_gripper[:, 0] & ~sig.contact_support
    assert segments[:, 0].max() == 2 and (np.diff(segments[:, 0]) >= 0).all()
    firsts = [int(np.argmax(held & (segments[:, 0] == j))) for j in range(2)]
    assert 0 < firsts[0] < firsts[1]
    # the second hold's grasp is well after the first release ends; the last segment,
    # after the second release, holds nothing
    assert not held[firsts[1] - 100:firsts[1]].any()
    assert not held[segments[:, 0] == 2].any()
    # a 0.1 s flicker of the contact while the command stays closed is no new hold
    flicker = sig.contact_gripper.copy()
    mid = (firsts[0] + np.flatnonzero(segments[:, 0] == 1)[0]) // 2
    flicker[mid:mid + int(0.1 / rec.dt), 0] = False
    np.testing.assert_array_equal(twin.hold_segments(rec.controls, flicker), segments)

    ev = sparse.SparseEvaluator(rec, twin)
    start, _ = ev._grasp()
    # each hold's anchor: its first step touched once its grasp has formed (the object
    # still on the table: the slide of the fingers during the lift-off counts)
    formed = twin.grasp_formed(rec.controls, sig.contact_gripper, rec.sensordata)[:, 0]
    touched = sig.contact_gripper[:, 0] & formed
    anchors = [int(np.argmax(touched & (segments[:, 0] == j))) for j in range(2)]
    assert anchors[0] <= firsts[0] and anchors[1] <= firsts[1]
    for j, first in enumerate([*anchors, -1]):
        assert (start[segments[:, 0] == j, 0] == first).all()
    samples = np.array([[0.05, 1.0], [0.9, 0.76], [1.7, 0.94], [0.8, 0.3]])
    chain = history.chained_failures(ev, [rec.n_steps - 2 * ev.horizon], samples)
    gt = brute_force(traj, twin=twin, samples=samples).classification
    assert (gt.max_slip > 1e-4).sum() >= 3
    np.testing.assert_allclose(chain.max_slip, gt.max_slip, rtol=0, atol=1e-12)


def test_the_first_watched_failure_decides_whether_a_rollout_confirms_it():
    """A slip during the hold stands even if the sample's motor rule also fires after the
    release before its block of steps ends (what the rules see after the first failure
    depends on the block's length); a first failure after the release goes to a rollout."""
    F = sparse.Failure
    quiet = np.full((1, 2), F.PASS, dtype=np.int8)
    result = history.ChainedResult(steps=np.array([100]), samples=np.zeros((2, 2)),
                                   failure=quiet, start=0, stepped=0, end=400,
                                   slip_step=np.array([200, 300]),
                                   drop_step=np.full(2, -1),
                                   motor_step=np.array([260, -1]), max_slip=np.zeros(2),
                                   incomplete=np.zeros(2, bool), release=250)
    np.testing.assert_array_equal(result.failed, [True, True])
    np.testing.assert_array_equal(result.to_confirm, [False, True])


def test_the_chains_decisions_do_not_depend_on_its_block_length(twin, demo_recording):
    ev = sparse.SparseEvaluator(demo_recording, twin)
    samples = np.array([[0.05, 1.0], [0.6, 0.3], [3.0, 0.5], [8.0, 1.4]])
    steps = [1946, 2290, 3406]
    runs = [history.chained_failures(ev, steps, samples, block=b) for b in (100, 400, 1000)]
    for other in runs[1:]:
        np.testing.assert_array_equal(other.failure, runs[0].failure)
        np.testing.assert_array_equal(other.failed, runs[0].failed)
        np.testing.assert_array_equal(other.to_confirm, runs[0].to_confirm)
        np.testing.assert_array_equal(other.near(0.8), runs[0].near(0.8))
    assert runs[0].failed.any() and not runs[0].failed.all()


def test_a_chain_shared_out_to_two_threads_is_the_chain_in_one(twin, demo_recording):
    # each sample's chain is its own: two Python threads, each with one MuJoCo thread and
    # half the samples, give every field of the result to the bit
    samples = np.array([[0.05, 1.0], [0.6, 0.3], [3.0, 0.5], [8.0, 1.4], [0.3, 0.9]])
    steps = [1946, 2290, 3406]
    one = history.chained_failures(sparse.SparseEvaluator(demo_recording, twin, nthread=1),
                                   steps, samples, block=1000)
    ev = sparse.SparseEvaluator(demo_recording, twin, nthread=2)
    assert ev._parts(samples.shape[0], history._SPLIT_LEAST) == 2
    two = history.chained_failures(ev, steps, samples, block=1000)
    for f in dataclasses.fields(history.ChainedResult):
        a, b = getattr(one, f.name), getattr(two, f.name)
        if isinstance(a, np.ndarray):
            np.testing.assert_array_equal(b, a, err_msg=f.name)
        else:
            assert b == a, f.name
    assert one.failed.any() and not one.failed.all()
