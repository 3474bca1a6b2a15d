"""The end-to-end audit: verdicts against known answers, report contents, determinism."""

import dataclasses
import json
import warnings

import numpy as np
import pytest

from critmoment import analysis, report
from critmoment import verdict as vd
from critmoment.analysis import AnalyzeOptions, Verdict, analyze, safe_subbox
from critmoment.exceptions import ParameterError
from critmoment.params import UncertaintyBox
from critmoment.twin import Twin
from critmoment.validation import brute_force

FAST = AnalyzeOptions(n_samples=64, search=False, map_resolution=6, critical_grid=9)


@pytest.fixture(scope="module")
def nominal_report(twin, demo_traj):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return analyze(demo_traj, twin=twin, options=FAST)


def test_nominal_demo_is_conditional_with_a_critical_mass(nominal_report, scenario):
    r = nominal_report
    assert r.verdict is Verdict.CONDITIONAL
    assert 0.0 < r.p_success < 1.0
    lo, hi = r.p_success_interval
    assert lo < r.p_success < hi
    masses = [mr.critical["mass"] for mr in r.moments if mr.critical["mass"] is not None]
    assert masses, "expected a critical mass at some moment"
    assert all(scenario.box.low[0] < m < scenario.box.high[0] for m in masses)
    # heavier is worse: the failing side of the mass is above the critical value
    assert all(mr.critical_side["mass"] == "above" for mr in r.moments
               if mr.critical["mass"] is not None)
    assert r.safe_region is not None and r.safe_region["mass"][1] < scenario.box.high[0]
    assert r.safe_region_text.startswith("safe for mass ≤")


def test_the_audit_reports_its_contact_model_and_task(nominal_report):
    doc = nominal_report.to_json()
    cm = doc["contact_model"]
    # the bundled scene is hard (elliptic, impratio 10): a held cube creeps well under the
    # tolerance, so the sweep keeps its short horizon
    assert (cm["cone"], cm["impratio"], cm["soft"], cm["creep_horizon"]) == (
        "elliptic", 10.0, False, 0)
    assert 0 < cm["creep_rate"] < 1e-3
    # its nominal grip is far from the friction cone: the force ratio decides everywhere
    assert cm["force_ratio_untrusted_at"] == [] and not nominal_report.force_ratio_untrusted
    manifest = doc["manifest"]
    assert manifest["task"]["kind"] == "handover"
    # FAST has no search, so no whole-motion bound; see test_the_load_bound_* for it
    assert doc["load_bound"] is None
    assert manifest["unlimited_actuators"] == []
    assert manifest["limits"]["left/waist"] == {"limit": 10.0, "source": "scenario"}


def test_the_load_bound_flags_the_largest_mass_over_the_whole_motion(twin, demo_traj):
    from critmoment.analysis import _load_bound
    from critmoment.recording import rollout as run

    lb = _load_bound(run(demo_traj, twin=twin), twin)
    nominal, heavy = lb["masses"]
    assert nominal["mass"] == 0.05 and nominal["first_failing_time"] is None
    # 10 kg saturates a joint while it is carried (after the lift-off, 3.4 s in)
    assert heavy["mass"] == 10.0 and 3.0 < heavy["first_failing_time"] < 4.0
    assert heavy["actuator"].startswith("right/")
    assert 0.05 < lb["min_critical_payload"] < 10.0


def test_narrow_box_is_safe(twin, demo_traj, scenario):
    box = scenario.box.with_range("mass", 0.05, 0.2).with_range("friction", 0.5, 1.5)
    r = analyze(demo_traj, twin=Twin(scenario.replace(box=box)), options=FAST)
    assert r.verdict is Verdict.SAFE
    assert r.p_success == 1.0 and r.passes()
    assert all(mr.max_cost <= scenario.cost.threshold for mr in r.moments)


def test_mass_narrowed_alone_stays_conditional_at_low_friction(twin, demo_traj, scenario):
    # 0.2 kg at μ = 0.2 needs more friction than two 5 N pads supply: not safe everywhere
    box = scenario.box.with_range("mass", 0.05, 0.2)
    r = analyze(demo_traj, twin=Twin(scenario.replace(box=box)), options=FAST)
    assert r.verdict is Verdict.CONDITIONAL
    # the region leaves that corner out: cut at low friction, or (since a round shrinks only
    # from the failures sparse evaluation decides alone) at the heavier masses, mass <=
    # 0.125 kg at any friction, where a 49-point full-rollout grid passes
    assert (r.safe_region["friction"][0] > box.low[1]
            or r.safe_region["mass"][1] < box.high[0])
    # a gate of P ≥ 1 asks for no failure: a CONDITIONAL audit found one, whatever its
    # samples estimate (a failing sliver gave P = 1.000 and exit 0 with --min-success 1)
    assert not r.passes(1.0)
    assert not dataclasses.replace(r, p_success=1.0).passes(1.0)
    assert dataclasses.replace(r, p_success=1.0).passes(0.99)
    # a gate that is no probability is an error, not a silent False (or a raw TypeError)
    for bad in ("0.5", 2, -0.1, float("nan")):
        with pytest.raises(ParameterError, match=r"min_success: expected a number in \[0, 1\]"):
            r.passes(bad)
    with pytest.raises(ParameterError, match=r"timings: expected True or False, got str"):
        r.to_json(timings="no")


def test_nominal_beyond_the_critical_mass_is_unsafe(demo_traj, scenario):
    box = scenario.box.with_range("mass", 0.05, 10.0, nominal=3.0)
    r = analyze(demo_traj, twin=Twin(scenario.replace(box=box)), options=FAST)
    assert r.verdict is Verdict.UNSAFE
    assert not r.passes() and not r.passes(0.99)
    assert any("nominal" in c for c in r.failure_causes)
    # the cause says what the nominal run lacks of the task, measured
    assert any("task is not completed" in c and "the nominal run: " in c
               for c in r.failure_causes), r.failure_causes


def test_report_json_schema_and_html(nominal_report, tmp_path):
    paths = report.write_report(nominal_report, tmp_path)
    doc = json.loads(paths["json"].read_text())
    assert doc["schema"] == "critmoment.report/1"
    assert doc["verdict"] == "CONDITIONAL"
    for key in ("p_success", "p_success_interval", "moments", "uncertainty", "timings",
                "manifest"):
        assert key in doc
    for m in doc["moments"]:
        for key in ("step", "time", "label", "reason", "worst_case", "min_fos_contact",
                    "min_fos_motor", "max_cost", "critical", "dominant"):
            assert key in m
    assert set(doc["manifest"]) >= {"critmoment", "mujoco", "model_sha256", "seed", "options"}
    html = paths["html"].read_text()
    assert "CONDITIONAL" in html and html.count("data:image/png;base64,") >= 3
    assert "<script" not in html  # self-contained, static
    text = report.summary_text(nominal_report)
    assert "CONDITIONAL" in text and "P(success)" in text


def test_same_seed_same_report(twin, demo_traj, nominal_report):
    again = analyze(demo_traj, twin=twin, options=FAST)
    assert again.to_json(timings=False) == nominal_report.to_json(timings=False)


def test_safe_subbox_in_two_dimensions():
    from critmoment.params import FrictionParameter, MassParameter

    box = UncertaintyBox((MassParameter("mass", "box", 0.0 + 1e-3, 1.0, 0.1),
                          FrictionParameter("friction", "box", 0.0 + 1e-3, 1.0, 1.0)))
    rng = np.random.default_rng(3)
    x = rng.uniform(1e-3, 1.0, size=(400, 2))
    failed = (x[:, 0] > 0.6) & (x[:, 1] < 0.5)  # heavy and slippery fails
    region = safe_subbox(x, failed, box, ["above", "below"])
    inside = np.ones(len(x), bool)
    for j, name in enumerate(("mass", "friction")):
        lo, hi = region[name]
        inside &= (x[:, j] > lo) & (x[:, j] < hi)  # a cut may sit on a failing sample
    assert not (inside & failed).any()
    # the best anchored box keeps one full axis: mass ≤ ~0.6 (all friction) or friction ≥ ~0.5
    area = np.prod([region[n][1] - region[n][0] for n in ("mass", "friction")])
    assert area > 0.45


def test_bad_options():
    with pytest.raises(ParameterError, match="n_samples"):
        AnalyzeOptions(n_samples=2)
    with pytest.raises(ParameterError, match="min_success"):
        AnalyzeOptions(min_success=1.5)
    with pytest.raises(ParameterError, match="horizon"):
        AnalyzeOptions(horizon=0)
    for bad in (0.0, 1.5, True):
        with pytest.raises(ParameterError, match="verify"):
            AnalyzeOptions(verify=bad)
    with pytest.raises(ParameterError, match="max_moments"):
        AnalyzeOptions(max_moments=0)
    with pytest.raises(ParameterError, match="search_patience"):
        AnalyzeOptions(search_patience=0)


@pytest.fixture(scope="module")
def boundary_reports(twin, demo_traj, scenario):
    """Audits of a box that ends near the critical mass, with and without verification."""
    box = scenario.box.with_range("mass", 0.05, 1.5)
    boundary = Twin(scenario.replace(box=box))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        # chain=False: these test the verification alone; chained segments have their own test
        return {v: analyze(demo_traj, twin=boundary,
                           options=dataclasses.replace(FAST, verify=v, chain=False))
                for v in (None, 0.8)}, boundary


def test_chained_segments_decide_the_samples_that_pass_without_a_rollout(boundary_reports):
    """The samples that pass at the moments with no rollout are carried on their own state;
    each failure of the chain stands or, where the chain is the weaker evidence, is decided
    by its own full rollout (mass <= 1.5 kg box, demo seed 8, whose cube starts far
    sideways: nominal-state evaluation misses failures that come from the sample's own
    history, and the chain fails six samples); every failure that stands is real."""
    from critmoment import demos

    _, boundary = boundary_reports
    traj = demos.scripted_transfer(8, twin=boundary)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        checked, chained = (analyze(traj, twin=boundary,
                                    options=dataclasses.replace(FAST, verify=0.8, chain=c))
                            for c in (False, True))
    np.testing.assert_array_equal(chained.sweep.cost, checked.sweep.cost)
    v = chained.verification
    assert v["chained"] > 0 and v["chained_failed"] > 0
    assert v["chained_confirmed"] <= v["chained_rolled_out"] <= v["chained_failed"]
    newly = chained.failed & ~checked.failed
    stand = v["chained_failed"] - v["chained_rolled_out"] + v["chained_confirmed"]
    assert int(newly.sum()) == stand > 0
    bf = brute_force(traj, twin=boundary, samples=chained.sweep.samples[newly])
    assert bf.failed.all()  # every chained failure that stands is a real failure
    # the causes say how the chain's own failures failed, as brute force classifies them
    line = next(c for c in chained.failure_causes if "fail on their own path (chained" in c)
    decided_by_chain = v["chained_failed"] - v["chained_rolled_out"]
    if decided_by_chain:
        from critmoment.verdict import _KIND_WORDS

        counts = [int(part.split()[0]) for part in line.split("moments: ")[1].rstrip(")")
                  .split(", ")]
        assert sum(counts) == decided_by_chain
        assert any(word in line for word in _KIND_WORDS.values())
    # chained segments only add failures
    assert not (checked.failed & ~chained.failed).any()


def test_verification_reruns_the_near_threshold_safes(boundary_reports, demo_traj):
    reports, boundary = boundary_reports
    plain, checked = reports[None], reports[0.8]
    assert plain.verification is None
    np.testing.assert_array_equal(plain.failed, plain.sweep.failed_any)
    # same moments and sweep; verification only adds failures, among the near-threshold safes
    np.testing.assert_array_equal(checked.sweep.cost, plain.sweep.cost)
    threshold = boundary.scenario.cost.threshold
    worst = checked.sweep.cost.max(axis=0)
    near = ~checked.sweep.failed_any & (worst >= 0.8 * threshold)
    # and the samples that fail only inside the elliptic cone (sticking)
    stick = checked.sweep.failed_sticking_only
    rerun = near | stick
    v = checked.verification
    assert v["rollouts"] == int(rerun.sum()) and int(near.sum()) > 0
    assert v["sticking"] == int(stick.sum())
    assert v["cost_from"] == pytest.approx(0.8 * threshold)
    np.testing.assert_array_equal(checked.failed[~rerun], plain.failed[~rerun])
    # the verdict of each re-run sample is its own full rollout's real outcome
    own = brute_force(demo_traj, twin=boundary, samples=checked.sweep.samples[rerun]).failed
    np.testing.assert_array_equal(checked.failed[rerun], own)
    assert v["failed"] == v["near_failed"] + v["sticking_failed"] == int(own.sum())
    assert v["unlifted"] == 0
    assert checked.p_success == pytest.approx(1.0 - checked.failed.mean())
    assert checked.to_json()["verification"] == {k: v[k] for k in v}


def test_the_causes_name_how_the_own_rollouts_failed(boundary_reports, demo_traj):
    """gym's SO-101 with pads: its 30 real failures were a shoulder saturating, found only by
    the samples' own runs, and the causes named only grip slip. The samples decided by their
    own full rollout now say how they failed, as brute force classifies them."""
    from collections import Counter

    from critmoment import verdict as vd

    reports, boundary = boundary_reports
    checked = reports[0.8]
    opts = vd.DecisionOptions(threshold=boundary.scenario.cost.threshold, chain=False)
    rerun = vd.samples_to_rerun(checked.sweep, opts, nominal_completed=True).any
    truth = brute_force(demo_traj, twin=boundary, samples=checked.sweep.samples[rerun])
    c = truth.classification
    counts = Counter("tracking" if o.value == "motor" and lag else o.value
                     for o, lag in zip(c.outcome, c.motor_tracking, strict=True)
                     if o.value != "success")
    assert sum(counts.values()) == checked.verification["failed"] > 0
    line = [c for c in checked.failure_causes
            if c.startswith("how the ") and "failing on their own full rollout failed: " in c]
    assert len(line) == 1, checked.failure_causes
    assert line[0].startswith(f"how the {sum(counts.values())} sample(s) failing on their own "
                              f"full rollout failed: ")
    words = {"dropped": "dropped", "slipped": "slipped (or turned) in the grip", "motor": "motor overload",
             "tracking": "lost tracking (a joint lagged its target)",
             "not_completed": "task not completed", "diverged": "simulation diverged"}
    for outcome, k in counts.items():
        assert f"{k} {words[outcome]}" in line[0]


def test_the_failure_lines_say_where_in_the_box_each_way_of_failing_lies():
    # A cube the fingers never let go (high friction) and one that slips out (low friction)
    # are both failures of the friction parameter; the lines say which side each lies on.
    from critmoment.params import FrictionParameter, MassParameter
    from critmoment.verdict import _kinds_text, _own_failures_text

    box = UncertaintyBox((MassParameter("mass", "box", 0.025, 0.3, 0.05),
                          FrictionParameter("friction", "box", 0.3, 6.0, 1.0)))
    own = {"not_completed": (2, None, ()), "dropped": (3, 4.0, ())}
    points = {"not_completed": np.array([[0.054, 5.9], [0.034, 4.57]]),
              "dropped": np.array([[0.2, 0.4], [0.28, 0.35], [0.03, 0.5]])}
    text = _own_failures_text(own, points, box)
    assert ("3 dropped (first at t = 4 s; all at friction ≤ 0.5), 2 task not completed (all "
            "at friction ≥ 4.57)") in text, text
    one = _kinds_text({"motor": 1}, {"motor": np.array([[0.29, 1.2]])}, box)
    assert one == "1 motor overload (at mass = 0.29 kg and friction = 1.2)"
    both_sides = _kinds_text({"dropped": 2}, {"dropped": np.array([[0.2, 0.4], [0.03, 2.0]])},
                             box)
    assert both_sides == "2 dropped"
    assert _kinds_text({"dropped": 2}) == "2 dropped"


def test_the_own_failures_line_names_the_motor():
    from critmoment.verdict import _own_failures_text

    text = _own_failures_text({"motor": (30, 3.31, ("shoulder_lift",)),
                               "dropped": (2, 4.0, ())})
    assert text.startswith("how the 32 sample(s) failing on their own full rollout failed: 30 "
                           "motor overload (shoulder_lift; first at t = 3.31 s), 2 dropped "
                           "(first at t = 4 s); suggestion: check the named actuators' limits")
    assert _own_failures_text({}) == ""
    lagged = _own_failures_text({"tracking": (51, 1.5, ("A_ARTz",))})
    assert lagged.startswith("how the 51 sample(s) failing on their own full rollout failed: "
                             "51 lost tracking (a joint lagged its target) (A_ARTz; first at "
                             "t = 1.5 s); suggestion: the named joints could not follow")
    assert "[limits]" not in lagged


@pytest.mark.parametrize("seed", [0, 7, 14])
def test_moments_include_lift_off_and_hand_over(twin, seed):
    import sys
    from pathlib import Path

    from critmoment import demos
    from critmoment.recording import rollout

    sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "benchmarks"))
    from moments_recall import ground_truth

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rec = rollout(demos.scripted_transfer(seed, twin=twin), twin=twin)
    moments = analysis.detect_moments(rec, twin)
    assert len(moments) <= 8
    steps = np.array([m.step for m in moments])
    lift, handover = ground_truth(rec, twin.scenario)
    assert np.min(np.abs(steps - lift)) <= 10
    assert np.min(np.abs(steps - handover)) <= 10
    labels = {m.label.value for m in moments}
    assert {"lift-off", "hand-over"} <= labels
    scores = [m.score for m in moments]
    assert scores == sorted(scores, reverse=True)


def test_untouched_box_has_no_critical_moment(twin):
    from critmoment import suite
    from critmoment.recording import rollout

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rec = rollout(suite.make("no_grasp", seed=0, twin=twin), twin=twin)
    moments = analysis.detect_moments(rec, twin)
    assert moments
    assert all(not m.critical and m.score < twin.scenario.cost.threshold for m in moments)


def test_first_failure_sweep_gives_the_exhaustive_verdict(twin, demo_traj, nominal_report):
    full = analyze(demo_traj, twin=twin, options=dataclasses.replace(FAST, exhaustive=True))
    fast = nominal_report
    assert fast.options.exhaustive is False
    assert fast.verdict is full.verdict and fast.p_success == full.p_success
    assert fast.safe_region_text == full.safe_region_text
    np.testing.assert_array_equal(fast.failed, full.failed)
    # per moment: the first failures that stand partition the sweep's failing samples
    # that fail in the end
    assert sum(mr.fail_fraction for mr in fast.moments) == pytest.approx(
        (fast.sweep.failed_any & fast.failed).mean())
    assert all(mr.reached == 1.0 for mr in full.moments)
    assert any(mr.reached < 1.0 for mr in fast.moments)
    for a, b in zip(fast.moments, full.moments, strict=True):
        assert a.critical == b.critical
        assert a.fail_fraction <= b.fail_fraction


def test_a_squeeze_is_decided_by_rollouts_not_by_the_sparse_cost(twin, scenario):
    """`jitter` squeezes the cube off the table before lifting it: sparse evaluation calls
    that a failure even at the nominal parameters, the runs themselves succeed."""
    from critmoment import suite

    traj = suite.make("jitter", seed=0, twin=twin)
    box = scenario.box.with_range("mass", 0.05, 0.2).with_range("friction", 0.5, 1.5)
    # every contact excursion counts at once (persistence 0): the squeeze's brief ones too
    light = Twin(scenario.replace(box=box, sparse=dataclasses.replace(scenario.sparse,
                                                                      persistence=0.0)))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        strict = analyze(traj, twin=light, options=dataclasses.replace(FAST, verify=None))
        checked = analyze(traj, twin=light, options=FAST)
    # sparse evaluation alone calls part of the box a failure at the squeeze
    assert strict.verdict is not Verdict.SAFE and strict.p_success < 1.0
    assert strict.nominal_cost > scenario.cost.threshold
    assert checked.nominal_cost == strict.nominal_cost
    assert checked.verdict is Verdict.SAFE and checked.p_success == 1.0
    v = checked.verification
    assert v["unlifted"] > 0 and v["unlifted_failed"] == 0
    assert any("squeeze" in c for c in checked.failure_causes)
    assert any(mr.squeeze for mr in checked.moments)
    assert not any(mr.squeeze for mr in strict.moments if mr.fail_fraction == 0
                   and all(v is None for v in mr.critical.values()))


# --------------------------------------------------------------------------
# one critical-value routine; the stated safe region holds
# --------------------------------------------------------------------------


def test_critical_values_are_the_sparse_routine_and_bracket_the_crossing(
        nominal_report, twin, demo_traj):
    from critmoment import sparse
    from critmoment.sparse import OthersAt, SparseEvaluator

    r = nominal_report
    rec = r.recording
    engine = SparseEvaluator(rec, twin)
    steps = np.array([mr.moment.step for mr in r.moments])
    cvs = sparse.critical_values(rec, twin, steps, evaluator=engine, n_grid=FAST.critical_grid,
                                 others=(OthersAt.NOMINAL,))
    by = {(cv.step, cv.parameter): cv for cv in cvs}
    for mr in r.moments:
        for name in twin.scenario.box.names:
            cv = by[int(mr.moment.step), name]
            assert mr.critical[name] == cv.value
            assert mr.critical_side[name] == (None if cv.direction is None
                                              else cv.direction.value)
    # the critical mass at the lift-off separates passing from failing masses
    lift = next(mr for mr in r.moments if mr.moment.label.value == "lift-off")
    m_star = lift.critical["mass"]
    assert m_star is not None and lift.critical_side["mass"] == "above"
    samples = np.tile(twin.scenario.box.nominal, (2, 1))
    samples[:, 0] = [0.99 * m_star, 1.01 * m_star]
    check = engine.evaluate([lift.moment.step], samples)
    assert check.failed[0].tolist() == [False, True]


def _region_fails(traj, twin, region, per_edge=6, inside=16):
    """Full rollouts of the region's corners and edges and of ``inside`` points in it (a
    scrambled Sobol set, not the audit's own): the points whose real run fails."""
    from scipy.stats import qmc

    box = twin.scenario.box
    pts, _ = vd.region_points(region, box, per_edge=per_edge)
    lo = np.array([region[n][0] for n in box.names])
    hi = np.array([region[n][1] for n in box.names])
    u = qmc.Sobol(d=box.ndim, scramble=True, seed=7).random(inside)
    pts = np.vstack([pts, lo + u * (hi - lo)])
    bf = brute_force(traj, twin=twin, samples=pts)
    return pts[bf.failed], pts.shape[0]


def test_stated_region_holds_under_full_rollouts_narrow_box(demo_traj, scenario):
    """The fast variant: mass ≤ 1 kg, where the outcome changes inside the box."""
    narrow = Twin(scenario.replace(box=scenario.box.with_range("mass", 0.05, 1.0)))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = analyze(demo_traj, twin=narrow, options=FAST)
    assert r.verdict is Verdict.CONDITIONAL and r.safe_region is not None
    assert r.region_check is not None and r.region_check.holds
    # the corners and coarse edge points (and any point near the threshold) of the holding
    # round are decided on their own run, as a sample is; the densified points between them
    # by sparse evaluation, since no chained sample failed on its own run here
    check = r.region_check
    coarse, _ = vd.region_points(check.region, narrow.scenario.box, per_edge=3)
    assert check.own_runs >= coarse.shape[0] and check.n_chained + check.n_rollouts >= 8
    assert "also on their own run" in r.safe_region_text
    # asked for every point (what the audit asks where a chained sample failed), each has one
    every = analysis.check_region(
        check.region, trajectory=demo_traj, twin=narrow,
        evaluator=analysis.audit_evaluator(r.recording, narrow)[0],
        steps=np.array([mr.moment.step for mr in r.moments]), sides=["above", "below"],
        options=analysis.decision_options(FAST, narrow.scenario.cost.threshold),
        nominal_completed=True)
    assert every.holds and every.own_runs == every.points.shape[0]
    failing, n = _region_fails(demo_traj, narrow, r.safe_region)
    assert n == 20 + 16 and failing.size == 0, f"the stated region fails at {failing}"
    assert r.to_json()["verification"]["region"]["holds"] is True


@pytest.mark.slow
def test_demo_safe_region_holds_under_full_rollouts(twin, demo_traj):
    """`critmoment demo --seed 0` (the audit's defaults): the stated region holds."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = analyze(demo_traj, twin=twin, options=AnalyzeOptions(seed=0))
    assert r.safe_region is not None
    failing, _ = _region_fails(demo_traj, twin, r.safe_region, per_edge=9)
    assert failing.size == 0, f"the stated region fails at {failing}"


def test_a_region_shrinks_only_from_failures_sparse_evaluation_decides_alone(twin,
                                                                             demo_traj):
    """A round whose sparse evaluation fails a point in a way it decides alone shrinks the
    region from those points only: the points whose failure only their own run decides
    (a settled grip, a margin) wait for it. Counting them too had cut the demo's first
    claim (mass <= 0.668 kg) to 0.568 kg at friction >= 0.857, and a Panda cube with
    solref 0.04 to "no safe region" after four rounds, where mass 0.05-0.5 kg at friction
    0.6-1.5 holds on every full run. The demo's region keeps the first claim's mass bound,
    and holds under its own check (the slow test runs its corners, edges and inside)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = analyze(demo_traj, twin=twin, options=AnalyzeOptions(seed=0))
    check = r.region_check
    assert check is not None and check.holds
    assert r.safe_region["mass"][1] == pytest.approx(check.first_claim["mass"][1])
    assert r.safe_region["mass"][1] > 0.66


def test_eight_samples_that_all_fail_state_no_region(twin, demo_traj):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = analyze(demo_traj, twin=twin,
                    options=dataclasses.replace(FAST, n_samples=8, seed=1))
    assert r.failed.all() and r.p_success == 0.0
    assert r.verdict is Verdict.CONDITIONAL
    assert r.safe_region is None and r.safe_region_text.startswith("no safe region")


def test_huge_mass_range_gives_a_consistent_statement(demo_traj, scenario):
    huge = Twin(scenario.replace(box=scenario.box.with_range("mass", 0.05, 1e9)))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = analyze(demo_traj, twin=huge, options=FAST)
    if r.p_success == 0.0:
        assert r.safe_region is None
    if r.safe_region is not None:
        nominal = dict(zip(huge.scenario.box.names, huge.scenario.box.nominal, strict=True))
        for mr in r.moments:
            for name, value in mr.critical.items():
                others_in = all(r.safe_region[q][0] <= nominal[q] <= r.safe_region[q][1]
                                for q in nominal if q != name)
                if value is None or mr.squeeze or not others_in:
                    continue
                lo, hi = r.safe_region[name]
                if mr.critical_side[name] == "above":
                    assert hi <= value, (name, r.safe_region, value)
                else:
                    assert lo >= value, (name, r.safe_region, value)
    assert "≥ 8.5" not in r.safe_region_text


def test_the_report_says_where_the_force_ratio_does_not_decide(scenario, demo_traj):
    """Cost constants that put the nominal grip on the contact threshold all through the
    carry (a stand-in for chattering mesh fingers): the audit says the force ratio is not
    trusted at its moments, in report.json and in the summary, and still runs to a
    verdict."""
    from critmoment.report import report_json, summary_text
    from critmoment.scenario import CostParams

    twin = Twin(scenario.replace(cost=CostParams(A=40.0, alpha=0.1)))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = analyze(demo_traj, twin=twin, options=FAST)
    assert r.force_ratio_untrusted == tuple(int(mr.moment.step) for mr in r.moments) != ()
    doc = report_json(r)
    assert doc["contact_model"]["force_ratio_untrusted_at"] == list(r.force_ratio_untrusted)
    assert "force ratio not trusted" in summary_text(r)
    assert r.verdict is not Verdict.UNSAFE  # the nominal passes: its run completes


def test_threaded_audit_equals_a_sequential_one(twin, demo_traj, nominal_report):
    """The verification rollouts and the chained segments run in threads alongside the
    critical values and the searches; the report is the one a one-thread audit
    (``nthread=1``: no overlap, one MuJoCo thread) gives, and the timings are listed in
    STAGES order."""
    import dataclasses

    from critmoment import analysis

    assert isinstance(analysis._pool(1), analysis._InLine)
    sequential = analyze(demo_traj, twin=twin, options=dataclasses.replace(FAST, nthread=1))
    assert sequential.to_json(timings=False)["verdict"] == nominal_report.verdict.value
    keep = nominal_report.to_json(timings=False)
    again = sequential.to_json(timings=False)
    keep["manifest"]["options"].pop("nthread", None)
    again["manifest"]["options"].pop("nthread", None)
    assert again == keep
    order = [analysis.STAGES.index(k) for k in nominal_report.timings]
    assert order == sorted(order)


def test_untrusted_force_ratios_are_listed_only_at_moments_with_a_grip():
    """Where the nominal grip sits on the cone over the whole motion no moment trusts the
    force ratio, but a moment before the first touch has no ratio to distrust: it is not
    listed (a gantry's report named steps 13 and 117, long before any contact)."""
    import types

    from critmoment.analysis import _untrusted

    touch = np.zeros((400, 2), bool)
    touch[200:300, 0] = True
    rec = types.SimpleNamespace(signals=types.SimpleNamespace(contact_gripper=touch))
    ev = types.SimpleNamespace(horizon=10, persistence_steps=10,
                               contact_trusted=lambda steps: np.zeros(len(steps), bool))
    # 50: nothing near; 185: its window (20 steps) reaches the touch at 200; 250: gripped
    assert _untrusted(rec, ev, np.array([50, 185, 250, 350])) == (185, 250)
    ev.contact_trusted = lambda steps: np.array([False, False, True, False])
    assert _untrusted(rec, ev, np.array([50, 185, 250, 350])) == (185,)


def test_the_nominal_runs_own_motor_failure_is_named(twin, demo_recording):
    import dataclasses as dc

    from critmoment.analysis import nominal_run_failure
    from critmoment.groundtruth import Outcome, reference_from_recording

    ref = reference_from_recording(demo_recording, twin)
    assert nominal_run_failure(ref, twin, demo_recording.dt) is None
    motor = dc.replace(ref, outcome=Outcome.MOTOR, first_failure_step=670, motor_column=1)
    name = twin.actuator_names[np.flatnonzero(twin.motors)[1]]
    text = nominal_run_failure(motor, twin, demo_recording.dt)
    assert text.startswith(f"motor overload: actuator {name!r} held at 99.9% of its force "
                           f"limit or more for over 50 ms from t = 1.34 s")
    assert text.endswith("the task is completed all the same)")
    incomplete = dc.replace(ref, outcome=Outcome.NOT_COMPLETED)
    assert nominal_run_failure(incomplete, twin, demo_recording.dt) is None
    # a run that also does not complete its task is not said to complete it; a joint that
    # lags its target, well under its force limit, is a tracking loss, not an overload
    lagging = dc.replace(motor, completed=False, motor_tracking=True)
    text = nominal_run_failure(lagging, twin, demo_recording.dt)
    assert text.startswith(f"tracking loss: actuator {name!r}'s joint lagged its target by "
                           f"more than the nominal run's lag + 0.1 rad for over 50 ms from "
                           f"t = 1.34 s")
    assert text.endswith("nor is the task completed)")


def test_the_manifest_names_the_bytes_read_not_the_file_at_report_time(tmp_path, demo_traj):
    """A scenario or trajectory file rewritten while the audit runs: the manifest hashed
    the file at report time and named bytes the audit never read (twenty-fifth round)."""
    import hashlib
    import shutil

    from critmoment.analysis import AnalyzeOptions, _manifest
    from critmoment.scenario import bundled_scenario_path, load_scenario
    from critmoment.trajectory import load_trajectory, save_trajectory

    folder = tmp_path / "scn"
    shutil.copytree(bundled_scenario_path("aloha_transfer_cube").parent, folder)
    toml = folder / "scenario.toml"
    read = hashlib.sha256(toml.read_bytes()).hexdigest()
    sc = load_scenario(folder)
    save_trajectory(demo_traj, tmp_path / "t.npz")
    traj_read = hashlib.sha256((tmp_path / "t.npz").read_bytes()).hexdigest()
    traj = load_trajectory(tmp_path / "t.npz")
    toml.write_text(toml.read_text() + "\n# edited after loading\n")
    (tmp_path / "t.npz").write_bytes(b"rewritten")
    man = _manifest(sc, AnalyzeOptions(), traj)
    assert man["scenario_sha256"] == read
    assert man["trajectory_sha256"] == traj_read


def test_the_manifest_tells_apart_what_was_audited(tmp_path, demo_traj):
    """One file read with another object pose, a loaded trajectory changed in code, a
    scenario narrowed with Scenario.replace: each carried the file's hash alone, so audits
    with different verdicts had identical manifests; and a trajectory built in code with
    source='traj.npz' got the hash of whatever file of that name lay in the working
    folder."""
    import dataclasses

    from critmoment.analysis import AnalyzeOptions, _manifest
    from critmoment.scenario import load_scenario
    from critmoment.trajectory import Trajectory, load_trajectory, save_trajectory

    sc = load_scenario()
    save_trajectory(demo_traj, tmp_path / "t.npz")
    traj = load_trajectory(tmp_path / "t.npz")
    opt = AnalyzeOptions()
    base = _manifest(sc, opt, traj)
    posed = load_trajectory(tmp_path / "t.npz", object_pose=[0.2, 0.45, 0.02, 1, 0, 0, 0])
    changed = dataclasses.replace(traj, actions=traj.actions * 0.9)
    narrow = sc.replace(box=sc.box.with_range("mass", 0.05, 1.0))
    for other in (_manifest(sc, opt, posed), _manifest(sc, opt, changed)):
        assert other["trajectory_sha256"] == base["trajectory_sha256"]  # the file read
        assert other["trajectory_content_sha256"] != base["trajectory_content_sha256"]
    other = _manifest(narrow, opt, traj)
    assert other["scenario_content_sha256"] != base["scenario_content_sha256"]
    # the same inputs read again: the same identities
    again = _manifest(load_scenario(), opt, load_trajectory(tmp_path / "t.npz"))
    assert again["trajectory_content_sha256"] == base["trajectory_content_sha256"]
    assert again["scenario_content_sha256"] == base["scenario_content_sha256"]
    # built in code: no file hash, whatever lies in the working folder
    built = Trajectory(traj.actions, fps=traj.fps, source=str(tmp_path / "t.npz"))
    assert _manifest(sc, opt, built)["trajectory_sha256"] is None


def test_own_rollouts_of_a_point_run_once(twin, demo_traj, demo_recording, monkeypatch):
    """A point rolled out before (the same values to the bit: a face the region check's
    shrink kept, in its next round) keeps its outcome; only new points are run, each once."""
    from critmoment import analysis

    roll = analysis._Rollouts(demo_traj, twin, 1, recording=demo_recording)
    points = np.array([[0.05, 1.0], [3.0, 0.3]])
    np.testing.assert_array_equal(roll(points), [False, True])
    ran = []
    real = analysis._brute_force

    def counting(traj, *, samples, **kwargs):
        ran.append(np.array(samples))
        return real(traj, samples=samples, **kwargs)

    monkeypatch.setattr(analysis, "_brute_force", counting)
    again = np.array([[3.0, 0.3], [0.05, 1.0], [3.0, 0.3], [0.2, 1.2], [0.2, 1.2]])
    np.testing.assert_array_equal(roll(again), [True, False, True, False, False])
    assert len(ran) == 1
    np.testing.assert_array_equal(ran[0], [[0.2, 1.2]])


def test_critical_values_are_checked_by_the_full_run_just_past_them():
    """A critical value is sparse evaluation's, from the nominal state at one moment. Per
    parameter and side the most binding one is run just past it (the others at nominal):
    one that completes is refuted (out of the causes' values, the region's cuts and the
    sides' votes) and the next is run; one that fails stands with the less binding ones.
    One whose failing side holds the nominal value is refuted by a nominal run that
    completes, without a run (a chunked hand-over crossed for mass below 0.654 kg beside
    the nominal 0.05 kg, and no safe region was stated)."""
    from critmoment.moments import Moment, MomentLabel
    from critmoment.params import FrictionParameter, MassParameter

    box = UncertaintyBox((MassParameter("mass", "box", 0.05, 1.05, 0.05),
                          FrictionParameter("friction", "box", 0.2, 1.6, 1.0)))

    def moment(step, critical, side):
        m = Moment(step=step, time=step * 0.002, label=MomentLabel.LIFT_OFF, reason="test")
        return vd.MomentReport(moment=m, worst_case={}, max_cost=2.0, min_fos_contact=1.0,
                               min_fos_motor=3.0, critical=critical, critical_side=side,
                               dominant="contact", limiting_actuator="a", fail_fraction=0.5)

    reports = [moment(100, {"mass": 0.3, "friction": None}, {"mass": "above", "friction": None}),
               moment(200, {"mass": 0.5, "friction": 0.9}, {"mass": "above", "friction": "below"}),
               moment(300, {"mass": 0.7, "friction": 1.2}, {"mass": "above", "friction": "below"}),
               moment(400, {"mass": 0.6, "friction": None}, {"mass": "below", "friction": None})]
    runs = []

    def roll(points):  # the real runs fail for mass above 0.45 kg or friction below 0.95
        runs.append(np.array(points))
        return (points[:, 0] > 0.45) | (points[:, 1] < 0.95)

    out = analysis._check_critical(reports, box, roll, True)
    # mass: 0.3 refuted (0.31 completes), then 0.5 stands (0.51 fails) and so does 0.7 unrun;
    # friction below 1.2 holds the nominal 1.0: refuted by the nominal run; 0.9 stands
    assert out[0].critical["mass"] is None and out[0].critical_side["mass"] is None
    assert out[0].critical_refuted == {"mass": ("above", 0.3)}
    assert not out[1].critical_refuted
    assert out[2].critical == {"mass": 0.7, "friction": None}
    assert out[2].critical_refuted == {"friction": ("below", 1.2)}
    assert out[3].critical_refuted == {"mass": ("below", 0.6)}
    tried = np.vstack(runs[:2])
    np.testing.assert_allclose(tried, [[0.31, 1.0], [0.05, 0.886], [0.51, 1.0]])  # 1 % past
    # the runs just inside the standing values (0.49 kg; friction 0.914) fail too: each is
    # moved to where the own runs begin to fail, bisected from the nominal value
    np.testing.assert_allclose(runs[2], [[0.05, 0.914], [0.49, 1.0]])
    assert len(runs) == 3 + 2 * analysis.CRITICAL_BISECTIONS
    assert 0.45 - 0.44 / 32 <= out[1].critical["mass"] <= 0.45
    assert 0.95 <= out[1].critical["friction"] <= 0.95 + 0.086 / 32
    # where the runs just inside pass, the values stand as sparse evaluation put them
    runs.clear()
    out = analysis._check_critical(reports, box, lambda p: (roll(p) & (p[:, 0] > 0.495))
                                   | (p[:, 1] < 0.905), True)
    assert out[1].critical == {"mass": 0.5, "friction": 0.9}
    # a value within a step of the nominal: the point "inside" it lies past the nominal,
    # and no bisection can put it on the nominal's far side
    near_nominal = {("friction", "below"): (0, 0.995)}
    assert analysis._critical_from_inside(
        near_nominal, box, lambda p: ~np.isclose(p[:, 1], 1.0)) == {}
    # a nominal run that fails refutes nothing by itself: those values are run
    runs.clear()
    analysis._check_critical(reports, box, roll, False)
    tried = np.vstack(runs)
    assert any(np.allclose(row, [0.05, 1.2 - 0.014]) for row in tried)
    assert any(np.allclose(row, [0.6 - 0.01, 1.0]) for row in tried)


def test_a_critical_value_moves_only_with_runs_that_fail_the_moments_way():
    """probe r38: a grip-slip moment at 3.94 s read "fails for mass above 0.1 kg" (the
    nominal) where every run failed from 6.5 s on a joint held at its limit, and a slope's
    friction was put on the grasp where the cubes slid off before it. A standing value
    moves only with own runs that fail as its moment says (a drop or slip for the grip, an
    overload for a motor), no earlier than just before it; and not at all where the nominal
    run fails its ground truth."""
    import types

    from critmoment.moments import Moment, MomentLabel
    from critmoment.params import FrictionParameter, MassParameter

    box = UncertaintyBox((MassParameter("mass", "box", 0.05, 1.05, 0.1),
                          FrictionParameter("friction", "box", 0.2, 1.6, 1.0)))
    m = Moment(step=1970, time=3.94, label=MomentLabel.LIFT_OFF, reason="test")
    grip = vd.MomentReport(moment=m, worst_case={}, max_cost=2.0, min_fos_contact=1.0,
                           min_fos_motor=3.0, critical={"mass": 0.8, "friction": None},
                           critical_side={"mass": "above", "friction": None},
                           dominant="contact", limiting_actuator="a", fail_fraction=0.5)

    class Roll:
        def __init__(self, kind, time):
            self.kind, self.time, self.outcomes = kind, time, {}

        def __call__(self, points):
            fails = points[:, 0] > 0.45
            for p, f in zip(points, fails, strict=True):
                self.outcomes[analysis._point_key(p)] = (
                    self.kind if f else "success", self.time if f else None, None)
            return fails

        def nominal(self):
            return types.SimpleNamespace(outcome=analysis.Outcome.SUCCESS)

    stood = {("mass", "above"): (0, 0.8)}
    moved = analysis._critical_from_inside(stood, box, Roll("dropped", 4.2), [grip])
    assert 0.44 <= moved[(0, "mass")] <= 0.45
    assert analysis._critical_from_inside(stood, box, Roll("motor", 6.5), [grip]) == {}
    assert analysis._critical_from_inside(stood, box, Roll("dropped", 1.5), [grip]) == {}
    # a nominal run that fails its ground truth (a joint held at its limit): nothing moves
    failing = Roll("dropped", 4.2)
    failing.nominal = lambda: types.SimpleNamespace(outcome=analysis.Outcome.MOTOR)
    out = analysis._check_critical([grip], box, failing, True)
    assert out[0].critical["mass"] == 0.8
    out = analysis._check_critical([grip], box, Roll("dropped", 4.2), True)
    assert 0.44 <= out[0].critical["mass"] <= 0.45


def test_a_moment_says_how_many_samples_fail_on_their_own_runs_after_it():
    """probe r35 (OpenMANIPULATOR-X): 28 of 32 samples dropped the cube on their own runs
    just after the audited lift-off, while every moment's line read "fails 0 % of the box
    here". Each moment now counts the samples that pass sparse evaluation everywhere and fail
    on their own run (rollout, else chain) after it and before the next moment in time (the
    moments come by importance, not time)."""
    from types import SimpleNamespace

    moments = [SimpleNamespace(time=t) for t in (2.0, 1.0, 3.0)]   # by importance
    samples = np.arange(6, dtype=float)[:, None]
    failed = np.array([True, True, True, True, False, True])
    sweep = SimpleNamespace(failed=np.zeros((3, 6), bool))
    sweep.failed[0, 5] = True                      # fails at a moment: counted there
    rerun = np.array([True, False, False, False, False, False])
    runs = SimpleNamespace(rerun=rerun, chained=~rerun,
                           chained_steps=np.array([-1, 750, 1600, 100, -1, -1]))
    roll = SimpleNamespace(outcomes={analysis._point_key(samples[0]): ("dropped", 1.2, None)})
    out = analysis._own_failures_after(moments, sweep, failed, runs, roll, samples, 0.002)
    # sample 0 at 1.2 s and 1 at 1.5 s: after the moment at 1 s; 2 at 3.2 s: after 3 s;
    # 3 at 0.2 s: before every moment (the causes say it)
    np.testing.assert_allclose(out, [0.0, 2 / 6, 1 / 6])
