"""Tests of critmoment.verdict: the pure decision (no simulation), on hand-made evidence."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from critmoment import verdict as vd
from critmoment.exceptions import ParameterError
from critmoment.moments import Moment, MomentLabel
from critmoment.params import FrictionParameter, MassParameter, UncertaintyBox
from critmoment.scenario import CostParams
from critmoment.sparse import SparseMode, SparseResult

THRESHOLD = 0.9
#: the decision without chained segments (tested on their own below)
OPT = vd.DecisionOptions(threshold=THRESHOLD, chain=False)


def _box(mass_high: float = 1.0) -> UncertaintyBox:
    return UncertaintyBox((MassParameter("mass", "box", 0.05, mass_high, 0.05),
                           FrictionParameter("friction", "box", 0.2, 1.5, 1.0)))


def _sweep(cost: np.ndarray, samples: np.ndarray, *, unlifted: np.ndarray | None = None,
           diverged: np.ndarray | None = None,
           sticking: np.ndarray | None = None) -> SparseResult:
    """A SparseResult of m moments × n samples with the given costs (the rest neutral)."""
    cost = np.atleast_2d(np.asarray(cost, dtype=np.float64))
    m, n = cost.shape
    diverged = np.zeros((m, n), bool) if diverged is None else diverged
    return SparseResult(
        steps=np.arange(m, dtype=np.int64) * 100 + 100, samples=np.asarray(samples, float),
        parameter_names=("mass", "friction"), gripper_names=("g",), actuator_names=("a",),
        horizon=1, mode=SparseMode.STEP, cost_params=CostParams(threshold=THRESHOLD),
        fos_contact=np.full((m, n, 1), 2.0), fos_grasp=np.full((m, n), 2.0),
        fos_motor=np.full((m, n), 3.0), motor_argmax=np.zeros((m, n), np.int64),
        cost=np.where(diverged, np.inf, cost), cost_contact=cost, cost_motor=np.zeros((m, n)),
        object_acc=np.zeros((m, n, 3)), actuator_norm=np.zeros((m, n, 1)),
        contact_support=np.zeros((m, n), bool), contact_gripper=np.ones((m, n, 1), bool),
        stage=np.full((m, n), 4, np.int8), worst_step=np.zeros((m, n), np.int64),
        diverged=diverged,
        unlifted_failure=np.zeros((m, n), bool) if unlifted is None else unlifted,
        sticking_failure=np.zeros((m, n), bool) if sticking is None else sticking)


def _grid(box: UncertaintyBox, n: int = 21) -> np.ndarray:
    u = np.linspace(0.0, 1.0, n)
    g0, g1 = np.meshgrid(u, u, indexing="ij")
    return box.from_unit(np.stack([g0.ravel(), g1.ravel()], axis=1))


def _cost(samples: np.ndarray) -> np.ndarray:
    """Heavy and slippery fails: cost = threshold on the line mass = 0.4·friction."""
    return THRESHOLD * samples[:, 0] / (0.4 * samples[:, 1])


def _moment(step: int, critical=None, side=None) -> vd.MomentReport:
    m = Moment(step=step, time=step * 0.002, label=MomentLabel.LIFT_OFF, reason="test")
    return vd.MomentReport(moment=m, worst_case={"mass": 1.0, "friction": 0.2}, max_cost=2.0,
                           min_fos_contact=1.0, min_fos_motor=3.0,
                           critical=critical or {"mass": None, "friction": None},
                           critical_side=side or {"mass": None, "friction": None},
                           dominant="contact", limiting_actuator="a", fail_fraction=0.5)


# --------------------------------------------------------------------------
# which samples fail
# --------------------------------------------------------------------------


def test_a_chained_failure_fails_a_sample_that_passes_without_a_rollout():
    chain = vd.DecisionOptions(threshold=THRESHOLD, chain=True)
    samples = np.array([[0.1, 1.0], [0.5, 1.0], [0.3, 1.0], [0.2, 1.0]])
    sweep = _sweep([[0.1, 1.5, 0.8, 0.5]], samples)
    near, *_ = vd.samples_to_rerun(sweep, chain, nominal_completed=True)
    # passing, no rollout: samples 0 and 3 are carried on their own state
    to_chain = vd.samples_to_chain(sweep, near, chain)
    assert to_chain.tolist() == [True, False, False, True]
    base = dict(sweep=sweep, nominal_completed=True, rerun=near,
                rerun_failed=np.array([False, False, False, False]))
    with pytest.raises(ParameterError, match="chained evaluation of every sample"):
        vd.failing_samples(vd.SampleEvidence(**base), chain)
    ev = vd.SampleEvidence(**base, chained=to_chain,
                           chained_failed=np.array([False, False, False, True]))
    # sample 3 fails on its own history; sample 1 fails at the moments; 2 passed its rollout
    assert vd.failing_samples(ev, chain).tolist() == [False, True, False, True]
    assert not vd.samples_to_chain(sweep, near, OPT).any()


def test_the_causes_count_the_samples_that_fail_only_on_their_own_path():
    """Samples that pass every moment but fail their chain are failures no moment's line
    counts ("fails 0% of the box"): a cause says how many, so that a low P(success) with
    quiet moments is explained."""
    chain = vd.DecisionOptions(threshold=THRESHOLD, chain=True)
    box = _box()
    samples = np.array([[0.1, 1.0], [0.5, 1.0], [0.3, 1.0], [0.2, 1.0]])
    sweep = _sweep([[0.1, 1.5, 0.3, 0.5]], samples)
    near, *_ = vd.samples_to_rerun(sweep, chain, nominal_completed=True)
    to_chain = vd.samples_to_chain(sweep, near, chain)
    assert to_chain.tolist() == [True, False, True, True]

    def causes(chained_failed):
        se = vd.SampleEvidence(sweep=sweep, nominal_completed=True, rerun=near,
                               rerun_failed=np.zeros(4, bool), chained=to_chain,
                               chained_failed=np.array(chained_failed))
        ev = vd.Evidence(box=box, samples=se, nominal_cost=0.1, moments=(_moment(100),))
        return vd.decide(ev, chain).causes

    assert any("2 of 3 samples that pass at every audited moment fail on their own path"
               in c for c in causes([False, False, True, True]))
    assert not any("on their own path" in c for c in causes([False, False, False, False]))


def test_failures_only_where_the_nominal_run_fails_too_are_decided_by_rollouts():
    """A sample restored from the nominal run's state at a moment where the nominal
    parameters fail too inherits that state, and is decided by its own rollout; while the
    nominal run completes its task (which overrules its parameters' sparse failure: genesis'
    franka_sim Panda, a shoulder at 99.3 % of its limit through the lift), a sample that
    also fails where the nominal parameters do not stays a failure. While the nominal run
    does not complete its task, every failing sample is decided by its own rollout: that
    run may have gone wrong before any moment fails (an ALOHA wrist turn that shifted the
    nominal cube in the grip; two heavier samples failed at the hand-over restored from
    that state and really hand it over)."""
    chain = vd.DecisionOptions(threshold=THRESHOLD, chain=True)
    samples = np.array([[0.1, 1.0], [0.5, 1.0], [0.3, 1.0], [0.2, 1.0]])
    # moment 0: the nominal fails there; moment 1: it does not
    sweep = _sweep([[1.5, 0.1, 1.5, 0.1], [0.1, 1.5, 1.5, 0.1]], samples)
    nominal_failed = np.array([True, False])
    assert vd.inherited_failures(sweep, nominal_failed,
                                 nominal_completed=True).tolist() == [True, False, False,
                                                                      False]
    assert not vd.inherited_failures(sweep, nominal_failed, nominal_completed=True,
                                     trust_run=False).any()
    assert vd.inherited_failures(sweep, nominal_failed,
                                 nominal_completed=False).tolist() == [True, True, True,
                                                                       False]
    assert not vd.inherited_failures(sweep, None, nominal_completed=False).any()
    for completed, inherited in ((True, [True, False, False, False]),
                                 (False, [True, True, True, False])):
        reruns = vd.samples_to_rerun(sweep, chain, nominal_completed=completed,
                                     nominal_failed=nominal_failed)
        assert reruns.inherited.tolist() == inherited
        assert reruns.any.tolist() == inherited
        to_chain = vd.samples_to_chain(sweep, reruns.any, chain, nominal_completed=completed)
        base = dict(sweep=sweep, nominal_completed=completed, chained=to_chain,
                    chained_failed=np.zeros(4, bool), nominal_failed=nominal_failed)
        with pytest.raises(ParameterError, match="own rollout's outcome"):
            vd.failing_samples(vd.SampleEvidence(**base), chain)
        real = np.array([False, False, True, False])  # sample 1 hands over on its own run
        ev = vd.SampleEvidence(**base, rerun=reruns.any, rerun_failed=real)
        # sample 0 placed its cube on its own run; with the nominal run completing, 1 and
        # 2 fail where the nominal parameters did not, and stay failures
        expect = [False, True, True, False] if completed else [False, False, True, False]
        assert vd.failing_samples(ev, chain).tolist() == expect
    with pytest.raises(ParameterError, match="nominal_failed"):
        vd.inherited_failures(sweep, np.array([True]), nominal_completed=False)


def test_a_nominal_run_that_fails_its_task_leaves_each_sample_to_its_own_run():
    """The nominal parameters fail the task (UNSAFE either way); with the chained segments
    each sample that passes the moments is decided by its own run, which ends with the
    task's rule (a Panda + Robotiq 2F-85 spawn whose nominal run drops its cube while 28 of
    64 samples place theirs); without them every sample fails, since sparse evaluation
    never sees the task's rule."""
    chain = vd.DecisionOptions(threshold=THRESHOLD, chain=True)
    plain = vd.DecisionOptions(threshold=THRESHOLD, chain=False)
    box = _box()
    samples = np.array([[0.1, 1.0], [0.5, 1.0], [0.3, 1.0], [0.2, 1.0]])
    sweep = _sweep([[0.1, 1.5, 0.3, 0.5]], samples)
    near, *_ = vd.samples_to_rerun(sweep, chain, nominal_completed=False)
    to_chain = vd.samples_to_chain(sweep, near, chain, nominal_completed=False)
    assert to_chain.tolist() == [True, False, True, True]
    se = vd.SampleEvidence(sweep=sweep, nominal_completed=False, rerun=near,
                           rerun_failed=np.zeros(4, bool), chained=to_chain,
                           chained_failed=np.array([False, False, True, False]))
    assert vd.failing_samples(se, chain).tolist() == [False, True, True, False]
    decision = vd.decide(vd.Evidence(box=box, samples=se, nominal_cost=0.1,
                                     moments=(_moment(100),)), chain)
    assert decision.verdict is vd.Verdict.UNSAFE and decision.p_success == 0.5
    bare = vd.SampleEvidence(sweep=sweep, nominal_completed=False)
    assert vd.failing_samples(bare, plain).all()
    decision = vd.decide(vd.Evidence(box=box, samples=bare, nominal_cost=0.1,
                                     moments=(_moment(100),)), plain)
    assert decision.verdict is vd.Verdict.UNSAFE and decision.p_success == 0.0
    # the cause names the stages, not only their numbers
    named = vd.decide(vd.Evidence(box=box, samples=bare, nominal_cost=0.1,
                                  moments=(_moment(100),), nominal_stage=(4, 0),
                                  stage_names=("untouched", "touched", "carried", "placed",
                                               "released")), plain)
    assert any("(stage 4 (released) reached, final stage 0 (untouched);" in c
               for c in named.causes)


def test_failing_samples_is_the_sparse_failure_unless_a_rollout_decided():
    samples = np.array([[0.1, 1.0], [0.5, 1.0], [0.3, 1.0], [0.2, 1.0]])
    sweep = _sweep([[0.1, 1.5, 0.8, 0.5]], samples)
    near, unlifted, *_ = vd.samples_to_rerun(sweep, OPT, nominal_completed=True)
    assert near.tolist() == [False, False, True, False]  # 0.8 ≥ 0.8 × 0.9, passes
    assert not unlifted.any()
    with pytest.raises(ParameterError, match="own rollout"):
        vd.failing_samples(vd.SampleEvidence(sweep=sweep, nominal_completed=True), OPT)
    ev = vd.SampleEvidence(sweep=sweep, nominal_completed=True, rerun=near,
                           rerun_failed=np.array([False, False, True, False]))
    assert vd.failing_samples(ev, OPT).tolist() == [False, True, True, False]
    # without verification the sparse evaluation alone decides
    plain = vd.DecisionOptions(threshold=THRESHOLD, verify=None, chain=False)
    assert vd.failing_samples(vd.SampleEvidence(sweep=sweep, nominal_completed=True),
                              plain).tolist() == [False, True, False, False]
    # a nominal run that fails the task fails every sample, and nothing is re-run
    assert not any(m.any() for m in vd.samples_to_rerun(sweep, OPT, nominal_completed=False))
    assert vd.failing_samples(vd.SampleEvidence(sweep=sweep, nominal_completed=False),
                              OPT).all()


def test_sticking_failures_are_decided_by_rollouts():
    """A sample whose only failures are sticking ones (or sticking and unlifted) needs its
    own rollout, which decides it; one that also fails otherwise at some moment fails."""
    samples = np.array([[0.1, 1.0], [0.5, 1.0], [0.3, 1.0], [0.2, 1.0], [0.4, 1.0]])
    cost = [[1.2, 1.2, 1.2, 1.2, 1.2], [0.1, 1.2, 1.2, 0.1, 1.2]]
    # 0: sticking once; 1: sticking, then unlifted; 2: sticking twice; 3: unlifted only;
    # 4: sticking, then a failure of its own
    stick = np.array([[True, True, True, False, True], [False, False, True, False, False]])
    unl = np.array([[False, False, False, True, False], [False, True, False, False, False]])
    sweep = _sweep(cost, samples, unlifted=unl, sticking=stick)
    np.testing.assert_array_equal(sweep.failed_sticking_only,
                                  [True, True, True, False, False])
    near, unlifted, sticking, *_ = vd.samples_to_rerun(sweep, OPT, nominal_completed=True)
    assert sticking.tolist() == [True, True, True, False, False] and not near.any()
    assert unlifted.tolist() == [False, False, False, True, False]
    with pytest.raises(ParameterError, match="own rollout"):
        vd.failing_samples(vd.SampleEvidence(sweep=sweep, nominal_completed=True,
                                             rerun=unlifted, rerun_failed=np.zeros(5, bool)),
                           OPT)
    rerun = vd.samples_to_rerun(sweep, OPT, nominal_completed=True).any
    ev = vd.SampleEvidence(sweep=sweep, nominal_completed=True, rerun=rerun,
                           rerun_failed=np.array([False, True, False, False, False]))
    assert vd.failing_samples(ev, OPT).tolist() == [False, True, False, False, True]
    off = dataclasses.replace(OPT, verify_sticking=False)
    assert not vd.samples_to_rerun(sweep, off, nominal_completed=True).sticking.any()
    with pytest.raises(ParameterError, match="verify_sticking: expected True or False"):
        dataclasses.replace(OPT, verify_sticking="no")


def test_unlifted_failures_are_decided_by_rollouts():
    samples = np.array([[0.1, 1.0], [0.5, 1.0]])
    unl = np.array([[True, False]])
    sweep = _sweep([[1.2, 1.2]], samples, unlifted=unl)
    near, unlifted, *_ = vd.samples_to_rerun(sweep, OPT, nominal_completed=True)
    assert unlifted.tolist() == [True, False] and not near.any()
    ev = vd.SampleEvidence(sweep=sweep, nominal_completed=True, rerun=unlifted,
                           rerun_failed=np.zeros(2, bool))
    assert vd.failing_samples(ev, OPT).tolist() == [False, True]


# --------------------------------------------------------------------------
# the safe region
# --------------------------------------------------------------------------


def test_safe_subbox_keeps_failures_out_of_the_region():
    box = _box()
    rng = np.random.default_rng(3)
    x = box.from_unit(rng.uniform(0.0, 1.0, size=(400, 2)))
    failed = _cost(x) > THRESHOLD
    region = vd.safe_subbox(x, failed, box, ["above", "below"])
    inside = ((x[:, 0] < region["mass"][1]) & (x[:, 1] > region["friction"][0]))
    assert not (inside & failed).any()
    assert region["mass"][0] == box.low[0] and region["friction"][1] == box.high[1]


def test_no_region_when_every_sample_fails():
    box = _box(10.0)
    x = box.from_unit(np.random.default_rng(0).uniform(size=(8, 2)))
    assert vd.candidate_region(x, np.ones(8, bool), box, ["above", "below"]) is None


def test_candidate_region_is_cut_at_a_critical_value():
    box = _box()
    x = _grid(box, 5)
    failed = np.zeros(len(x), bool)
    failed[np.argmax(x[:, 0] - x[:, 1])] = True  # only the heavy, slippery corner
    crit = _moment(100, {"mass": 0.6, "friction": None}, {"mass": "above", "friction": None})
    region = vd.candidate_region(x, failed, box, ["above", "below"], [crit])
    # friction 1.0 (nominal) lies inside, so the region stops at the critical mass
    assert region["mass"][1] <= 0.6


def test_round_inward_never_grows_the_region():
    box = _box()
    region = {"mass": (0.05, 0.35249), "friction": (0.45251, 1.5)}
    r = vd.round_inward(region, box)
    assert r == {"mass": (0.05, 0.352), "friction": (0.453, 1.5)}


def _check_and_shrink(region, box, sides, *, per_edge, dense_per_edge, rounds=4):
    """The region check's rounds against the known boundary of ``_cost``: check the corners
    and edges, shrink on failures; the last region, after asserting that it holds on a
    denser check."""
    for _ in range(rounds):
        pts, _ = vd.region_points(region, box, per_edge=per_edge)
        fails = _cost(pts) > THRESHOLD
        if not fails.any():
            break
        region = vd.round_inward(vd.shrink_region(region, pts[fails], box, sides,
                                                  passing=pts[~fails]), box)
        assert region is not None
    dense, _ = vd.region_points(region, box, per_edge=dense_per_edge)
    assert not (_cost(dense) > THRESHOLD).any()
    return region


def test_shrinking_lands_on_a_checked_point_that_passed():
    """Check, shrink, check again on a known boundary: the region ends up holding."""
    region = {"mass": (0.05, 0.5), "friction": (0.2, 1.5)}  # claims too much: (0.5, 0.2) fails
    region = _check_and_shrink(region, _box(), ["above", "below"], per_edge=9,
                               dense_per_edge=41)
    assert region["mass"][1] > 0.1  # not shrunk to nothing


def _box3() -> UncertaintyBox:
    from critmoment.params import ComOffsetParameter

    return UncertaintyBox(_box().parameters + (ComOffsetParameter("com", "box", -0.01, 0.01,
                                                                  0.0),))


def test_three_parameters_keep_a_parameter_that_does_not_matter_whole():
    """Fails iff mass > 0.8 kg over mass × friction × centre of mass: the sub-box is the 2-D
    answer with the centre of mass over its whole range (the cut of one axis below every
    failing sample made it a sliver of whichever axis they reached lowest)."""
    box3 = _box3().parameters
    box3 = UncertaintyBox((MassParameter("mass", "box", 0.05, 1.5, 0.05),) + box3[1:])
    from scipy.stats import qmc

    x = box3.from_unit(qmc.Sobol(3, seed=0).random(64))
    failed = x[:, 0] > 0.8
    region = vd.safe_subbox(x, failed, box3, ["above", "below", "above"])
    assert region["friction"] == (0.2, 1.5)
    assert region["com"][0] == -0.01 and region["com"][1] > 0.009
    assert 0.75 < region["mass"][1] < 0.85
    inside = np.all([(x[:, j] > lo) & (x[:, j] < hi) for j, (lo, hi) in
                     enumerate(region.values())], axis=0)
    assert not (inside & failed).any()


def test_three_parameter_shrinking_converges_within_the_rounds():
    """The check's shrink with three parameters, on a known boundary (heavy and slippery
    fails; the centre of mass does not matter): within 4 rounds the region holds on a dense
    check of its corners and edges and keeps most of the mass range."""
    region = {"mass": (0.05, 0.5), "friction": (0.2, 1.5), "com": (-0.01, 0.01)}
    region = _check_and_shrink(region, _box3(), ["above", "below", "above"], per_edge=5,
                               dense_per_edge=21)
    assert region["mass"][1] > 0.2 and region["com"] == (-0.01, 0.01)


def test_failures_at_both_ends_of_a_parameter_move_both_faces():
    """Failing at low and at high friction (a grip that slips, and one that drags the
    object along): the failing sides' cut cannot keep the low-friction failures out (they
    sit on the face it keeps), so both faces move in, half way to the passing points, and
    the region that is left excludes every failure."""
    box = _box()
    region = {"mass": (0.05, 0.5), "friction": (0.2, 1.5)}
    pts, _ = vd.region_points(region, box, per_edge=3)
    fails = (pts[:, 1] <= 0.2) | (pts[:, 1] >= 1.5)
    out = vd.shrink_region(region, pts[fails], box, ["above", "above"], passing=pts[~fails])
    assert out is not None
    assert out["mass"] == (0.05, 0.5)
    assert 0.2 < out["friction"][0] < 0.85 < out["friction"][1] < 1.5
    np.testing.assert_allclose(out["friction"], (0.525, 1.175))
    # a region with a failure inside every possible cut is no region
    assert vd.shrink_region({"mass": (0.05, 0.05), "friction": (0.2, 0.2)},
                            np.array([[0.05, 0.2]]), box, ["above", "above"]) is None


def test_a_two_sided_parameter_failing_at_one_corner_converges_on_a_passing_corner():
    """A dragged cube: friction fails at both ends of the box (slippery, and so grippy that
    the table pulls a heavy cube out of the grip: mass × friction > 0.5), mass above. After
    the first cut every failure lies at the high-friction face: the new region's worst
    corner is a checked point that passed there, and the check holds in 2 rounds (the
    greedy face cut moved the mass face in a little each round, each new corner on the
    diagonal boundary failing again, and after 4 rounds there was no region)."""
    box = _box()

    def fails(x):
        return (x[:, 1] < 0.35) | (x[:, 0] * x[:, 1] > 0.5)

    region = {"mass": (0.05, 0.8), "friction": (0.3, 1.5)}
    rounds = 0
    while rounds < 4:
        rounds += 1
        pts, _ = vd.region_points(region, box, per_edge=3)
        pts = np.vstack([pts, vd.interior_points(region, box)])
        bad = fails(pts)
        if not bad.any():
            break
        region = vd.round_inward(vd.shrink_region(region, pts[bad], box, ["above", "both"],
                                                  passing=pts[~bad]), box)
        assert region is not None
    assert rounds <= 2
    dense, _ = vd.region_points(region, box, per_edge=41)
    assert not fails(dense).any()
    assert not fails(vd.interior_points(region, box, scale=4)).any()
    assert region["mass"][1] > 0.3


def _com_box() -> UncertaintyBox:
    from critmoment.params import ComOffsetParameter

    return UncertaintyBox((MassParameter("mass", "box", 0.05, 1.0, 0.05),
                           ComOffsetParameter("com", "box", -0.02, 0.02, 0.0)))


def _com_fails(x: np.ndarray) -> np.ndarray:
    """A centre of mass past 1.2 cm either way drops the object; so does mass > 0.8 kg."""
    return (np.abs(x[:, 1]) > 0.012) | (x[:, 0] > 0.8)


def test_a_parameter_failing_on_both_sides_of_its_nominal_is_two_sided():
    from scipy.stats import qmc

    box = _com_box()
    x = box.from_unit(qmc.Sobol(2, seed=0).random(256))
    failed = _com_fails(x)
    assert vd.fail_sides(x, failed, box) == ["above", "both"]
    # the moments' critical values naming both sides say so too, without the samples
    votes = [{"mass": "above", "com": "below"}, {"mass": "above", "com": "above"}]
    assert vd.fail_sides(x, np.zeros(len(x), bool), box, votes) == ["above", "both"]
    # a side with no failure is one-sided, as before
    assert vd.fail_sides(x, failed & (x[:, 1] > -0.012), box) == ["above", "above"]


def test_a_two_sided_parameter_gets_a_region_around_its_nominal():
    """Failing past ±1.2 cm: with one side per parameter no sub-box at the box's corner is
    free of failures (the old answer, "no safe region"); two-sided, the region keeps the
    nominal inside, excludes every failing sample and reaches near both true faces."""
    from scipy.stats import qmc

    box = _com_box()
    x = box.from_unit(qmc.Sobol(2, seed=0).random(256))
    failed = _com_fails(x)
    assert vd.safe_subbox(x, failed, box, ["above", "above"]) is not None  # a sliver
    one = vd.safe_subbox(x, failed, box, ["above", "above"])
    region = vd.safe_subbox(x, failed, box, ["above", "both"])
    lo, hi = region["com"]
    assert -0.013 < lo < -0.0105 and 0.0105 < hi < 0.013
    assert 0.7 < region["mass"][1] <= 0.8 + 1e-9 and region["mass"][0] == 0.05
    inside = vd.within(x, region, box)
    assert not (inside & failed & ~np.isclose(x[:, 1], lo) & ~np.isclose(x[:, 1], hi)
                & ~np.isclose(x[:, 0], region["mass"][1])).any()
    # it holds far more of the prior than the one-sided cut
    vol = np.prod([box.to_unit(np.array([[region[n][1] for n in box.names]]))[0]
                   - box.to_unit(np.array([[region[n][0] for n in box.names]]))[0]])
    vol_one = np.prod([box.to_unit(np.array([[one[n][1] for n in box.names]]))[0]
                       - box.to_unit(np.array([[one[n][0] for n in box.names]]))[0]])
    assert vol > 1.5 * vol_one
    # and the check's rounds move whichever face a failing check point is at, until the
    # region holds on a dense check of its corners and edges
    out = {"mass": (0.05, 0.5), "com": (-0.016, 0.016)}
    for _ in range(8):
        pts, _ = vd.region_points(out, box, per_edge=9)
        fails = _com_fails(pts)
        if not fails.any():
            break
        out = vd.round_inward(vd.shrink_region(out, pts[fails], box, ["above", "both"],
                                               passing=pts[~fails]), box)
    dense, _ = vd.region_points(out, box, per_edge=41)
    assert not _com_fails(dense).any()
    assert out["mass"] == (0.05, 0.5)
    assert -0.012 <= out["com"][0] < -0.009 and 0.009 < out["com"][1] <= 0.012


def test_decide_states_a_two_sided_region():
    from scipy.stats import qmc

    box = _com_box()
    x = box.from_unit(qmc.Sobol(2, seed=0).random(64))
    cost = np.where(_com_fails(x), 2.0, 0.1)
    d = vd.decide(_evidence(box, x, cost, moments=(_moment(100),)), OPT)
    assert d.verdict is vd.Verdict.CONDITIONAL
    lo, hi = d.region_to_check["com"]
    assert -0.014 < lo < -0.008 and 0.008 < hi < 0.014
    assert d.region_to_check["mass"][1] > 0.5


def test_region_points_cover_corners_and_densified_edges():
    box = _box()
    region = {"mass": (0.05, 0.5), "friction": (0.4, 1.5)}
    pts, edges = vd.region_points(region, box, per_edge=5)
    assert len(edges) == 4 and pts.shape == (4 * 5 - 4, 2)
    corners = {(a, b) for a in (0.05, 0.5) for b in (0.4, 1.5)}
    assert corners <= {tuple(np.round(p, 12)) for p in pts}
    hot = vd.hot_edges(edges, _cost(pts), near=0.8 * THRESHOLD)
    assert hot and len(hot) < 4
    dense, dense_edges = vd.region_points(region, box, per_edge=5, dense=hot)
    assert all(dense_edges[i].size == 17 for i in hot)
    assert ((dense >= np.array([0.05, 0.4]) - 1e-12) & (dense <= np.array([0.5, 1.5]) + 1e-12)).all()


# --------------------------------------------------------------------------
# the decision
# --------------------------------------------------------------------------


def _evidence(box, samples, cost, **kw):
    sweep = _sweep(cost[None], samples)
    near, *_ = vd.samples_to_rerun(sweep, OPT, nominal_completed=True)
    se = vd.SampleEvidence(sweep=sweep, nominal_completed=True, rerun=near,
                           rerun_failed=np.zeros(len(samples), bool))
    return vd.Evidence(box=box, samples=se, nominal_cost=0.1, **kw)


def test_decide_asks_for_the_region_check_then_states_it_with_its_evidence():
    box = _box()
    x = _grid(box, 11)
    ev = _evidence(box, x, _cost(x), moments=(_moment(100),))
    first = vd.decide(ev, OPT)
    assert first.verdict is vd.Verdict.CONDITIONAL
    assert first.region_to_check is not None and first.safe_region is None
    assert 0 < first.p_success < 1
    lo, hi = first.p_success_interval
    assert lo < first.p_success < hi
    pts, _ = vd.region_points(first.region_to_check, box)
    check = vd.RegionCheck(region=first.region_to_check, points=pts,
                           failed=np.zeros(len(pts), bool), rolled_out=np.arange(len(pts)) < 4,
                           rounds=1, n_sparse=len(pts), n_rollouts=4,
                           chained=np.arange(len(pts)) >= 4, n_chained=len(pts) - 4,
                           first_claim=first.region_to_check)
    final = vd.decide(vd.Evidence(**{**ev.__dict__, "region": check}), OPT)
    assert final.safe_region == first.region_to_check
    assert final.safe_region_text.startswith("safe for mass ≤")
    assert (f"checked at {len(pts)} points of its corners, edges and inside by sparse evaluation and "
            f"on each point's own run: {len(pts) - 4} chained through the moments, 4 full "
            "rollouts") in final.safe_region_text
    assert check.to_json()["own_runs_last_round"] == len(pts)
    # a check that found no holding region leaves none
    failed_check = vd.RegionCheck(region=None, points=pts, failed=np.ones(len(pts), bool),
                                  rolled_out=np.zeros(len(pts), bool), rounds=4,
                                  n_sparse=80, n_rollouts=8, first_claim=first.region_to_check)
    none = vd.decide(vd.Evidence(**{**ev.__dict__, "region": failed_check}), OPT)
    assert none.safe_region is None and none.safe_region_text.startswith("no safe region")


def test_decide_all_failing_samples_state_no_region():
    box = _box(10.0)
    x = box.from_unit(np.random.default_rng(1).uniform(size=(8, 2)))
    ev = _evidence(box, x, np.full(8, 2.0), moments=(_moment(100),))
    d = vd.decide(ev, OPT)
    assert d.verdict is vd.Verdict.CONDITIONAL and d.p_success == 0.0
    assert d.region_to_check is None and d.safe_region is None
    assert d.safe_region_text.startswith("no safe region")


def test_decide_unsafe_at_nominal_and_safe_needs_the_whole_box_checked():
    box = _box()
    x = _grid(box, 5)
    bad_nominal = _evidence(box, x, _cost(x), nominal_failed=True)
    # the nominal run completes the task: with nominal_by_run it decides the nominal
    # parameters; without, the sparse failure at nominal makes the verdict UNSAFE
    d = vd.decide(bad_nominal, OPT)
    assert d.verdict is not vd.Verdict.UNSAFE
    assert any("nominal run itself completes the task" in c for c in d.causes)
    strict = vd.DecisionOptions(threshold=THRESHOLD, chain=False, nominal_by_run=False)
    d = vd.decide(bad_nominal, strict)
    assert d.verdict is vd.Verdict.UNSAFE and d.region_to_check is None
    assert any("fails at the nominal parameters" in c for c in d.causes)
    good = _evidence(box, x, np.full(len(x), 0.1))
    d = vd.decide(good, OPT)
    assert d.verdict is vd.Verdict.SAFE and d.p_success == 1.0
    whole = {"mass": (0.05, 1.0), "friction": (0.2, 1.5)}
    assert d.region_to_check == whole
    shrunk = {"mass": (0.05, 0.8), "friction": (0.2, 1.5)}
    pts, _ = vd.region_points(shrunk, box)
    check = vd.RegionCheck(region=shrunk, points=pts, failed=np.zeros(len(pts), bool),
                           rolled_out=np.zeros(len(pts), bool), rounds=2, n_sparse=32,
                           n_rollouts=8, first_claim=whole)
    d = vd.decide(vd.Evidence(**{**good.__dict__, "region": check}), OPT)
    # a corner of the whole box failed its check: not SAFE, the shrunk region is stated
    assert d.verdict is vd.Verdict.CONDITIONAL and d.safe_region == shrunk
    assert any("first claimed" in c for c in d.causes)


def test_fail_sides_follow_the_critical_values_then_the_failures_then_the_trend():
    box = _box()
    x = _grid(box, 9)
    failed = _cost(x) > THRESHOLD
    assert vd.fail_sides(x, failed, box) == ["above", "below"]
    votes = [{"mass": "below", "friction": None}]
    assert vd.fail_sides(x, failed, box, votes)[0] == "below"
    # the failures themselves, where they correlate significantly, come before the cost's
    # trend (a cost that never crosses the threshold can slope the other way)
    assert vd.fail_sides(x, failed, box, (), {"mass": -1.0, "friction": 2.0}) == [
        "above", "below"]
    # where they do not (no failure at all), the trend decides
    none = np.zeros(len(x), bool)
    assert vd.fail_sides(x, none, box, (), {"mass": -1.0, "friction": 2.0}) == [
        "below", "above"]


def test_decision_options_are_checked():
    with pytest.raises(ParameterError, match="verify"):
        vd.DecisionOptions(threshold=0.9, verify=1.5)
    with pytest.raises(ParameterError, match="threshold"):
        vd.DecisionOptions(threshold=float("nan"))


def test_without_moments_nothing_fails_and_the_whole_box_is_stated():
    box = _box()
    ev = vd.Evidence(box=box, samples=vd.SampleEvidence(sweep=None, nominal_completed=True),
                     nominal_cost=0.0)
    d = vd.decide(ev, OPT)
    assert d.verdict is vd.Verdict.SAFE and d.region_to_check is None
    assert d.safe_region_text == "safe over the whole box"


def test_worst_case_rollouts_follow_each_switch():
    """A failing worst case that only its own rollout can decide is rolled out by the switch
    of its own kind: a sticking one with ``verify_sticking`` even when unlifted failures are
    not rolled out, an unlifted one only with ``verify_unlifted``."""
    moments = [_moment(100)]
    both = vd.DecisionOptions(threshold=THRESHOLD)
    sticking_only = dataclasses.replace(both, verify_unlifted=False)
    unlifted_only = dataclasses.replace(both, verify_sticking=False)
    neither = dataclasses.replace(both, verify_unlifted=False, verify_sticking=False)
    assert sticking_only.only_a_rollout_decides(False, True)
    assert not sticking_only.only_a_rollout_decides(True, False)
    assert unlifted_only.only_a_rollout_decides(True, False)
    assert not unlifted_only.only_a_rollout_decides(False, True)
    assert not dataclasses.replace(both, verify=None).only_a_rollout_decides(True, True)
    for opt, kind, rolled in [(sticking_only, (False, True), True),
                              (sticking_only, (True, False), False),
                              (unlifted_only, (True, False), True),
                              (unlifted_only, (False, True), False),
                              (neither, (True, True), False)]:
        worst = {100: opt.only_a_rollout_decides(*kind)}
        steps = vd.worst_cases_to_rerun(moments, {100: True}, worst, opt, n_failed=0)
        assert steps == ([100] if rolled else []), (opt, kind)
    # a failing sample decides the verdict already: no worst-case rollout
    assert vd.worst_cases_to_rerun(moments, {100: True}, {100: True}, both, n_failed=1) == []


def test_a_motor_failure_with_every_motor_under_its_limit_is_for_a_rollout():
    """The cost crosses the threshold through the sum of its terms while no motor reaches
    its limit (gymnasium-robotics' kitchen Franka, elliptic cone: a wrist at FOS 1.17 beside
    a grip at FOS 2.65, cost 1.03): 39 of 64 samples were decided failing and really
    succeed. Such a sample is decided by its own rollout; a motor at its limit is not."""
    from critmoment.sparse import MOTOR_MARGIN, Failure

    samples = np.array([[0.1, 1.0], [0.2, 1.0], [0.3, 1.0], [0.4, 1.0], [0.5, 1.0]])
    # 0: margin at moment 0; 1: a motor at its limit; 2: margin, then a real contact
    # failure; 3: margin and a sticking failure; 4: passes
    cost = np.array([[1.03, 1.2, 1.03, 1.03, 0.1], [0.1, 0.1, 1.5, 1.2, 0.1]])
    sweep = dataclasses.replace(
        _sweep(cost, samples, sticking=np.array([[False] * 5,
                                                 [False, False, False, True, False]])),
        failure=np.array([[Failure.MOTOR, Failure.MOTOR, Failure.MOTOR, Failure.MOTOR,
                           Failure.PASS],
                          [Failure.PASS, Failure.PASS, Failure.CONTACT, Failure.CONTACT,
                           Failure.PASS]], dtype=np.int8),
        fos_motor=np.array([[1.17, 1.0, 1.17, 1.0 + MOTOR_MARGIN, 3.0], [3.0] * 5]))
    np.testing.assert_array_equal(sweep.failed_margin_only(),
                                  [True, False, False, True, False])
    reruns = vd.samples_to_rerun(sweep, OPT, nominal_completed=True)
    # a sample with both margin and sticking failures is one of the margin group
    assert reruns.margin.tolist() == [True, False, False, True, False]
    assert not reruns.sticking.any()
    ev = vd.SampleEvidence(sweep=sweep, nominal_completed=True, rerun=reruns.any,
                           rerun_failed=np.zeros(5, bool))
    assert vd.failing_samples(ev, OPT).tolist() == [False, True, True, False, False]
    off = dataclasses.replace(OPT, verify_margin=False)
    assert not vd.samples_to_rerun(sweep, off, nominal_completed=True).margin.any()
    assert OPT.only_a_rollout_decides(False, False, margin=True)
    assert not off.only_a_rollout_decides(False, False, margin=True)
    counts = vd.SampleRuns(reruns=reruns, chained=np.zeros(5, bool),
                           chained_failed=np.zeros(5, bool), suspect=np.zeros(5, bool),
                           rerun_failed=np.zeros(5, bool)).counts(np.zeros(5, bool))
    assert (counts["margin"], counts["margin_failed"]) == (2, 0)


def test_a_motor_failure_that_touches_its_limit_only_briefly_is_for_a_rollout():
    """A jump in the targets (an ACT-like chunk's boundary) puts a wrist at its force limit
    for 11-19 steps, where the ground truth's saturation needs 25 in a row: the motor FOS
    touches 1, yet the run completes (ALOHA, 50-step chunks: 1-3 false unsafes of 32 near
    the nominal). A motor failure stands only where a motor sat at the limit for a motor
    failure's duration (``saturated``); the others are margin failures, for the sample's
    own run."""
    from critmoment.sparse import Failure

    samples = np.array([[0.1, 1.0], [0.2, 1.0], [0.3, 1.0]])
    base = dataclasses.replace(
        _sweep(np.array([[1.2, 1.2, 0.1]]), samples),
        failure=np.array([[Failure.MOTOR, Failure.MOTOR, Failure.PASS]], dtype=np.int8),
        fos_motor=np.array([[1.0, 1.0, 3.0]]))
    # without the flag (results built elsewhere) a touch of the limit stands, as before
    assert base.margin_failure.tolist() == [[False, False, False]]
    flagged = dataclasses.replace(base, saturated=np.array([[False, True, False]]))
    assert flagged.margin_failure.tolist() == [[True, False, False]]
    reruns = vd.samples_to_rerun(flagged, OPT, nominal_completed=True)
    assert reruns.margin.tolist() == [True, False, False]


def test_a_failure_only_by_a_slip_under_the_ground_truths_tolerance_is_for_a_rollout():
    """The sparse slip tolerance (5 mm over the horizon) is tighter than the ground truth's
    (1 cm for 50 ms): a sample that fails only by a slip between them is decided by its own
    rollout (robosuite Panda + Robotiq 2F-85, elliptic, narrow box, seed 1: three samples
    slipped 5.0-5.4 mm at one moment and really succeed)."""
    from critmoment.sparse import Failure

    samples = np.array([[0.1, 1.0], [0.2, 1.0], [0.3, 1.0], [0.4, 1.0]])
    # 0: a 6 mm slip; 1: a 12 mm slip; 2: a 6 mm slip, then a contact failure; 3: passes
    cost = np.array([[1.0, 1.0, 1.0, 0.1], [0.1, 0.1, 1.5, 0.1]])
    sweep = dataclasses.replace(
        _sweep(cost, samples),
        failure=np.array([[Failure.SLIP, Failure.SLIP, Failure.SLIP, Failure.PASS],
                          [Failure.PASS, Failure.PASS, Failure.CONTACT, Failure.PASS]],
                         dtype=np.int8),
        slip=np.array([[0.006, 0.012, 0.006, 0.0], [0.0, 0.0, 0.0, 0.0]]))
    np.testing.assert_array_equal(sweep.failed_slip_only(0.01), [True, False, False, False])
    reruns = vd.samples_to_rerun(sweep, OPT, nominal_completed=True)
    assert reruns.slipping.tolist() == [True, False, False, False]
    assert reruns.any.tolist() == [True, False, False, False]
    # its rollout decides it; the others keep the sparse decision
    ev = vd.SampleEvidence(sweep=sweep, nominal_completed=True, rerun=reruns.any,
                           rerun_failed=np.zeros(4, bool))
    assert vd.failing_samples(ev, OPT).tolist() == [False, True, True, False]
    off = dataclasses.replace(OPT, verify_slip=False)
    assert not vd.samples_to_rerun(sweep, off, nominal_completed=True).slipping.any()
    tight = dataclasses.replace(OPT, slip_confirm=0.005)
    assert not vd.samples_to_rerun(sweep, tight, nominal_completed=True).slipping.any()
    assert OPT.only_a_rollout_decides(False, False, True)
    assert not off.only_a_rollout_decides(False, False, True)
    with pytest.raises(ParameterError, match="slip_confirm: expected a length > 0 m"):
        dataclasses.replace(OPT, slip_confirm=0.0)


def test_slip_confirm_is_the_ground_truths_slip_tolerance():
    from critmoment.groundtruth import OutcomeCriteria

    assert vd.DecisionOptions(threshold=0.9).slip_confirm == OutcomeCriteria().slip_tolerance


def test_blocked_grid_equals_the_point_by_point_test():
    # the two-parameter fast path of the safe sub-box search gives the same cuts as
    # comparing every bad point with every cut
    rng = np.random.default_rng(0)
    for margin in (0.0, 0.01):
        bad = rng.random((200, 2))
        bad[:20] = np.round(bad[:20], 1)  # ties with the cuts
        cands = [np.unique(np.concatenate([np.round(rng.random(40), 1), [1.0]]))
                 for _ in range(2)]
        grids = np.meshgrid(*cands, indexing="ij")
        cuts = np.stack([g.reshape(-1) for g in grids], axis=1)
        if margin > 0:
            inside = bad[None] <= cuts[:, None] + margin * (1 - 1e-9)
        else:
            inside = bad[None] < cuts[:, None]
        expected = inside.all(axis=2).any(axis=1)
        assert np.array_equal(vd._blocked_grid(bad, cands, margin), expected)


@pytest.mark.parametrize("make_box, n", [(_box, 8), (_box3, 16)])
def test_interior_points_lie_strictly_inside_and_spread(make_box, n):
    box = make_box()
    region = {p.name: (p.low + 0.1 * (p.high - p.low), p.low + 0.6 * (p.high - p.low))
              for p in box.parameters}
    pts = vd.interior_points(region, box)
    assert pts.shape == (n, box.ndim)
    assert vd.within(pts, region, box).all()
    lo = np.array([region[p][0] for p in box.names])
    hi = np.array([region[p][1] for p in box.names])
    assert ((pts > lo) & (pts < hi)).all()  # none on a face: those are the edges' points
    # each half of every parameter's range holds some of them
    mid = (lo + hi) / 2
    assert ((pts < mid).any(axis=0) & (pts > mid).any(axis=0)).all()
    np.testing.assert_array_equal(pts, vd.interior_points(region, box))  # deterministic
    assert not vd.within(np.array([[hi[0] * 1.01] + list(mid[1:])]), region, box)[0]


def test_a_nominal_run_that_fails_the_ground_truths_motor_rule_is_unsafe():
    """A wrist held at its limit for 80 ms in the nominal run (over the ground truth's 50 ms,
    under the feasibility check's 100 ms) while the task completes: the audit said
    CONDITIONAL with "the nominal run itself completes the task, which decides the nominal
    parameters", where brute force calls the nominal parameters a motor failure."""
    box = _box()
    x = _grid(box, 11)
    cost = _cost(x)
    ev = _evidence(box, x, cost, moments=(_moment(100),))
    assert vd.decide(ev, OPT).verdict is vd.Verdict.CONDITIONAL
    why = "motor overload: actuator 'joint6' held at 99.9% of its force limit"
    failing = vd.Evidence(**{**ev.__dict__, "nominal_run_failure": why})
    decision = vd.decide(failing, OPT)
    assert decision.verdict is vd.Verdict.UNSAFE and decision.safe_region is None
    assert decision.causes[0] == f"the nominal run itself fails: {why}"
    # a sparse excursion the nominal run survives is still the run's to decide
    squeezed = vd.Evidence(**{**ev.__dict__, "nominal_failed": True, "nominal_cost": 1.2})
    assert vd.decide(squeezed, OPT).verdict is not vd.Verdict.UNSAFE


def test_the_nominal_reference_carries_its_own_outcome(twin, demo_recording):
    from critmoment.groundtruth import Outcome, reference_from_recording

    ref = reference_from_recording(demo_recording, twin)
    assert ref.outcome is Outcome.SUCCESS and ref.first_failure_step == -1


def test_a_moment_whose_failures_the_own_runs_overturn_is_no_cause():
    """A chunk cut mid-motion failed the sweep at t = 0 by joint1 for every sample; each
    sample's own run passed it, and the causes still said "motor overload at joint1:
    peak-load at t = 0.00 s (100% of the box)"."""
    base = vd.MomentReport(moment=_moment(100).moment, worst_case={"mass": 1.0},
                           max_cost=1.5, min_fos_contact=3.0, min_fos_motor=1.0,
                           critical={"mass": None}, critical_side={"mass": None},
                           dominant="motor", limiting_actuator="joint1", fail_fraction=0.0)
    assert vd._causes([base], THRESHOLD)  # a worst case over the threshold: a cause
    overturned = dataclasses.replace(base, overturned=True)
    assert vd._causes([overturned], THRESHOLD) == []


def test_a_face_cut_keeps_the_nominal_inside_where_another_cut_clears_the_failure():
    """A failure where the CoM offset reaches its end, beside the nominal grip force: the
    greedy cut took the larger volume, through the grip's face (grip ≤ 34.7 N of a rated and
    nominal 35 N), and the region excluded the nominal (twenty-sixth round). A cut through
    the CoM's face clears it as well and keeps the nominal."""
    from critmoment.params import ComOffsetParameter, ForceLimitParameter

    box = UncertaintyBox((ComOffsetParameter("com", "box", -0.02, 0.02, 0.0),
                          ForceLimitParameter("grip", "finger", 5.0, 35.0, 35.0)))
    failing = box.from_unit(np.array([[0.9975, 0.9967]]))
    passing = box.from_unit(np.array([[0.9, 0.5], [0.5, 0.95]]))
    cut = vd._any_face_cut(box.low, box.high, failing, box, 0.01, passing)
    assert cut["grip"] == (5.0, 35.0)
    assert cut["com"][0] == -0.02 and 0.0 < cut["com"][1] < 0.0199


def test_a_log_uniform_regions_ends_are_the_boxs_own():
    """A log-uniform prior's round trip through its quantiles gave a region of mass ≥
    0.05000000000000001 for a box from 0.05: the box's own end tested as outside it."""
    box = UncertaintyBox((MassParameter("mass", "box", 0.05, 2.0, 0.1, prior="loguniform"),
                          FrictionParameter("friction", "box", 0.2, 1.5, 1.0)))
    region = {"mass": (0.05000000000000001, 0.217), "friction": (0.28, 1.4999999999999996)}
    out = vd.round_inward(region, box)
    assert out == {"mass": (0.05, 0.217), "friction": (0.28, 1.5)}


def test_a_cause_speaks_of_the_boxs_own_parameters_with_their_units():
    """A box holding only the shoulder's force limit was told "reduce the uncertainty of the
    object's mass and friction", and the values came without units ("fails for shoulder
    below 23.5")."""
    from critmoment.params import ForceLimitParameter, MassParameter

    shoulder = ForceLimitParameter(name="shoulder", target="joint2", low=5.0, high=87.0,
                                   nominal=87.0, torque=True)
    mr = vd.MomentReport(moment=_moment(100).moment, worst_case={"shoulder": 5.0},
                         max_cost=1.5, min_fos_contact=3.0, min_fos_motor=1.0,
                         critical={"shoulder": 23.5}, critical_side={"shoulder": "below"},
                         dominant="motor", limiting_actuator="joint2", fail_fraction=0.4)
    (cause,) = vd._causes([mr], THRESHOLD, UncertaintyBox((shoulder,)))
    assert "fails for shoulder below 23.5 N·m" in cause
    assert cause.endswith("reduce the uncertainty of joint2's force limit, or push the "
                          "object instead of lifting it")
    mass = MassParameter(name="mass", target="box", low=0.05, high=1.0, nominal=0.05)
    both = UncertaintyBox((mass, shoulder))
    assert vd._box_words(both) == "box's mass and joint2's force limit"
    # with two parameters, the critical value holds the other at its nominal value, and the
    # cause says so (a friction "below 0.0904" beside failures up to 0.28 at heavier masses)
    two = dataclasses.replace(mr, critical={"mass": None, "shoulder": 23.5},
                              critical_side={"mass": None, "shoulder": "below"})
    (cause,) = vd._causes([two], THRESHOLD, both)
    assert "fails for shoulder below 23.5 N·m with the others at nominal" in cause
    assert vd._box_words(UncertaintyBox((mass,))) == "the object's mass"


def test_critical_values_of_a_failing_nominal_run_are_stated_as_unchecked():
    """Where the nominal run does not complete its task, no run just past a critical value
    can refute it: the causes give the values as sparse evaluation's from the failing
    nominal's states, not as where the motion fails (a low-cost robot arm whose nominal
    drops its cube had "fails for mass above 2.57 kg")."""
    chain = vd.DecisionOptions(threshold=THRESHOLD, chain=True)
    box = _box()
    samples = np.array([[0.1, 1.0], [0.5, 1.0]])
    sweep = _sweep([[0.1, 1.5]], samples)
    crit = _moment(100, {"mass": 0.4, "friction": None}, {"mass": "above", "friction": None})
    for completed, text in ((True, "(fails for mass above 0.4 kg"),
                            (False, "crosses for mass above 0.4 kg")):
        se = vd.SampleEvidence(sweep=sweep, nominal_completed=completed,
                               rerun=np.ones(2, bool), rerun_failed=np.array([False, True]),
                               chained=np.zeros(2, bool), chained_failed=np.zeros(2, bool))
        causes = vd.decide(vd.Evidence(box=box, samples=se, nominal_cost=0.1,
                                       moments=(crit,)), chain).causes
        assert any(text in c for c in causes), causes
        assert completed or not any("(fails for" in c for c in causes)


def test_a_region_that_leaves_out_the_nominal_says_so():
    """probe r38 (Google Robot): "safe for 0.149 ≤ mass ≤ 0.206 kg at friction ≥ 1.48"
    beside a passing nominal 0.05 kg, friction 1, read as if the nominal were unsafe; the
    text now says the region leaves it out (a box checked to hold, not every passing
    point). A region holding the nominal reads as before."""
    box = _box()
    sliver = {"mass": (0.149, 0.206), "friction": (1.48, 1.5)}
    text = vd.region_text(sliver, box, vd.Verdict.CONDITIONAL)
    assert text.startswith("safe for 0.149 ≤ mass ≤ 0.206 kg at friction ≥ 1.48")
    assert text.endswith("; it leaves out the nominal mass = 0.05 kg and friction = 1: the "
                         "region is one box checked to hold, not every passing point")
    holding = {"mass": (0.05, 0.5), "friction": (0.6, 1.5)}
    assert vd.region_text(holding, box, vd.Verdict.CONDITIONAL) == (
        "safe for mass ≤ 0.5 kg at friction ≥ 0.6")
