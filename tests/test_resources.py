"""Library calls are bounded as the CLI is, and refuse bad input with a CritmomentError.

Each test fails on the code before the fuzz round's fixes: unbounded rollouts, brute
forces and simulations, unbounded audit options, a horizon longer than the recording,
raw TypeError/AttributeError/ValueError tracebacks, and ``progress=5`` taken for True.
"""

from __future__ import annotations

import dataclasses
import warnings

import mujoco
import numpy as np
import pytest

import critmoment as cm
from critmoment import analysis, budget, report, search, validation
from critmoment import sparse as sp
from critmoment.exceptions import (
    CritmomentWarning,
    OutputError,
    ParameterError,
    ResourceLimitError,
)
from critmoment.moments import Moment, MomentLabel
from critmoment.twin import STATE_SPEC

NOMINAL = np.array([[0.05, 1.0]])


# -- 1: full rollouts of a user trajectory are within max_steps / max_batch_steps ------
def test_rollout_refuses_more_steps_than_max_steps(twin, demo_traj):
    """The CLI refused 10⁶ rows; cm.rollout ran out of memory (11.5 GiB) instead."""
    with budget.limits(max_steps=3999), pytest.raises(
            ResourceLimitError, match=r"rollout of .*at most 3,999 physics steps \(max_steps\), "
                                      r"got 4,000"):
        cm.rollout(demo_traj, twin=twin)


def test_brute_force_refuses_beyond_max_batch_steps(twin, demo_traj):
    samples = np.repeat(NOMINAL, 4, axis=0)
    with budget.limits(max_batch_steps=15_999), pytest.raises(
            ResourceLimitError, match=r"brute-force full rollouts.*4 samples x 4000"):
        cm.brute_force(demo_traj, twin=twin, samples=samples)


def test_simulate_checks_its_arrays_and_the_step_limit(twin):
    nstate = mujoco.mj_stateSize(twin.model, STATE_SPEC)
    controls = np.zeros((5, twin.model.nu))
    with budget.limits(max_steps=4), pytest.raises(ResourceLimitError, match="max_steps"):
        cm.simulate(twin, np.zeros(nstate), controls)
    with pytest.raises(ParameterError, match=rf"state0: expected shape \({nstate},\)"):
        cm.simulate(twin, np.zeros(3), controls)
    with pytest.raises(ParameterError, match=rf"controls: expected shape \(T, {twin.model.nu}\)"):
        cm.simulate(twin, np.zeros(nstate), np.zeros((5, 3)))
    with pytest.raises(ParameterError, match="expected the same number of simulations"):
        cm.simulate(twin, np.zeros((3, nstate)), controls, samples=np.repeat(NOMINAL, 2, 0))


# -- 2, 3, 6: options that size the work have upper bounds ---------------------------------
@pytest.mark.parametrize("field, value, bound", [
    ("map_resolution", 3000, r"\[0, 400\]"),
    ("critical_grid", 10**6, r"\[5, 1025\]"),
    ("search_trials", 10**7, r"\[1, 4096\]"),
])
def test_audit_options_have_upper_bounds(field, value, bound):
    with pytest.raises(ParameterError, match=rf"{field}: expected an integer in {bound}"):
        cm.AnalyzeOptions(**{field: value})
    top = int(bound.split(", ")[1].rstrip(r"\]"))
    assert getattr(cm.AnalyzeOptions(**{field: top}), field) == top


def test_thread_counts_are_bounded_everywhere(twin, demo_traj, demo_recording):
    """mujoco.batch raised ValueError('Could not allocate memory') for 100,000 threads."""
    match = rf"nthread: expected at most {budget.MAX_THREADS} threads"
    with pytest.raises(ParameterError, match=match):
        cm.AnalyzeOptions(nthread=100_000)
    with pytest.raises(ParameterError, match=match):
        sp.SparseEvaluator(demo_recording, twin, nthread=100_000)
    with pytest.raises(ParameterError, match=match):
        cm.brute_force(demo_traj, twin=twin, samples=NOMINAL, nthread=100_000)
    with pytest.raises(ParameterError, match=match):
        cm.validate(demo_traj, twin=twin, n_samples=4, nthread=100_000)
    assert cm.AnalyzeOptions(nthread=budget.MAX_THREADS).nthread == budget.MAX_THREADS


def test_cost_map_nearest_sample_matches_argmin_without_the_distance_matrix():
    """The map took cells × samples × 2 floats (8.6 GiB for 3000² cells and 64 samples);
    the nearest sample is now found by a k-d tree, ties to the lowest index as argmin."""
    rng = np.random.default_rng(3)
    sites = rng.random((300, 2))
    sites[7] = sites[3]  # an exact tie: argmin keeps the first
    grid = np.linspace(0.0, 1.0, 41)
    g0, g1 = np.meshgrid(grid, grid, indexing="ij")
    cells = np.stack([g0.ravel(), g1.ravel()], axis=1)
    d2 = ((cells[:, None, :] - sites[None, :, :]) ** 2).sum(axis=-1)
    np.testing.assert_array_equal(analysis._nearest(cells, sites), np.argmin(d2, axis=1))
    assert analysis._nearest(cells[:3], sites[:1]).tolist() == [0, 0, 0]


# -- 4: the audit's work estimate counts what the horizon costs ----------------------
def test_check_audit_counts_every_evaluation_not_only_the_sweep(twin, demo_traj):
    """8 samples × 1 moment × horizon 1000 is 8,000 sweep steps, which the old check
    counted alone; the ranking, curves, critical values, search and region check step the
    horizon too (a [sparse] horizon of 3999 took 485 s within the sweep's limit)."""
    opt = cm.AnalyzeOptions(n_samples=8, max_moments=1, horizon=1000)
    total, words = budget.audit_work(demo_traj, twin, opt)
    assert total > 50 * 8 * 1000
    assert "horizon 1000" in words and "critical_grid 17" in words
    with budget.limits(max_batch_steps=100_000), pytest.raises(
            ResourceLimitError, match=r"sparse sweep and the audit's other simulations.*"
                                      r"--max-batch-steps"):
        budget.check_audit(demo_traj, twin, opt)
    cheaper = budget.audit_work(demo_traj, twin, dataclasses.replace(opt, horizon=10))[0]
    costlier = budget.audit_work(demo_traj, twin, dataclasses.replace(
        opt, search_trials=4096, critical_grid=1025))[0]
    assert cheaper < total < costlier


# -- 5: a horizon must leave the recording room for its moments --------------------
@pytest.mark.parametrize("horizon, told", [
    (100_000, r"got 100,000 steps \(200 s\): it must be shorter than the recording of "
              r"4,000 steps = 8 s"),
    (3990, r"got 3,990 steps \(7.98 s\): it would leave only steps \[0, 10\]"),
])
def test_horizon_beyond_half_the_recording_is_refused_at_the_start(twin, demo_traj, horizon,
                                                                   told):
    """Before: a ParameterError deep in the sweep ('steps in [0, -96000]'), or the audited
    moments silently moved to step 10."""
    opt = cm.AnalyzeOptions(n_samples=8, max_moments=2, horizon=horizon)
    match = r"horizon: expected at most half of the recording, 2,000 physics steps \(4 s\), "
    with pytest.raises(ParameterError, match=match + told):
        budget.check_audit(demo_traj, twin, opt)
    with pytest.raises(ParameterError, match=match):
        cm.validate(demo_traj, twin=twin, n_samples=4, horizon=horizon)
    budget.check_audit(demo_traj, twin, dataclasses.replace(opt, horizon=2000))  # half: ok


def test_evaluator_refuses_a_horizon_longer_than_the_recording(twin, demo_recording):
    with pytest.raises(ParameterError, match=r"horizon: expected at most the recording's "
                                             r"4,000 physics steps \(8 s\), got 5,000"):
        sp.SparseEvaluator(demo_recording, twin, horizon=5000)


def test_moments_moved_by_the_horizon_are_named_in_a_warning(twin, demo_recording,
                                                             monkeypatch):
    ev = sp.SparseEvaluator(demo_recording, twin, horizon=500)
    late = Moment(step=3900, time=7.8, label=MomentLabel.RELEASE, reason="release")
    early = Moment(step=1000, time=2.0, label=MomentLabel.GRASP, reason="grasp")
    monkeypatch.setattr(analysis, "detect_moments", lambda *a, **k: [late, early])
    with pytest.warns(CritmomentWarning, match=r"1 moment\(s\) lie within the horizon's 500 "
                      r"steps.*from step 3500.*release at step 3900 \(t = 7.800 s\)"):
        _, steps = analysis.audit_moments(demo_recording, twin, ev, 2)
    assert steps.tolist() == [3500, 1000]
    monkeypatch.setattr(analysis, "detect_moments", lambda *a, **k: [early])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        analysis.audit_moments(demo_recording, twin, ev, 1)


# -- 7: public functions answer bad arguments with a CritmomentError -----------------
@pytest.mark.parametrize("samples", ["abc", [[1.0, None]], [[0.05, 1.0], [0.05]], None])
def test_validate_checks_explicit_samples(twin, demo_traj, samples):
    """'abc' raised ValueError from numpy inside the box's check (None: predict's)."""
    call = validation.predict if samples is None else cm.validate
    with pytest.raises(ParameterError, match=r"samples: expected a real array of shape "
                                             r"\(n, 2\) for parameters \['mass', 'friction'\]"):
        call(demo_traj, twin=twin, samples=samples)


def test_validate_checks_criteria_before_any_work(twin, demo_traj):
    with pytest.raises(ParameterError, match="criteria: expected an OutcomeCriteria"), \
            budget.limits(max_steps=10):  # refused before the rollout's own check
        cm.validate(demo_traj, twin=twin, n_samples=4, criteria=None)


def test_write_report_checks_its_arguments(tmp_path):
    with pytest.raises(ParameterError, match="report: expected an AuditReport"):
        report.write_report(None, tmp_path / "out")
    dummy = analysis.AuditReport.__new__(analysis.AuditReport)  # no field is read
    for out in (None, 5):
        with pytest.raises(ParameterError, match=r"output folder: expected a folder path "
                                                 r"\(str or os.PathLike\)"):
            report.write_report(dummy, out)


def test_write_report_names_the_output_folder_not_a_cli_flag(tmp_path):
    """A library call said "--out '...'", the CLI's flag."""
    afile = tmp_path / "a_file"
    afile.write_text("x")
    dummy = analysis.AuditReport.__new__(analysis.AuditReport)
    with pytest.raises(OutputError, match=r"^output folder '.*a_file': expected a folder"):
        report.write_report(dummy, afile)
    with pytest.raises(OutputError, match=r"^--out '"):  # the CLI's wording is kept
        report.StagedOutput(afile, command="analyze")


# -- 8: progress is a bool or a callable ------------------------------------------
@pytest.mark.parametrize("progress", [5, "yes", None])
def test_progress_must_be_a_bool_or_a_callable(demo_traj, progress):
    """5 was taken for True (and the audit ran)."""
    with pytest.raises(ParameterError, match="progress: expected True, False or a callable"):
        cm.analyze(demo_traj, progress=progress)


def test_critical_values_alone_are_within_max_batch_steps(twin, demo_recording):
    """The audit's option was bounded, but sp.critical_values(n_grid=...) called alone was
    not; its sweeps now count against max_batch_steps before any work."""
    with budget.limits(max_batch_steps=3_999), pytest.raises(
            ResourceLimitError, match=r"critical values' sweeps: expected at most 3,999 .*got "
                                      r"4,000 .*2 placement\(s\) x 1 moment\(s\) x 2 "
                                      r"parameter\(s\) x n_grid 100 x horizon 10"):
        sp.critical_values(demo_recording, twin, [1707], n_grid=100)


@pytest.mark.parametrize("call, match", [
    (lambda ev: search.search_worst_case(ev, [1707], n_trials=10**7), r"n_trials: .*\[1, 4096\]"),
    (lambda ev: search.search_worst_case(ev, [1707], batch_size=10**6), r"batch_size: .*\[1, 4096\]"),
    (lambda ev: search.surrogate_worst_case(ev, [1707], starts=10**6), r"starts: .*\[1, 4096\]"),
    (lambda ev: search.surrogate_worst_case(ev, [1707], max_iter=10**9), r"max_iter: .*100000\]"),
])
def test_the_searches_called_alone_are_bounded(twin, demo_recording, call, match):
    """The audit's search options were bounded, but the search functions called alone took
    any budget (Optuna keeps every trial in memory)."""
    ev = sp.SparseEvaluator(demo_recording, twin)
    with pytest.raises(ParameterError, match=match):
        call(ev)


def test_the_audits_search_bound_is_the_searchs():
    assert analysis.MAX_SEARCH_TRIALS == search.MAX_TRIALS
