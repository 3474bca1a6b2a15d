"""The end-to-end audit: frequent rollout → moments → bounds/search → sparse sweep → verdict.

:func:`analyze` chains the stages and returns an :class:`AuditReport`, the object
``critmoment analyze`` renders as ``report.json``, figures, ``report.html`` and a terminal
summary (see :mod:`critmoment.report`). Each stage is also callable alone.
"""

from __future__ import annotations

import dataclasses
import enum
import logging
import platform
import sys
import time
from collections.abc import Callable, Mapping, Sequence

import numpy as np

from critmoment import budget
from critmoment import sparse as sp
from critmoment.exceptions import ParameterError
from critmoment.feasibility import FeasibilityReport, check_fit, preflight
from critmoment.moments import Moment, MomentDetector, MomentLabel
from critmoment.recording import Recording, model_hash, rollout
from critmoment.scenario import Scenario, load_scenario
from critmoment.trajectory import Trajectory, input_identity
from critmoment.twin import Twin

__all__ = [
    "Verdict",
    "AnalyzeOptions",
    "MomentReport",
    "AuditReport",
    "detect_moments",
    "audit_moments",
    "sensitivity_function",
    "safe_subbox",
    "analyze",
    "REPORT_SCHEMA",
]

log = logging.getLogger(__name__)

REPORT_SCHEMA = "critmoment.report/1"


class Verdict(enum.Enum):
    """Outcome of an audit."""

    SAFE = "SAFE"                #: cost ≤ threshold over the whole box at every moment
    CONDITIONAL = "CONDITIONAL"  #: fails somewhere in the box; safe in a stated sub-box
    UNSAFE = "UNSAFE"            #: fails at the nominal parameters


@dataclasses.dataclass(frozen=True)
class AnalyzeOptions:
    """Options of :func:`analyze`.

    Attributes:
        seed: seeds the Sobol sweep and the search (same seed → same report).
        n_samples: Sobol samples of the box for P(success) (a power of 2 is best).
        max_moments: moments audited in depth (the most sensitive ones).
        horizon: physics steps per sparse evaluation (default: the scenario's).
        search_trials: simulated evaluations the Optuna search may spend per moment.
        search_patience: the search of a moment stops after this many batches (of 8
            samples) without a higher cost (None: it spends ``search_trials``).
        search: run the analytic bounds and the worst-case search.
        critical_grid: grid points per parameter for the critical values.
        confidence: confidence level of the P(success) interval.
        min_success: P(success) at which ``passes`` accepts a non-SAFE verdict.
        nthread: threads for MuJoCo's batch (0: all CPUs).
        map_resolution: cells per axis of the mass × friction cost map, the nearest Sobol
            sample's cost per cell (0 to skip).
        require_task: a nominal rollout that does not complete the scenario's task (stage 4
            reached and kept) makes the verdict UNSAFE.
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
            (:func:`critmoment.validation.brute_force`: the object dropped or slipped, a joint
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

    def __post_init__(self):
        if self.n_samples < 8:
            raise ParameterError(f"n_samples: expected >= 8, got {self.n_samples}")
        if self.max_moments < 1:
            raise ParameterError(f"max_moments: expected >= 1, got {self.max_moments}")
        if self.horizon is not None and self.horizon < 1:
            raise ParameterError(f"horizon: expected >= 1 or None, got {self.horizon}")
        if self.search_patience is not None and self.search_patience < 1:
            raise ParameterError(
                f"search_patience: expected >= 1 or None, got {self.search_patience}")
        if self.search_trials < 1:
            raise ParameterError(f"search_trials: expected >= 1, got {self.search_trials}")
        if not 0 < self.confidence < 1:
            raise ParameterError(f"confidence: expected in (0, 1), got {self.confidence}")
        if self.min_success is not None and not 0 <= self.min_success <= 1:
            raise ParameterError(f"min_success: expected in [0, 1], got {self.min_success}")
        if self.critical_grid < 5:
            raise ParameterError(f"critical_grid: expected >= 5, got {self.critical_grid}")
        if self.map_resolution < 0:
            raise ParameterError(f"map_resolution: expected >= 0, got {self.map_resolution}")
        if self.verify is not None and (isinstance(self.verify, bool)
                                        or not 0 < self.verify <= 1):
            raise ParameterError(f"verify: expected a fraction of the threshold in (0, 1] or "
                                 f"None, got {self.verify!r}")


@dataclasses.dataclass(frozen=True)
class MomentReport:
    """What the audit found at one critical moment.

    Attributes:
        moment: the moment (step, time, label, reason, sensitivity score).
        worst_case: parameter values of the highest cost found (sweep and search; empty
            when no sample reached the moment and the search did not run).
        max_cost: that cost (NaN when none was found).
        min_fos_contact: lowest grasp FOS over the sweep's samples that reach the moment
            (inf when never loaded, NaN when none reaches it).
        min_fos_motor: lowest motor FOS over the same samples.
        critical: per parameter, the value where the cost crosses the threshold with the
            others at nominal (None where it never crosses).
        critical_side: per parameter, "above"/"below" (which side fails) or None.
        dominant: the cost term dominating the failures here ("contact" / "motor" / None):
            over the sweep's samples failing here, or else over the failing points of the
            critical-value curves.
        limiting_actuator: the actuator limiting the motor FOS at the worst case.
        fail_fraction: fraction of the sweep's samples failing at this moment; unless the
            sweep is exhaustive, the samples whose first failure is here.
        reached: fraction of the sweep's samples evaluated at this moment: all of them when
            the sweep is exhaustive, else those that pass at every earlier moment.
        squeeze: every failure seen here (sweep and critical-value curves) is an unlifted
            one: the grip squeezes the object off its support without lifting it, and the
            samples' own rollouts decide them.
        analytic: analytic bounds (Pinocchio), JSON-able, or None.
        search: worst-case search summary, JSON-able, or None.
    """

    moment: Moment
    worst_case: Mapping[str, float]
    max_cost: float
    min_fos_contact: float
    min_fos_motor: float
    critical: Mapping[str, float | None]
    critical_side: Mapping[str, str | None]
    dominant: str | None
    limiting_actuator: str
    fail_fraction: float
    analytic: Mapping | None = None
    search: Mapping | None = None
    reached: float = 1.0
    squeeze: bool = False


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
        timings: seconds per stage.
        manifest: versions, model hash, seed and options.
        failed: per Sobol sample of ``sweep``, whether it fails (sparse evaluation at the
            moments, then the verification rollouts), (n,) bool.
        verification: the verification stage's summary (``fraction``, ``cost_from``,
            ``rollouts``, ``failed``), or None when it did not run.
        feasibility: the twin's feasibility and the trajectory's fit on the nominal rollout
            (:func:`critmoment.feasibility.preflight`), or None when not checked.
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
    feasibility: FeasibilityReport | None = None

    def passes(self, min_success: float | None = None) -> bool:
        """SAFE, or CONDITIONAL with P(success) ≥ ``min_success`` (the CLI's exit code 0)."""
        if self.verdict is Verdict.SAFE:
            return True
        if self.verdict is Verdict.UNSAFE:
            return False
        threshold = self.options.min_success if min_success is None else min_success
        return threshold is not None and self.p_success >= threshold

    def to_json(self, *, timings: bool = True) -> dict:
        """The ``report.json`` document (schema ``critmoment.report/1``)."""
        from critmoment.report import report_json

        return report_json(self, timings=timings)


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
        res = evaluator.evaluate(steps, probe)
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
    steps = np.array([min(m.step, recording.n_steps - evaluator.horizon)
                      for m in candidates[:max_moments]], dtype=np.int64)
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


# -- stage: safe region --------------------------------------------------------------
def _fail_sides(samples: np.ndarray, cost: np.ndarray, box) -> list[str]:
    """Per parameter, the side where cost grows (rank correlation sign): "above"/"below"."""
    sides = []
    rank_c = np.argsort(np.argsort(cost))
    for j in range(box.ndim):
        rank_x = np.argsort(np.argsort(samples[:, j]))
        corr = np.corrcoef(rank_x, rank_c)[0, 1] if np.std(rank_c) > 0 else 0.0
        sides.append("below" if corr < 0 else "above")
    return sides


def safe_subbox(samples: np.ndarray, failed: np.ndarray, box, sides: Sequence[str]
                ) -> dict[str, tuple[float, float]] | None:
    """The largest (prior volume) sub-box anchored at the box's safe corner with no failure.

    Each parameter keeps its safe end (the one opposite its failing side) and gets a cut
    chosen among the sample coordinates; with k ≤ 2 every pair of cuts is tried, above that
    the cuts shrink one coordinate at a time.

    Args:
        samples: parameter samples, (n, k).
        failed: which samples fail, (n,).
        box: the uncertainty box.
        sides: per parameter, "above" (large values fail) or "below".

    Returns:
        {name: (low, high)}, or None when even the safe corner's neighbourhood fails.
    """
    unit = box.to_unit(samples)
    # orient every axis so that failure lies at large u
    u = np.where(np.array(sides) == "below", 1.0 - unit, unit)
    bad = u[failed]
    if bad.shape[0] == 0:
        return {p.name: (p.low, p.high) for p in box.parameters}
    k = box.ndim
    # cut candidates: the failing samples' coordinates (at most 64 per axis, by quantile)
    cands = []
    for j in range(k):
        c = np.unique(np.concatenate([[1.0], bad[:, j]]))
        if c.size > 64:
            c = np.unique(np.concatenate([[1.0], np.quantile(bad[:, j], np.linspace(0, 1, 63),
                                                               method="lower")]))
        cands.append(c)
    best, best_vol = None, 0.0
    if k <= 2:
        grids = np.meshgrid(*cands, indexing="ij")
        cuts = np.stack([g.reshape(-1) for g in grids], axis=1)  # (c, k) upper cuts in u
        # a cut is clean when no failing sample lies strictly inside [0, cut)
        inside = (bad[None, :, :] < cuts[:, None, :]).all(axis=2).any(axis=1)
        vol = np.prod(cuts, axis=1)
        vol[inside] = -1.0
        i = int(np.argmax(vol))
        if vol[i] > 0:
            best, best_vol = cuts[i], vol[i]
    else:
        cut = np.ones(k)
        while ((bad < cut).all(axis=1)).any():
            inside = bad[(bad < cut).all(axis=1)]
            j = int(np.argmax(cut - inside.min(axis=0)))
            cut[j] = inside[:, j].min()
        best, best_vol = cut, float(np.prod(cut))
    if best is None or best_vol <= 0:
        return None
    region = {}
    for j, p in enumerate(box.parameters):
        lo_u, hi_u = (0.0, best[j]) if sides[j] == "above" else (1.0 - best[j], 1.0)
        pts = box.from_unit(np.array([[lo_u if i == j else 0.5 for i in range(k)],
                                      [hi_u if i == j else 0.5 for i in range(k)]]))
        region[p.name] = (float(pts[0, j]), float(pts[1, j]))
    return region


def _region_text(region, box, verdict: Verdict) -> str:
    if verdict is Verdict.SAFE:
        return "safe over the whole box"
    if region is None:
        return "no safe sub-box found around the nominal parameters"
    parts = []
    for p in box.parameters:
        lo, hi = region[p.name]
        unit = f" {p.unit}" if p.unit else ""
        if np.isclose(lo, p.low) and np.isclose(hi, p.high):
            continue
        if np.isclose(lo, p.low):
            parts.append(f"{p.name} ≤ {hi:.3g}{unit}")
        elif np.isclose(hi, p.high):
            parts.append(f"{p.name} ≥ {lo:.3g}{unit}")
        else:
            parts.append(f"{lo:.3g} ≤ {p.name} ≤ {hi:.3g}{unit}")
    if not parts:
        return "safe over the whole box"
    return "safe for " + " at ".join(parts)


_SUGGEST = {
    "contact": ("grip slip", "reduce the uncertainty of the object's mass and friction, grip "
                "differently (more pad contact, more grip force), or lift more slowly"),
    "motor": ("motor overload", "slow down, carry the object closer to the arm's base, reduce "
              "the mass uncertainty, or push the object instead of lifting it"),
    "diverged": ("simulation diverged", "check the model and the trajectory near this moment"),
}


def _causes(reports: Sequence[MomentReport], threshold: float) -> list[str]:
    """One line per failure cause (grip slip, overload of one actuator, ...), the moments where
    it limits (with their critical values) and the suggestion.

    A moment counts where sweep samples fail there, where the cost crosses the threshold
    along a critical-value curve, or where the worst case found fails (with a first-failure
    sweep a later moment's failures are hidden behind earlier ones; its critical values and
    worst case still say where it would fail).
    """
    groups: dict[str, list[str]] = {}
    for mr in reports:
        crossed = any(v is not None for v in mr.critical.values())
        if mr.dominant is None or (mr.fail_fraction == 0 and not crossed
                                   and not mr.max_cost > threshold):
            continue
        name = _SUGGEST[mr.dominant][0]
        if mr.dominant == "motor":
            name = f"{name} at {mr.limiting_actuator}"
        crit = ", ".join(f"{k} {mr.critical_side[k]} {v:.3g}" for k, v in mr.critical.items()
                         if v is not None)
        if mr.squeeze:
            where = (f" (a squeeze without a lift: sparse evaluation fails "
                     f"{'for ' + crit if crit else 'there'}; the samples' own rollouts decide)")
        elif crit:
            where = f" (fails for {crit})"
        elif mr.fail_fraction > 0:
            where = f" ({mr.fail_fraction:.0%} of the box)"
        else:
            where = " (at " + ", ".join(f"{k} = {v:.3g}" for k, v in mr.worst_case.items()) + ")"
        groups.setdefault(f"{mr.dominant}|{name}", []).append(
            f"{mr.moment.label.value} at t = {mr.moment.time:.2f} s{where}")
    return [f"{key.split('|', 1)[1]}: {'; '.join(where)}; suggestion: "
            f"{_SUGGEST[key.split('|', 1)[0]][1]}" for key, where in groups.items()]


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
    for j, p in enumerate(box.parameters):
        u = np.full((n, box.ndim), 0.5)
        u[:, j] = np.linspace(0.0, 1.0, n)
        samples = box.from_unit(u)
        samples[:, [i for i in range(box.ndim) if i != j]] = box.nominal[
            [i for i in range(box.ndim) if i != j]]
        res = evaluator.evaluate(steps, samples)
        for row, s in enumerate(steps):
            out[int(s)][p.name] = _select(res, row)
    return out


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


def _crossing(samples_j: np.ndarray, cost: np.ndarray, threshold: float, nominal: float):
    """Crossing of cost = threshold along one sampled curve nearest nominal (linear interp)."""
    fail = cost > threshold
    flips = np.flatnonzero(fail[1:] != fail[:-1])
    if flips.size == 0:
        return None, None
    xs = []
    for i in flips:
        c0, c1 = cost[i], cost[i + 1]
        if np.isfinite(c0) and np.isfinite(c1) and c1 != c0:
            t = (threshold - c0) / (c1 - c0)
        else:
            t = 0.5
        xs.append(samples_j[i] + t * (samples_j[i + 1] - samples_j[i]))
    i = int(np.argmin(np.abs(np.array(xs) - nominal)))
    side = "above" if fail[flips[i] + 1] else "below"
    return float(xs[i]), side


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

    Returns:
        The audit report.
    """
    opt = options or AnalyzeOptions()
    if seed is not None:
        opt = dataclasses.replace(opt, seed=int(seed))
    if twin is None:
        twin = Twin(scenario if isinstance(scenario, Scenario) else load_scenario(scenario))
    sc = twin.scenario
    budget.check_audit(trajectory, twin, opt)  # seed domain, rollout and sweep size
    box = sc.box
    threshold = sc.cost.threshold
    say = _progress(progress)
    timings: dict[str, float] = {}

    def stage(name):
        return _Timer(timings, name, say)

    with stage("rollout"):
        check_fit(trajectory, None, twin)  # width and units, naming the likely mistake
        rec = rollout(trajectory, twin=twin)
        feasibility = preflight(trajectory, rec, twin) if opt.check_feasibility else None
    with stage("moments"):
        evaluator = sp.SparseEvaluator(rec, twin, horizon=opt.horizon, nthread=opt.nthread)
        candidates, steps = audit_moments(rec, twin, evaluator, opt.max_moments)
        chosen = candidates[:steps.size]
    with stage("sweep"):
        samples = sp.sweep_samples(box, n=opt.n_samples, seed=opt.seed)
        probe = np.vstack([box.nominal[None, :], samples])
        res_all = evaluator.evaluate(steps, probe, first_failure=not opt.exhaustive)
        nominal_cost = float(res_all.worst_cost()[0]) if steps.size else 0.0
        res = _select_samples(res_all, slice(1, None))
        failed = res.failed_any if steps.size else np.zeros(len(samples), bool)
    verification = None
    if opt.verify is not None and steps.size:
        with stage("verification"):
            from critmoment.validation import rerun_in_full

            failed, near, unlifted = rerun_in_full(
                trajectory, twin=twin, samples=res.samples, failed=failed,
                cost=res.worst_cost(),
                unlifted=res.failed_unlifted_only if opt.verify_unlifted else None,
                verify=opt.verify, nthread=opt.nthread)
            rerun = near | unlifted
            verification = {"fraction": float(opt.verify),
                            "cost_from": float(opt.verify * threshold),
                            "rollouts": int(rerun.sum()),
                            "failed": int(failed[rerun].sum()),
                            "near": int(near.sum()), "near_failed": int(failed[near].sum()),
                            "unlifted": int(unlifted.sum()),
                            "unlifted_failed": int(failed[unlifted].sum())}
    n_fail = int(failed.sum())
    p = 1.0 - n_fail / len(samples)
    interval = sp.wilson_interval(len(samples) - n_fail, len(samples), confidence=opt.confidence)
    with stage("critical values"):
        curves = _curves(evaluator, steps, box, opt.critical_grid) if steps.size else {}
    searches: dict[int, dict] = {}
    analytics: dict[int, dict] = {}
    if opt.search and steps.size:
        with stage("analytic bounds and search"):
            analytics, searches = _search_all(rec, twin, evaluator, steps, opt)
    moment_reports = []
    worst_unlifted: dict[int, bool] = {}  # per failing moment: its worst case is unlifted
    for row, m in enumerate(chosen):
        s = int(steps[row])
        cost = res.cost[row]
        here = ~np.isnan(cost)  # the samples evaluated at this moment (inf: diverged)
        worst_case, max_cost, motor = {}, float("nan"), None
        if here.any():
            worst = int(np.argmax(np.where(here, np.where(np.isinf(cost), 1e9, cost), -np.inf)))
            worst_case = dict(zip(box.names, map(float, res.samples[worst]), strict=False))
            max_cost, motor = float(cost[worst]), int(res.motor_argmax[row, worst])
        sr = searches.get(s)
        if sr is not None and sr.get("worst_cost") is not None and not (
                sr["worst_cost"] <= max_cost):
            worst_case, max_cost = dict(sr["worst_case"]), float(sr["worst_cost"])
        crit, side = {}, {}
        for j, pname in enumerate(box.names):
            c = curves[s][pname]
            crit[pname], side[pname] = _crossing(c.samples[:, j], c.cost[0], threshold,
                                                 box.nominal[j])
        fails_here = res.failed[row]
        dominant = _dominant(res, row, fails_here)
        if dominant is None:
            dominant = next((d for c in curves[s].values()
                             if (d := _dominant(c, 0, c.failed[0])) is not None), None)
        if worst_case and max_cost > threshold:
            one = evaluator.evaluate([s], [[worst_case[n] for n in box.names]])
            worst_unlifted[s] = bool(one.unlifted_failure[0, 0])
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
            fail_fraction=float(fails_here.mean()), analytic=analytics.get(s),
            search=searches.get(s), reached=float(here.mean()), squeeze=bool(squeeze)))
    task_failed = opt.require_task and not rec.completed
    if task_failed:
        # sparse evaluation perturbs a run that already failed: it cannot estimate success
        p, interval = 0.0, sp.wilson_interval(0, len(samples), confidence=opt.confidence)
    # unlifted failures are for rollouts to decide: the nominal one is the recording itself
    rolled = opt.verify is not None and opt.verify_unlifted and steps.size > 0
    nominal_squeeze = (rolled and nominal_cost > threshold and rec.completed
                       and bool(res_all.failed_unlifted_only[0]))
    if (nominal_cost > threshold and not nominal_squeeze) or task_failed:
        verdict = Verdict.UNSAFE
    elif n_fail == 0 and _worst_cases_pass(moment_reports, worst_unlifted, trajectory, twin,
                                           opt, verification if rolled else None):
        verdict = Verdict.SAFE
    else:
        verdict = Verdict.CONDITIONAL
    region = None
    if verdict is not Verdict.UNSAFE and steps.size:
        worst_cost = res.worst_cost()
        region = safe_subbox(res.samples, failed, box, _fail_sides(res.samples, worst_cost, box))
    cost_map = None
    if opt.map_resolution and box.ndim >= 2 and steps.size:
        cost_map = _cost_map(res, box, opt.map_resolution)
    causes = tuple(_causes(moment_reports, threshold))
    if nominal_squeeze:
        causes = (f"the nominal cost exceeds the threshold ({nominal_cost:.3g} > {threshold:g}) "
                  f"only where the grip squeezes the object off its support without lifting "
                  f"it; the nominal run completes the task",) + causes
    elif nominal_cost > threshold:
        causes = (f"fails at the nominal parameters (max cost {nominal_cost:.3g} > "
                  f"{threshold:g})",) + causes
    if verification and verification["near_failed"]:
        causes += (f"{verification['near_failed']} of {verification['near']} samples that pass "
                   f"at the moments with a cost ≥ {verification['cost_from']:.3g} fail in "
                   f"their own full rollout (between the moments or by not completing the "
                   f"task); suggestion: reduce the uncertainty near the safe region's edge",)
    if task_failed:
        causes = (f"the task is not completed at the nominal parameters (stage "
                  f"{int(rec.stage.max())} reached, final stage {int(rec.stage[-1])}, 4 needed "
                  f"and kept to the end)",) + causes
    manifest = _manifest(sc, opt, trajectory)
    return AuditReport(
        verdict=verdict, p_success=p, p_success_interval=interval,
        moments=tuple(moment_reports), candidates=tuple(candidates), safe_region=region,
        safe_region_text=_region_text(region, box, verdict), failure_causes=causes,
        nominal_cost=nominal_cost, recording=rec, sweep=res, curves=curves, cost_map=cost_map,
        scenario=sc, options=opt, timings=timings, manifest=manifest, failed=failed,
        verification=verification, feasibility=feasibility)


def _worst_cases_pass(reports: Sequence[MomentReport], worst_unlifted: Mapping[int, bool],
                      trajectory, twin, opt: AnalyzeOptions, verification: dict | None) -> bool:
    """No moment's worst case fails, or (with ``verification``, the audit's summary) the ones
    that do fail only where the object is squeezed off its support without a lift
    (``worst_unlifted``, by moment step) and succeed in their own full rollout. Adds
    ``worst_cases`` and ``worst_cases_failed`` to ``verification``."""
    threshold = twin.scenario.cost.threshold
    failing = [mr for mr in reports if not mr.max_cost <= threshold]
    if not failing:
        return True
    if verification is None or not all(worst_unlifted.get(int(mr.moment.step), False)
                                       for mr in failing):
        return False
    names = twin.scenario.box.names
    points = np.array([[mr.worst_case[n] for n in names] for mr in failing])
    from critmoment.validation import brute_force

    real = brute_force(trajectory, twin=twin, samples=points, nthread=opt.nthread).failed
    verification["worst_cases"] = int(points.shape[0])
    verification["worst_cases_failed"] = int(real.sum())
    return not real.any()


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
    d2 = ((cells[:, None, :] - u[None, :, :]) ** 2).sum(axis=-1)
    grid = worst[np.argmin(d2, axis=1)].reshape(g0.shape)
    axes = box.from_unit(np.tile(grid_u[:, None], (1, box.ndim)))
    return (box.names[0], axes[:, 0], box.names[1], axes[:, 1], grid)


def _search_all(rec, twin, evaluator, steps, opt):
    """Analytic bounds, CasADi/Optuna worst cases and their verification per moment."""
    from critmoment import dynamics, search

    pin_model = dynamics.from_mujoco(twin.model)
    analytics, searches = {}, {}
    for s in steps:
        out = search.audit_moment(evaluator, int(s), pin_model=pin_model,
                                  n_trials=opt.search_trials, seed=opt.seed,
                                  patience=opt.search_patience)
        analytics[int(s)] = {**out["analytic"], "verification": out.get("verification")}
        searches[int(s)] = out["search"]
    return analytics, searches


def _manifest(sc: Scenario, opt: AnalyzeOptions, traj: Trajectory) -> dict:
    import mujoco

    import critmoment

    return {
        "critmoment": critmoment.__version__,
        "mujoco": mujoco.__version__,
        "numpy": np.__version__,
        "python": sys.version.split()[0],
        "platform": platform.platform(terse=True),
        "scenario": sc.name,
        # file names and content hashes, not paths: identical inputs, identical manifests
        "scenario_file": input_identity(sc.path)["name"] if sc.path else None,
        "scenario_sha256": input_identity(sc.path)["sha256"] if sc.path else None,
        "model_sha256": model_hash(sc),
        "trajectory": input_identity(traj.source)["name"],
        "trajectory_sha256": input_identity(traj.source)["sha256"],
        "seed": opt.seed,
        "options": dataclasses.asdict(opt),
    }


def _progress(progress):
    if callable(progress):
        return progress
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
