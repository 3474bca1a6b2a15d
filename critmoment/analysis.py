"""The end-to-end audit: frequent rollout → moments → bounds/search → sparse sweep → verdict.

:func:`analyze` chains the stages and returns an :class:`AuditReport`, the object
``critmoment analyze`` renders as ``report.json``, figures, ``report.html`` and a terminal
summary (see :mod:`critmoment.report`). Each stage is also callable alone.

The audit computes the evidence (sparse evaluations, the full rollouts of the samples they
cannot decide, :func:`critmoment.groundtruth.brute_force`, the critical values of
:func:`critmoment.sparse.critical_values`, the check of the safe region,
:func:`check_region`); the decision itself is :func:`critmoment.verdict.decide`, pure, the
same path :func:`critmoment.validation.predict` measures.
"""

from __future__ import annotations

import concurrent.futures
import contextlib
import contextvars
import dataclasses
import functools
import logging
import math
import platform
import sys
import threading
import time
import warnings
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np

from critmoment import budget, contactmodel, history
from critmoment import sparse as sp
from critmoment import verdict as vd
from critmoment.exceptions import CritmomentWarning, ParameterError
from critmoment.feasibility import FeasibilityReport, check_fit, preflight
from critmoment.groundtruth import (
    NominalReference,
    Outcome,
    OutcomeCriteria,
    _brute_force,
    reference_from_recording,
)
from critmoment.moments import Moment, MomentDetector, MomentLabel
from critmoment.recording import (
    Recording,
    at_scenario_rate,
    check_task_window,
    model_hash,
    rollout,
)
from critmoment.scenario import Scenario
from critmoment.trajectory import Trajectory, check_trajectory, input_identity, printable_name
from critmoment.twin import Twin, entry_point, resolve_twin
from critmoment.verdict import MomentReport, Verdict, safe_subbox

__all__ = [
    "Verdict",
    "AnalyzeOptions",
    "MomentReport",
    "AuditReport",
    "detect_moments",
    "audit_moments",
    "sensitivity_function",
    "safe_subbox",
    "decision_options",
    "check_region",
    "sample_runs",
    "analyze",
    "REPORT_SCHEMA",
]

log = logging.getLogger(__name__)

REPORT_SCHEMA = "critmoment.report/1"

#: upper bounds of the options that size work no physics-step limit counts alone (the
#: work they add is counted by :func:`critmoment.budget.check_audit` too): the cost map's
#: cells per axis (a 400 × 400 map is finer than its figure), the critical values' grid
#: points per parameter, and the search's evaluations per moment (Optuna's TPE slows with
#: every trial it has seen)
MAX_MAP_RESOLUTION = 400
MAX_CRITICAL_GRID = 1025
MAX_SEARCH_TRIALS = 4096  # search.MAX_TRIALS (search is imported lazily: Optuna, CasADi)


@dataclasses.dataclass(frozen=True)
class AnalyzeOptions:
    """Options of :func:`analyze`.

    Attributes:
        seed: seeds the Sobol sweep and the search (same seed → same report).
        n_samples: Sobol samples of the box for P(success) (a power of 2 is best).
        max_moments: moments audited in depth (the most sensitive ones).
        horizon: physics steps per sparse evaluation (default: the scenario's); at most half
            of the recording (:func:`critmoment.budget.check_horizon`).
        search_trials: simulated evaluations the Optuna search may spend per moment (at
            most :data:`MAX_SEARCH_TRIALS`).
        search_patience: the search of a moment stops after this many batches (of 8
            samples) without a higher cost (None: it spends ``search_trials``).
        search: run the analytic bounds and the worst-case search.
        critical_grid: grid points per parameter for the critical values (at most
            :data:`MAX_CRITICAL_GRID`).
        confidence: confidence level of the P(success) interval.
        min_success: P(success) at which ``passes`` accepts a non-SAFE verdict.
        nthread: threads for MuJoCo's batch (0: all CPUs; at most
            :data:`critmoment.budget.MAX_THREADS`). With 1 the audit runs in one
            thread throughout (its own runs do not overlap the other stages).
        map_resolution: cells per axis of the mass × friction cost map, the nearest Sobol
            sample's cost per cell (0 to skip; at most :data:`MAX_MAP_RESOLUTION`).
        chain: carry every sample that passes at the moments without a rollout of its own on
            its own state through the moments (:func:`critmoment.history.chained_failures`,
            :func:`critmoment.verdict.samples_to_chain`): the sample's own history (a grip
            that shifts, a collision that never happens at nominal) decides it.
        require_task: a nominal rollout that does not complete the scenario's task (its
            success rule, :meth:`critmoment.task.Task.success`) makes the verdict UNSAFE.
        exhaustive: evaluate every Sobol sample at every moment over the whole horizon.
            By default each sample stops at its first failure, as the real run would
            (:meth:`critmoment.sparse.SparseEvaluator.evaluate` with ``first_failure``):
            the verdict, P(success), the safe region and each sample's first failing moment
            are the same, the per-moment box statistics then cover the samples that reach
            the moment (``MomentReport.reached``), and the sweep costs a fraction of the
            stepping wherever much of the box fails.
        verify: a fraction of the cost threshold, or None. Every Sobol sample that passes
            the sparse evaluation with a cost at or above ``verify × threshold`` at some
            moment gets its own full rollout, and that rollout's real outcome decides it
            (:func:`critmoment.groundtruth.brute_force`: the object dropped or slipped, a joint
            lost tracking or saturated, the task not completed). Near the boundary sparse
            evaluation at a few moments can miss a failure that happens between them; the
            default 0.8 brings the measured false-safe rate to 0 (``docs/validation.md``)
            for a few full rollouts.
        verify_unlifted: with ``verify``, a sample that fails only where the nominal run
            squeezes the object off its support without lifting it
            (``SparseResult.unlifted_failure``) gets its own full rollout too, which decides
            it: the sparse evaluation cannot tell a squeeze that a heavier object survives
            on the table from a failed lift.
    """

    seed: int = 0
    n_samples: int = 256
    max_moments: int = 8
    horizon: int | None = None
    search_trials: int = 48
    search_patience: int | None = 2
    search: bool = True
    critical_grid: int = 17
    confidence: float = 0.95
    min_success: float | None = None
    nthread: int = 0
    map_resolution: int = 40
    require_task: bool = True
    verify: float | None = 0.8
    verify_unlifted: bool = True
    exhaustive: bool = False
    check_feasibility: bool = True  # critmoment.feasibility.preflight on the nominal rollout
    chain: bool = True

    def __post_init__(self):
        budget.check_seed(self.seed, what="seed")
        _option_int("n_samples", self.n_samples, 8)
        _option_int("max_moments", self.max_moments, 1)
        _option_int("horizon", self.horizon, 1, none=True)
        _option_int("search_trials", self.search_trials, 1, most=MAX_SEARCH_TRIALS)
        _option_int("search_patience", self.search_patience, 1, none=True)
        _option_int("critical_grid", self.critical_grid, 5, most=MAX_CRITICAL_GRID)
        _option_int("nthread", self.nthread, 0)
        budget.check_nthread(self.nthread)
        _option_int("map_resolution", self.map_resolution, 0, most=MAX_MAP_RESOLUTION)
        _option_real("confidence", self.confidence, "in (0, 1)", lambda v: 0 < v < 1)
        _option_real("min_success", self.min_success, "in [0, 1]", lambda v: 0 <= v <= 1,
                     none=True)
        _option_real("verify", self.verify, "in (0, 1] (a fraction of the threshold)",
                     lambda v: 0 < v <= 1, none=True)
        for name in ("search", "require_task", "verify_unlifted", "exhaustive",
                     "check_feasibility", "chain"):
            _option_bool(name, getattr(self, name))


def _option_bool(name: str, value: Any) -> None:
    """An option that must be True or False (a string such as "no" is not)."""
    if not isinstance(value, (bool, np.bool_)):
        raise ParameterError(f"{name}: expected True or False, got "
                             f"{type(value).__name__} {value!r}")


def _option_int(name: str, value: Any, least: int, *, none: bool = False,
                most: int | None = None) -> None:
    """An option that must be an integer >= ``least`` (and <= ``most``; or None where
    ``none``)."""
    if value is None and none:
        return
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)) \
            or value < least:
        raise ParameterError(f"{name}: expected an integer >= {least}"
                             f"{' or None' if none else ''}, got {type(value).__name__} "
                             f"{value!r}")
    if most is not None and value > most:
        raise ParameterError(f"{name}: expected an integer in [{least}, {most}] (the upper "
                             f"bound of critmoment.analysis.AnalyzeOptions), got {value!r}")


def _option_real(name: str, value: Any, expected: str, ok: Callable[[float], bool], *,
                 none: bool = False) -> None:
    """An option that must be a finite real number for which ``ok`` holds (or None)."""
    if value is None and none:
        return
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer,
                                                                      np.floating)) \
            or not math.isfinite(value) or not ok(float(value)):
        raise ParameterError(f"{name}: expected a number {expected}"
                             f"{' or None' if none else ''}, got {type(value).__name__} "
                             f"{value!r}")


@dataclasses.dataclass(frozen=True, eq=False)
class AuditReport:
    """The result of :func:`analyze`.

    Attributes:
        verdict: SAFE, CONDITIONAL or UNSAFE.
        p_success: probability of success under the prior (fraction of Sobol samples that
            pass at every moment).
        p_success_interval: Wilson interval of ``p_success``.
        moments: the audited moments, most sensitive first.
        candidates: every candidate moment considered, ranked.
        safe_region: the safe sub-box, per parameter (low, high), or None when none found.
        safe_region_text: the safe sub-box in words.
        failure_causes: per failing moment, the cause and the suggestion, in words.
        nominal_cost: max cost at the nominal parameters over the moments.
        recording: the frequent rollout.
        sweep: the sparse evaluations of the Sobol sweep (m moments × n samples).
        curves: per moment and parameter, the 1-D sweep behind the critical values.
        cost_map: (axes, cost grid) of the first two parameters at the worst moment, or None.
        scenario: the scenario.
        options: the options.
        timings: seconds per stage, in :data:`STAGES` order (wall time; verification and
            the chained segments run alongside the critical values and the searches,
            so the stages overlap and sum to more than the audit).
        manifest: versions, model hash, seed and options.
        failed: per Sobol sample of ``sweep``, whether it fails (sparse evaluation at the
            moments, then the verification rollouts), (n,) bool.
        verification: the verification stage's summary (``fraction``, ``cost_from``,
            ``rollouts``, ``failed``, ``near``, ``unlifted``, ... and ``region``, the safe
            region's check), or None when it did not run.
        region_check: the check of the stated safe region on its corners, edges and inside
            (:func:`check_region`), or None when no region was claimed.
        feasibility: the twin's feasibility and the trajectory's fit on the nominal rollout
            (:func:`critmoment.feasibility.preflight`), or None when not checked.
        contact_model: the contact model's check (:func:`critmoment.contactmodel.
            check_contact_model`: cone, impratio, noslip, the measured creep of a held object).
        force_ratio_untrusted: steps of the audited moments with a grip on the object where
            the contact force ratio does not decide, because the nominal grip, whose run
            completes the task, already sits on the friction cone there (or, in all, for
            the persistence time over the whole motion) (:meth:`critmoment.sparse.SparseEvaluator.
            contact_trusted`): measured slip and the motor criterion decide them.
        load_bound: the analytic motor bound over the whole motion
            (:func:`critmoment.dynamics.trajectory_load_bound`) at the nominal and the
            largest mass: per mass the first time [s] a joint saturates (as the ground truth
            counts it) and which, and the smallest payload any step can take; None without
            ``search``.
        warnings: the warnings of the run the caller attached, one line each, for the
            report's record (the command line attaches every warning of the run: actions
            clipped to their range, an object pose assumed, keys ignored, ...; the library
            leaves them to the caller's ``warnings`` handling and this empty).
        unlimited_motors: the motor-checked actuators (``Twin.motors``: the arm's, not a
            gripper's fingers, whose squeeze is limited on purpose) with no force limit in
            the scenario or the MJCF: their motor FOS is not checked.
    """

    verdict: Verdict
    p_success: float
    p_success_interval: tuple[float, float]
    moments: tuple[MomentReport, ...]
    candidates: tuple[Moment, ...]
    safe_region: Mapping[str, tuple[float, float]] | None
    safe_region_text: str
    failure_causes: tuple[str, ...]
    nominal_cost: float
    recording: Recording
    sweep: sp.SparseResult | None
    curves: Mapping[int, Mapping[str, sp.SparseResult]]
    cost_map: tuple | None
    scenario: Scenario
    options: AnalyzeOptions
    timings: Mapping[str, float]
    manifest: Mapping
    failed: np.ndarray | None = None
    verification: Mapping | None = None
    region_check: vd.RegionCheck | None = None
    feasibility: FeasibilityReport | None = None
    contact_model: contactmodel.ContactModelReport | None = None
    load_bound: Mapping | None = None
    force_ratio_untrusted: tuple[int, ...] = ()
    unlimited_motors: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

    def passes(self, min_success: float | None = None) -> bool:
        """SAFE, or CONDITIONAL with P(success) ≥ ``min_success`` (the CLI's exit code 0).
        A ``min_success`` of 1 asks for no failure anywhere: a CONDITIONAL audit found one
        (a worst case or a region point that fails), whatever its samples estimate (a
        failing sliver of 0.2 % of the box gave P = 1.000 over 256 samples)."""
        _option_real("min_success", min_success, "in [0, 1]", lambda v: 0 <= v <= 1,
                     none=True)
        if self.verdict is Verdict.SAFE:
            return True
        if self.verdict is Verdict.UNSAFE:
            return False
        threshold = self.options.min_success if min_success is None else min_success
        return threshold is not None and threshold < 1.0 and self.p_success >= threshold

    def to_json(self, *, timings: bool = True) -> dict:
        """The ``report.json`` document (schema ``critmoment.report/1``)."""
        from critmoment.report import report_json

        _option_bool("timings", timings)
        return report_json(self, timings=bool(timings))


# -- stage: critical moments ----------------------------------------------------------
def sensitivity_function(evaluator: sp.SparseEvaluator, box) -> Callable[[np.ndarray], np.ndarray]:
    """Score moments by how much the cost moves over the box.

    The probe is the 3**k grid of each parameter's low end, prior median and high end (the
    box's corners, its centre and the mid-points of its faces). The score is the mean cost
    over the probe: the corners alone saturate (a 10 kg cube at μ = 0.2 fails wherever the
    grip carries it), the mean tells moments that fail over much of the box from moments that
    fail at one corner.
    """
    grids = np.meshgrid(*[[0.0, 0.5, 1.0]] * box.ndim, indexing="ij")
    probe = box.from_unit(np.stack([g.reshape(-1) for g in grids], axis=1))

    def score(steps: np.ndarray) -> np.ndarray:
        steps = np.asarray(steps, dtype=np.int64)
        if steps.size == 0:
            return np.zeros(0)
        res = evaluator.evaluate(steps, probe, settle=False)
        return np.mean(np.minimum(res.cost, 10.0), axis=1)

    return score


def detect_moments(recording: Recording, twin: Twin, *, evaluator: sp.SparseEvaluator | None = None,
                   max_moments: int = 8, min_gap: float = 0.2, **options) -> list[Moment]:
    """Candidate critical moments, ranked by sensitivity over the box.

    Change points and contact events (:class:`~critmoment.moments.MomentDetector`) are
    scored with :func:`sensitivity_function`. Contact events (grasp, lift-off, hand-over, ...)
    are always kept; change points fill the remaining places in score order, skipping any
    closer than ``min_gap`` to a moment already taken, so that one long sensitive phase
    (carrying the object) does not crowd out the others. A change point shortly after a
    contact event names that event in its reason.

    Args:
        recording: the frequent rollout.
        twin: its twin.
        evaluator: a sparse evaluator of ``recording`` to reuse.
        max_moments: at most this many moments are returned.
        min_gap: smallest time between two returned moments [s].
        **options: keyword options of :class:`~critmoment.moments.MomentDetector`.

    Returns:
        The moments, most sensitive first; ``critical`` marks those whose score exceeds the
        scenario's cost threshold.
    """
    if min_gap < 0:
        raise ParameterError(f"min_gap: expected >= 0 s, got {min_gap}")
    evaluator = evaluator or sp.SparseEvaluator(recording, twin)
    options.setdefault("max_candidates", 32)
    detector = MomentDetector(max_moments=options["max_candidates"], **options).fit(recording)
    last = recording.n_steps - evaluator.horizon
    sens = sensitivity_function(evaluator, twin.scenario.box)

    def clipped(steps):
        return sens(np.minimum(np.asarray(steps, dtype=np.int64), last))

    ranked = detector.predict(sensitivity=clipped, threshold=twin.scenario.cost.threshold)
    events = sorted((m for m in ranked if m.label is not MomentLabel.CHANGE_POINT),
                    key=lambda m: m.step)
    gap = int(round(min_gap / recording.dt))
    # contact events are always candidates; change points fill the other places, at least
    # min_gap away from everything taken, in order of sensitivity
    chosen: list[Moment] = list(events[:max_moments])
    for m in ranked:
        if len(chosen) >= max_moments:
            break
        if m.label is not MomentLabel.CHANGE_POINT or any(
                abs(m.step - c.step) < gap for c in chosen):
            continue
        before = [e for e in events if 0 < m.step - e.step <= 4 * gap]
        if before:
            e = before[-1]
            m = dataclasses.replace(
                m, reason=f"{(m.step - e.step) * recording.dt:.2f} s after {e.label.value} "
                          f"({e.reason.split(';')[0]}); {m.reason}")
        chosen.append(m)
    chosen.sort(key=lambda m: (-m.score, m.step))
    return [dataclasses.replace(m, reason=_dedupe(m.reason)) for m in chosen]


def audit_moments(recording: Recording, twin: Twin, evaluator: sp.SparseEvaluator,
                  max_moments: int) -> tuple[list[Moment], np.ndarray]:
    """The audit's moments: the ranked candidates and the steps of the first ``max_moments``.

    :func:`analyze` and :func:`critmoment.validation.predict` both call this, so validation
    tests exactly the moments the audit evaluates.

    Returns:
        (candidates, most sensitive first; steps of the audited ones, clipped so that the
        evaluator's horizon fits in the recording, (m,) int64).
    """
    if isinstance(max_moments, bool) or not isinstance(max_moments, (int, np.integer)) \
            or max_moments < 1:
        raise ParameterError(f"max_moments: expected an integer >= 1, got {max_moments!r}")
    candidates = detect_moments(recording, twin, evaluator=evaluator,
                                max_moments=max(8, int(max_moments)))
    last = recording.n_steps - evaluator.horizon
    steps = np.array([min(m.step, last) for m in candidates[:max_moments]], dtype=np.int64)
    moved = [m for m in candidates[:max_moments] if m.step > last]
    if moved:
        dt = recording.dt
        names = "; ".join(f"{m.label.value} at step {m.step} (t = {m.step * dt:.3f} s)"
                          for m in moved)
        warnings.warn(
            f"{len(moved)} moment(s) lie within the horizon's {evaluator.horizon} steps of "
            f"the recording's end and are audited from step {last} (t = {last * dt:.3f} s) "
            f"instead, over the steps up to the end: {names}; a shorter horizon audits "
            f"them where they happen", CritmomentWarning, stacklevel=2)
    return candidates, steps


def _dedupe(reason: str) -> str:
    """Keep the first of several reasons that say the same thing (change point per channel)."""
    seen, parts = set(), []
    for part in reason.split("; "):
        key = part.split(" (jump")[0]
        if key not in seen:
            seen.add(key)
            parts.append(part)
    return "; ".join(parts)


# -- the pipeline --------------------------------------------------------------------
_TERM_NAME = {sp.Term.CONTACT: "contact", sp.Term.MOTOR: "motor", sp.Term.DIVERGED: "diverged"}


def _dominant(res: sp.SparseResult, row: int, mask: np.ndarray) -> str | None:
    if not mask.any():
        return None
    terms = res.dominant[row][mask]
    values, counts = np.unique(terms, return_counts=True)
    return _TERM_NAME[sp.Term(int(values[np.argmax(counts)]))]


def _curves(evaluator, steps: np.ndarray, box, n: int) -> dict[int, dict[str, sp.SparseResult]]:
    """1-D sweeps of each parameter (others nominal) at every moment: thesis Figs. 5–6."""
    out: dict[int, dict[str, sp.SparseResult]] = {int(s): {} for s in steps}
    grids = []
    for j in range(box.ndim):
        u = np.full((n, box.ndim), 0.5)
        u[:, j] = np.linspace(0.0, 1.0, n)
        samples = box.from_unit(u)
        samples[:, [i for i in range(box.ndim) if i != j]] = box.nominal[
            [i for i in range(box.ndim) if i != j]]
        grids.append((steps, samples))
    for p, res in zip(box.parameters, evaluator.evaluate_many(grids, settle=False), strict=True):
        for row, s in enumerate(steps):
            out[int(s)][p.name] = _select(res, row)
    return out


def _passing_note(one: sp.SparseResult, evaluator: sp.SparseEvaluator) -> str:
    """Why a worst case whose cost crosses the threshold does not fail (``one``: its own
    evaluation, one moment and one sample, passing)."""
    persistence = float(evaluator.settings.persistence)
    excursion = float(one.excursion[0, 0])
    if excursion < persistence:
        return (f"the cost stays over the threshold for {excursion * 1e3:.0f} ms, under the "
                f"{persistence * 1e3:.0f} ms a contact failure must persist")
    return "the grip has not moved: its force ratio on the cone is not a slip"


def _select(res: sp.SparseResult, row: int) -> sp.SparseResult:
    """One moment's rows of a result, as a result with m = 1."""
    fields = {}
    for f in dataclasses.fields(res):
        v = getattr(res, f.name)
        if f.name in ("steps",):
            v = v[row:row + 1]
        elif isinstance(v, np.ndarray) and f.name != "samples" and v.ndim >= 1 \
                and v.shape[0] == res.n_moments:
            v = v[row:row + 1]
        fields[f.name] = v
    return sp.SparseResult(**fields)


@entry_point
def analyze(trajectory: Trajectory, scenario: Scenario | str | None = None, *,
            seed: int | None = None, twin: Twin | None = None,
            options: AnalyzeOptions | None = None,
            progress: bool | Callable[[str], None] = False) -> AuditReport:
    """Audit a trajectory: is it safe over the scenario's uncertainty box?

    Args:
        trajectory: the trajectory to audit.
        scenario: a Scenario, a path or bundled name, or None for the bundled one.
        seed: shortcut for ``options.seed``.
        twin: a twin to reuse (its scenario wins).
        options: audit options (:class:`AnalyzeOptions`).
        progress: True to print stage progress on stderr, or a callable taking a message.
            It is called from the audit's own threads too (the physics thread says
            "verification ..." and "chained segments ..." while this one works), so it
            must be thread-safe; an exception it raises stops the audit, as an interrupt
            does.

    Returns:
        The audit report.

    Raises:
        ParameterError: bad options, a ``progress`` that is neither a bool nor a callable,
            or a horizon longer than half the recording.
        ResourceLimitError: the rollout or the audit's simulations beyond the limits of
            :mod:`critmoment.budget` (:func:`critmoment.budget.check_audit`).
        TrajectoryError: a trajectory the scenario cannot play (its width, its units, a
            rate it cannot reach, targets out of range under ``range_policy = "error"``).
        ScenarioError: a scenario that cannot be loaded or does not fit the model.
        InputFileError: a scenario given by a path that does not exist, or an unknown
            bundled name.
        InfeasibleTwinError: the twin cannot reproduce the nominal motion
            (:func:`critmoment.feasibility.check_feasibility`).
        SimulationDivergedError: the nominal run diverges.
    """
    check_trajectory(trajectory)
    say = _progress(progress)
    if options is not None and not isinstance(options, AnalyzeOptions):
        raise ParameterError(f"options: expected AnalyzeOptions (critmoment.AnalyzeOptions"
                             f"(n_samples=..., ...)), got {type(options).__name__}")
    opt = options or AnalyzeOptions()
    if seed is not None:
        opt = dataclasses.replace(opt, seed=budget.check_seed(seed))
    twin = resolve_twin(scenario, twin)
    trajectory = at_scenario_rate(trajectory, twin)
    sc = twin.scenario
    if opt.search:
        _load_solvers()
    check_task_window(twin, trajectory)  # a success rule no run of this length can meet
    budget.check_audit(trajectory, twin, opt)  # seed domain, rollout and sweep size
    box = sc.box
    threshold = sc.cost.threshold
    timings: dict[str, float] = {}

    def stage(name):
        return _Timer(timings, name, say)

    with stage("rollout"):
        check_fit(trajectory, None, twin)  # width and units, naming the likely mistake
        rec = rollout(trajectory, twin=twin)
        feasibility = preflight(trajectory, rec, twin) if opt.check_feasibility else None
    with stage("moments"):
        evaluator, contact = audit_evaluator(rec, twin, horizon=opt.horizon, chain=opt.chain,
                                             nthread=opt.nthread)
        candidates, steps = audit_moments(rec, twin, evaluator, opt.max_moments)
        chosen = candidates[:steps.size]
    with stage("sweep"):
        samples = sp.sweep_samples(box, n=opt.n_samples, seed=opt.seed)
        probe = np.vstack([box.nominal[None, :], samples])
        res_all = evaluator.evaluate(steps, probe, first_failure=not opt.exhaustive)
        nominal_cost = float(res_all.worst_cost()[0]) if steps.size else 0.0
        res = _select_samples(res_all, slice(1, None))
    dopt = decision_options(opt, threshold)
    roll = _Rollouts(trajectory, twin, opt.nthread, recording=rec)

    def alongside():
        # the critical values and the searches (mostly Python) while the samples' own runs
        # go on in MuJoCo's threads: no result depends on the overlap
        with stage("critical values"):
            curves = _curves(evaluator, steps, box, opt.critical_grid) if steps.size else {}
            critical = _critical_values(rec, twin, evaluator, steps, opt.critical_grid)
        searches: dict[int, dict] = {}
        load_bound = None
        analytics: dict[int, dict] = {}
        if opt.search and steps.size:
            with stage("analytic bounds and search"):
                analytics, searches = _search_all(rec, twin, evaluator, steps, opt)
                load_bound = _load_bound(rec, twin)
        return curves, critical, searches, load_bound, analytics

    runs, (curves, critical, searches, load_bound, analytics) = sample_runs(
        evaluator, steps, samples, res, dopt, roll=roll, nominal_completed=rec.completed,
        nthread=opt.nthread, stage=stage, alongside=alongside)
    verification = None
    sample_evidence = runs.evidence(res, nominal_completed=rec.completed)
    failed = vd.failing_samples(sample_evidence, dopt)
    if opt.verify is not None and steps.size:
        verification = {"fraction": float(opt.verify),
                        "cost_from": float(opt.verify * threshold), **runs.counts(failed)}
    own_after = _own_failures_after(chosen, res, failed, runs, roll, samples, rec.dt)
    moment_reports = []
    worst_failed_sparse: dict[int, bool] = {}  # per moment: its worst case fails (sparse)
    worst_unlifted: dict[int, bool] = {}  # per failing moment: its worst case is unlifted
    worst_cases = [_worst_case(res, row, searches.get(int(steps[row])), box)
                   for row in range(len(chosen))]
    # the failing worst cases, evaluated again alone (one batch call for all moments)
    failing = [row for row, (case, cost, _) in enumerate(worst_cases)
               if case and not cost <= threshold]
    again = dict(zip(failing, evaluator.evaluate_many(
        [([int(steps[row])], [[worst_cases[row][0][n] for n in box.names]])
         for row in failing]), strict=True))
    for row, m in enumerate(chosen):
        s = int(steps[row])
        worst_case, max_cost, motor = worst_cases[row]
        crit = {name: critical[s][name].value for name in box.names}
        side = {name: (None if critical[s][name].direction is None
                       else critical[s][name].direction.value) for name in box.names}
        fails_here = res.failed[row]
        standing = fails_here & failed  # failures their own runs, where any, confirm
        dominant = _dominant(res, row, fails_here)
        if dominant is None:
            dominant = next((d for c in curves[s].values()
                             if (d := _dominant(c, 0, c.failed[0])) is not None), None)
        worst_fails, worst_note = None, ""
        if row in again:
            one = again[row]
            worst_failed_sparse[s] = worst_fails = bool(one.failed[0, 0])
            if not worst_fails:
                worst_note = _passing_note(one, evaluator)
            # unlifted or sticking: only a rollout can say whether it really fails
            worst_unlifted[s] = dopt.only_a_rollout_decides(
                bool(one.unlifted_failure[0, 0]), bool(one.sticking_failure[0, 0]),
                bool(one.short_slip(dopt.slip_confirm)[0, 0]),
                bool(one.margin_failure[0, 0]))
            if dominant is None:
                # only the search's worst case fails here: its own evaluation says why
                dominant = _dominant(one, 0, one.failed[0])
                if dominant is not None:
                    motor = int(one.motor_argmax[0, 0])
        if motor is None:  # no sample reached the moment: the first curve's worst point
            c = curves[s][box.names[0]]
            motor = int(c.motor_argmax[0, int(np.argmax(np.nan_to_num(c.cost[0], nan=-1.0)))])
        seen = [(res.failed[row], res.unlifted_failure[row])] + [
            (c.failed[0], c.unlifted_failure[0]) for c in curves[s].values()]
        squeeze = (any(f.any() for f, _ in seen)
                   and all((u[f]).all() for f, u in seen))
        moment_reports.append(MomentReport(
            moment=m, worst_case=worst_case, max_cost=max_cost,
            min_fos_contact=_nanmin(res.fos_grasp[row]),
            min_fos_motor=_nanmin(res.fos_motor[row]),
            critical=crit, critical_side=side, dominant=dominant,
            limiting_actuator=twin.actuator_names[motor],
            fail_fraction=float(standing.mean()), own_fail_fraction=float(own_after[row]),
            analytic=analytics.get(s),
            overturned=bool(fails_here.any() and not standing.any()),
            search=searches.get(s), reached=float((~np.isnan(res.cost[row])).mean()),
            squeeze=bool(squeeze), audited_step=None if s == int(m.step) else s,
            worst_fails=worst_fails, worst_note=worst_note))
    # each stated critical value checked by the full run just past it (the others at nominal)
    moment_reports = _check_critical(moment_reports, box, roll, rec.completed)
    # the failing worst cases that only a rollout can decide (squeezes)
    worst_failed: dict[int, bool] = {}
    rerun_steps = vd.worst_cases_to_rerun(moment_reports, worst_failed_sparse, worst_unlifted,
                                          dopt, n_failed=int(failed.sum()))
    if rerun_steps:
        by_step = {mr.step: mr for mr in moment_reports}
        points = np.array([[by_step[s].worst_case[n] for n in box.names] for s in rerun_steps])
        real = roll(points)
        worst_failed = dict(zip(rerun_steps, map(bool, real), strict=True))
        moment_reports = [
            dataclasses.replace(mr, worst_fails=worst_failed[mr.step], worst_note=(
                "" if worst_failed[mr.step] else "its own full run completes the task"))
            if mr.step in worst_failed else mr for mr in moment_reports]
        if verification is not None:
            verification["worst_cases"] = len(rerun_steps)
            verification["worst_cases_failed"] = int(real.sum())
    chain_points = _chain_failure_points(runs, failed, samples)
    evidence = vd.Evidence(
        box=box, samples=sample_evidence, nominal_cost=nominal_cost,
        nominal_failed=bool(res_all.failed_any[0]) if steps.size else False,
        nominal_unlifted=bool(res_all.failed_unlifted_only[0]) if steps.size else False,
        nominal_stage=(int(rec.stage.max()), int(rec.stage[-1])),
        completion_rule=_completion_rule(rec, twin), stage_names=tuple(twin.task.stage_names),
        moments=tuple(moment_reports), worst_failed=worst_failed_sparse,
        worst_unlifted=worst_unlifted,
        worst_rollouts_failed=worst_failed, trend=_trend(curves, box),
        own_failures=roll.failures(samples[runs.rerun]),
        chain_failures={kind: len(rows) for kind, rows in chain_points.items()},
        own_failure_points=roll.failure_points(samples[runs.rerun]),
        chain_failure_points=chain_points,
        nominal_run_failure=nominal_run_failure(roll.nominal(), twin, rec.dt))
    decision = vd.decide(evidence, dopt)
    region_check = None
    if decision.region_to_check is not None and steps.size:
        with stage("safe region check"):
            sides = evidence.sides(decision.failed)
            region_check = check_region(decision.region_to_check, trajectory=trajectory,
                                        twin=twin, evaluator=evaluator, steps=steps,
                                        sides=sides, options=dopt,
                                        nominal_completed=rec.completed,
                                        exhaustive=opt.exhaustive, nthread=opt.nthread,
                                        reference=roll.nominal(),
                                        every_point=bool((failed & runs.chained).any()),
                                        known=samples[(runs.chained | runs.rerun) & ~failed])
        decision = vd.decide(dataclasses.replace(evidence, region=region_check), dopt)
        if verification is not None:
            verification["region"] = region_check.to_json()
    cost_map = None
    if opt.map_resolution and box.ndim >= 2 and steps.size:
        cost_map = _cost_map(res, box, opt.map_resolution)
    manifest = _manifest(sc, opt, trajectory, twin)
    return AuditReport(
        verdict=decision.verdict, p_success=decision.p_success,
        p_success_interval=decision.p_success_interval,
        moments=tuple(moment_reports), candidates=tuple(candidates),
        safe_region=decision.safe_region, safe_region_text=decision.safe_region_text,
        failure_causes=decision.causes,
        nominal_cost=nominal_cost, recording=rec, sweep=res, curves=curves, cost_map=cost_map,
        scenario=sc, options=opt, timings=_in_order(timings), manifest=manifest, failed=decision.failed,
        verification=verification, region_check=region_check, feasibility=feasibility,
        contact_model=contact, load_bound=load_bound,
        force_ratio_untrusted=_untrusted(rec, evaluator, steps),
        unlimited_motors=twin.unlimited_motors)


#: how far past a critical value its check runs, in the parameter's prior (unit) scale
CRITICAL_STEP = 0.01


def _check_critical(reports: Sequence[vd.MomentReport], box, roll: Callable[..., np.ndarray],
                    nominal_completed: bool) -> list[vd.MomentReport]:
    """The moments' critical values, each checked where it binds by the full run just past it
    (``CRITICAL_STEP`` of the parameter's range on its failing side, the others at nominal).

    A critical value is sparse evaluation's: restored from the nominal state at one moment,
    the cost crosses the threshold there. The sample's own run can differ: a Panda carrying
    its cube tilted 40° crossed at joint6 for mass above 0.383 kg, and cut the safe region
    there, while full runs up to 1.2 kg complete. Per parameter and side the most binding
    value (the lowest "above", the highest "below") is run; one that fails stands (moved
    to where the own runs begin to fail where its run just inside it fails too:
    :func:`_critical_from_inside`), and so
    do the less binding ones of that side (they cut no more); one that completes is
    refuted (``MomentReport.critical_refuted``: out of the causes' critical values, the
    region's cuts and the sides' votes), and the next one is run, until one stands. One
    whose failing side holds the nominal value is refuted by the nominal run where that
    completes the task (an ACT-like chunked hand-over crossed for mass below 0.654 kg
    beside the nominal 0.05 kg: with "above 0.315 kg" at another moment, the run just
    past it failed for the other reason, mass read as failing both ways, and no safe
    region was stated).
    """
    reports = list(reports)
    refuted: dict[tuple[int, str], tuple[str, float]] = {}
    settled: set[tuple[str, str]] = set()
    stood: dict[tuple[str, str], tuple[int, float]] = {}  # the most binding value that fails
    nominal = dict(zip(box.names, map(float, box.nominal), strict=True))
    for i, mr in enumerate(reports):
        for name in box.names:
            value, side = mr.critical.get(name), mr.critical_side.get(name)
            if (nominal_completed and value is not None and not mr.squeeze
                    and (side == "above" and value < nominal[name]
                         or side == "below" and value > nominal[name])):
                refuted[(i, name)] = (side, float(value))
    while True:
        todo: dict[tuple[str, str], tuple[int, float]] = {}
        for i, mr in enumerate(reports):
            if mr.squeeze:
                continue
            for name in box.names:
                value, side = mr.critical.get(name), mr.critical_side.get(name)
                key = (name, side)
                if value is None or side is None or key in settled or (i, name) in refuted:
                    continue
                best = todo.get(key)
                if best is None or (value < best[1] if side == "above" else value > best[1]):
                    todo[key] = (i, float(value))
        if not todo:
            break
        points = np.array([_past_critical(box, name, side, value)
                           for (name, side), (_, value) in todo.items()])
        for ((name, side), (i, value)), failed in zip(todo.items(), roll(points), strict=True):
            if failed:
                settled.add((name, side))
                stood[(name, side)] = (i, value)
            else:
                refuted[(i, name)] = (side, value)
    reference = roll.nominal() if hasattr(roll, "nominal") else None
    nominal_passes = nominal_completed and (reference is None
                                            or reference.outcome is Outcome.SUCCESS)
    moved = _critical_from_inside(stood, box, roll, reports) if nominal_passes else {}
    for (i, name), value in moved.items():
        reports[i] = dataclasses.replace(reports[i], critical={
            **reports[i].critical, name: value})
    out = []
    for i, mr in enumerate(reports):
        gone = {name: value for (j, name), value in refuted.items() if j == i}
        if gone:
            mr = dataclasses.replace(
                mr, critical={k: (None if k in gone else v) for k, v in mr.critical.items()},
                critical_side={k: (None if k in gone else v)
                               for k, v in mr.critical_side.items()},
                critical_refuted=gone)
        out.append(mr)
    return out


#: full runs that bisect, between the nominal value and a critical value whose run just
#: inside it fails too, for where the own runs begin to fail
CRITICAL_BISECTIONS = 5


def _critical_from_inside(stood: Mapping[tuple[str, str], tuple[int, float]], box,
                          roll: Callable[..., np.ndarray],
                          reports: Sequence[vd.MomentReport] = ()
                          ) -> dict[tuple[int, str], float]:
    """The standing critical values (per parameter and side, the most binding one whose run
    just past it fails) whose run ``CRITICAL_STEP`` inside them fails too, each moved to
    where the own runs begin to fail: ``CRITICAL_BISECTIONS`` full runs bisect between the
    nominal value (its run completes the task) and the failing inside point, and the last
    passing value is stated ({(report index, parameter): value}).

    Sparse evaluation restores the nominal state, and a sample's own run can fail earlier:
    where a held object creeps down the pads (a WidowX 250 s on a pyramidal cone), "fails
    for mass above 0.185 kg" was stated while full runs fail from 0.12 kg; a lying cylinder
    on a Panda, "above 1.38 kg" where full runs drop it at 1.0 kg.

    Only a run that fails the moment's way counts (:func:`_fails_there`): a grip-slip
    moment's value had moved to the nominal 0.1 kg where every run failed later on a joint
    held at its limit, and to a slope's friction where cubes slid off before the grasp. The
    caller runs this only where the nominal run passes its ground truth."""
    out: dict[tuple[int, str], float] = {}
    if not stood:
        return out
    keys = list(stood)
    inside = np.array([_past_critical(box, name, "below" if side == "above" else "above",
                                      stood[(name, side)][1]) for name, side in keys])
    for (name, side), point, failed in zip(keys, inside, roll(inside), strict=True):
        mr = reports[stood[(name, side)][0]] if reports else None
        if not _fails_there(roll, point, mr, failed=bool(failed)):
            continue
        j = box.index(name)
        lo = _unit_of(box, j, box.nominal[j])  # passes: the nominal run completes the task
        hi = _unit_of(box, j, point[j])  # fails
        if (hi - lo) * (_unit_of(box, j, stood[(name, side)][1]) - lo) <= 0:
            continue  # the value lies within a step of the nominal
        for _ in range(CRITICAL_BISECTIONS):
            mid = 0.5 * (lo + hi)
            if _fails_there(roll, _nominal_with(box, j, mid), mr):
                hi = mid
            else:
                lo = mid
        out[(stood[(name, side)][0], name)] = float(_nominal_with(box, j, lo)[j])
    return out


#: the ground truth's outcomes that a moment's dominant cause can lead to
_CAUSE_OUTCOMES = {"contact": {Outcome.DROPPED.value, Outcome.SLIPPED.value,
                               Outcome.NOT_COMPLETED.value},
                   "motor": {Outcome.MOTOR.value, "tracking"}}
#: how long before a moment its run's first failure may lie and still be the moment's [s]
_CAUSE_LEAD = 0.05


def _fails_there(roll: Callable[..., np.ndarray], point: np.ndarray,
                 mr: vd.MomentReport | None, *, failed: bool | None = None) -> bool:
    """``point``'s own run fails (``failed``, when it has run), and as moment ``mr`` says
    it would: an outcome its dominant cause leads to (a slip or a drop for the grip, an
    overload or a lag for a motor), first failing no earlier than just before the moment."""
    if failed is None:
        failed = bool(roll(np.asarray(point, dtype=np.float64)[None])[0])
    if not failed:
        return False
    got = getattr(roll, "outcomes", {}).get(_point_key(point))
    if mr is None or got is None:
        return True
    kind, first, _ = got
    family = _CAUSE_OUTCOMES.get(mr.dominant or "")
    if family is not None and kind not in family:
        return False
    return first is None or first >= mr.moment.time - _CAUSE_LEAD


def _unit_of(box, j: int, value: float) -> float:
    """Parameter ``j`` at ``value`` in its prior's unit scale."""
    point = box.nominal.astype(np.float64).copy()
    point[j] = value
    return float(box.to_unit(point[None])[0, j])


def _nominal_with(box, j: int, u: float) -> np.ndarray:
    """The nominal point with parameter ``j`` at unit value ``u`` (within the box), the
    others at their nominal values exactly."""
    unit = box.to_unit(box.nominal[None])
    unit[0, j] = min(max(u, 0.0), 1.0)
    point = box.nominal.astype(np.float64).copy()
    point[j] = box.from_unit(unit)[0, j]
    return point


def _past_critical(box, name: str, side: str, value: float) -> np.ndarray:
    """The nominal point with ``name`` moved ``CRITICAL_STEP`` of its prior's range past
    ``value`` on the failing ``side`` (within the box)."""
    j = box.index(name)
    return _nominal_with(box, j, _unit_of(box, j, value)
                         + (CRITICAL_STEP if side == "above" else -CRITICAL_STEP))


def _completion_rule(rec: Recording, twin: Twin) -> str:
    """The task's rule in words, and what the nominal run lacks of it."""
    rule = f"needed: {twin.task.describe()}"
    short = rec.shortfalls()
    return f"{rule}; the nominal run: {'; '.join(short)}" if short else rule


def _worst_case(res: sp.SparseResult, row: int, search: Mapping | None, box
                ) -> tuple[dict[str, float], float, int | None]:
    """A moment's worst case: the sweep's costliest sample there, or the search's worst
    case when it costs more; (parameters by name, cost, the sweep's limiting actuator or
    None)."""
    cost = res.cost[row]
    here = ~np.isnan(cost)  # the samples evaluated at this moment (inf: diverged)
    worst_case, max_cost, motor = {}, float("nan"), None
    if here.any():
        worst = int(np.argmax(np.where(here, np.where(np.isinf(cost), 1e9, cost), -np.inf)))
        worst_case = dict(zip(box.names, map(float, res.samples[worst]), strict=False))
        max_cost, motor = float(cost[worst]), int(res.motor_argmax[row, worst])
    if search is not None and search.get("worst_cost") is not None and not (
            search["worst_cost"] <= max_cost):
        worst_case, max_cost = dict(search["worst_case"]), float(search["worst_cost"])
    return worst_case, max_cost, motor


def _untrusted(rec: Recording, evaluator: sp.SparseEvaluator, steps: np.ndarray
               ) -> tuple[int, ...]:
    """The audited moments whose contact force ratio does not decide and where a gripper
    touches the object in the nominal run's window (before the first touch there is no
    ratio to distrust)."""
    touched = rec.signals.contact_gripper.any(axis=-1)
    h = evaluator.horizon + evaluator.persistence_steps
    return tuple(int(k) for k, ok in zip(steps, evaluator.contact_trusted(steps), strict=True)
                 if not ok and touched[int(k):int(k) + h].any())


def sample_runs(evaluator: sp.SparseEvaluator, steps: np.ndarray, samples: np.ndarray,
                sweep: sp.SparseResult | None, options: vd.DecisionOptions, *,
                roll: Callable[..., np.ndarray], nominal_completed: bool, nthread: int = 0,
                stage: Callable | None = None,
                alongside: Callable[[], Any] | None = None,
                chained_before: dict | None = None) -> tuple[vd.SampleRuns, Any]:
    """The samples' own runs that complete the sweep's evidence: the one path of
    :func:`analyze` and :func:`critmoment.validation.predict`.

    The samples the sweep cannot decide (:func:`critmoment.verdict.samples_to_rerun`) get
    their own full rollout; those that pass without one are chained (:func:`chain_samples`),
    and the chained samples it names go on to their own full rollout. With ``nthread`` other
    than 1 the rollouts and then the chain run in a thread of their own (with the
    evaluator's and ``roll``'s MuJoCo threads; the chain shares its samples out to two
    Python threads, :func:`critmoment.history.chained_failures`) while ``alongside`` runs in
    this one, which then takes the rollouts if that thread has not started them.

    Args:
        evaluator: the audit's sparse evaluator.
        steps: the audited moments' steps, (m,).
        samples: the parameter samples, (n, k).
        sweep: their sparse evaluation at ``steps``, or None without moments.
        options: the decision options.
        roll: full rollouts of parameter points, ``roll(points, nthread=None)`` -> failed.
        nominal_completed: the nominal run completes the task.
        nthread: threads (0: all CPUs; 1: everything in this thread, in turn).
        stage: a context-manager factory timing a named stage, or None.
        alongside: work for this thread meanwhile, or None.
        chained_before: the chains' results by point, kept across calls with the same
            evaluator, moments and options (:func:`chain_samples`), or None.

    Returns:
        The :class:`~critmoment.verdict.SampleRuns` and what ``alongside`` returned.
    """
    timer = stage or (lambda name: contextlib.nullcontext())
    n = samples.shape[0]
    moments = steps.size > 0 and sweep is not None
    # the moments where the nominal parameters fail the sparse evaluation: a sample restored
    # there inherits the nominal run's state, whose own run says whether that is a failure
    nominal_failed = _nominal_failed(evaluator, steps) if moments else None
    reruns = vd.samples_to_rerun(sweep, options, nominal_completed=nominal_completed,
                                 nominal_failed=nominal_failed)
    rerun = reruns.any
    # one physics thread beside this one, with all of MuJoCo's threads, running the
    # rollouts and then the chain (divisible across threads, it ends the overlap; a batch of
    # 5 rollouts on 2 threads ended on one), unless this thread, done with ``alongside``,
    # has taken the rollouts: not the chain and the rollouts each in a thread of their own
    # with all MuJoCo threads (3.3-4.9 s against 4.0-5.5 s, and about 1 s more CPU;
    # 2026-12-03, demo audit)

    def verify():
        failed = np.zeros(n, bool)
        if options.verify is not None and moments:
            with timer("verification"):
                if rerun.any():
                    failed[rerun] = roll(samples[rerun])
        return failed

    def chain():
        if not (options.chain and moments):
            return (np.zeros(n, bool), np.zeros(n, bool), np.zeros(n, bool), [None] * n,
                    np.full(n, -1, np.int64))
        with timer("chained segments"):
            return chain_samples(evaluator.fork(), steps, samples, sweep, rerun, options,
                                 nominal_completed=nominal_completed,
                                 chained_before=chained_before)

    verifying = _Once(verify)

    def physics():
        verifying.run()
        return chain()

    with budget.cancel_scope() as cancel, _pool(nthread) as pool:
        # in a copy of this thread's context: the budget in force (budget.limits, the
        # CLI's --max-steps) holds in the physics thread too, and so does the cancel scope
        chaining = pool.submit(contextvars.copy_context().run, physics)
        if not isinstance(chaining, _Done):
            # while the physics thread steps (with all MuJoCo threads), this thread's sparse
            # evaluations take one: five busy threads on two cores cost 6.5 s of CPU for
            # the demo audit, three 6.1 s (2026-12-03, medians of 8)
            evaluator.busy = lambda: not chaining.done()
        try:
            try:
                extra = alongside() if alongside is not None else None
            finally:
                evaluator.busy = None
            verifying.run()  # this thread takes the rollouts if that thread has not
            chained, chained_failed, suspect, kinds, chained_steps = chaining.result()
            rerun_failed = verifying.result()
        except BaseException:
            # stopped (an interrupt, a timeout, an error here): the physics thread stops at
            # its next batch, not at the end of its stage (4 s on the demo; minutes on a
            # long run, past a CI runner's grace before SIGKILL)
            cancel.set()
            raise
    if suspect.any() and options.verify is not None:
        with timer("chained segments"):
            # failed on its own path (approximately its own run): its own rollout decides
            rerun_failed[suspect] = roll(samples[suspect])
    else:
        suspect = np.zeros(n, bool)
    return vd.SampleRuns(reruns=reruns, chained=chained, chained_failed=chained_failed,
                         suspect=suspect, rerun_failed=rerun_failed,
                         nominal_failed=nominal_failed, chained_kinds=tuple(kinds),
                         chained_steps=chained_steps), extra


def nominal_run_failure(reference: NominalReference | None, twin: Twin,
                         dt: float) -> str | None:
    """How the nominal run itself fails by the ground truth's rules other than the task's,
    in words, or None (a success, or a run that only does not complete its task: the task's
    own rule speaks for that)."""
    if reference is None or reference.outcome in (Outcome.SUCCESS, Outcome.NOT_COMPLETED):
        return None
    when = (f" from t = {reference.first_failure_step * dt:.3g} s"
            if reference.first_failure_step >= 0 else "")
    if reference.outcome is Outcome.MOTOR:
        actuator = _motor_name(twin, reference.motor_column)
        name = f" {actuator!r}" if actuator is not None else ""
        c = OutcomeCriteria()
        task = ("the task is completed all the same" if reference.completed
                else "nor is the task completed")
        if reference.motor_tracking:
            motors = np.flatnonzero(twin.motors)
            slide = (0 <= reference.motor_column < motors.size
                     and bool(twin.slide[motors[reference.motor_column]]))
            tolerance = (f"{c.tracking_tolerance_slide:g} m" if slide
                         else f"{c.tracking_tolerance:g} rad")
            return (f"tracking loss: actuator{name}'s joint lagged its target by more than "
                    f"the nominal run's lag + {tolerance} for over "
                    f"{c.tracking_time * 1e3:g} ms{when} (the ground truth's rule; {task})")
        return (f"motor overload: actuator{name} held at {c.saturation:.1%} of its force limit "
                f"or more for over {c.motor_time * 1e3:g} ms{when} (the ground truth's rule; "
                f"{task})")
    return f"{reference.outcome.value}{when}"


def _motor_name(twin: Twin, column: int) -> str | None:
    """The actuator of column ``column`` of the motor-checked actuators (``Twin.motors``
    order, as ``Classification.motor_column`` counts them), or None for −1."""
    motors = np.flatnonzero(twin.motors)
    return twin.actuator_names[motors[column]] if 0 <= column < motors.size else None


def _own_failures_after(moments, sweep: sp.SparseResult, failed: np.ndarray,
                        runs: vd.SampleRuns, roll: _Rollouts, samples: np.ndarray,
                        dt: float) -> np.ndarray:
    """Per moment (time order), the fraction of the sweep's samples that pass sparse
    evaluation at every moment and fail on their own run (its full rollout, else its chain)
    first after the moment and before the next (:attr:`MomentReport.own_fail_fraction`)."""
    out = np.zeros(len(moments))
    n = samples.shape[0]
    if not len(moments) or n == 0:
        return out
    times = np.array([float(m.time) for m in moments])
    order = np.argsort(times, kind="stable")  # the moments come by importance
    times = times[order]
    own = np.asarray(failed, bool) & ~np.asarray(sweep.failed, bool).any(axis=0)
    rerun = runs.rerun
    for i in np.flatnonzero(own):
        when = None
        if rerun[i]:
            got = roll.outcomes.get(_point_key(samples[i]))
            when = None if got is None else got[1]
        elif runs.chained[i] and runs.chained_steps is not None and runs.chained_steps[i] >= 0:
            when = float(runs.chained_steps[i]) * dt
        if when is None or when < times[0]:
            continue
        out[order[int(np.searchsorted(times, when, side="right")) - 1]] += 1.0 / n
    return out


def _chain_failure_points(runs: vd.SampleRuns, failed: np.ndarray, samples: np.ndarray
                          ) -> dict[str, np.ndarray]:
    """The failures the chain decided (not sent on to a rollout), by how they failed
    (``history.ChainedResult.kinds``): each kind's samples (k, d), most first."""
    out: dict[str, list[np.ndarray]] = {}
    if runs.chained_kinds:
        for i in np.flatnonzero(runs.chained & ~runs.suspect & failed):
            out.setdefault(runs.chained_kinds[i] or "not_completed", []).append(samples[i])
    return {kind: np.array(rows)
            for kind, rows in sorted(out.items(), key=lambda kv: -len(kv[1]))}


def _nominal_failed(evaluator: sp.SparseEvaluator, steps: np.ndarray) -> np.ndarray:
    """(m,) bool: the nominal parameters fail the sparse evaluation at each moment."""
    nominal = evaluator.evaluate(steps, evaluator.twin.scenario.box.nominal[None])
    return np.asarray(nominal.failed[:, 0], dtype=bool)


class _Once:
    """A call that runs once, in whichever thread asks first; ``result`` waits for it."""

    def __init__(self, fn: Callable[[], Any]):
        self._fn, self._lock, self._started = fn, threading.Lock(), False
        self._done = threading.Event()
        self._value: Any = None
        self._error: BaseException | None = None

    def run(self) -> None:
        with self._lock:
            if self._started:
                return
            self._started = True
        try:
            self._value = self._fn()
        except BaseException as exc:  # re-raised by result(), in the thread that waits
            self._error = exc
        finally:
            self._done.set()

    def result(self) -> Any:
        self._done.wait()
        if self._error is not None:
            raise self._error
        return self._value


class _Done:
    """A finished call, as a future."""

    def __init__(self, value):
        self._value = value

    def result(self):
        return self._value


class _InLine:
    """An executor that runs each call where it is submitted (a one-thread audit)."""

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def submit(self, fn, *args, **kwargs):
        return _Done(fn(*args, **kwargs))


def _pool(nthread: int):
    """A thread for the samples' own runs, or none when the audit is asked for one thread
    (``nthread`` 1)."""
    if nthread == 1:
        return _InLine()
    return concurrent.futures.ThreadPoolExecutor(max_workers=1)


#: the stages in the order they start (verification and the chained segments run alongside
#: the critical values and the searches)
STAGES = ("rollout", "moments", "sweep", "verification", "chained segments", "critical values",
          "analytic bounds and search", "safe region check")


def _in_order(timings: Mapping[str, float]) -> dict[str, float]:
    """The stage timings in :data:`STAGES` order, whichever thread finished first."""
    return {name: timings[name] for name in STAGES if name in timings}


def _load_bound(rec: Recording, twin: Twin) -> dict | None:
    """The whole-motion analytic motor bound, in words and numbers (see AuditReport)."""
    from critmoment import dynamics

    try:
        bound = dynamics.trajectory_load_bound(rec, twin)
    except ParameterError as exc:
        return {"error": str(exc)}
    steps = bound.first_failing_step
    per_mass = []
    for i, m in enumerate(bound.masses):
        k = int(steps[i])
        per_mass.append({"mass": float(m),
                         "first_failing_time": float(k * bound.dt) if k >= 0 else None,
                         "actuator": bound.limiting_at(i, k) if k >= 0 else None,
                         "min_fos": float(np.min(bound.fos[i]))})
    finite = bound.critical_mass[np.isfinite(bound.critical_mass)]
    return {"masses": per_mass,
            "min_critical_payload": float(finite.min()) if finite.size else None,
            "unbounded": list(bound.unbounded)}


def audit_evaluator(recording: Recording, twin: Twin, *, horizon: int | None = None,
                    mode: sp.SparseMode = sp.SparseMode.STEP, nthread: int = 0,
                    chain: bool = True
                    ) -> tuple[sp.SparseEvaluator, contactmodel.ContactModelReport]:
    """The audit's sparse evaluator, after checking the contact model.

    On a soft contact model (a held object creeps while the force ratio looks safe,
    measured by :func:`critmoment.contactmodel.check_contact_model`, which warns) creep is
    measured on each sample's own state: with ``chain`` the chained segments watch the
    object's slip in its grip over the whole hold with the ground truth's rule
    (:func:`critmoment.history.chained_failures`), so the sweep keeps its short horizon
    (the scenario's ``creep_horizon``, 0 unless set); without it the sweep measures slip
    over the report's ``creep_horizon``. Shared by :func:`analyze` and
    :func:`critmoment.validation.predict`.
    """
    contact = contactmodel.check_contact_model(twin, recording)
    creep = twin.scenario.sparse.creep_horizon
    if not chain and not creep:
        creep = int(getattr(contact, "creep_horizon", 0) or 0)
    evaluator = sp.SparseEvaluator(recording, twin, horizon=horizon, mode=mode,
                                   nthread=nthread, creep_horizon=creep)
    return evaluator, contact


def decision_options(opt: AnalyzeOptions, threshold: float) -> vd.DecisionOptions:
    """The decision's options from the audit's (``verify``, ``verify_unlifted``,
    ``require_task``, ``confidence``) and the scenario's cost threshold."""
    return vd.DecisionOptions(threshold=float(threshold), verify=opt.verify,
                              verify_unlifted=opt.verify_unlifted,
                              require_task=opt.require_task, confidence=opt.confidence,
                              chain=opt.chain)


def chain_samples(evaluator: sp.SparseEvaluator, steps: np.ndarray, samples: np.ndarray,
                  sweep: sp.SparseResult | None, rerun: np.ndarray,
                  options: vd.DecisionOptions, *, nominal_completed: bool = True,
                  chained_before: dict | None = None
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[str | None], np.ndarray]:
    """The chained evidence of the decision: which samples were carried on their own state
    (:func:`critmoment.verdict.samples_to_chain`), whether they failed there, and which of
    them their own full rollout should decide (with verification on: the failures of
    ``ChainedResult.to_confirm``, and the passes that came within ``options.verify`` of a
    watched rule's limit, ``ChainedResult.near``, as the sweep's passes near the cost
    threshold are), each (n,) bool; how each chained failure failed
    (``ChainedResult.kinds``) and at which step (−1 for none), (n,) int. Shared by :func:`analyze`, :func:`check_region` and
    :func:`critmoment.validation.predict`.

    A chain is the sample's own run only approximately (it starts from the nominal state
    before the parameters act, and applies the sparse decision at the moments on top of the
    ground truth's rules), and its errors are on the failing side: a moment's force ratio
    on the cone without a real slip, and, after the release, events that turn on where the
    object was set down. Measured on robosuite's Panda + Robotiq 2F-85 with an elliptic cone
    (narrow box), the chain's two failures the rollouts overturned were joint-tracking
    losses at steps 3856 and 4120 of 5000, after the release, in samples whose full-rollout
    outcome flips with a 1e-6–1e-4 change of the cube's mass (docs/real_models.md). Slips
    and drops during the hold, measured with the ground truth's own rules, stand: on ACT's
    scene the chain fails 41 of 64 samples so, every one a real failure.

    ``chained_before`` (a dict, filled here) keeps each chained point's result by its
    value, for calls with the same evaluator, moments and options: a chain is the sample's
    own run, independent of the samples beside it, so a point the region check chained in
    an earlier round (a face the shrink kept) is not stepped again."""
    n = samples.shape[0]
    chained = np.zeros(n, bool)
    chained_failed = np.zeros(n, bool)
    suspect = np.zeros(n, bool)
    kinds: list[str | None] = [None] * n
    first = np.full(n, -1, np.int64)
    if sweep is None or steps.size == 0:
        return chained, chained_failed, suspect, kinds, first
    chained = vd.samples_to_chain(sweep, rerun, options, nominal_completed=nominal_completed)
    known = {} if chained_before is None else chained_before
    rows = np.flatnonzero(chained)
    keys = {int(i): _point_key(samples[i]) for i in rows}
    todo = np.array([i for i, key in keys.items() if key not in known], dtype=np.int64)
    if todo.size:
        result = history.chained_failures(evaluator, steps, samples[todo])
        near = (result.near(options.verify) if options.verify is not None
                else np.zeros(todo.size, bool))
        # a pass that lost its object where the nominal run carries it (a catch, or a
        # stumble picked up again): the chain's fall rule ran on its approximate run; with
        # verification the sample's own rollout decides whether it fell (a chained fall
        # goes there too, ChainedResult.to_confirm)
        if result.drop_step is not None:
            near = near | ((result.drop_step >= 0) & ~result.failed)
        for i, failed, confirm, close, (kind, step) in zip(
                todo, result.failed, result.to_confirm, near, result.first_failures(),
                strict=True):
            known[keys[int(i)]] = (bool(failed), bool(confirm or close), kind, step)
    for i, key in keys.items():
        chained_failed[i], suspect[i], kinds[i], first[i] = known[key]
    return chained, chained_failed, suspect, kinds, first


def check_region(region: Mapping[str, tuple[float, float]], *, trajectory: Trajectory,
                 twin: Twin, evaluator: sp.SparseEvaluator, steps: np.ndarray,
                 sides: Sequence[str], options: vd.DecisionOptions, nominal_completed: bool,
                 exhaustive: bool = False, nthread: int = 0, per_edge: int = 3,
                 margin: float = 0.01, max_rounds: int = 4,
                 reference: NominalReference | None = None,
                 every_point: bool = True, known: np.ndarray | None = None) -> vd.RegionCheck:
    """Check a claimed safe region on its corners, edges and inside, and shrink it until it
    holds.

    Each round evaluates the region's corners and edges (:func:`critmoment.verdict.
    region_points`, ``per_edge`` points per edge, corners included, 4× denser on edges where
    the cost comes within ``verify × threshold``, unless a coarse point already fails) and
    points inside it (:func:`critmoment.verdict.interior_points`: an outcome need not be
    monotone in the parameters) by
    sparse evaluation at the audit's moments. While a point fails there in a way sparse
    evaluation decides alone, the region shrinks at once. Once none does, every point is
    decided as a sample of the sweep is, by :func:`sample_runs` and
    :func:`critmoment.verdict.failing_samples` (the one decision path): the points the
    sweep cannot decide by their own full rollout, every other one by its own run through
    the moments (chained, with ``options.chain``). A region holds only where each of its
    checked points passes so: sparse evaluation from the nominal states alone passed
    corners whose own runs drop the object (robosuite's xArm7 with its own gripper, where
    friction changes the path). When a point fails, the region's failing-side faces move
    in (:func:`critmoment.verdict.shrink_region`: its new worst corner is a checked point
    that passed, ``margin`` prior-quantile units from every failing one) and the next
    round checks the new region.

    Args:
        region: the claimed region, {name: (low, high)}.
        trajectory: the trajectory.
        twin: its twin.
        evaluator: the audit's sparse evaluator.
        steps: the audited moments' steps, (m,).
        sides: per parameter, the failing side ("above"/"below"/"both").
        options: the decision options.
        nominal_completed: the nominal run completes the task.
        exhaustive: evaluate every moment over its whole horizon (else first failure).
        nthread: threads (0: all CPUs).
        per_edge: points per edge, corners included.
        margin: distance a shrunk face keeps from a failing point (prior quantiles).
        max_rounds: rounds before giving up (no region then).
        reference: the nominal run of an earlier :func:`~critmoment.groundtruth.brute_force`
            of this trajectory, or None.
        every_point: decide every checked point on its own run; else only the corners,
            the coarse edge points (``per_edge`` per edge) and the densified points the
            sweep's path would roll out (within ``verify × threshold``), the others by their
            sparse evaluation (:func:`analyze` asks for every point where a sample that
            passed its sparse evaluation failed on its own run: there the sparse passes do
            not stand for the runs).
        known: parameter values (m, k) that already passed on their own runs (the sweep's
            chained or rolled-out samples): those inside a round's region stand for as many
            of its inside points (:func:`critmoment.verdict.interior_points`).

    Returns:
        The :class:`~critmoment.verdict.RegionCheck`.
    """
    box = twin.scenario.box
    near = options.verify if options.verify is not None else 0.8  # of a limit: densify there
    near_cost = near * options.threshold
    first = dict(region)
    roll = _Rollouts(trajectory, twin, nthread, reference)
    nominal_failed = _nominal_failed(evaluator, steps) if steps.size else None
    n_sparse = n_rollouts = n_chained = 0
    # a point on a face the shrink kept comes back the same to the bit: its chain and its
    # rollout (roll keeps those) are not run again
    chained_before: dict = {}
    current: dict | None = vd.round_inward(first, box)
    pts = np.zeros((0, box.ndim))
    fails = rolled = chained = np.zeros(0, bool)
    rounds = 0
    for rnd in range(1, max_rounds + 1):
        if current is None:
            break
        rounds = rnd
        # where the sweep's own runs overturned a sparse pass the motion depends on its path:
        # four times as many points inside
        inside = vd.interior_points(current, box, scale=4 if every_point else 1)
        # the sweep's samples in the region that passed on their own runs are checked points
        # inside it already: as many fewer new ones
        n_known = int(vd.within(known, current, box).sum()) if known is not None else 0
        inside = inside[:max(0, inside.shape[0] - n_known)]
        pts, edges = vd.region_points(current, box, per_edge=per_edge)
        pts = np.vstack([pts, inside])
        res = evaluator.evaluate(steps, pts, first_failure=not exhaustive)
        n_sparse += pts.shape[0]
        hot = vd.hot_edges(edges, res.worst_cost(), near=near_cost)
        undecided = functools.partial(vd.samples_to_rerun, options=options,
                                      nominal_completed=nominal_completed,
                                      nominal_failed=nominal_failed)
        if hot and not (_sparse_fails(res, undecided).any() and rnd < max_rounds):
            pts, edges = vd.region_points(current, box, per_edge=per_edge, dense=hot)
            pts = np.vstack([pts, inside])
            res = evaluator.evaluate(steps, pts, first_failure=not exhaustive)
            n_sparse += pts.shape[0]
        rolled, chained = np.zeros(pts.shape[0], bool), np.zeros(pts.shape[0], bool)
        sparse_fails = _sparse_fails(res, undecided)
        if sparse_fails.any():
            # it shrinks: no runs this round, and only from the failures sparse evaluation
            # decides alone (a cube with solref 0.04: one such failure had made every point
            # failing only where its own run decides count, the faces moved 3 % a round,
            # and after four rounds "no safe region" was stated where mass 0.05-0.5 kg at
            # friction 0.6-1.5 holds on every full run)
            fails = sparse_fails
        else:
            own = _own_run_points(pts, current, box, per_edge, res, undecided, every_point)

            def decide_own(points: np.ndarray, res_own: sp.SparseResult):
                runs, _ = sample_runs(evaluator, steps, points, res_own, options, roll=roll,
                                      nominal_completed=nominal_completed, nthread=nthread,
                                      chained_before=chained_before)
                failed = vd.failing_samples(
                    runs.evidence(res_own, nominal_completed=nominal_completed), options)
                return runs, failed

            runs, own_failed = decide_own(pts[own], _select_samples(res, own))
            fails = np.zeros(pts.shape[0], bool)
            fails[own] = own_failed
            rolled[own] = runs.rerun
            chained[own] = runs.chained & ~runs.rerun
            if not fails.any():
                # an own run that came near a watched rule's limit (a slip of 0.8 tolerance
                # or more, a saturation near its time) marks its edge as the cost marks it:
                # the outcome can turn between the coarse points, where the cost says
                # nothing (a lever's slip grows past 1 cm between two passing edge points)
                close = np.zeros(pts.shape[0], bool)
                close[own] = runs.suspect | roll.near_rule(pts[own], near)
                by_rule = sorted({i for i, e in enumerate(edges) if close[e].any()} - set(hot))
                if by_rule:
                    dense, _ = vd.region_points(current, box, per_edge=per_edge,
                                                dense=sorted(set(hot) | set(by_rule)))
                    extra = dense[~_among(dense, pts, box)]
                    if extra.shape[0]:
                        res_x = evaluator.evaluate(steps, extra, first_failure=not exhaustive)
                        n_sparse += extra.shape[0]
                        runs_x, failed_x = decide_own(extra, res_x)
                        pts = np.vstack([pts, extra])
                        fails = np.concatenate([fails, failed_x])
                        rolled = np.concatenate([rolled, runs_x.rerun])
                        chained = np.concatenate([chained, runs_x.chained & ~runs_x.rerun])
            n_rollouts += int(rolled.sum())
            n_chained += int(chained.sum())
        if not fails.any():
            return vd.RegionCheck(region=current, points=pts, failed=fails, rolled_out=rolled,
                                  rounds=rnd, n_sparse=n_sparse, n_rollouts=n_rollouts,
                                  n_chained=n_chained, chained=chained, first_claim=first,
                                  known_inside=n_known)
        # the new worst corner is a point that passed on its own run where the round ran
        # any (a densified edge point's sparse pass is weaker: a dragged cube's edge point
        # passed there, and failed on its own run as the next round's corner)
        passed = ~fails & (rolled | chained)
        passed = passed if passed.any() else ~fails
        current = vd.round_inward(vd.shrink_region(current, pts[fails], box, sides,
                                                   margin=margin, passing=pts[passed]), box)
    return vd.RegionCheck(region=None, points=pts, failed=fails, rolled_out=rolled,
                          rounds=rounds, n_sparse=n_sparse, n_rollouts=n_rollouts,
                          n_chained=n_chained, chained=chained, first_claim=first)


def _own_run_points(pts: np.ndarray, region: Mapping[str, tuple[float, float]], box,
                    per_edge: int, res: sp.SparseResult,
                    undecided: Callable[[sp.SparseResult], vd.Reruns],
                    every_point: bool) -> np.ndarray:
    """(p,) bool: the checked points decided on their own run. With ``every_point``, all;
    else the corners, the coarse edge points (``per_edge`` per edge) and the interior
    points, and the points between them the sweep's path would roll out (a pass within
    ``verify × threshold``, a failure only a rollout decides); the others keep their sparse
    decision."""
    if every_point:
        return np.ones(pts.shape[0], bool)
    coarse, _ = vd.region_points(region, box, per_edge=per_edge)
    coarse = np.vstack([coarse, vd.interior_points(region, box)])  # (every_point: all anyway)
    return _among(pts, coarse, box) | undecided(res).any


def _among(points: np.ndarray, others: np.ndarray, box) -> np.ndarray:
    """(p,) bool: each of ``points`` is one of ``others`` (to 1e-9 of the box's ranges)."""
    scale = np.maximum(np.abs(box.high - box.low), 1e-300)
    close = np.abs(points[:, None, :] - others[None, :, :]) <= 1e-9 * scale
    return close.all(axis=2).any(axis=1)


def _sparse_fails(res: sp.SparseResult,
                  undecided: Callable[[sp.SparseResult], vd.Reruns]) -> np.ndarray:
    """(p,) bool: the points whose sparse evaluation fails in a way it decides alone (not
    one that only their own rollout decides, ``undecided``:
    :func:`critmoment.verdict.samples_to_rerun` with the audit's options and nominal run)."""
    # (the near passes among the reruns fail nowhere: every failing rerun is one of these)
    return np.asarray(res.failed_any, dtype=bool) & ~undecided(res).any


def _point_key(point: np.ndarray) -> bytes:
    """A parameter point's values to the bit, as a dictionary key (a run is its own)."""
    return np.asarray(point, dtype=np.float64).tobytes()


class _Rollouts:
    """Full rollouts of parameter points (their real outcome: failed), sharing one nominal
    reference over the calls: read from ``recording`` (the frequent rollout, the brute
    force's nominal run to the bit: :func:`critmoment.groundtruth.reference_from_recording`)
    when given, else run by the first call."""

    def __init__(self, trajectory: Trajectory, twin: Twin, nthread: int,
                 reference: NominalReference | None = None, chunk: int = 16,
                 recording: Recording | None = None):
        self.trajectory, self.twin, self.nthread = trajectory, twin, nthread
        self.reference, self.chunk, self.recording = reference, chunk, recording
        self._lock = threading.Lock()
        #: per point rolled out (its bytes): (outcome, first failure time [s] or None, the
        #: motor-checked actuator of a motor failure or None)
        self.outcomes: dict[bytes, tuple[str, float | None, str | None]] = {}
        #: per point rolled out that passed: how close its run came to a rule's limit (the
        #: largest of slip / slip tolerance and saturation time / motor time)
        self.closeness: dict[bytes, float] = {}

    def nominal(self) -> NominalReference | None:
        """The nominal reference, read from the recording on first use (None without one
        until a call has run it)."""
        with self._lock:
            if self.reference is None and self.recording is not None:
                self.reference = reference_from_recording(self.recording, self.twin)
            return self.reference

    def __call__(self, points: np.ndarray, nthread: int | None = None) -> np.ndarray:
        """(p,) bool: each point's real outcome is a failure. A point already rolled out
        (the same values to the bit) is not run again: a run is its own, whatever runs
        beside it."""
        nthread = self.nthread if nthread is None else nthread
        points = sp.check_samples(self.twin.scenario.box, points)
        keys = [_point_key(p) for p in points]
        new, seen = [], set()
        for i, key in enumerate(keys):
            if key not in self.outcomes and key not in seen:
                seen.add(key)
                new.append(i)
        if new:
            self._run(points[new], nthread)
        return np.array([self.outcomes[key][0] != Outcome.SUCCESS.value for key in keys],
                        dtype=bool)

    def _run(self, points: np.ndarray, nthread: int) -> None:
        # the audit's own runs: check_audit counted them before the audit started
        bf = _brute_force(self.trajectory, twin=self.twin, samples=points,
                          criteria=OutcomeCriteria(), chunk=self.chunk,
                          nthread=budget.check_nthread(nthread), reference=self.nominal(),
                          t_start=time.perf_counter())
        self.reference = bf.reference
        c = bf.classification
        close = np.maximum(c.max_slip / c.criteria.slip_tolerance,
                           c.saturation_time / c.criteria.motor_time)
        for point, outcome, step, column, tracking, level in zip(
                bf.samples, c.outcome, c.first_failure_step, c.motor_column, c.motor_tracking,
                close, strict=True):
            key = _point_key(point)
            name = _motor_name(self.twin, column) if outcome is Outcome.MOTOR else None
            # a motor failure by a joint lagging its target is named so, not an overload
            kind = "tracking" if outcome is Outcome.MOTOR and tracking else outcome.value
            self.outcomes[key] = (kind, float(step) * c.dt if step >= 0 else None, name)
            if outcome is Outcome.SUCCESS:
                self.closeness[key] = float(level)

    def near_rule(self, points: np.ndarray, fraction: float) -> np.ndarray:
        """(p,) bool: the rolled-out ``points`` whose run came within ``fraction`` of a
        ground-truth rule's limit without failing: a slip of ``fraction`` × the slip
        tolerance or more, or a saturation held ``fraction`` × its time or more."""
        return np.array([self.closeness.get(_point_key(p), 0.0) >= fraction
                         for p in np.asarray(points, float)], dtype=bool)

    def _failing(self, points: np.ndarray):
        """The rolled-out ``points`` that fail, each with its (outcome, first failure time,
        actuator)."""
        for point in np.asarray(points, float):
            got = self.outcomes.get(_point_key(point))
            if got is not None and got[0] != Outcome.SUCCESS.value:
                yield point, got

    def failure_points(self, points: np.ndarray) -> dict[str, np.ndarray]:
        """The rolled-out ``points`` that fail, per outcome (k, d)."""
        out: dict[str, list[np.ndarray]] = {}
        for point, got in self._failing(points):
            out.setdefault(got[0], []).append(point)
        return {kind: np.array(rows) for kind, rows in out.items()}

    def failures(self, points: np.ndarray) -> dict[str, tuple[int, float | None,
                                                              tuple[str, ...]]]:
        """How the rolled-out ``points`` that fail failed: per outcome, (how many, the
        earliest failure time [s], the actuators of the motor failures)."""
        out: dict[str, list] = {}
        for _, got in self._failing(points):
            entry = out.setdefault(got[0], [0, None, []])
            entry[0] += 1
            if got[1] is not None and (entry[1] is None or got[1] < entry[1]):
                entry[1] = got[1]
            if got[2] is not None and got[2] not in entry[2]:
                entry[2].append(got[2])
        return {k: (v[0], v[1], tuple(v[2])) for k, v in out.items()}


def _trend(curves: Mapping[int, Mapping[str, sp.SparseResult]], box) -> dict[str, float]:
    """Per parameter, the cost at the high end minus the low end of its 1-D curves (others
    nominal), summed over the moments (costs clipped at 10; infinite: diverged)."""
    out = {}
    for p in box.parameters:
        total = 0.0
        for by_name in curves.values():
            c = np.clip(np.nan_to_num(by_name[p.name].cost[0], nan=0.0, posinf=10.0), 0, 10)
            total += float(c[-1] - c[0])
        out[p.name] = total
    return out


def _critical_values(rec, twin, evaluator, steps: np.ndarray, n_grid: int
                     ) -> dict[int, dict[str, sp.CriticalValue]]:
    """Per moment and parameter, the critical value with the others at nominal: the one
    routine, :func:`critmoment.sparse.critical_values` (grid, then bisection)."""
    out: dict[int, dict[str, sp.CriticalValue]] = {int(s): {} for s in steps}
    if not steps.size:
        return out
    for cv in sp.critical_values(rec, twin, steps, evaluator=evaluator, n_grid=n_grid,
                                 others=(sp.OthersAt.NOMINAL,)):
        out[int(cv.step)][cv.parameter] = cv
    return out


def _nanmin(values: np.ndarray) -> float:
    """Smallest non-NaN value, NaN when there is none (no warning)."""
    values = values[~np.isnan(values)]
    return float(values.min()) if values.size else float("nan")


def _select_samples(res: sp.SparseResult, cols: slice) -> sp.SparseResult:
    fields = {}
    n = res.n_samples
    for f in dataclasses.fields(res):
        v = getattr(res, f.name)
        if f.name == "samples":
            v = v[cols]
        elif isinstance(v, np.ndarray) and v.ndim >= 2 and v.shape[1] == n and f.name != "steps":
            v = v[:, cols]
        fields[f.name] = v
    return sp.SparseResult(**fields)


def _cost_map(res: sp.SparseResult, box, res_n: int):
    """Max cost over the moments on a grid of the first two parameters, from the Sobol sweep.

    Each cell shows the worst cost of the nearest Sobol sample (in the prior's unit square of
    the two parameters; the others vary over the box), so the map costs no simulation.
    """
    u = box.to_unit(res.samples)[:, :2]
    worst = res.worst_cost()
    worst = np.where(np.isfinite(worst), worst, np.nan)
    grid_u = np.linspace(0.0, 1.0, res_n)
    g0, g1 = np.meshgrid(grid_u, grid_u, indexing="ij")
    cells = np.stack([g0.ravel(), g1.ravel()], axis=1)
    grid = worst[_nearest(cells, u)].reshape(g0.shape)
    axes = box.from_unit(np.tile(grid_u[:, None], (1, box.ndim)))
    return (box.names[0], axes[:, 0], box.names[1], axes[:, 1], grid)


def _nearest(points: np.ndarray, sites: np.ndarray) -> np.ndarray:
    """(p,) index of the nearest site (s, d) to each point (p, d), the lowest index among
    equally near ones (as ``argmin`` of all distances), in O((p + s) log s) time and
    O(p + s) memory: the cells × samples distance matrix of a 400² map and 10⁵ samples
    would take 128 GB."""
    from scipy.spatial import cKDTree

    k = min(2, sites.shape[0])
    dist, idx = cKDTree(sites).query(points, k=k)
    if k == 1:
        return np.asarray(idx, dtype=np.int64)
    tie = dist[:, 1] <= dist[:, 0]
    best = idx[:, 0].copy()
    best[tie] = np.minimum(idx[tie, 0], idx[tie, 1])
    return best.astype(np.int64)


def _load_solvers() -> None:
    """Pinocchio, CasADi and Optuna imported whole before the audit's work, with the
    interrupt signals held back (:func:`critmoment.search.load_solvers`): a Ctrl-C or a
    stop signal is then raised after them, not inside a half-done import."""
    from critmoment._signals import signals_held

    with signals_held():
        from critmoment import dynamics, search  # noqa: F401
    search.load_solvers()


def _search_all(rec, twin, evaluator, steps, opt):
    """Analytic bounds, CasADi/Optuna worst cases and their verification per moment."""
    from critmoment import dynamics, search

    pin_model = dynamics.from_mujoco(twin.model)
    analytics, searches = {}, {}
    # the moments' searches side by side: one batch call per round for all of them
    for out in search.audit_moments(evaluator, [int(s) for s in steps], pin_model=pin_model,
                                    n_trials=opt.search_trials, seed=opt.seed,
                                    patience=opt.search_patience):
        analytics[out["step"]] = {**out["analytic"], "verification": out.get("verification")}
        searches[out["step"]] = out["search"]
    return analytics, searches


def _manifest(sc: Scenario, opt: AnalyzeOptions, traj: Trajectory,
              twin: Twin | None = None) -> dict:
    # not the threads: the report is the same on any number (the CLI's default, all CPUs,
    # and the library's gave byte-different documents for the same audit)
    options = {k: v for k, v in dataclasses.asdict(opt).items() if k != "nthread"}
    return input_manifest(sc, traj, seed=opt.seed, options=options, twin=twin)


def input_manifest(sc: Scenario, traj: Trajectory, *, seed: int | None,
                   options: Mapping, twin: Twin | None = None) -> dict:
    """What an audit or a validation ran on, for its document: the versions, the scenario,
    the model and the trajectory by name and hash (not paths), the seed and ``options``,
    the task and the force limits."""
    import mujoco

    import critmoment

    return {
        "critmoment": critmoment.__version__,
        "mujoco": mujoco.__version__,
        "numpy": np.__version__,
        "python": sys.version.split()[0],
        "platform": platform.platform(terse=True),
        "scenario": printable_name(sc.name),
        # file names and hashes, not paths: identical inputs, identical manifests. The
        # files' hashes say what was read (None for what was built in code: not whatever
        # file of that name lies in the working folder); the content hashes say what was
        # audited (a file read with another --object-pose, a scenario narrowed in code)
        "scenario_file": input_identity(sc.path)["name"] if sc.path else None,
        "scenario_sha256": sc.sha256,
        "scenario_content_sha256": sc.content_sha256(),
        "model_sha256": model_hash(sc if twin is None else twin),
        "trajectory": input_identity(traj.source)["name"],
        # which episode of a dataset or multi-episode file (two of one file share its name
        # and hash)
        "episode": (traj.meta or {}).get("episode_index"),
        "trajectory_sha256": traj.source_sha256,
        "trajectory_content_sha256": traj.content_sha256(),
        "seed": seed,
        "options": dict(options),
        "task": sc.task.to_json(),
        # each actuator's force limit and where it comes from; None where nothing limits it
        "limits": {a: {"limit": v if np.isfinite(v) else None,
                       "source": sc.limit_sources.get(a, "scenario")}
                   for a, v in sc.limits.items()},
        "unlimited_actuators": list(sc.unlimited),
    }


def _progress(progress) -> Callable[[str], None]:
    """The progress callback: ``progress`` itself, stderr for True, nothing for False.

    Raises:
        ParameterError: anything but a bool or a callable (``5`` is not True).
    """
    if callable(progress):
        return progress
    if not isinstance(progress, (bool, np.bool_)):
        raise ParameterError(f"progress: expected True, False or a callable taking a "
                             f"message, got {type(progress).__name__} {progress!r}")
    if progress:
        return lambda msg: print(msg, file=sys.stderr, flush=True)
    return lambda msg: None


class _Timer:
    def __init__(self, timings, name, say):
        self.timings, self.name, self.say = timings, name, say

    def __enter__(self):
        self.say(f"critmoment: {self.name} ...")
        self.t0 = time.perf_counter()
        return self

    def __exit__(self, *exc):
        dt = time.perf_counter() - self.t0
        self.timings[self.name] = self.timings.get(self.name, 0.0) + dt
        if exc[0] is None:
            self.say(f"critmoment: {self.name} done in {dt:.2f} s")
        return False
