"""The validation study: the audit's decisions against brute-force full rollouts.

:func:`predict` runs the audit's own method on parameter samples: the frequent rollout at
nominal parameters, the audit's critical moments (:func:`critmoment.analysis.audit_moments`,
the first ``max_moments`` of the ranked candidates, as :func:`critmoment.analysis.analyze`
takes them), one sparse evaluation per moment and sample, and the audit's decision path
(:func:`critmoment.verdict.samples_to_rerun`, :func:`critmoment.verdict.failing_samples`):
the same function decides which samples fail in ``analyze`` and here. One optional addition
to the method is prototyped here: an *envelope* check (sparse evaluations every ~0.1 s of the
carrying phase). The ground truth, :func:`critmoment.groundtruth.brute_force` (the real
outcome of each sample's full rollout, from the task's success rule and plain kinematics),
sits below the audit; its names stay importable from here. :func:`compare` builds the
confusion matrix; :func:`validate` chains the three.

The confusion matrix counts ``true_safe`` (predicted safe, succeeded), ``false_safe``
(predicted safe, failed), ``true_unsafe`` (predicted unsafe, failed) and ``false_unsafe``
(predicted unsafe, succeeded). The **false-safe rate** is false_safe / (false_safe +
true_unsafe): the fraction of the real failures that the audit called safe (the miss rate;
``None`` when no sample fails). Agreement is (true_safe + true_unsafe) / n. A validation in
which no sample really succeeds, or none really fails, is **vacuous**
(:attr:`ValidationResult.vacuous`): its false-safe rate says nothing about the method.
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Mapping

import numpy as np

from critmoment import budget
from critmoment import sparse as sp
from critmoment.analysis import (
    AnalyzeOptions,
    _option_bool,
    _Rollouts,
    _Timer,
    audit_evaluator,
    audit_moments,
    decision_options,
    input_manifest,
    sample_runs,
)
from critmoment.exceptions import ParameterError
from critmoment.feasibility import check_fit, preflight
from critmoment.groundtruth import (
    BruteForce,
    Classification,
    Outcome,
    OutcomeCriteria,
    _check_int,
    _check_positive,
    _Probe,  # noqa: F401 (the probe model, read by tests)
    brute_force,
    check_criteria,
    classify,
    ends_completed,
    grip_slip,
    rerun_in_full,
)
from critmoment.moments import Moment
from critmoment.recording import Recording, at_scenario_rate, rollout
from critmoment.scenario import Scenario
from critmoment.trajectory import Trajectory, check_trajectory, input_identity
from critmoment.twin import Twin, carried_flags, entry_point, resolve_twin
from critmoment.verdict import failing_samples

__all__ = [
    # the ground truth (critmoment.groundtruth), re-exported for compatibility
    "Outcome",
    "OutcomeCriteria",
    "Classification",
    "classify",
    "ends_completed",
    "grip_slip",
    "BruteForce",
    "brute_force",
    "rerun_in_full",
    # the validation study
    "Prediction",
    "predict",
    "envelope_steps",
    "MissedFailure",
    "ValidationResult",
    "confusion_counts",
    "compare",
    "validate",
    "VALIDATION_SCHEMA",
]

VALIDATION_SCHEMA = "critmoment.validation/1"

#: the audit's default options: validation tests what ``analyze`` does unless told otherwise
_AUDIT = AnalyzeOptions()

_CRITERIA = OutcomeCriteria()


# --------------------------------------------------------------------------
# sparse prediction
# --------------------------------------------------------------------------


@dataclasses.dataclass(frozen=True, eq=False)
class Prediction:
    """The audit's sparse prediction for parameter samples.

    Attributes:
        samples: the parameter values, (n, k).
        moments: the audited critical moments.
        steps: their physics steps as evaluated (clipped to T − horizon), (m,) int.
        envelope_steps: extra steps of the envelope check, (e,) int (empty without one).
        max_moments: moments asked for (``moments`` may hold fewer).
        horizon: physics steps per sparse evaluation.
        mode: STEP or SOLVE.
        cost: highest cost over the moments (and the envelope), (n,); +inf where diverged.
        cost_moments: highest cost over the moments alone, (n,).
        failed: predicted to fail, (n,) bool.
        verified: decided by the sample's own full rollout (``verify``), (n,) bool.
        nominal_completed: the frequent rollout completes the task.
        require_task: whether an incomplete nominal rollout makes every sample fail.
        seconds: wall time of the sparse method: frequent rollout, moment detection, sparse
            evaluations (and the verification's full rollouts) [s].
        timings: that time per stage [s].
        runs: how many samples each kind of own run decided, and how many of them fail
            (:meth:`critmoment.verdict.SampleRuns.counts`).
    """

    samples: np.ndarray
    moments: tuple[Moment, ...]
    steps: np.ndarray
    envelope_steps: np.ndarray
    max_moments: int
    horizon: int
    mode: sp.SparseMode
    cost: np.ndarray
    cost_moments: np.ndarray
    failed: np.ndarray
    verified: np.ndarray
    nominal_completed: bool
    require_task: bool
    seconds: float
    timings: Mapping[str, float]
    runs: Mapping[str, int] = dataclasses.field(default_factory=dict)


def _quiet(message: str) -> None:
    """No progress messages."""


def envelope_steps(recording: Recording, *, spacing: float, horizon: int = 1) -> np.ndarray:
    """Steps every ``spacing`` seconds over the phase where the nominal run carries the object.

    Args:
        recording: the frequent rollout.
        spacing: time between two envelope steps [s].
        horizon: the sparse horizon (steps are kept at most T − horizon).

    Returns:
        (e,) int steps, empty when the object is never carried.
    """
    spacing = _check_positive("spacing", spacing)
    sig = recording.signals
    carried = carried_flags(sig.contact_support, sig.contact_gripper)
    where = np.flatnonzero(carried)
    if where.size == 0:
        return np.zeros(0, dtype=np.int64)
    stride = max(1, int(round(spacing / recording.dt)))
    steps = np.arange(where[0], where[-1] + 1, stride)
    steps = steps[carried[steps]]
    return np.unique(np.minimum(steps, recording.n_steps - horizon)).astype(np.int64)


def predict(traj: Trajectory, *, twin: Twin, samples: np.ndarray, horizon: int | None = None,
            mode: sp.SparseMode = sp.SparseMode.STEP, max_moments: int | None = None,
            envelope: float | None = None, verify: float | None = _AUDIT.verify,
            verify_unlifted: bool = _AUDIT.verify_unlifted, require_task: bool = True,
            chain: bool = _AUDIT.chain, chunk: int = 16, nthread: int = 0) -> Prediction:
    """The audit's sparse prediction for parameter samples (the method under test).

    Runs what :func:`critmoment.analysis.analyze` runs to decide which samples fail: the
    frequent rollout, :func:`critmoment.analysis.audit_moments` with the evaluator's horizon
    (the first ``max_moments`` of its ranked candidates), one sparse evaluation per moment
    and sample, and the audit's own decision path, :func:`critmoment.verdict.samples_to_rerun`
    (the samples decided by their own full rollout) and
    :func:`critmoment.verdict.failing_samples` (which samples fail). There is no second
    copy of the decision here: validation measures the method itself.

    Args:
        traj: the trajectory.
        twin: the twin.
        samples: parameter values, (n, k).
        horizon: physics steps per sparse evaluation (default: the scenario's).
        mode: STEP or SOLVE (horizon 1).
        max_moments: moments audited (default: the audit's,
            :attr:`critmoment.analysis.AnalyzeOptions.max_moments`).
        envelope: if given, also evaluate every ``envelope`` seconds over the phase where the
            nominal run carries the object (:func:`envelope_steps`) [s].
        verify: a fraction of the cost threshold (default the audit's,
            :attr:`critmoment.analysis.AnalyzeOptions.verify`), or None: every sample predicted safe with
            a sparse cost at or above ``verify × threshold`` gets its own full rollout, whose
            outcome (:func:`brute_force`: dropped, slipped, motor, not completed, diverged)
            decides it.
        verify_unlifted: with ``verify``, samples that fail only where the object is squeezed
            off its support without a lift (``SparseResult.failed_unlifted_only``) get their
            own full rollout too (the audit's
            :attr:`critmoment.analysis.AnalyzeOptions.verify_unlifted`).
        require_task: an incomplete nominal rollout makes every sample fail.
        chunk: most full rollouts per batch call in the verification.
        nthread: threads (0: all CPUs).

    Returns:
        The :class:`Prediction`.
    """
    twin = resolve_twin(None, twin)
    traj = at_scenario_rate(check_trajectory(traj), twin)
    if max_moments is None:
        max_moments = _AUDIT.max_moments
    max_moments = _check_int("max_moments", max_moments, 1)
    chunk = _check_int("chunk", chunk, 1)
    # the audit's own decision options (AnalyzeOptions validates them as analyze does)
    audit = dataclasses.replace(_AUDIT, verify=verify, verify_unlifted=verify_unlifted,
                                require_task=require_task, chain=bool(chain))
    dopt = decision_options(audit, twin.scenario.cost.threshold)
    samples = sp.check_samples(twin.scenario.box, samples)
    nthread = budget.check_nthread(nthread)
    # the samples' own runs may reach one full rollout each; a horizon must leave the
    # recording room for its moments
    budget.check_validation(traj, twin, n_samples=samples.shape[0])
    if horizon is not None or mode is sp.SparseMode.STEP:  # SOLVE: the evaluator's horizon 1
        budget.check_audit_horizon(traj, twin, horizon)
    timings: dict[str, float] = {}
    t0 = time.perf_counter()
    check_fit(traj, None, twin)  # width and units, naming the likely mistake
    rec = rollout(traj, twin=twin)
    t1 = time.perf_counter()
    timings["rollout"] = t1 - t0
    preflight(traj, rec, twin)  # the twin can follow the nominal motion, or exit 2
    evaluator, _ = audit_evaluator(rec, twin, horizon=horizon, mode=mode, nthread=nthread,
                                   chain=bool(chain))
    h = evaluator.horizon
    # the audit's own selection (critmoment.analysis.audit_moments)
    candidates, steps = audit_moments(rec, twin, evaluator, max_moments)
    moments = tuple(candidates[:steps.size])
    t2 = time.perf_counter()
    timings["moments"] = t2 - t1
    extra = (envelope_steps(rec, spacing=envelope, horizon=h) if envelope is not None
             else np.zeros(0, dtype=np.int64))
    extra = np.setdiff1d(extra, steps)
    every = np.concatenate([steps, extra])
    n = samples.shape[0]
    res = None
    if every.size:
        # as the audit: each sample stops at its first failure (the same samples fail); the
        # envelope study compares moments with envelope steps, so it evaluates everything
        res = evaluator.evaluate(every, samples, first_failure=extra.size == 0)
        cost_all = res.worst_cost()
        cost_moments = res.worst_cost(slice(0, steps.size)) if steps.size else np.zeros(n)
    else:
        cost_all = cost_moments = np.zeros(n)
    t3 = time.perf_counter()
    timings["sparse evaluation"] = t3 - t2
    nominal_completed = rec.completed
    # the audit's own path (critmoment.analysis.sample_runs): which samples their own
    # rollouts and chains decide, then which fail (critmoment.verdict.failing_samples)
    # the audit's, its nominal reference read from the frequent rollout
    roll = _Rollouts(traj, twin, nthread, chunk=chunk, recording=rec)
    runs, _ = sample_runs(evaluator, steps, samples, res, dopt, roll=roll,
                          nominal_completed=nominal_completed, nthread=nthread,
                          stage=lambda name: _Timer(timings, name, _quiet))
    failed = failing_samples(runs.evidence(res, nominal_completed=nominal_completed), dopt)
    return Prediction(samples=samples, moments=moments, steps=steps, envelope_steps=extra,
                      max_moments=max_moments, horizon=h, mode=evaluator.mode, cost=cost_all,
                      cost_moments=cost_moments,
                      failed=failed, verified=runs.rerun, nominal_completed=nominal_completed,
                      require_task=bool(require_task), seconds=time.perf_counter() - t0,
                      timings=timings, runs=runs.counts(failed))


# --------------------------------------------------------------------------
# comparison
# --------------------------------------------------------------------------


def confusion_counts(predicted_failed: np.ndarray, real_failed: np.ndarray) -> dict[str, int]:
    """Confusion matrix of predictions against real outcomes.

    Args:
        predicted_failed: the audit predicts failure, (n,) bool.
        real_failed: the full rollout fails, (n,) bool.

    Returns:
        ``{"true_safe", "false_safe", "true_unsafe", "false_unsafe"}`` counts: predicted
        safe and succeeded, predicted safe and failed, predicted unsafe and failed, predicted
        unsafe and succeeded.
    """
    p = np.asarray(predicted_failed, dtype=bool)
    r = np.asarray(real_failed, dtype=bool)
    if p.shape != r.shape or p.ndim != 1:
        raise ParameterError(
            f"expected predicted_failed and real_failed of the same shape (n,), got {p.shape} "
            f"and {r.shape}")
    return {"true_safe": int((~p & ~r).sum()), "false_safe": int((~p & r).sum()),
            "true_unsafe": int((p & r).sum()), "false_unsafe": int((p & ~r).sum())}


@dataclasses.dataclass(frozen=True)
class MissedFailure:
    """A real failure the audit called safe.

    Attributes:
        sample: index of the sample.
        values: its parameter values, by name.
        outcome: its real outcome.
        max_cost: its highest sparse cost over the audited steps.
        first_failure_step: step of its earliest failure event (−1 if undetermined).
        first_failure_time: that step's time [s] (nan if undetermined).
        nearest_moment: the audited moment step nearest to the failure (−1 without moments).
        offset: failure time minus that moment's time [s] (nan if undetermined).
    """

    sample: int
    values: Mapping[str, float]
    outcome: Outcome
    max_cost: float
    first_failure_step: int
    first_failure_time: float
    nearest_moment: int
    offset: float

    def to_json(self) -> dict:
        return {"sample": self.sample, "values": dict(self.values),
                "outcome": self.outcome.value, "max_cost": _finite(self.max_cost),
                "first_failure_step": self.first_failure_step,
                "first_failure_time": _finite(self.first_failure_time),
                "nearest_moment": self.nearest_moment, "offset": _finite(self.offset)}


def _finite(x: float) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


@dataclasses.dataclass(frozen=True, eq=False)
class ValidationResult:
    """Sparse predictions against brute-force outcomes for one trajectory.

    Attributes:
        trajectory: the trajectory's source.
        parameter_names: names of the k parameters.
        samples: the parameter values, (n, k).
        outcome: the real outcome per sample.
        real_failed: the full rollout failed, (n,) bool.
        predicted_failed: the audit predicted failure, (n,) bool.
        max_cost: highest sparse cost per sample over the audited steps, (n,).
        first_failure_step: earliest failure event per sample, −1 for none, (n,) int.
        moment_steps: the audited moments' steps, (m,) int.
        envelope_steps: the envelope check's extra steps, (e,) int.
        horizon: sparse horizon [physics steps].
        mode: sparse mode.
        max_moments: moments audited.
        dt: physics step [s].
        sparse_seconds: wall time of the sparse method (frequent rollout, moments,
            evaluations, and the verification's full rollouts) [s].
        brute_force_seconds: wall time of the full rollouts and their classification [s].
        nominal_completed: the nominal run completes the task.
        criteria: the outcome tolerances.
        missed: the false safes, with where they fail relative to the moments.
        verified: the prediction was decided by the sample's own full rollout, (n,) bool.
        seed: Sobol seed of the samples, or None when the samples were given.
        runs: how many samples each kind of own run decided (the sweep's near, unlifted
            and sticking samples; the chained ones, and of those the failures and the near
            passes sent on to their own rollout), and how many of them fail
            (:meth:`critmoment.verdict.SampleRuns.counts`).
    """

    trajectory: str
    parameter_names: tuple[str, ...]
    samples: np.ndarray
    outcome: tuple[Outcome, ...]
    real_failed: np.ndarray
    predicted_failed: np.ndarray
    max_cost: np.ndarray
    first_failure_step: np.ndarray
    moment_steps: np.ndarray
    envelope_steps: np.ndarray
    horizon: int
    mode: sp.SparseMode
    max_moments: int
    dt: float
    sparse_seconds: float
    brute_force_seconds: float
    nominal_completed: bool
    criteria: OutcomeCriteria
    missed: tuple[MissedFailure, ...]
    verified: np.ndarray
    seed: int | None = None
    runs: Mapping[str, int] = dataclasses.field(default_factory=dict)
    #: what the validation ran on (:func:`critmoment.analysis.input_manifest`: versions,
    #: scenario, model and trajectory by name and hash, the box, the options), or None
    manifest: Mapping | None = None

    @property
    def n_samples(self) -> int:
        return int(self.samples.shape[0])

    @property
    def confusion(self) -> dict[str, int]:
        """``{"true_safe", "false_safe", "true_unsafe", "false_unsafe"}`` counts."""
        return confusion_counts(self.predicted_failed, self.real_failed)

    @property
    def false_safe_rate(self) -> float | None:
        """false_safe / (false_safe + true_unsafe): the share of real failures called safe;
        None when no sample really fails."""
        c = self.confusion
        failures = c["false_safe"] + c["true_unsafe"]
        return c["false_safe"] / failures if failures else None

    @property
    def vacuous(self) -> bool:
        """No sample really succeeds, or none really fails: the false-safe rate (and the
        agreement) then say nothing about the method's ability to tell the two apart."""
        real = np.asarray(self.real_failed, dtype=bool)
        return bool(real.all() or not real.any())

    @property
    def agreement(self) -> float:
        """(true_safe + true_unsafe) / n."""
        c = self.confusion
        return (c["true_safe"] + c["true_unsafe"]) / self.n_samples

    @property
    def compute_ratio(self) -> float:
        """sparse_seconds / brute_force_seconds."""
        if not self.brute_force_seconds:
            return math.nan
        return self.sparse_seconds / self.brute_force_seconds

    def outcome_counts(self) -> dict[str, int]:
        """Samples per real outcome."""
        return {o.value: sum(1 for x in self.outcome if x is o) for o in Outcome}

    def to_json(self, *, timings: bool = True) -> dict:
        """JSON-able document (schema ``critmoment.validation/1``).

        Args:
            timings: include the wall times (off for byte-comparable documents).
        """
        _option_bool("timings", timings)
        doc = {
            "schema": VALIDATION_SCHEMA,
            "trajectory": self.trajectory,
            "samples": self.n_samples,
            "seed": self.seed,
            "parameters": list(self.parameter_names),
            "horizon": self.horizon,
            "mode": self.mode.value,
            "max_moments": self.max_moments,
            "moment_steps": [int(s) for s in self.moment_steps],
            "envelope_steps": [int(s) for s in self.envelope_steps],
            "verified": int(self.verified.sum()),
            "own_runs": dict(self.runs),
            "nominal_completed": self.nominal_completed,
            "criteria": dataclasses.asdict(self.criteria),
            "confusion": self.confusion,
            "false_safe_rate": self.false_safe_rate,
            "vacuous": self.vacuous,
            "agreement": self.agreement,
            "outcomes": self.outcome_counts(),
            "missed": [m.to_json() for m in self.missed],
            "per_sample": [
                {"values": dict(zip(self.parameter_names, map(float, self.samples[i]), strict=False)),
                 "outcome": self.outcome[i].value, "real_failed": bool(self.real_failed[i]),
                 "predicted_failed": bool(self.predicted_failed[i]),
                 "verified": bool(self.verified[i]),
                 "max_cost": _finite(self.max_cost[i]),
                 "first_failure_step": int(self.first_failure_step[i])}
                for i in range(self.n_samples)],
            "manifest": self.manifest,
        }
        if timings:  # every wall time under "timings": the rest is identical run to run
            doc["timings"] = {"sparse_seconds": self.sparse_seconds,
                              "brute_force_seconds": self.brute_force_seconds,
                              "compute_ratio": _finite(self.compute_ratio)}
        return doc

    def summary_text(self) -> str:
        """A few lines for the terminal."""
        c = self.confusion
        fsr = self.false_safe_rate
        counts = ", ".join(f"{k} {v}" for k, v in self.outcome_counts().items() if v)
        lines = [
            f"validation of {self.trajectory}: {self.n_samples} samples, horizon "
            f"{self.horizon} ({self.mode.value}), moments at steps "
            f"{[int(s) for s in self.moment_steps]}"
            + (f" + {self.envelope_steps.size} envelope steps" if self.envelope_steps.size else "")
            + (f"; {int(self.verified.sum())} samples verified by full rollouts"
               if self.verified.any() else "")
            + (f"; {self.runs['chained']} chained ({self.runs['chained_rolled_out']} "
               f"failures and {self.runs['chained_near']} near passes of them rolled out)"
               if self.runs.get("chained") else ""),
            f"real outcomes: {counts}"
            + ("" if self.nominal_completed else
               "; the nominal run itself does not complete the task (UNSAFE at the nominal "
               "parameters; `critmoment rollout` says what it lacks)"),
            f"confusion: true safe {c['true_safe']}, false safe {c['false_safe']}, true unsafe "
            f"{c['true_unsafe']}, false unsafe {c['false_unsafe']}",
            f"false-safe rate {'n/a (no real failure)' if fsr is None else f'{fsr:.3f}'}, "
            f"agreement {self.agreement:.3f}"
            + (f"; VACUOUS: no real {'failure' if fsr is None else 'success'} among the "
               f"samples, the false-safe rate says nothing about the method"
               if self.vacuous else ""),
            f"time: sparse {self.sparse_seconds:.2f} s, brute force "
            f"{self.brute_force_seconds:.2f} s (ratio {self.compute_ratio:.3g})",
        ]
        for m in self.missed:
            vals = ", ".join(f"{k} = {v:.3g}" for k, v in m.values.items())
            where = ("" if m.first_failure_step < 0 else
                     f" first fails at t = {m.first_failure_time:.2f} s, "
                     f"{m.offset:+.2f} s from the moment at step {m.nearest_moment}")
            lines.append(f"  missed: sample {m.sample} ({vals}) {m.outcome.value}, max cost "
                         f"{m.max_cost:.3g};{where}")
        return "\n".join(lines)


def compare(brute: BruteForce, prediction: Prediction, *, trajectory: str = "",
            seed: int | None = None) -> ValidationResult:
    """Compare a sparse prediction with the brute-force outcomes of the same samples.

    Args:
        brute: the brute-force result.
        prediction: the sparse prediction.
        trajectory: the trajectory's source, for the report.
        seed: the Sobol seed of the samples, for the report.

    Returns:
        The :class:`ValidationResult`.
    """
    if brute.samples.shape != prediction.samples.shape or not np.array_equal(
            brute.samples, prediction.samples):
        raise ParameterError(
            f"expected the brute force and the prediction of the same samples, got shapes "
            f"{brute.samples.shape} and {prediction.samples.shape} (or different values)")
    real = brute.failed
    pred = prediction.failed
    first = brute.classification.first_failure_step
    dt = brute.dt
    moments = prediction.steps
    missed = []
    for i in np.flatnonzero(~pred & real):
        step = int(first[i])
        if step >= 0 and moments.size:
            j = int(np.argmin(np.abs(moments - step)))
            nearest, offset = int(moments[j]), (step - int(moments[j])) * dt
        else:
            nearest, offset = (int(moments[0]) if moments.size and step < 0 else -1), math.nan
        missed.append(MissedFailure(
            sample=int(i), values=dict(zip(brute.parameter_names, map(float, brute.samples[i]), strict=False)),
            outcome=brute.outcome[i], max_cost=float(prediction.cost[i]),
            first_failure_step=step, first_failure_time=step * dt if step >= 0 else math.nan,
            nearest_moment=nearest if step >= 0 else -1, offset=offset))
    return ValidationResult(
        trajectory=trajectory, parameter_names=brute.parameter_names, samples=brute.samples,
        outcome=brute.outcome, real_failed=real, predicted_failed=pred,
        max_cost=prediction.cost, first_failure_step=first, moment_steps=moments,
        envelope_steps=prediction.envelope_steps, horizon=prediction.horizon,
        mode=prediction.mode,
        max_moments=prediction.max_moments, dt=dt,
        sparse_seconds=prediction.seconds, brute_force_seconds=brute.seconds,
        nominal_completed=brute.nominal_completed, criteria=brute.classification.criteria,
        missed=tuple(missed), verified=prediction.verified, seed=seed,
        runs=prediction.runs)


@entry_point
def validate(traj: Trajectory, scenario: Scenario | str | None = None, *,
             twin: Twin | None = None, n_samples: int = 64, seed: int | None = 0,
             samples: np.ndarray | None = None, horizon: int | None = None,
             mode: sp.SparseMode = sp.SparseMode.STEP, max_moments: int | None = None,
             envelope: float | None = None, verify: float | None = _AUDIT.verify,
             verify_unlifted: bool = _AUDIT.verify_unlifted,
             require_task: bool = True, criteria: OutcomeCriteria = _CRITERIA,
             chain: bool = _AUDIT.chain, chunk: int = 16, nthread: int = 0
             ) -> ValidationResult:
    """Check the audit's sparse verdicts against brute-force full rollouts.

    Args:
        traj: the trajectory.
        scenario: a :class:`~critmoment.scenario.Scenario`, a path to a scenario.toml or its
            folder, or a bundled scenario's name (default the bundled one), as for
            :func:`critmoment.analysis.analyze`; or give ``twin``.
        twin: the twin.
        n_samples: Sobol samples of the uncertainty box (a power of 2 is best).
        seed: Sobol seed.
        samples: explicit parameter values (n, k) instead of the Sobol samples.
        horizon: sparse horizon [physics steps] (default: the scenario's).
        mode: sparse mode, STEP or SOLVE (horizon 1).
        max_moments: moments audited (default: the audit's,
            :attr:`critmoment.analysis.AnalyzeOptions.max_moments`).
        envelope: spacing of the envelope check over the carrying phase [s], or None.
        verify: re-run in full the samples predicted safe with a cost at or above this
            fraction of the threshold (see :func:`predict`; default the audit's,
            :attr:`critmoment.analysis.AnalyzeOptions.verify`), or None.
        verify_unlifted: with ``verify``, re-run in full the samples that fail only where the
            object is squeezed off its support without a lift (see :func:`predict`).
        require_task: an incomplete nominal rollout makes every prediction a failure.
        criteria: the outcome tolerances.
        chunk: most full rollouts per batch call.
        nthread: threads (0: all CPUs).

    Returns:
        The :class:`ValidationResult`.
    """
    twin = resolve_twin(scenario, twin)
    traj = at_scenario_rate(check_trajectory(traj), twin)
    box = twin.scenario.box
    # every argument checked before the first rollout, not after the prediction's work
    check_criteria(criteria)
    nthread = budget.check_nthread(nthread)
    chunk = _check_int("chunk", chunk, 1)
    if samples is None:
        n_samples = _check_int("n_samples", n_samples, 1)
        if seed is not None:
            seed = budget.check_seed(seed)
        budget.check_validation(traj, twin, n_samples=n_samples)
        samples = sp.sweep_samples(box, n=n_samples, seed=seed)
        used_seed = seed
    else:
        samples, used_seed = sp.check_samples(box, samples), None
        budget.check_validation(traj, twin, n_samples=samples.shape[0])
    prediction = predict(traj, twin=twin, samples=samples, horizon=horizon, mode=mode, chain=chain,
                         max_moments=max_moments, envelope=envelope, verify=verify,
                         verify_unlifted=verify_unlifted, require_task=require_task,
                         chunk=chunk, nthread=nthread)
    brute = brute_force(traj, twin=twin, samples=samples, criteria=criteria, chunk=chunk,
                        nthread=nthread)
    # the file's name, not its path: identical inputs give identical documents
    result = compare(brute, prediction, trajectory=input_identity(traj.source)["name"],
                     seed=used_seed)
    options = {"n_samples": int(samples.shape[0]), "horizon": prediction.horizon,
               "mode": prediction.mode.value, "max_moments": prediction.max_moments,
               "envelope": envelope, "verify": verify, "verify_unlifted": verify_unlifted,
               "require_task": require_task, "chain": chain,
               "criteria": dataclasses.asdict(criteria),
               "box": {p.name: {"range": [p.low, p.high], "nominal": p.nominal,
                                "prior": p.prior.value} for p in box.parameters},
               "samples_given": used_seed is None}
    return dataclasses.replace(result, manifest=input_manifest(
        twin.scenario, traj, seed=used_seed, options=options, twin=twin))
