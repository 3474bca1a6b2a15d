"""The audit's decision: which samples fail, the verdict, P(success), the safe region, causes.

Everything here is pure: no simulation. The audit (:func:`critmoment.analysis.analyze`)
computes the evidence first (the sparse sweep, the full rollouts of the samples sparse
evaluation cannot decide, the nominal run, the per-moment findings, the check of the
safe region) and passes it in; :func:`failing_samples` and :func:`decide` turn it into the
decision. The validation study (:func:`critmoment.validation.predict`) calls the same
:func:`samples_to_rerun` and :func:`failing_samples`, so it measures the method itself.

The decision path, in order:

1. :func:`samples_to_rerun`: which samples get their own full rollout (those that pass the
   sparse evaluation with a cost at or above ``verify × threshold``, those whose only
   failures are unlifted ones, ``SparseResult.failed_unlifted_only``, and those whose
   only failures are sticking ones, inside an elliptic friction cone,
   ``SparseResult.failed_sticking_only``); none when the nominal run itself fails the
   task and there are no chained segments (every sample fails then).
2. :func:`failing_samples`: a sample fails where its sparse evaluation fails at an audited
   moment (``SparseResult.failed``), unless its own rollout decided it; the rollout's real outcome
   decides the re-run samples, the chained segments (each sample's own run, ending with
   the task's rule) the others that pass; without them every sample fails when the
   nominal run does not complete the task (``require_task``).
3. :func:`candidate_region`: the largest sub-box, anchored at the box's safe corner, with
   no failing sample, cut where a critical value (others at nominal) says it fails; none
   when no sample passes. The audit checks it (:func:`region_points` on its corners and
   edges, densified where the cost is near the threshold, by sparse evaluation and then
   its corners and coarse edge points on their own run, the samples' decision path) and
   shrinks it
   (:func:`shrink_region`) until it holds: a :class:`RegionCheck`.
4. :func:`decide`: UNSAFE when the nominal parameters fail; SAFE when no sample and no
   worst case fails and the whole box passes its check; else CONDITIONAL with the checked
   region, stated with its evidence.
"""

from __future__ import annotations

import dataclasses
import enum
import itertools
import math
import numbers
from collections.abc import Mapping, Sequence
from typing import NamedTuple

import numpy as np

from critmoment.exceptions import ParameterError
from critmoment.moments import Moment
from critmoment.params import UncertaintyBox, kind_of
from critmoment.sparse import SparseResult, wilson_interval

__all__ = [
    "Verdict",
    "DecisionOptions",
    "MomentReport",
    "SampleEvidence",
    "RegionCheck",
    "Evidence",
    "Decision",
    "Reruns",
    "SampleRuns",
    "samples_to_rerun",
    "inherited_failures",
    "failing_samples",
    "samples_to_chain",
    "worst_cases_to_rerun",
    "fail_sides",
    "safe_subbox",
    "interior_points",
    "within",
    "candidate_region",
    "region_points",
    "hot_edges",
    "shrink_region",
    "round_inward",
    "region_text",
    "decide",
]


class Verdict(enum.Enum):
    """Outcome of an audit."""

    SAFE = "SAFE"                #: cost ≤ threshold over the whole box at every moment
    CONDITIONAL = "CONDITIONAL"  #: fails somewhere in the box; safe in a stated sub-box
    UNSAFE = "UNSAFE"            #: fails at the nominal parameters

    def __str__(self) -> str:  # print(report.verdict) says CONDITIONAL, not Verdict.CONDITIONAL
        return self.value


@dataclasses.dataclass(frozen=True)
class DecisionOptions:
    """What the decision takes from the audit's options.

    Attributes:
        threshold: cost above which a sample fails at a moment.
        verify: a fraction of the threshold, or None: samples that pass with a cost at or
            above ``verify × threshold`` are decided by their own full rollout.
        verify_unlifted: with ``verify``, samples whose only failures are unlifted ones are
            decided by their own full rollout too.
        verify_sticking: with ``verify``, samples whose only failures are sticking ones
            (a contact failure with the grasp inside an elliptic friction cone,
            ``SparseResult.sticking_failure``) are decided by their own full rollout too.
        verify_slip: with ``verify``, samples whose only failures are measured slips under
            ``slip_confirm`` (``SparseResult.failed_slip_only``: more than the sparse slip
            tolerance over the horizon, less than the ground truth's) are decided by their
            own full rollout too.
        verify_margin: with ``verify``, samples whose only failures are margin ones (the
            cost crossed the threshold through its motor term while every motor stayed
            under its limit, ``SparseResult.margin_failure``) are decided by their own
            full rollout too.
        slip_confirm: the slip a sparse slip failure must reach to stand on its own [m]
            (the ground truth's ``OutcomeCriteria.slip_tolerance``, 1 cm).
        require_task: a nominal run that does not complete the task fails every sample.
        confidence: confidence level of the P(success) interval.
        chain: every sample that passes at the moments and has no rollout of its own is
            carried on its own state from before its parameters first act through every
            moment to the end of the run (:func:`critmoment.history.chained_failures`); a
            failure there fails it, unless its own full rollout (with ``verify``) passes it. This
            sees what a sample's own history changes (a grip that shifts, a collision that
            never happens at nominal), which evaluation from the nominal states cannot.
        nominal_by_run: with ``verify``, a nominal run that completes the task decides the
            nominal parameters even where their sparse cost exceeds the threshold (contact
            chatter of a good grasp); without it only an unlifted squeeze is decided so.
    """

    threshold: float
    verify: float | None = 0.8
    verify_unlifted: bool = True
    verify_sticking: bool = True
    verify_slip: bool = True
    verify_margin: bool = True
    slip_confirm: float = 0.01
    require_task: bool = True
    confidence: float = 0.95
    chain: bool = True
    nominal_by_run: bool = True

    def __post_init__(self):
        if isinstance(self.threshold, bool) or not isinstance(self.threshold, numbers.Real) \
                or not math.isfinite(self.threshold):
            raise ParameterError(f"threshold: expected a finite number, got {self.threshold!r}")
        if self.verify is not None and (isinstance(self.verify, bool)
                                        or not isinstance(self.verify, numbers.Real)
                                        or not 0 < self.verify <= 1):
            raise ParameterError(f"verify: expected a fraction of the threshold in (0, 1] or "
                                 f"None, got {self.verify!r}")
        if isinstance(self.slip_confirm, bool) or not isinstance(
                self.slip_confirm, numbers.Real) or not self.slip_confirm > 0:
            raise ParameterError(f"slip_confirm: expected a length > 0 m, got "
                                 f"{self.slip_confirm!r}")
        for name in ("verify_unlifted", "verify_sticking", "verify_slip", "verify_margin",
                     "require_task",
                     "chain",
                     "nominal_by_run"):
            if not isinstance(getattr(self, name), (bool, np.bool_)):
                raise ParameterError(f"{name}: expected True or False, got "
                                     f"{getattr(self, name)!r}")
        if not 0 < self.confidence < 1:
            raise ParameterError(f"confidence: expected in (0, 1), got {self.confidence}")

    @property
    def rolls_squeezes(self) -> bool:
        """Some failures that only a rollout can decide (unlifted, sticking, short-slip or
        margin ones) are decided by rollouts."""
        return self.verify is not None and (self.verify_unlifted or self.verify_sticking
                                            or self.verify_slip or self.verify_margin)

    def only_a_rollout_decides(self, unlifted: bool, sticking: bool,
                               slipping: bool = False, margin: bool = False) -> bool:
        """Whether a failure, unlifted, sticking (a contact failure inside an elliptic
        cone), a short slip (under ``slip_confirm``) and/or a margin one (a motor under its
        limit), is one that the options decide by its own rollout."""
        return self.verify is not None and bool(
            (self.verify_unlifted and unlifted) or (self.verify_sticking and sticking)
            or (self.verify_slip and slipping) or (self.verify_margin and margin))


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
            others at nominal (None where it never crosses), from
            :func:`critmoment.sparse.critical_values`.
        critical_side: per parameter, "above"/"below" (which side fails) or None.
        dominant: the cost term dominating the failures here ("contact" / "motor" / None):
            over the sweep's samples failing here, or else over the failing points of the
            critical-value curves.
        limiting_actuator: the actuator limiting the motor FOS at the worst case.
        fail_fraction: fraction of the sweep's samples failing at this moment whose failure
            stands (their own run, where one decides them, fails too); unless the sweep is
            exhaustive, the samples whose first failure is here.
        reached: fraction of the sweep's samples evaluated at this moment: all of them when
            the sweep is exhaustive, else those that pass at every earlier moment.
        squeeze: every failure seen here (sweep and critical-value curves) is an unlifted
            one: the grip squeezes the object off its support without lifting it, and the
            samples' own rollouts decide them.
        analytic: analytic bounds (Pinocchio), JSON-able, or None.
        search: worst-case search summary, JSON-able, or None.
        overturned: samples of the sweep fail here, and each of them passes in the end (its
            own run decided it): the moment is no failure cause.
        audited_step: the step its sparse evaluation starts from when that is not the
            moment's own (a moment within the horizon of the recording's end is audited
            from the last step whose horizon fits), else None; see :attr:`step`.
        worst_fails: whether the worst case fails here by the samples' decision (its sparse
            evaluation, or its own rollout where one decided it); None where its cost
            stays at or under the threshold. A cost over the threshold that does not fail
            (a contact excursion shorter than the persistence) is no failure.
        worst_note: why a worst case whose cost crosses the threshold does not fail, or "".
        own_fail_fraction: fraction of the sweep's samples that pass sparse evaluation at
            every moment and fail on their own run (full rollout or chained segments) first
            after this moment and before the next: where the moments' own line reads "fails
            0 %" a cube dropped on its own run between them (an OpenMANIPULATOR-X's, 28 of
            32 samples, just after the audited lift-off).
        critical_refuted: per parameter, (side, value) of a critical value of sparse
            evaluation that the full run just past it (the others at nominal) refutes: that
            run completes the task. It is left out of ``critical`` and ``critical_side``
            (it cuts no region and sides no parameter).
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
    own_fail_fraction: float = 0.0
    analytic: Mapping | None = None
    search: Mapping | None = None
    reached: float = 1.0
    squeeze: bool = False
    audited_step: int | None = None
    overturned: bool = False
    worst_fails: bool | None = None
    worst_note: str = ""
    critical_refuted: Mapping[str, tuple[str, float]] = dataclasses.field(default_factory=dict)

    @property
    def step(self) -> int:
        """The step the audit evaluated this moment at (what its curves, critical values
        and worst case are keyed by)."""
        return int(self.moment.step if self.audited_step is None else self.audited_step)


@dataclasses.dataclass(frozen=True, eq=False)
class SampleEvidence:
    """What decides whether each of n samples fails.

    Attributes:
        sweep: sparse evaluations of the samples at the audited moments (m, n), or None
            when there is no moment (nothing fails then).
        nominal_completed: the nominal run completes the task.
        rerun: which samples have their own full rollout's outcome, (n,) bool, or None.
        rerun_failed: that outcome (the rollout failed), (n,) bool; read where ``rerun``.
        chained: which samples were carried on their own state through the moments
            (:func:`samples_to_chain`), (n,) bool, or None.
        chained_failed: they failed there, (n,) bool; read where ``chained``.
        nominal_failed: the nominal parameters fail at each audited moment (their sparse
            evaluation from the nominal state), (m,) bool, or None when not measured.
    """

    sweep: SparseResult | None
    nominal_completed: bool
    rerun: np.ndarray | None = None
    rerun_failed: np.ndarray | None = None
    chained: np.ndarray | None = None
    chained_failed: np.ndarray | None = None
    nominal_failed: np.ndarray | None = None

    @property
    def n_samples(self) -> int:
        return 0 if self.sweep is None else self.sweep.n_samples


class Reruns(NamedTuple):
    """The samples the sparse evaluation cannot decide (:func:`samples_to_rerun`), each
    (n,) bool."""

    near: np.ndarray      #: pass with a cost at or above ``verify × threshold``
    unlifted: np.ndarray  #: fail only unlifted (``SparseResult.failed_unlifted_only``)
    sticking: np.ndarray  #: fail only sticking (``SparseResult.failed_sticking_only``)
    slipping: np.ndarray  #: fail only by short slips (``SparseResult.failed_slip_only``)
    #: fail only by margin failures (a motor under its limit,
    #: ``SparseResult.failed_margin_only``)
    margin: np.ndarray
    #: fail only at moments where the nominal parameters fail too, whether the nominal run
    #: completes its task (which overrules that failure) or not (:func:`inherited_failures`)
    inherited: np.ndarray

    @property
    def any(self) -> np.ndarray:
        """(n,) bool: any of them."""
        return (self.near | self.unlifted | self.sticking | self.slipping | self.margin
                | self.inherited)


def _every_sample_fails(options: DecisionOptions, nominal_completed: bool) -> bool:
    """The nominal run fails a task the options require and no sample's own run can say
    otherwise (without the chained segments, sparse evaluation never sees the task's rule):
    every sample fails."""
    return options.require_task and not nominal_completed and not options.chain


def inherited_failures(sweep: SparseResult, nominal_failed: np.ndarray | None, *,
                       nominal_completed: bool, trust_run: bool = True) -> np.ndarray:
    """(n,) bool: the samples whose sparse failures the nominal run's own trouble may explain:
    every failing sample while the nominal run does not complete its task, and (with
    ``trust_run``) while it completes it, those failing only at moments where the nominal
    parameters fail too, so that its own run overrules the nominal parameters' sparse
    failure.

    Each sparse evaluation starts from the nominal run's state. Where that run has gone
    wrong by a moment (a gripper that drags the object at the release, a wrist driven into
    its limit), a sample restored there inherits the nominal run's trouble, which its own
    run may never meet (robosuite's UR5e + Robotiq 2F-85 with an elliptic cone and impratio
    1: four samples failed the sweep by the nominal run's wrist saturation at the release
    and really placed their cube). Where the nominal run completes the task although its
    parameters fail the sparse evaluation at a moment, that failure is not a real one for
    them, and a sample failing only there (as the nominal does) may not fail either
    (genesis' franka_sim Panda: a shoulder at 99.3 % of its limit through the lift, whatever
    the cube, at cost 0.99 against 0.9; every sample of the box was called failing while
    60 of 64 really succeed). Only their own run can say.

    A nominal run that does not complete its task may have gone wrong long before its
    parameters fail a moment, so there every failing sample inherits from it: an ALOHA
    wrist turned while carrying shifted the light nominal cube 4.4 mm between the fingers,
    the receiver closed on it with one finger and it fell at the release; two heavier
    samples, restored in that state at the hand-over, failed there while their own runs
    hand the cube over (agreement 0.938 on 32 samples, 1.000 with their own runs). It
    costs a rollout per failing sample, where the verdict is UNSAFE whatever they do.
    """
    n = sweep.n_samples
    if (nominal_failed is None or sweep.n_moments == 0
            or (nominal_completed and not trust_run)):
        return np.zeros(n, bool)
    nominal_failed = np.asarray(nominal_failed, dtype=bool)
    if nominal_failed.shape != (sweep.n_moments,):
        raise ParameterError(f"nominal_failed: expected ({sweep.n_moments},) bool, got "
                             f"shape {nominal_failed.shape}")
    if not nominal_completed:
        return np.array(sweep.failed_any, dtype=bool)
    elsewhere = (sweep.failed & ~nominal_failed[:, None]).any(axis=0)
    return sweep.failed_any & ~elsewhere


def samples_to_rerun(sweep: SparseResult | None, options: DecisionOptions, *,
                     nominal_completed: bool, nominal_failed: np.ndarray | None = None
                     ) -> Reruns:
    """The samples that sparse evaluation cannot decide, to be decided by their own rollout.

    Args:
        sweep: the sparse evaluations (m moments × n samples), or None.
        options: the decision options.
        nominal_completed: the nominal run completes the task.
        nominal_failed: the nominal parameters fail at each moment, (m,) bool, or None.

    Returns:
        The :class:`Reruns`: samples that pass with a cost ≥ ``verify × threshold``,
        samples whose only failures are unlifted ones, samples whose only failures are
        sticking (and unlifted) ones, samples whose only failures are short slips (and
        sticking and unlifted ones), samples whose only failures are margin ones (a motor
        under its limit; and sticking and unlifted ones) and samples that fail only where
        the nominal parameters fail too (:func:`inherited_failures`). All empty when ``verify`` is None, or when the
        nominal run fails the task and ``require_task`` makes every sample fail (without
        ``chain``: with it, each sample's own run applies the task's rule).
    """
    n = 0 if sweep is None else sweep.n_samples
    none = np.zeros(n, bool)
    if (sweep is None or sweep.n_moments == 0 or options.verify is None
            or _every_sample_fails(options, nominal_completed)):
        return Reruns(*(none.copy() for _ in Reruns._fields))
    cost = sweep.worst_cost()
    near = ~sweep.failed_any & (cost >= options.verify * options.threshold)
    unlifted = (sweep.failed_unlifted_only.copy() if options.verify_unlifted
                else none.copy())
    sticking = (sweep.failed_sticking_only.copy() if options.verify_sticking
                else none.copy())
    slipping = (sweep.failed_slip_only(options.slip_confirm) & ~sticking & ~unlifted
                if options.verify_slip else none.copy())
    margin = (sweep.failed_margin_only() & ~sticking & ~unlifted & ~slipping
              if options.verify_margin else none.copy())
    inherited = (inherited_failures(sweep, nominal_failed, nominal_completed=nominal_completed,
                                    trust_run=options.nominal_by_run)
                 & ~(unlifted | sticking | slipping | margin))
    return Reruns(near, unlifted, sticking, slipping, margin, inherited)


@dataclasses.dataclass(frozen=True, eq=False)
class SampleRuns:
    """Which samples the decision took from their own runs, and what those runs said.

    Attributes:
        reruns: the samples the sweep cannot decide (:func:`samples_to_rerun`), each
            decided by its own full rollout.
        chained: the samples carried on their own state (:func:`samples_to_chain`), (n,)
            bool.
        chained_failed: they failed there, (n,) bool (read where ``chained``).
        suspect: chained samples sent on to their own full rollout (a chained failure the
            chain is the weaker evidence for, or a chained pass near a watched rule's
            limit), (n,) bool.
        rerun_failed: the own full rollouts' real outcome (failed), (n,) bool (read where
            ``rerun``).
    """

    reruns: Reruns
    chained: np.ndarray
    chained_failed: np.ndarray
    suspect: np.ndarray
    rerun_failed: np.ndarray
    nominal_failed: np.ndarray | None = None
    #: how each chained failure failed on its chain (``history.ChainedResult.kinds``), None
    #: for the others; empty when not known
    chained_kinds: tuple[str | None, ...] = ()
    #: the step of each chained failure's earliest event (−1 for the others), (n,) int;
    #: None when not known
    chained_steps: np.ndarray | None = None

    @property
    def rerun(self) -> np.ndarray:
        """(n,) bool: decided by their own full rollout."""
        return self.reruns.any | self.suspect

    def evidence(self, sweep: SparseResult | None, *,
                 nominal_completed: bool) -> SampleEvidence:
        """The :class:`SampleEvidence` of these runs and the sweep they complete."""
        return SampleEvidence(sweep=sweep, nominal_completed=nominal_completed,
                              rerun=self.rerun, rerun_failed=self.rerun_failed,
                              chained=self.chained, chained_failed=self.chained_failed,
                              nominal_failed=self.nominal_failed)

    def counts(self, failed: np.ndarray) -> dict[str, int]:
        """How many samples each kind of own run decided, and how many of them fail
        (``failed``: the decision, (n,) bool), JSON-able: ``rollouts`` in all, the sweep's
        ``near``, ``unlifted`` and ``sticking`` samples, the ``chained`` ones, and of
        those the failures rolled out (``chained_rolled_out``, ``chained_confirmed``) and
        the near passes rolled out (``chained_near``, ``chained_near_failed``)."""
        failed = np.asarray(failed, dtype=bool)
        near, unlifted, sticking, slipping, margin, inherited = self.reruns
        rolled_fail = self.suspect & self.chained_failed
        rolled_near = self.suspect & ~self.chained_failed
        return {"rollouts": int(self.rerun.sum()), "failed": int(failed[self.rerun].sum()),
                "near": int(near.sum()), "near_failed": int(failed[near].sum()),
                "unlifted": int(unlifted.sum()),
                "unlifted_failed": int(failed[unlifted].sum()),
                "sticking": int(sticking.sum()),
                "sticking_failed": int(failed[sticking].sum()),
                "slipping": int(slipping.sum()),
                "slipping_failed": int(failed[slipping].sum()),
                "margin": int(margin.sum()),
                "margin_failed": int(failed[margin].sum()),
                "inherited": int(inherited.sum()),
                "inherited_failed": int(failed[inherited].sum()),
                "chained": int(self.chained.sum()),
                "chained_failed": int(self.chained_failed[self.chained].sum()),
                "chained_rolled_out": int(rolled_fail.sum()),
                "chained_confirmed": int(failed[rolled_fail].sum()),
                "chained_near": int(rolled_near.sum()),
                "chained_near_failed": int(failed[rolled_near].sum())}


def failing_samples(evidence: SampleEvidence, options: DecisionOptions) -> np.ndarray:
    """Which samples fail: the one decision path of ``analyze`` and ``validate``.

    A sample fails where its sparse evaluation fails at an audited moment
    (``SparseResult.failed``: the cost above the threshold, or diverged); a sample with its
    own full rollout (every sample :func:`samples_to_rerun` names must have one) is decided
    by that rollout's real outcome instead; a sample that passes with no rollout is decided
    by its chained evaluation on its own state (:func:`samples_to_chain`); with ``require_task`` and no chain every
    sample fails when the nominal run does not complete the task (the verdict is UNSAFE
    either way: the nominal parameters fail).

    Args:
        evidence: the sweep, the nominal completion and the rollouts' outcomes.
        options: the decision options.

    Returns:
        (n,) bool.

    Raises:
        ParameterError: a sample that needs its own rollout has none in ``evidence``.
    """
    sweep = evidence.sweep
    n = evidence.n_samples
    if sweep is None or sweep.n_moments == 0:
        failed = np.zeros(n, bool)
    else:
        failed = np.array(sweep.failed_any, dtype=bool)
    if _every_sample_fails(options, evidence.nominal_completed):
        return np.ones(n, bool)
    need = samples_to_rerun(sweep, options, nominal_completed=evidence.nominal_completed,
                            nominal_failed=evidence.nominal_failed).any
    if evidence.rerun is None:
        rerun = np.zeros(n, bool)
    else:
        rerun = np.asarray(evidence.rerun, dtype=bool)
        if rerun.shape != (n,) or evidence.rerun_failed is None \
                or np.shape(evidence.rerun_failed) != (n,):
            raise ParameterError(f"rerun, rerun_failed: expected ({n},) bool arrays, got "
                                 f"{np.shape(evidence.rerun)} and "
                                 f"{np.shape(evidence.rerun_failed)}")
    missing = need & ~rerun
    if missing.any():
        raise ParameterError(
            f"expected the own rollout's outcome of every sample to re-run, got none for "
            f"samples {np.flatnonzero(missing)[:10].tolist()}")
    if rerun.any():
        failed[rerun] = np.asarray(evidence.rerun_failed, dtype=bool)[rerun]
    if options.chain and sweep is not None and sweep.n_moments > 0:
        need = samples_to_chain(sweep, rerun, options)
        chained = (np.zeros(n, bool) if evidence.chained is None
                   else np.asarray(evidence.chained, dtype=bool))
        if need.any() and (chained.shape != (n,) or (need & ~chained).any()
                           or np.shape(evidence.chained_failed) != (n,)):
            raise ParameterError(
                f"expected the chained evaluation of every sample that passes without a "
                f"rollout ({int(need.sum())}), got chained {np.shape(evidence.chained)}")
        if need.any():
            failed[need] = np.asarray(evidence.chained_failed, dtype=bool)[need]
    return failed


def samples_to_chain(sweep: SparseResult, rerun: np.ndarray, options: DecisionOptions, *,
                     nominal_completed: bool = True) -> np.ndarray:
    """The samples to carry on their own state through the moments: those that pass at
    every audited moment and have no rollout of their own, (n,) bool (none without
    ``options.chain``). Where the nominal run does not complete a task the options require,
    they are chained all the same: each one's own run (its chain) ends with the task's
    rule (measured on robosuite's Panda + Robotiq 2F-85, seed 1: a nominal run that drops
    its cube, while 28 of 64 samples around it place theirs)."""
    n = sweep.n_samples
    if not options.chain or sweep.n_moments == 0:
        return np.zeros(n, bool)
    return ~np.asarray(sweep.failed_any, dtype=bool) & ~np.asarray(rerun, dtype=bool)


def worst_cases_to_rerun(moments: Sequence[MomentReport], worst_failed: Mapping[int, bool],
                         worst_unlifted: Mapping[int, bool], options: DecisionOptions, *,
                         n_failed: int) -> list[int]:
    """Steps of the moments whose failing worst case must be decided by its own rollout.

    Only when that can change the verdict to SAFE: no sample fails, and every moment whose
    worst case fails (``worst_failed``, by moment step: its sparse evaluation fails) fails
    only in a way the options decide by a rollout (``worst_unlifted``: an unlifted squeeze
    with ``verify_unlifted``, a sticking failure with ``verify_sticking``;
    :meth:`DecisionOptions.only_a_rollout_decides`). Empty otherwise.
    """
    failing = [mr.step for mr in moments if worst_failed.get(mr.step, False)]
    if n_failed or not failing or not options.rolls_squeezes:
        return []
    if not all(worst_unlifted.get(s, False) for s in failing):
        return []
    return failing


# -- the safe region -----------------------------------------------------------------
def fail_sides(samples: np.ndarray, failed: np.ndarray, box: UncertaintyBox,
               critical_sides: Sequence[Mapping[str, str | None]] = (),
               trend: Mapping[str, float] | None = None) -> list[str]:
    """Per parameter, the side where the motion fails: "above", "below" or "both".

    "both": the parameter fails on both sides of its nominal value (a centre-of-mass offset
    either way, a force limit that is both too weak to lift and too strong for the grip):
    the moments' critical values name both sides, or the failures grow significantly
    towards each end of the box, below and above the nominal (:func:`_both_sides`).

    Else, in order: the critical values' sides (``MomentReport.critical_side`` of each
    moment) by majority; else the sign of the rank correlation of the parameter with the
    samples' failures (the decisions themselves, chained and rolled-out ones included)
    where it is significant (|ρ| > 2/√n); else the sign of ``trend`` (how much the cost
    grows from the low to the high end of the parameter's 1-D curve with the others at
    nominal, summed over the moments); else the sign of the correlation, however weak. The
    cost's trend comes after the failures themselves: where the cost never crosses the
    threshold, the failures come from what the cost does not see (a soft grip's slip,
    watched on each sample's own run), and its slope can point the other way (ACT's scene
    with an elliptic cone: the motor term grows with friction, the slips that fail come at
    low friction).
    """
    sides = []
    failed = np.asarray(failed, dtype=np.float64)
    n = samples.shape[0]
    u_nom = box.to_unit(np.asarray(box.nominal, dtype=np.float64)[None])[0]
    for j, p in enumerate(box.parameters):
        votes = [cs.get(p.name) for cs in critical_sides]
        above, below = votes.count("above"), votes.count("below")
        inner = 0.0 < u_nom[j] < 1.0
        if inner and ((above and below) or _both_sides(samples[:, j], failed, p)):
            sides.append("both")
            continue
        if above != below:
            sides.append("above" if above > below else "below")
            continue
        corr = _rank_corr(samples[:, j], failed)
        if abs(corr) > 2.0 / np.sqrt(max(n, 1)):
            sides.append("below" if corr < 0 else "above")
            continue
        t = None if trend is None else trend.get(p.name)
        if t is not None and np.isfinite(t) and abs(t) > 1e-9:
            sides.append("above" if t > 0 else "below")
            continue
        sides.append("below" if corr < 0 else "above")
    return sides


def _rank_corr(x: np.ndarray, failed: np.ndarray) -> float:
    """Spearman's correlation of ``x`` with the failures (0 where either is constant)."""
    if x.size < 2 or np.std(failed) == 0:
        return 0.0
    rank_x = np.argsort(np.argsort(x, kind="stable"), kind="stable")
    if np.std(rank_x) == 0:
        return 0.0
    return float(np.corrcoef(rank_x, failed)[0, 1])


def _both_sides(x: np.ndarray, failed: np.ndarray, parameter) -> bool:
    """Whether the failures grow significantly towards both ends of a parameter: on each
    side of the nominal value, at least 8 samples, a failure, and failures correlating with
    the distance from the nominal beyond chance (ρ > 2/√n of that side)."""
    x_nom = float(np.asarray(parameter.nominal, dtype=np.float64))
    for side in (x < x_nom, x > x_nom):
        m = int(side.sum())
        if m < 8 or not failed[side].any():
            return False
        if not _rank_corr(np.abs(x[side] - x_nom), failed[side]) > 2.0 / np.sqrt(m):
            return False
    return True


def _oriented(box: UncertaintyBox, points: np.ndarray, sides: Sequence[str]) -> np.ndarray:
    """Unit coordinates, each axis oriented so that failure lies at large values."""
    unit = box.to_unit(np.asarray(points, dtype=np.float64).reshape(-1, box.ndim))
    return np.where(np.array(sides) == "below", 1.0 - unit, unit)


def _region_of_cut(box: UncertaintyBox, cut: np.ndarray, sides: Sequence[str],
                   low: np.ndarray | None = None) -> dict[str, tuple[float, float]]:
    """The region of oriented unit coordinates [``low``, ``cut``] (``low`` 0 where None)."""
    low = np.zeros(box.ndim) if low is None else low
    region = {}
    for j, p in enumerate(box.parameters):
        lo_u, hi_u = (low[j], cut[j]) if sides[j] != "below" else (1.0 - cut[j], 1.0 - low[j])
        pts = box.from_unit(np.array([[lo_u if i == j else 0.5 for i in range(box.ndim)],
                                      [hi_u if i == j else 0.5 for i in range(box.ndim)]]))
        region[p.name] = (float(np.clip(pts[0, j], p.low, p.high)),
                          float(np.clip(pts[1, j], p.low, p.high)))
    return region


def _blocked_grid(inside_bad: np.ndarray, cands: Sequence[np.ndarray],
                  margin: float) -> np.ndarray:
    """For the grid of two-parameter cuts ``cands[0] × cands[1]`` (row-major), whether a bad
    point lies inside the box up to each cut: per first cut, the lowest second coordinate
    among the bad points inside it in the first, compared with each second cut (the same
    comparisons as point by point, in O(grid + points · first cuts))."""
    shift, inside = _inside_test(margin)
    t0, t1 = (c + shift for c in cands)
    first = inside(inside_bad[None, :, 0], t0[:, None])
    low = np.where(first, inside_bad[None, :, 1], np.inf).min(axis=1, initial=np.inf)
    return inside(low[:, None], t1[None, :]).reshape(-1)


def _inside_test(margin: float) -> tuple[float, np.ufunc]:
    """How :func:`_best_cut` tests a bad point against a cut, per coordinate: (shift of the
    cut, comparison): strictly below it without a margin, else at most ``margin`` (less a
    hair) above it."""
    if margin > 0:
        return margin * (1 - 1e-9), np.less_equal
    return 0.0, np.less


def _best_cut(bad: np.ndarray, a: np.ndarray, b: np.ndarray, margin: float,
              extra: np.ndarray | None = None) -> np.ndarray | None:
    """The upper cuts c (a < c ≤ b) of the largest box [a, c] (oriented unit coordinates)
    that keeps every ``bad`` point (q, k) out: strictly outside without a margin (a point on
    the face is allowed), else at least ``margin`` away. The cuts are chosen among the bad
    points' coordinates minus ``margin`` and the coordinates of ``extra`` points (r, k).
    None when no such box exists."""
    k = a.size
    inside_bad = bad[(bad >= a - 1e-12).all(axis=1)] if bad.size else bad.reshape(0, k)
    if inside_bad.shape[0] == 0:
        return b.copy()
    cands = []
    for j in range(k):
        c = inside_bad[:, j] - margin
        if extra is not None and extra.size:
            c = np.concatenate([c, extra[:, j]])
        c = np.unique(np.concatenate([[b[j]], c[(c > a[j]) & (c < b[j])]]))
        if c.size > 64:
            c = np.unique(np.concatenate([[b[j]], np.quantile(c, np.linspace(0, 1, 63),
                                                              method="lower")]))
        cands.append(c)

    shift, inside_of = _inside_test(margin)

    def blocked(cuts: np.ndarray) -> np.ndarray:
        inside = inside_of(inside_bad[None, :, :], cuts[:, None, :] + shift)
        return inside.all(axis=2).any(axis=1)

    if k <= 2:
        grids = np.meshgrid(*cands, indexing="ij")
        cuts = np.stack([g.reshape(-1) for g in grids], axis=1)
        vol = np.prod(cuts - a, axis=1)
        vol[_blocked_grid(inside_bad, cands, margin) if k == 2 else blocked(cuts)] = -1.0
        i = int(np.argmax(vol))
        return cuts[i] if vol[i] > 0 else None
    # k > 2: one bad point at a time, the (point, axis) cut that keeps the most volume (a
    # cut of one axis below every bad point keeps the least: the region became a sliver
    # of whichever parameter's bad points lay lowest)
    cut = b.copy()
    for _ in range(inside_bad.shape[0]):
        inside = inside_bad[inside_of(inside_bad, cut + shift).all(axis=1)]
        if inside.shape[0] == 0:
            break
        values = np.minimum(inside - margin, cut)  # (q, k): the cut that puts p out on j
        kept = np.where(values > a, (values - a) / (cut - a), -1.0)
        p, j = np.unravel_index(int(np.argmax(kept)), kept.shape)
        if kept[p, j] <= 0:
            return None
        cut[j] = values[p, j]
    # then each face out again as far as the bad points the others keep out allow (an early
    # cut may have been made redundant by a later one)
    for j in range(k):
        others = np.arange(k) != j
        held = inside_of(inside_bad[:, others], cut[others] + shift).all(axis=1)
        cut[j] = min(b[j], float((inside_bad[held, j] - margin).min(initial=np.inf)))
    if blocked(cut[None])[0]:
        return None
    return cut


def safe_subbox(samples: np.ndarray, failed: np.ndarray, box: UncertaintyBox,
                sides: Sequence[str], *, margin: float = 0.0
                ) -> dict[str, tuple[float, float]] | None:
    """The largest (prior volume) sub-box anchored at the box's safe corner with no failure.

    Each parameter keeps its safe end (the one opposite its failing side) and gets a cut
    chosen among the failing samples' coordinates (minus ``margin``); with k ≤ 2 every pair
    of cuts is tried, above that the cuts shrink one coordinate at a time. A parameter that
    fails on both sides of its nominal value (side "both") gets both faces cut: its low
    face is tried at the box's low end and just above each failing sample below the
    nominal value (at most 64 places, spread in quantiles; 16 each for two or more such
    parameters), its high face as a one-sided parameter's.

    Args:
        samples: parameter samples, (n, k).
        failed: which samples fail, (n,).
        box: the uncertainty box.
        sides: per parameter, "above" (large values fail), "below" or "both".
        margin: distance kept from each failing sample, in the unit (prior-quantile)
            coordinates: 0 lets a failing sample lie on the region's edge.

    Returns:
        {name: (low, high)}, or None when even the safe corner's neighbourhood fails.
    """
    u = _oriented(box, samples, sides)
    bad = u[np.asarray(failed, dtype=bool)]
    margin = float(margin)
    both = [j for j, side in enumerate(sides) if side == "both"]
    ones = np.ones(box.ndim)
    if not both:
        cut = _best_cut(bad, np.zeros(box.ndim), ones, margin)
        return None if cut is None else _region_of_cut(box, cut, sides)
    u_nom = box.to_unit(np.asarray(box.nominal, dtype=np.float64)[None])[0]
    most = 64 if len(both) == 1 else 16
    lows = []
    for j in both:
        c = bad[:, j] + margin
        c = np.unique(np.concatenate([[0.0], c[(bad[:, j] < u_nom[j]) & (c <= u_nom[j])]]))
        if c.size > most:
            c = np.unique(np.concatenate([[0.0], np.quantile(c, np.linspace(0, 1, most - 1),
                                                             method="lower")]))
        lows.append(c)
    best, best_vol = None, 0.0
    for low in itertools.product(*lows):
        a = np.zeros(box.ndim)
        a[both] = low
        # a failing sample at or under a low face is out of the region
        out = (bad[:, both] <= a[both] - margin + 1e-12).any(axis=1)
        cut = _best_cut(bad[~out], a, ones, margin)
        if cut is None:
            continue
        vol = float(np.prod(cut - a))
        if vol > best_vol:
            best, best_vol = (a, cut), vol
    return None if best is None else _region_of_cut(box, best[1], sides, best[0])


def candidate_region(samples: np.ndarray, failed: np.ndarray, box: UncertaintyBox,
                     sides: Sequence[str], moments: Sequence[MomentReport] = (), *,
                     margin: float = 0.0) -> dict[str, tuple[float, float]] | None:
    """The region to check: :func:`safe_subbox`, none when no sample passes, and cut where a
    critical value (the others at nominal, inside the region) says the motion fails.

    A moment whose failures are all unlifted ones (``squeeze``) does not cut: rollouts
    decide those.
    """
    failed = np.asarray(failed, dtype=bool)
    if failed.size == 0 or failed.all():
        return None
    region = safe_subbox(samples, failed, box, sides, margin=margin)
    if region is None:
        return None
    nominal = dict(zip(box.names, map(float, box.nominal), strict=True))
    for mr in moments:
        if mr.squeeze:
            continue
        for name in box.names:
            value, side = mr.critical.get(name), mr.critical_side.get(name)
            if value is None or side is None:
                continue
            others_inside = all(region[q][0] <= nominal[q] <= region[q][1]
                                for q in box.names if q != name)
            if not others_inside:
                continue
            lo, hi = region[name]
            if side == "above" and value < hi:
                hi = value
            elif side == "below" and value > lo:
                lo = value
            if hi <= lo:
                return None
            region[name] = (lo, hi)
    return region


def round_inward(region: Mapping[str, tuple[float, float]] | None, box: UncertaintyBox, *,
                 digits: int = 3) -> dict[str, tuple[float, float]] | None:
    """The region with each cut bound rounded to ``digits`` significant digits towards its
    inside, so that the stated numbers are the checked ones; the box's own ends stay."""
    if region is None:
        return None
    out = {}
    for p in box.parameters:
        lo, hi = region[p.name]
        # a face at the box's end is the end itself (a log-uniform prior's round trip
        # through its quantiles gave 0.05000000000000001 for 0.05)
        at_end = 1e-9 * (p.high - p.low)
        lo = p.low if abs(lo - p.low) <= at_end else _round(lo, digits, up=True)
        hi = p.high if abs(hi - p.high) <= at_end else _round(hi, digits, up=False)
        if not hi > lo:  # nothing left, or a single value: no region
            return None
        out[p.name] = (float(lo), float(hi))
    return out


def _round(x: float, digits: int, *, up: bool) -> float:
    if x == 0 or not math.isfinite(x):
        return x
    scale = 10.0 ** (digits - 1 - math.floor(math.log10(abs(x))))
    y = (math.ceil(x * scale - 1e-9) if up else math.floor(x * scale + 1e-9)) / scale
    return float(y)


def region_points(region: Mapping[str, tuple[float, float]], box: UncertaintyBox, *,
                  per_edge: int = 5, dense: Sequence[int] = (), factor: int = 4
                  ) -> tuple[np.ndarray, list[np.ndarray]]:
    """Points on the region's corners and edges.

    Args:
        region: {name: (low, high)}.
        box: the box (its parameter order and prior give the spacing).
        per_edge: points per edge, corners included (≥ 2), evenly spaced in prior quantiles.
        dense: indices of the edges (in the returned order) sampled ``factor`` times more
            densely (where the cost came near the threshold).
        factor: the densification.

    Returns:
        (points (p, k), edges): ``edges`` lists, per edge, the rows of ``points`` along it
        in order; the corners are shared rows.
    """
    if per_edge < 2:
        raise ParameterError(f"per_edge: expected >= 2, got {per_edge}")
    k = box.ndim
    lo = np.array([region[n][0] for n in box.names])
    hi = np.array([region[n][1] for n in box.names])
    u_lo, u_hi = box.to_unit(lo[None])[0], box.to_unit(hi[None])[0]
    rows: dict[bytes, int] = {}
    pts: list[np.ndarray] = []

    def add(u: np.ndarray) -> int:
        x = np.clip(box.from_unit(u[None])[0], lo, hi)
        x[u == u_lo] = lo[u == u_lo]
        x[u == u_hi] = hi[u == u_hi]
        key = np.round(x, 12).tobytes()
        if key not in rows:
            rows[key] = len(pts)
            pts.append(x)
        return rows[key]

    edges = []
    dense = set(int(e) for e in dense)
    for j in range(k):
        others = [i for i in range(k) if i != j]
        for corner in np.ndindex(*([2] * len(others))):
            base = u_lo.copy()
            for i, c in zip(others, corner, strict=True):
                base[i] = u_hi[i] if c else u_lo[i]
            edge = []
            n_t = per_edge if len(edges) not in dense else factor * (per_edge - 1) + 1
            for tt in np.linspace(0.0, 1.0, n_t):
                u = base.copy()
                u[j] = u_lo[j] + tt * (u_hi[j] - u_lo[j])
                edge.append(add(u))
            edges.append(np.array(list(dict.fromkeys(edge)), dtype=np.int64))
    if k == 0:
        return np.zeros((0, 0)), []
    return np.array(pts), edges


def within(points: np.ndarray, region: Mapping[str, tuple[float, float]],
           box: UncertaintyBox) -> np.ndarray:
    """(n,) bool: which of ``points`` (n, k) lie in ``region`` (its faces included)."""
    points = np.asarray(points, dtype=np.float64).reshape(-1, box.ndim)
    lo = np.array([region[name][0] for name in box.names])
    hi = np.array([region[name][1] for name in box.names])
    return ((points >= lo) & (points <= hi)).all(axis=1)


def interior_points(region: Mapping[str, tuple[float, float]], box: UncertaintyBox, *,
                    scale: int = 1) -> np.ndarray:
    """Points inside the region, ``scale`` × 2^(k+1) of them (8 for two parameters): the
    first points of an unscrambled Sobol sequence after its origin, spread in prior
    quantiles. A region
    whose corners and edges pass can still fail inside where the outcome is not monotone in
    the parameters (a drop on robosuite's Panda + Robotiq 2F-85 at (0.111 kg, μ 1.33) inside
    a region whose 8 corner and edge points passed).

    Returns:
        (scale × 2^(k+1), k) points, deterministic for a region; the first 2^(k+1) are the
        same for every ``scale`` (a power of two).
    """
    from scipy.stats import qmc

    k = box.ndim
    if k == 0:
        return np.zeros((0, 0))
    if scale < 1 or scale & (scale - 1):
        raise ParameterError(f"scale: expected a power of two >= 1, got {scale!r}")
    n = scale * 2 ** (k + 1)
    u = qmc.Sobol(d=k, scramble=False).random_base2(int(np.log2(n)) + 1)[1:n + 1]
    lo = np.array([region[name][0] for name in box.names])
    hi = np.array([region[name][1] for name in box.names])
    u_lo, u_hi = box.to_unit(lo[None])[0], box.to_unit(hi[None])[0]
    return np.clip(box.from_unit(u_lo + u * (u_hi - u_lo)), lo, hi)


def hot_edges(edges: Sequence[np.ndarray], cost: np.ndarray, *, near: float) -> list[int]:
    """Indices of the edges with a point whose cost is at or above ``near`` (a failure, a
    divergence or an unknown cost counts too): where the check is densified.

    Args:
        edges: per edge, the rows of the checked points along it.
        cost: each point's highest sparse cost, (p,) (+inf where diverged, NaN unknown).
        near: the cost from which an edge is densified.
    """
    hot = ~(np.nan_to_num(np.asarray(cost, dtype=np.float64), nan=np.inf) < near)
    return [i for i, e in enumerate(edges) if hot[e].any()]


#: at most this many parameters failing at both ends get their faces chosen by a passing
#: corner in :func:`shrink_region` (2**n orientations tried); more move any face greedily
MAX_BOTH_FACES = 4


def shrink_region(region: Mapping[str, tuple[float, float]], failing: np.ndarray,
                  box: UncertaintyBox, sides: Sequence[str], *, margin: float = 0.01,
                  passing: np.ndarray | None = None) -> dict[str, tuple[float, float]] | None:
    """The largest sub-box of ``region`` with its failing-side faces moved in until it keeps
    ``margin`` (unit, prior-quantile coordinates) from every failing check point.

    With ``passing``, the new region's worst corner (the one at the failing-side faces) is
    the checked point that passed and gives the largest region keeping ``margin`` from
    every failing point: the faces then land where the check found the motion passing,
    not just past a failure on a boundary that runs across them. Without one, the faces
    move to ``margin`` inside the failing points.

    Args:
        region: {name: (low, high)}.
        failing: the failing check points, (q, k).
        box: the box.
        sides: per parameter, the failing side ("above"/"below"/"both"). A "both"
            parameter's worst corner is taken on the side of its nominal value where the
            failing points lie (both sides tried where they lie on both, for at most
            ``MAX_BOTH_FACES`` such parameters); where no passing corner keeps them out, any
            face may move (:func:`_any_face_cut`).
        margin: distance kept from each failing point.
        passing: the check points that passed, (r, k), or None.

    Returns:
        The shrunk region, or None when no sub-box is left.
    """
    lo = np.array([region[n][0] for n in box.names], dtype=np.float64)
    hi = np.array([region[n][1] for n in box.names], dtype=np.float64)
    if "both" in sides:
        # a parameter failing on both sides of its nominal value: one of its faces moves,
        # whichever gives a passing corner the most room (the failures of the round can all
        # lie on one side: a dragged cube's friction fails at both ends of the box, but the
        # shrunk region's failing corner at its high end only); else any face may move
        both = [j for j, side in enumerate(sides) if side == "both"]
        # each such parameter's worst corner lies on the side of its nominal value where the
        # failing points are (a corner on the other side, the friction's low face when the
        # failures lie at its high one, would leave the failing corner unchecked)
        u_nom = box.to_unit(np.asarray(box.nominal, dtype=np.float64)[None])[0]
        u_bad = box.to_unit(np.asarray(failing, dtype=np.float64).reshape(-1, box.ndim))
        choices = [[face for face, on in (("above", u_bad[:, j] > u_nom[j]),
                                          ("below", u_bad[:, j] <= u_nom[j])) if on.any()]
                   for j in both]
        best = None
        for faces in itertools.product(*choices) if len(both) <= MAX_BOTH_FACES else ():
            one_sided = list(sides)
            for j, face in zip(both, faces, strict=True):
                one_sided[j] = face
            found = _passing_corner(lo, hi, failing, box, one_sided, margin, passing)
            if found is not None and (best is None or found[1] > best[2]):
                best = (one_sided, found[0], found[1])
        if best is None:
            return _any_face_cut(lo, hi, failing, box, float(margin), passing)
        return _region_below_cut(lo, hi, best[1], box, best[0])
    found = _passing_corner(lo, hi, failing, box, sides, margin, passing)
    cut = None if found is None else found[0]
    a, b = _oriented_faces(lo, hi, box, sides)
    if cut is None:
        bad = _oriented(box, failing, sides)
        cut = _best_cut(bad, a, b, float(margin))
    if cut is None:
        # a failure on a face the failing sides keep (failures at both ends of a
        # parameter): move any face
        return _any_face_cut(lo, hi, failing, box, float(margin), passing)
    if box.ndim >= 3 and float(np.max(b - cut)) <= 3.0 * margin:
        # three or more parameters, only a hair past the failing points (no passing corner
        # clean of them: failures along a whole face): the next round would fail just
        # inside; faces move half way to the nearest passing point instead, so that the
        # rounds converge. (With two, a failing corner on a diagonal boundary moves along
        # it by the passing corners; half-way moves of one face there did not converge on
        # the demo's seed 5.)
        moved = _any_face_cut(lo, hi, failing, box, float(margin), passing)
        if moved is not None:
            return moved
    return _region_below_cut(lo, hi, cut, box, sides)


def _oriented_faces(lo: np.ndarray, hi: np.ndarray, box: UncertaintyBox,
                    sides: Sequence[str]) -> tuple[np.ndarray, np.ndarray]:
    """The region [lo, hi] in oriented unit coordinates (failure at large values): (a, b)."""
    orient = np.array(sides) == "below"
    u_lo, u_hi = box.to_unit(lo[None])[0], box.to_unit(hi[None])[0]
    return np.where(orient, 1.0 - u_hi, u_lo), np.where(orient, 1.0 - u_lo, u_hi)


def _passing_corner(lo: np.ndarray, hi: np.ndarray, failing: np.ndarray, box: UncertaintyBox,
                    sides: Sequence[str], margin: float, passing: np.ndarray | None
                    ) -> tuple[np.ndarray, float] | None:
    """The checked point that passed and, as the new worst corner of [lo, hi] (``sides``
    one-sided), gives the largest region keeping ``margin`` from every failing point:
    (its oriented unit coordinates, the region's volume there), or None."""
    if passing is None or not np.size(passing):
        return None
    a, b = _oriented_faces(lo, hi, box, sides)
    bad = _oriented(box, failing, sides)
    corners = np.clip(_oriented(box, passing, sides), a, b)
    corners = corners[(corners > a + 1e-12).all(axis=1)]
    if not corners.shape[0]:
        return None
    inside = (bad[None, :, :] >= a - 1e-12) & (bad[None, :, :] <= corners[:, None, :] + margin)
    clean = ~inside.all(axis=2).any(axis=1)
    if not clean.any():
        return None
    vol = np.where(clean, np.prod(corners - a, axis=1), -1.0)
    i = int(np.argmax(vol))
    return corners[i], float(vol[i])


def _region_below_cut(lo: np.ndarray, hi: np.ndarray, cut: np.ndarray, box: UncertaintyBox,
                      sides: Sequence[str]) -> dict[str, tuple[float, float]]:
    """[lo, hi] with its failing-side faces (``sides`` one-sided) moved to ``cut`` (oriented
    unit coordinates); a face the cut does not move keeps its exact value."""
    orient = np.array(sides) == "below"
    _, b = _oriented_faces(lo, hi, box, sides)
    out = {}
    for j, p in enumerate(box.parameters):
        if np.isclose(cut[j], b[j], rtol=0, atol=1e-12):
            out[p.name] = (float(lo[j]), float(hi[j]))
            continue
        u_cut = 1.0 - cut[j] if orient[j] else cut[j]
        x = box.from_unit(np.where(np.arange(box.ndim) == j, u_cut, 0.5)[None])[0, j]
        x = float(np.clip(x, lo[j], hi[j]))
        out[p.name] = (x, float(hi[j])) if orient[j] else (float(lo[j]), x)
    return out


def _any_face_cut(lo: np.ndarray, hi: np.ndarray, failing: np.ndarray, box: UncertaintyBox,
                  margin: float, passing: np.ndarray | None = None
                  ) -> dict[str, tuple[float, float]] | None:
    """The region [lo, hi] cut, face by face, until every failing point is outside it: each
    cut moves one face, low or high, of one parameter past a failing point on it, half way
    (in prior quantiles; at least ``margin``) towards the nearest checked point that passed
    inside, or the opposite face; of the possible cuts, the one that keeps the most volume.
    Greedy, for failures at both ends of a parameter, where the failing sides' cut finds
    none; the next round of the check verifies what it leaves. None when nothing is left."""
    start_lo = box.to_unit(lo[None])[0].astype(np.float64)
    start_hi = box.to_unit(hi[None])[0].astype(np.float64)
    u_lo, u_hi = start_lo.copy(), start_hi.copy()
    bad = box.to_unit(np.asarray(failing, dtype=np.float64).reshape(-1, box.ndim))
    good = (np.zeros((0, box.ndim)) if passing is None or not np.size(passing) else
            box.to_unit(np.asarray(passing, dtype=np.float64).reshape(-1, box.ndim)))
    tol = 1e-12
    # the nominal parameters stay inside where a cut can keep them: of two cuts that each
    # clear a failing point, the one through the parameter the failure is at the end of,
    # not a face at the nominal's end of another (a four-parameter box failing where the
    # CoM offset reaches ±2 cm was cut at grip ≤ 34.7 N of a rated and nominal 35 N)
    u_nom = box.to_unit(np.asarray(box.nominal, dtype=np.float64)[None])[0]

    def keeps_nominal(new_lo: np.ndarray, new_hi: np.ndarray) -> bool:
        return bool(((u_nom >= new_lo - tol) & (u_nom <= new_hi + tol)).all())

    for _ in range(bad.shape[0]):
        inside = bad[((bad >= u_lo - tol) & (bad <= u_hi + tol)).all(axis=1)]
        if inside.shape[0] == 0:
            break
        best, best_key = None, (False, -1.0)
        for f in inside:
            for j in range(box.ndim):
                below = good[:, j][good[:, j] < f[j] - tol]
                above = good[:, j][good[:, j] > f[j] + tol]
                to_lo = f[j] - max(below.max(initial=u_lo[j]), u_lo[j])
                to_hi = min(above.min(initial=u_hi[j]), u_hi[j]) - f[j]
                for face, value in ((1, f[j] - max(margin, 0.5 * to_lo)),
                                    (0, f[j] + max(margin, 0.5 * to_hi))):
                    new_lo, new_hi = u_lo.copy(), u_hi.copy()
                    (new_hi if face else new_lo)[j] = value
                    if not (new_hi[j] - new_lo[j] > tol):
                        continue
                    key = (keeps_nominal(new_lo, new_hi), float(np.prod(new_hi - new_lo)))
                    if key > best_key:
                        best, best_key = (new_lo, new_hi), key
        if best is None:
            return None
        u_lo, u_hi = best
    if ((bad >= u_lo - tol) & (bad <= u_hi + tol)).all(axis=1).any():
        return None
    x_lo, x_hi = box.from_unit(u_lo[None])[0], box.from_unit(u_hi[None])[0]
    out = {}
    for j, p in enumerate(box.parameters):
        # a face that did not move keeps its exact value
        a = lo[j] if u_lo[j] == start_lo[j] else float(np.clip(x_lo[j], lo[j], hi[j]))
        b = hi[j] if u_hi[j] == start_hi[j] else float(np.clip(x_hi[j], lo[j], hi[j]))
        out[p.name] = (float(a), float(b))
    return out


@dataclasses.dataclass(frozen=True, eq=False)
class RegionCheck:
    """The check of a safe region on its corners, edges and inside.

    Attributes:
        region: the region that holds, {name: (low, high)}, or None when none does.
        points: the points checked in the last (holding) round, (p, k).
        failed: their decision (sparse evaluation, then their own runs: the one decision
            path of the sweep's samples), (p,) bool.
        rolled_out: which of them have their own full rollout, (p,) bool.
        rounds: check-and-shrink rounds.
        n_sparse: points evaluated by sparse evaluation over every round.
        n_rollouts: full rollouts over every round.
        first_claim: the region first claimed (before any shrinking), or None.
        n_chained: points carried on their own state through the moments (chained
            segments, each its own run from the start) over every round.
        chained: which points of the last round were chained, (p,) bool, or None.
        known_inside: the sweep's samples inside the region that passed on their own runs;
            they count among its inside points (fewer new ones are checked).
    """

    region: Mapping[str, tuple[float, float]] | None
    points: np.ndarray
    failed: np.ndarray
    rolled_out: np.ndarray
    rounds: int
    n_sparse: int
    n_rollouts: int
    first_claim: Mapping[str, tuple[float, float]] | None = None
    n_chained: int = 0
    chained: np.ndarray | None = None
    known_inside: int = 0

    @property
    def own_runs(self) -> int:
        """Points of the last round decided on their own run (full rollout or chain)."""
        own = np.asarray(self.rolled_out, dtype=bool)
        if self.chained is not None:
            own = own | np.asarray(self.chained, dtype=bool)
        return int(own.sum())

    @property
    def holds(self) -> bool:
        return self.region is not None and not self.failed.any()

    @property
    def shrunk(self) -> bool:
        return self.first_claim is not None and dict(self.first_claim) != (
            dict(self.region) if self.region is not None else None)

    def to_json(self) -> dict:
        return {"region": (None if self.region is None else
                           {k: [float(a), float(b)] for k, (a, b) in self.region.items()}),
                "first_claim": (None if self.first_claim is None else
                                {k: [float(a), float(b)]
                                 for k, (a, b) in self.first_claim.items()}),
                "holds": self.holds, "rounds": self.rounds,
                "points": int(self.points.shape[0]), "sparse": self.n_sparse,
                "rollouts": self.n_rollouts, "chained": self.n_chained,
                "rollouts_last_round": int(self.rolled_out.sum()),
                "own_runs_last_round": self.own_runs, "known_inside": self.known_inside}


@dataclasses.dataclass(frozen=True, eq=False)
class Evidence:
    """Everything :func:`decide` needs, computed before (no simulation in the decision).

    Attributes:
        box: the uncertainty box.
        samples: the sweep's evidence (sparse results, the rollouts' outcomes).
        nominal_cost: highest sparse cost at the nominal parameters over the moments.
        nominal_failed: the sparse evaluation of the nominal parameters fails at a moment
            (``SparseResult.failed_any``).
        nominal_unlifted: the nominal parameters fail only through unlifted failures.
        nominal_stage: (highest stage reached, final stage) of the nominal run.
        moments: per audited moment, what was found there.
        worst_failed: per moment step, whether its worst case fails there (sparse).
        worst_unlifted: per moment step whose worst case fails, whether only its own
            rollout decides it (:meth:`DecisionOptions.only_a_rollout_decides`: unlifted
            or sticking, as the options say).
        worst_rollouts_failed: per moment step whose worst case got its own rollout, its
            real outcome (failed).
        region: the check of the safe region, or None when it was not checked.
        completion_rule: the task's completion rule in words, for the causes.
        trend: per parameter, how much the cost grows from its low to its high end along
            the 1-D curves with the others at nominal (summed over the moments), or None
            (see :func:`fail_sides`).
        own_failures: how the samples decided by their own full rollout failed, per
            outcome (``groundtruth.Outcome`` value): (how many, earliest failure time [s] or
            None, the actuators of the motor failures); for the causes.
        chain_failures: how the failures the chained segments decided failed, per kind
            (``history.ChainedResult.kinds``): how many; for the causes.
        own_failure_points, chain_failure_points: per key of ``own_failures`` and of
            ``chain_failures``, the (k, d) parameter values of the samples that failed that
            way; the causes say where in the box they lie.
        nominal_run_failure: how the nominal run itself fails by the ground truth's rules
            other than the task's (a motor held at its limit, a divergence), in words, or
            None: it fails the nominal parameters.
    """

    box: UncertaintyBox
    samples: SampleEvidence
    nominal_cost: float
    nominal_failed: bool = False
    nominal_unlifted: bool = False
    nominal_stage: tuple[int, int] = (4, 4)
    moments: tuple[MomentReport, ...] = ()
    worst_failed: Mapping[int, bool] = dataclasses.field(default_factory=dict)
    worst_unlifted: Mapping[int, bool] = dataclasses.field(default_factory=dict)
    worst_rollouts_failed: Mapping[int, bool] = dataclasses.field(default_factory=dict)
    region: RegionCheck | None = None
    completion_rule: str = "stage 4 needed and kept to the end"
    trend: Mapping[str, float] | None = None
    own_failures: Mapping[str, tuple[int, float | None, tuple[str, ...]]] = (
        dataclasses.field(default_factory=dict))
    chain_failures: Mapping[str, int] = dataclasses.field(default_factory=dict)
    own_failure_points: Mapping[str, np.ndarray] = dataclasses.field(default_factory=dict)
    chain_failure_points: Mapping[str, np.ndarray] = dataclasses.field(default_factory=dict)
    nominal_run_failure: str | None = None
    #: the task's stage names, for the causes (stage 0 is "untouched", ...)
    stage_names: tuple[str, ...] = ()

    def sides(self, failed: np.ndarray) -> list[str]:
        """The failing side of each parameter (:func:`fail_sides`) for these failures."""
        samples = (self.samples.sweep.samples if self.samples.sweep is not None
                   else np.zeros((0, self.box.ndim)))
        return fail_sides(samples, failed, self.box,
                          [mr.critical_side for mr in self.moments if not mr.squeeze],
                          self.trend)


@dataclasses.dataclass(frozen=True, eq=False)
class Decision:
    """The audit's decision.

    Attributes:
        verdict: SAFE, CONDITIONAL or UNSAFE.
        failed: per sample of the sweep, whether it fails, (n,) bool.
        p_success: fraction of the samples that pass (0 when the nominal run fails the
            task).
        p_success_interval: Wilson interval of ``p_success``.
        safe_region: the checked region that holds, or None.
        safe_region_text: the region in words, with its evidence.
        causes: the failure causes, in words.
        region_to_check: the region the evidence must check before the region can be
            stated (the whole box for a SAFE candidate), or None when there is none or
            ``evidence.region`` checked it.
        near: samples re-run because their cost was near the threshold, (n,) bool.
        unlifted: samples re-run because they failed only unlifted, (n,) bool.
        sticking: samples re-run because they failed only sticking, (n,) bool.
        slipping: samples re-run because they failed only by short slips, (n,) bool.
        margin: samples re-run because they failed only by the cost's margin with every
            motor under its limit, (n,) bool.
    """

    verdict: Verdict
    failed: np.ndarray
    p_success: float
    p_success_interval: tuple[float, float]
    safe_region: Mapping[str, tuple[float, float]] | None
    safe_region_text: str
    causes: tuple[str, ...]
    region_to_check: Mapping[str, tuple[float, float]] | None
    near: np.ndarray
    unlifted: np.ndarray
    sticking: np.ndarray
    slipping: np.ndarray
    margin: np.ndarray


def _nominal_fails(evidence: Evidence, options: DecisionOptions) -> tuple[bool, bool, bool]:
    """(nominal fails, nominal squeeze only, task failed)."""
    se = evidence.samples
    has_moments = se.sweep is not None and se.sweep.n_moments > 0
    task_failed = options.require_task and not se.nominal_completed
    # the nominal parameters have their own full run, the recording: where it completes the
    # task, it decides them (a sparse excursion there is contact chatter, or a squeeze
    # without a lift, that the real run survived)
    squeeze = (options.verify is not None and has_moments and evidence.nominal_failed
               and se.nominal_completed
               and (evidence.nominal_unlifted or not options.verify_unlifted
                    or options.nominal_by_run))
    # the nominal run's own real outcome: a motor the ground truth's rule fails it by (held
    # at its limit for 50 ms) fails the nominal parameters whatever the task says
    run_failed = options.require_task and evidence.nominal_run_failure is not None
    return ((evidence.nominal_failed and not squeeze) or task_failed or run_failed,
            squeeze and not run_failed, task_failed)


def _worst_cases_pass(evidence: Evidence, options: DecisionOptions) -> bool:
    steps = [mr.step for mr in evidence.moments if evidence.worst_failed.get(mr.step, False)]
    if not steps:
        return True
    if not options.rolls_squeezes or not all(evidence.worst_unlifted.get(s, False)
                                             for s in steps):
        return False
    return all(s in evidence.worst_rollouts_failed and not evidence.worst_rollouts_failed[s]
               for s in steps)


def decide(evidence: Evidence, options: DecisionOptions) -> Decision:
    """The verdict, P(success), the safe region and the causes from the evidence.

    Pure: call it once without ``evidence.region`` to learn the region to check
    (``Decision.region_to_check``), check it, and call it again with the check.

    Args:
        evidence: what the audit measured.
        options: the decision options.

    Returns:
        The :class:`Decision`.
    """
    box = evidence.box
    se = evidence.samples
    n = se.n_samples
    failed = failing_samples(se, options)
    near, unlifted, sticking, slipping, margin, _ = samples_to_rerun(
        se.sweep, options, nominal_completed=se.nominal_completed,
        nominal_failed=se.nominal_failed)
    n_fail = int(failed.sum())
    nominal_fails, nominal_squeeze, task_failed = _nominal_fails(evidence, options)
    if n:
        p = 1.0 - n_fail / n
        interval = wilson_interval(n - n_fail, n, confidence=options.confidence)
    else:
        p, interval = (0.0 if nominal_fails else 1.0), (0.0, 1.0)
    if task_failed and _every_sample_fails(options, se.nominal_completed):
        p = 0.0
        interval = wilson_interval(0, n, confidence=options.confidence) if n else (0.0, 1.0)
    has_moments = se.sweep is not None and se.sweep.n_moments > 0
    candidate = None
    if nominal_fails:
        verdict = Verdict.UNSAFE
    elif n_fail == 0 and _worst_cases_pass(evidence, options):
        verdict = Verdict.SAFE
        candidate = {p_.name: (p_.low, p_.high) for p_ in box.parameters}
    else:
        verdict = Verdict.CONDITIONAL
        if has_moments:
            sweep = se.sweep
            sides = evidence.sides(failed)
            candidate = round_inward(candidate_region(sweep.samples, failed, box, sides,
                                                      evidence.moments), box)
    check = evidence.region
    region = None
    to_check = None
    if candidate is not None:
        if check is None and not has_moments:
            region = candidate  # no moment to check it at: nothing in the box can fail
        elif check is None:
            to_check = candidate
        elif check.holds:
            region = dict(check.region)
    if verdict is Verdict.SAFE and check is not None and not (
            region is not None and _is_whole_box(region, box)):
        verdict = Verdict.CONDITIONAL  # the whole box did not pass its own check
    text = region_text(region, box, verdict, check)
    if verdict is Verdict.CONDITIONAL and region is None and n and failed.all():
        text = f"no safe region: all {n} samples of the box fail"
    causes = tuple(_causes(evidence.moments, options.threshold, box,
                           nominal_completed=evidence.samples.nominal_completed))
    if nominal_squeeze:
        where = ("only where the grip squeezes the object off its support without lifting it"
                 if evidence.nominal_unlifted else "at a moment")
        causes = (f"the nominal cost exceeds the threshold ({evidence.nominal_cost:.3g} > "
                  f"{options.threshold:g}) {where}, but the nominal run itself completes the "
                  f"task, which decides the nominal parameters",) + causes
    elif evidence.nominal_failed:
        causes = (f"fails at the nominal parameters (max cost {evidence.nominal_cost:.3g} > "
                  f"{options.threshold:g})",) + causes
    if evidence.nominal_run_failure is not None and options.require_task:
        causes = (f"the nominal run itself fails: {evidence.nominal_run_failure}",) + causes
    if near.any() and se.rerun_failed is not None:
        near_failed = int(np.asarray(se.rerun_failed, bool)[near].sum())
        if near_failed:
            causes += (f"{near_failed} of {int(near.sum())} samples that pass at the moments "
                       f"with a cost ≥ {options.verify * options.threshold:.3g} fail in their "
                       f"own full rollout (between the moments or by not completing the "
                       f"task); suggestion: reduce the uncertainty near the safe region's "
                       f"edge",)
    own = _own_failures_text(evidence.own_failures, evidence.own_failure_points, box)
    if own:
        causes += (own,)
    if se.chained is not None and has_moments:
        chained = np.asarray(se.chained, dtype=bool)
        chain_failed = int((chained & failed).sum())
        if chain_failed:
            # the moments' lines count only the failures at the moments
            kinds = _kinds_text(evidence.chain_failures, evidence.chain_failure_points,
                                box)
            causes += (f"{chain_failed} of {int(chained.sum())} samples that pass at every "
                       f"audited moment fail on their own path (chained segments, each "
                       f"sample's own run through the moments: "
                       + (kinds if kinds else "a slip, a drop or a motor overload between or "
                          "after them, or the task not completed") + ")",)
    if check is not None and check.shrunk and check.region is not None:
        causes += (f"the safe region first claimed ({_bounds_text(check.first_claim, box)}) "
                   f"failed its check at its corners, edges and inside and was shrunk to "
                   f"{_bounds_text(check.region, box)}",)
    if task_failed:
        reached, final = (f"{n} ({evidence.stage_names[n]})"
                          if 0 <= n < len(evidence.stage_names) else str(n)
                          for n in evidence.nominal_stage)
        causes = (f"the task is not completed at the nominal parameters (stage {reached} "
                  f"reached, final stage {final}; {evidence.completion_rule})",) + causes
    return Decision(verdict=verdict, failed=failed, p_success=float(p),
                    p_success_interval=(float(interval[0]), float(interval[1])),
                    safe_region=region, safe_region_text=text, causes=causes,
                    region_to_check=to_check, near=near, unlifted=unlifted,
                    sticking=sticking, slipping=slipping, margin=margin)


_KIND_WORDS = {"motor": "motor overload", "tracking": "lost tracking (a joint lagged its target)",
               "dropped": "dropped", "slipped": "slipped (or turned) in the grip",
               "diverged": "simulation diverged", "not_completed": "task not completed",
               "moment": "failed a moment on its own state"}


def _kinds_text(counts: Mapping[str, int], points: Mapping[str, np.ndarray] | None = None,
                box: UncertaintyBox | None = None) -> str:
    """``{"motor": 3, "slipped": 1}`` in words: "3 motor overload, 1 slipped (or turned) in the
    grip", each with where in the box its samples lie (:func:`_where_text`)."""
    return ", ".join(f"{k} {_KIND_WORDS.get(kind, kind)}"
                     + _parenthesis(_where_text((points or {}).get(kind), box))
                     for kind, k in counts.items())


def _parenthesis(text: str) -> str:
    return f" ({text})" if text else ""


def _where_text(points: np.ndarray | None, box: UncertaintyBox | None) -> str:
    """Where in the box the samples that failed one way lie, per parameter on one side of
    the nominal: "all at friction ≥ 4.57". A failure of high friction (a cube the fingers
    never let go) and one of low friction (a cube that slips out) read the same otherwise.
    One sample is given whole; parameters whose failures lie on both sides are left out."""
    if points is None or box is None:
        return ""
    pts = np.asarray(points, dtype=float).reshape(-1, box.ndim)
    if not len(pts):
        return ""
    units = [f" {p.unit}" if p.unit else "" for p in box.parameters]
    if len(pts) == 1:
        return "at " + _and([f"{p.name} = {v:.3g}{u}" for p, v, u
                             in zip(box.parameters, pts[0], units, strict=True)])
    parts = []
    for j, (p, u) in enumerate(zip(box.parameters, units, strict=True)):
        lo, hi = float(pts[:, j].min()), float(pts[:, j].max())
        if np.isclose(lo, hi) or p.low == p.high:
            continue
        if lo > p.nominal:
            parts.append(f"{p.name} ≥ {lo:.3g}{u}")
        elif hi < p.nominal:
            parts.append(f"{p.name} ≤ {hi:.3g}{u}")
    return "all at " + _and(parts) if parts else ""


def _own_failures_text(own: Mapping[str, tuple[int, float | None, tuple[str, ...]]],
                       points: Mapping[str, np.ndarray] | None = None,
                       box: UncertaintyBox | None = None) -> str:
    """How the samples decided by their own full rollout failed, in one cause line: the
    failures that no moment shows (a motor overloaded away from the object, a drop between
    the moments) are named by what really happened, and where in the box they lie."""
    if not own:
        return ""
    parts = []
    for outcome, (count, first, actuators) in sorted(own.items(), key=lambda kv: -kv[1][0]):
        what = _KIND_WORDS.get(outcome, outcome)
        detail = []
        if actuators:
            detail.append(", ".join(actuators))
        if first is not None:
            detail.append(f"first at t = {first:.3g} s")
        where = _where_text((points or {}).get(outcome), box)
        if where:
            detail.append(where)
        parts.append(f"{count} {what}" + (f" ({'; '.join(detail)})" if detail else ""))
    total = sum(count for count, _, _ in own.values())
    text = (f"how the {total} sample(s) failing on their own full rollout failed: "
            + ", ".join(parts))
    if "motor" in own:
        text += ("; suggestion: check the named actuators' limits ([limits]) against the "
                 "payload range, or slow the motion where they saturate")
    if "tracking" in own:
        text += ("; suggestion: the named joints could not follow their targets (a servo too "
                 "soft or slow for the motion or the load, or a contact holding the joint "
                 "back): check the servos' gains and what the arm touches there, or slow the "
                 "motion")
    return text


def _is_whole_box(region: Mapping[str, tuple[float, float]], box: UncertaintyBox) -> bool:
    return all(np.isclose(region[p.name][0], p.low) and np.isclose(region[p.name][1], p.high)
               for p in box.parameters)


def _bounds_text(region: Mapping[str, tuple[float, float]] | None, box: UncertaintyBox) -> str:
    if region is None:
        return "none"
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
    return " at ".join(parts) if parts else "the whole box"


def region_text(region: Mapping[str, tuple[float, float]] | None, box: UncertaintyBox,
                verdict: Verdict, check: RegionCheck | None = None) -> str:
    """The safe region in words, with the evidence that checked it."""
    if verdict is Verdict.UNSAFE:
        return "no safe region: fails at the nominal parameters"
    evidence = ""
    if check is not None and region is not None:
        p, own = int(check.points.shape[0]), check.own_runs
        rolled = int(np.asarray(check.rolled_out, dtype=bool).sum())
        runs = ", ".join(part for part in (
            f"{own - rolled} chained through the moments" if own > rolled else "",
            f"{rolled} full rollout{'s' if rolled != 1 else ''}" if rolled else "") if part)
        where = "its corners, edges and inside"
        known = int(getattr(check, "known_inside", 0))
        if known:
            runs += (f"; and the sweep's {known} sample{'s' if known != 1 else ''} inside it "
                     f"passed on {'their' if known != 1 else 'its'} own run{'s' if known != 1 else ''}")
        if own == p:
            evidence = (f" (checked at {p} points of {where} by sparse evaluation and on "
                        f"each point's own run: {runs})")
        elif own:
            evidence = (f" (checked at {p} points of {where} by sparse evaluation, {own} of "
                        f"them (its corners, its edges' coarse points, the points inside and "
                        f"those near the threshold) also on their own run: {runs})")
        else:
            evidence = (f" (checked at {p} points of {where} by sparse evaluation only)")
    if region is None:
        if check is not None and check.first_claim is not None:
            return (f"no safe region: every sub-box tried failed its check at its corners, "
                    f"edges and inside ({check.n_sparse} sparse evaluations, {check.n_chained} chained runs, "
                    f"{check.n_rollouts} full rollouts)")
        return ("no safe region: no sub-box at the box's safe corner is free of failing "
                "samples")
    words = _bounds_text(region, box)
    if words == "the whole box":
        return "safe over the whole box" + evidence
    return "safe for " + words + evidence + _nominal_outside(region, box)


def _nominal_outside(region: Mapping[str, tuple[float, float]], box: UncertaintyBox) -> str:
    """Where the stated region leaves out the nominal values, a clause that says so: a
    checked box of passing points need not hold them all (a Google Robot's "0.149 ≤ mass
    ≤ 0.206 kg at friction ≥ 1.48" beside its passing nominal 0.05 kg, friction 1)."""
    out = [f"{p.name} = {p.nominal:.3g}{' ' + p.unit if p.unit else ''}"
           for p in box.parameters
           if not region[p.name][0] - 1e-12 <= p.nominal <= region[p.name][1] + 1e-12]
    if not out:
        return ""
    return (f"; it leaves out the nominal {_and(out)}: the region is one box checked to hold, "
            f"not every passing point")


_SUGGEST = {
    "contact": ("grip slip", "reduce the uncertainty of {box}, grip differently (more pad "
                "contact, more grip force), or lift more slowly"),
    "motor": ("motor overload", "slow down, carry the object closer to the arm's base, reduce "
              "the uncertainty of {box}, or push the object instead of lifting it"),
    "diverged": ("simulation diverged", "check the model and the trajectory near this moment"),
}
#: how a suggestion names a parameter of each kind (:data:`critmoment.params.PARAMETER_KINDS`)
_PARAMETER_WORDS = {"mass": "mass", "friction": "friction", "com_offset": "centre of mass",
                    "force_limit": "force limit"}


def _box_words(box: UncertaintyBox | None) -> str:
    """The box's parameters as a suggestion names them: "the object's mass and friction",
    "joint2's force limit", ..."""
    if box is None:
        return "the uncertain parameters"
    kinds = [kind_of(p) for p in box.parameters]
    words = [_PARAMETER_WORDS.get(k, p.name) for k, p in zip(kinds, box.parameters, strict=True)]
    targets = {p.target for p in box.parameters}
    if len(targets) == 1 and set(kinds) <= {"mass", "friction", "com_offset"}:  # the object's
        return "the object's " + _and(words)
    return _and([f"{p.target}'s {w}" for p, w in zip(box.parameters, words, strict=True)])


def _and(names: Sequence[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``."""
    return " and ".join(names) if len(names) <= 2 else ", ".join(names[:-1]) + " and " + names[-1]


def _causes(reports: Sequence[MomentReport], threshold: float,
            box: UncertaintyBox | None = None, *, nominal_completed: bool = True) -> list[str]:
    """One line per failure cause (grip slip, overload of one actuator, ...), the moments where
    it limits (with their critical values) and the suggestion.

    A moment counts where sweep samples fail there, where the cost crosses the threshold
    along a critical-value curve, or where the worst case found fails (with a first-failure
    sweep a later moment's failures are hidden behind earlier ones; its critical values and
    worst case still say where it would fail). Where the nominal run does not complete its
    task, no run just past a critical value can refute it (every run there starts on the
    nominal's failing path), so the values are given as sparse evaluation's, unchecked (a
    low-cost robot arm whose nominal drops the cube had "fails for mass above 2.57 kg").
    """
    units = {p.name: f" {p.unit}" if p.unit else "" for p in box.parameters} if box else {}
    groups: dict[str, list[str]] = {}
    for mr in reports:
        crossed = any(v is not None for v in mr.critical.values())
        worst = mr.worst_fails if mr.worst_fails is not None else mr.max_cost > threshold
        if mr.dominant is None or mr.overturned or (mr.fail_fraction == 0 and not crossed
                                                    and not worst):
            continue
        name = _SUGGEST[mr.dominant][0]
        if mr.dominant == "motor":
            name = f"{name} at {mr.limiting_actuator}"
        crit = ", ".join(f"{k} {mr.critical_side[k]} {v:.3g}{units.get(k, '')}"
                         for k, v in mr.critical.items() if v is not None)
        # a critical value is where one parameter alone crosses, the others at nominal
        # (elsewhere in the box it can lie elsewhere: the region says where it holds)
        others = " with the others at nominal" if len(mr.critical) > 1 else ""
        if mr.squeeze:
            where = (f" (a squeeze without a lift: sparse evaluation fails "
                     f"{'for ' + crit if crit else 'there'}; the samples' own rollouts decide)")
        elif crit and not nominal_completed:
            where = (f" (sparse evaluation from the failing nominal run's states crosses for "
                     f"{crit}{others}; not checked by own runs)")
        elif crit:
            where = f" (fails for {crit}{others})"
        elif mr.fail_fraction > 0:
            where = f" ({mr.fail_fraction:.0%} of the box)"
        else:
            where = " (at " + ", ".join(f"{k} = {v:.3g}{units.get(k, '')}"
                                        for k, v in mr.worst_case.items()) + ")"
        if mr.critical_refuted:
            where += ("; " + ", ".join(f"{k} {side} {v:.3g}{units.get(k, '')}"
                                       for k, (side, v) in mr.critical_refuted.items())
                      + " by sparse evaluation alone (its full run completes)")
        groups.setdefault(f"{mr.dominant}|{name}", []).append(
            f"{mr.moment.label.value} at t = {mr.moment.time:.2f} s{where}")
    return [f"{key.split('|', 1)[1]}: {'; '.join(where)}; suggestion: "
            f"{_SUGGEST[key.split('|', 1)[0]][1].format(box=_box_words(box))}"
            for key, where in groups.items()]

