"""Ground truth: the real outcome of whole-trajectory rollouts, below the audit.

For every parameter sample of the uncertainty box, :func:`brute_force` re-runs the *whole*
trajectory with that sample's physics (batched through :func:`critmoment.recording.simulate`,
i.e. ``mujoco.batch.Batch.rollout`` on all threads) and :func:`classify` names the real
outcome (:class:`Outcome`) from the task's success rule and plain kinematics (contacts, the
object's displacement in the holding gripper, joint tracking, actuator saturation): never
from the audit's cost. :func:`rerun_in_full` is the audit's verification, which decides the
samples sparse evaluation cannot decide by their own rollout.

This module sits below the audit (:mod:`critmoment.analysis` imports it) and below the
validation study (:mod:`critmoment.validation`, which compares the audit's decisions with
these outcomes); it imports neither.

Outcomes (the definitions, with the tolerances of :class:`OutcomeCriteria`):

* ``DIVERGED``: the sample's simulation diverged (MuJoCo warning or non-finite readings).
* ``MOTOR``: a motor-checked actuator's force (``Twin.motors``: the arm's hinges and
  slides, not a gripper's fingers) stays at its limit (|force| ≥ ``saturation`` × limit) for longer than
  ``motor_time``, or its joint lags its target by more than the nominal run does, by over
  ``tracking_tolerance`` (``tracking_tolerance_slide`` for a slide), for longer than
  ``tracking_time`` —
  unless this happens only after the object was dropped (then it is a consequence).
* ``DROPPED``: the task is not completed and, for longer than ``drop_time``, the object is not
  carried (touches the support, or no gripper) at steps where the nominal run carries it; the
  drop is the last such loss (an earlier one, a late lift, was recovered from). Not a run
  that ends with the object still carried where the nominal run has let it go: that one was
  never released (``NOT_COMPLETED``), whatever it touched on the way; nor a run whose object
  is never lifted by the task's rule (``Task.lifted``): it was never picked up; nor one whose
  object a gripper touches at every step from the loss until the nominal run's last carried
  step: set down in the grip, not dropped. Also, task
  completed or not, a fall: at a step where the nominal run carries it, the object lies on a
  support, or at rest on anything (:func:`resting`), touched by no gripper, having fallen
  more than ``fall_height`` since a gripper last touched it (:func:`fall_steps`; a catch at a hand-over touches no support, an object set
  down early is still touched).
* ``SLIPPED``: the object moved in a holding gripper by more than ``slip_tolerance`` for
  longer than ``slip_time`` (see :func:`grip_slip`): the farthest of its points
  (:attr:`~critmoment.twin.Twin.grip_points`: a turn in the grip moves its ends) in the frame
  of the gripper's base body, along the pads (the fingers' closing axes removed: squeezing is not
  slip), counted from the step both the sample and the nominal run first hold it with that
  gripper, minus the nominal run's own displacement, at steps where the nominal run holds it
  with that gripper alone and not in the release that ends its hold (an object moves in a
  gripper that lets go: that is the release; :meth:`~critmoment.twin.Twin.slip_counted`).
  With ``slip_is_failure`` (default) a run that slips counts as a failure even when it
  completes the task; otherwise it is ``SUCCESS`` when completed.
* ``NOT_COMPLETED``: the task is not completed (``completed`` of :func:`classify`: the task's
  physical success rule; without it :func:`~critmoment.recording.ends_completed`, the run
  ends in stage 4) and none of the above
  explains it (e.g. the object was never grasped, as in the nominal run itself).
* ``SUCCESS``: completed, and none of the above.

A sample has exactly one outcome, the first in the order DIVERGED, MOTOR, DROPPED, SLIPPED,
NOT_COMPLETED that applies; the step of its earliest failure event (``first_failure_step``)
is kept for the analysis of missed failures.
"""

from __future__ import annotations

import dataclasses
import enum
import itertools
import math
import numbers
import threading
import time
import weakref
from collections.abc import Sequence
from typing import Any

import mujoco
import numpy as np

from critmoment import actuators as act_info
from critmoment import budget
from critmoment.actuators import body_chain, common_ancestor
from critmoment.exceptions import ParameterError
from critmoment.recording import (
    batched_rollouts,
    ends_completed,
    initial_state,
    prepare_controls,
)
from critmoment.trajectory import Trajectory
from critmoment.twin import SlipMasks, Twin, carried_flags, entry_point

__all__ = [
    "Outcome",
    "OutcomeCriteria",
    "Classification",
    "classify",
    "ends_completed",
    "grip_slip",
    "beyond_nominal",
    "hold_starts",
    "BruteForce",
    "NominalReference",
    "brute_force",
    "rerun_in_full",
    "tracking_tolerances",
]

_SENSOR_PREFIX = "critmoment:validate:"


class Outcome(enum.Enum):
    """Real outcome of one full rollout (see the module docstring for the definitions)."""

    SUCCESS = "success"
    DIVERGED = "diverged"
    MOTOR = "motor"
    DROPPED = "dropped"
    SLIPPED = "slipped"
    NOT_COMPLETED = "not_completed"

    def __str__(self) -> str:  # print(outcome) says dropped
        return self.value


#: precedence of the failure outcomes: the first that applies names the sample's outcome
_PRECEDENCE = (Outcome.DIVERGED, Outcome.MOTOR, Outcome.DROPPED, Outcome.SLIPPED,
               Outcome.NOT_COMPLETED)


@dataclasses.dataclass(frozen=True)
class OutcomeCriteria:
    """Tolerances that turn a full rollout into an :class:`Outcome`.

    Attributes:
        slip_tolerance: largest displacement of the object in a holding gripper, relative to
            the nominal run, that is not slip [m] (1 cm: a quarter of the bundled 4 cm cube).
        slip_time: how long the displacement must exceed the tolerance to count [s]
            (transients at the hand-over settle within a few tens of ms).
        slip_is_failure: a run that slips but completes the task counts as a failure.
        saturation: fraction of the force limit at which a motor-checked actuator (an arm's
            hinge or slide, not a finger: ``Twin.motors``) is saturated.
        motor_time: how long a saturation must last to count [s].
        tracking_tolerance: how much more than in the nominal run a rotational joint may lag
            its target [rad].
        tracking_tolerance_slide: the same for an arm's slide joint (a lift, a gantry axis)
            [m].
        tracking_time: how long a tracking loss must last to count [s].
        drop_time: longest ignored loss of the object where the nominal run carries it [s]
            (the debounce of the drop test).
        fall_height: how far the object must fall, out of every gripper onto a support (or
            anything it comes to rest on) where the nominal run carries it, for the fall to fail a run that completes its task
            [m] (a cube dropped 12 cm mid-carry onto the table, picked up again and placed
            had counted as a success).
    """

    slip_tolerance: float = 0.01
    slip_time: float = 0.05
    slip_is_failure: bool = True
    saturation: float = 0.999
    motor_time: float = 0.05
    tracking_tolerance: float = 0.1
    tracking_time: float = 0.05
    drop_time: float = 0.02
    tracking_tolerance_slide: float = 0.01
    fall_height: float = 0.03

    def __post_init__(self):
        for name in ("slip_tolerance", "tracking_tolerance", "tracking_tolerance_slide",
                     "fall_height"):
            _check_positive(name, getattr(self, name))
        for name in ("slip_time", "motor_time", "tracking_time", "drop_time"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, numbers.Real) or not (
                    math.isfinite(value) and value >= 0):
                raise ParameterError(f"{name}: expected a finite time >= 0 s, got {value!r}")
        if not isinstance(self.saturation, numbers.Real) or not 0 < self.saturation <= 1:
            raise ParameterError(f"saturation: expected a fraction in (0, 1], got "
                                 f"{self.saturation!r}")

    def steps(self, seconds: float, dt: float) -> int:
        """Shortest run of steps that lasts *longer* than ``seconds`` at step ``dt`` [s]."""
        return int(round(seconds / dt)) + 1


def _check_positive(name: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not (
            math.isfinite(value) and value > 0):
        raise ParameterError(f"{name}: expected a finite number > 0, got {value!r}")
    return float(value)


def _check_int(name: str, value: Any, minimum: int) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < minimum:
        raise ParameterError(f"{name}: expected an integer >= {minimum}, got {value!r}")
    return int(value)


# --------------------------------------------------------------------------
# classification of full rollouts
# --------------------------------------------------------------------------


def _run_length(flags: np.ndarray) -> np.ndarray:
    """Length of the run of True ending at each step, (n, T) int (0 where False)."""
    t = flags.shape[-1]
    idx = np.arange(t)
    last_false = np.maximum.accumulate(np.where(flags, -1, idx), axis=-1)
    return idx - last_false


def _first_run(flags: np.ndarray, min_len: int) -> np.ndarray:
    """First step of the first run of at least ``min_len`` True values, (n,) int, −1 if none."""
    long = _run_length(flags) >= min_len
    hit = long.any(axis=-1)
    return np.where(hit, np.argmax(long, axis=-1) - min_len + 1, -1)


def _last_run(flags: np.ndarray, min_len: int) -> np.ndarray:
    """First step of the last run of at least ``min_len`` True values, (n,) int, −1 if none."""
    length = _run_length(flags)
    long = length >= min_len
    hit = long.any(axis=-1)
    end = flags.shape[-1] - 1 - np.argmax(long[:, ::-1], axis=-1)
    start = end - length[np.arange(flags.shape[0]), end] + 1
    return np.where(hit, start, -1)


@dataclasses.dataclass(frozen=True, eq=False)
class Classification:
    """Real outcomes of n full rollouts.

    Attributes:
        outcome: one :class:`Outcome` per sample.
        completed: the task was completed, (n,) bool.
        first_failure_step: step of the earliest failure event of a failed sample (slip,
            drop, motor, divergence; for NOT_COMPLETED the start of the final loss of stage
            4, or −1 when stage 4 was never reached); −1 for a success, (n,) int.
        slip_step: first step of the first slip, −1 if none, (n,) int.
        drop_step: first step of the last loss of the object where the nominal run carries
            it (the drop; an earlier loss, such as a lift that starts late, was recovered
            from), −1 if none (counted as DROPPED only when not completed), (n,) int.
        motor_step: first step of the first motor saturation or tracking loss, −1 if none,
            (n,) int.
        max_slip: largest displacement in a holding gripper relative to the nominal run [m],
            (n,) (0 where never held).
        saturation_time: longest saturation of a rotational actuator [s], (n,).
        motor_column: which motor-checked actuator (its column of ``actuator_norm``, in
            ``Twin.motors`` order) the first motor event is of, −1 if none, (n,) int.
        motor_tracking: the first motor event is a tracking loss (the joint lags its
            target), not a saturation, (n,) bool.
        dt: physics step [s].
        criteria: the tolerances used.
    """

    outcome: tuple[Outcome, ...]
    completed: np.ndarray
    first_failure_step: np.ndarray
    slip_step: np.ndarray
    drop_step: np.ndarray
    motor_step: np.ndarray
    max_slip: np.ndarray
    saturation_time: np.ndarray
    motor_column: np.ndarray
    motor_tracking: np.ndarray
    dt: float
    criteria: OutcomeCriteria

    @property
    def failed(self) -> np.ndarray:
        """(n,) bool: the outcome is anything but SUCCESS."""
        return np.array([o is not Outcome.SUCCESS for o in self.outcome], dtype=bool)

    def counts(self) -> dict[str, int]:
        """Samples per outcome, every outcome listed."""
        return {o.value: sum(1 for x in self.outcome if x is o) for o in Outcome}

    @staticmethod
    def concatenate(parts: Sequence[Classification]) -> Classification:
        """Join classifications of successive chunks of samples."""
        if not parts:
            raise ParameterError("expected at least one classification to concatenate")
        arrays = {f.name: np.concatenate([getattr(p, f.name) for p in parts])
                  for f in dataclasses.fields(Classification)
                  if f.name not in ("outcome", "dt", "criteria")}
        return Classification(outcome=tuple(o for p in parts for o in p.outcome),
                              dt=parts[0].dt, criteria=parts[0].criteria, **arrays)


#: the object's speed [m/s] under which, touched by no gripper, it lies on something (a
#: fixed geom the scenario does not list as a support: a crate, another object)
LYING_SPEED = 0.05


def resting(contact_support: np.ndarray, speed: np.ndarray | None) -> np.ndarray:
    """Where the object lies on something, (..., T) bool: it touches a support, or (with
    ``speed`` [m/s], (..., T)) moves slower than ``LYING_SPEED``, at rest on whatever holds
    it up (touched by no gripper, an object that slow is not in flight)."""
    support = np.asarray(contact_support, bool)
    if speed is None:
        return support
    return support | (np.asarray(speed, dtype=np.float64) < LYING_SPEED)


def fall_steps(contact_gripper: np.ndarray, contact_support: np.ndarray,
               nominal_carried: np.ndarray, height: np.ndarray, fall_height: float,
               speed: np.ndarray | None = None) -> np.ndarray:
    """Where each run's object first lies fallen, (n,) int (−1: never): the first step of a
    stretch where the nominal run carries the object and the run's object touches a support
    (or, with ``speed``, rests on anything, below ``LYING_SPEED``) and no gripper, having
    fallen more than ``fall_height`` [m] from its height at the last step a gripper touched
    it (after a gripper first held it off its support); the step returned is the first
    after that last touch (when it left the grip).

    Args:
        contact_gripper: (n, T, G) bool.
        contact_support: (n, T) bool.
        nominal_carried: (T,) bool.
        height: the object's height along the world's up [m], (n, T).
        fall_height: [m].
        speed: the object's speed [m/s], (n, T), or None (only the supports count: a cube
            fallen onto a crate the scenario does not list, at rest there, is one too).
    """
    touched = np.asarray(contact_gripper, bool).any(axis=-1)
    support = resting(contact_support, speed)
    height = np.asarray(height, dtype=np.float64)
    n, t = support.shape
    out = np.full(n, -1, np.int64)
    lying = ~touched & support & np.asarray(nominal_carried, bool)[None, :t]
    held = carried_flags(support, contact_gripper)
    for i in np.flatnonzero(lying.any(axis=1)):
        first_held = np.flatnonzero(held[i])
        if not first_held.size:
            continue
        starts = np.flatnonzero(np.diff(np.concatenate([[False], lying[i]])
                                        .astype(np.int8)) == 1)
        for s0 in starts[starts > first_held[0]]:
            last = np.flatnonzero(touched[i, :s0])
            if last.size and height[i, last[-1]] - height[i, s0] > fall_height:
                out[i] = last[-1] + 1
                break
    return out


def classify(*, dt: float, stage: np.ndarray, contact_gripper: np.ndarray,
             contact_support: np.ndarray, nominal_carried: np.ndarray,
             actuator_norm: np.ndarray, tracking_excess: np.ndarray | None = None,
             slip: np.ndarray | None = None, diverged: np.ndarray | None = None,
             diverged_step: np.ndarray | None = None,
             completed: np.ndarray | None = None,
             criteria: OutcomeCriteria = OutcomeCriteria(),
             object_height: np.ndarray | None = None,
             object_speed: np.ndarray | None = None,
             lifted: np.ndarray | None = None) -> Classification:
    """Classify n full rollouts from their signals.

    Args:
        dt: physics step [s].
        stage: task stage per step, (n, T) int.
        contact_gripper: the object touches gripper g, (n, T, G) bool.
        contact_support: the object touches the support, (n, T) bool.
        nominal_carried: the nominal run carries the object (off the support, touched by a
            gripper), (T,) bool.
        actuator_norm: force / limit of the rotational actuators, (n, T, r).
        tracking_excess: how much more than in the nominal run each rotational joint lags
            its target, |q − target| − |q_nominal − target| [rad], (n, T, r), or None.
        slip: displacement of the object in its holding gripper relative to the nominal run
            [m], (n, T) (0 where not held), or None (see :func:`grip_slip`).
        diverged: the simulation diverged, (n,) bool, or None.
        diverged_step: the step it diverged at, (n,) int, or None.
        completed: the task's physical success rule per run, (n,) bool (the scenario's
            ``task.success``), or None for :func:`~critmoment.recording.ends_completed` of
            ``stage`` (the run ends in stage 4).
        criteria: the tolerances.
        object_height: the object's height along the world's up [m], (n, T), for the fall
            rule (:func:`fall_steps`); None: no fall is counted in a completed run.
        object_speed: the object's speed [m/s], (n, T), for the fall rule (an object at
            rest on something the scenario does not list as a support), or None.
        lifted: the task's lift rule per run (``Task.lifted``: a rise of ``lift_height``),
            (n,) bool, or None for the run reaching stage 2: a run never lifted is not
            ``DROPPED``.

    Returns:
        The :class:`Classification`.

    Raises:
        ParameterError: arrays of inconsistent shapes.
    """
    _check_positive("dt", dt)
    stage = np.asarray(stage)
    if stage.ndim != 2:
        raise ParameterError(f"stage: expected shape (n, T), got {stage.shape}")
    n, t = stage.shape
    contact_gripper = np.asarray(contact_gripper, dtype=bool)
    contact_support = np.asarray(contact_support, dtype=bool)
    nominal_carried = np.asarray(nominal_carried, dtype=bool)
    actuator_norm = np.asarray(actuator_norm, dtype=np.float64)
    expect = {"contact_gripper": (contact_gripper, 3), "contact_support": (contact_support, 2),
              "actuator_norm": (actuator_norm, 3)}
    if tracking_excess is not None:
        tracking_excess = np.asarray(tracking_excess, dtype=np.float64)
        expect["tracking_excess"] = (tracking_excess, 3)
    if slip is not None:
        slip = np.asarray(slip, dtype=np.float64)
        expect["slip"] = (slip, 2)
    for name, (arr, ndim) in expect.items():
        if arr.ndim != ndim or arr.shape[:2] != (n, t):
            raise ParameterError(
                f"{name}: expected {ndim} axes with leading shape (n, T) = {(n, t)}, got "
                f"{arr.shape}")
    if nominal_carried.shape != (t,):
        raise ParameterError(f"nominal_carried: expected shape ({t},), got {nominal_carried.shape}")
    diverged = np.zeros(n, bool) if diverged is None else np.asarray(diverged, dtype=bool)
    if diverged.shape != (n,):
        raise ParameterError(f"diverged: expected shape ({n},), got {diverged.shape}")
    diverged_step = (np.full(n, -1) if diverged_step is None
                     else np.asarray(diverged_step, dtype=np.int64))
    c = criteria

    if completed is None:
        completed = ends_completed(stage)
    else:
        completed = np.asarray(completed, dtype=bool)
        if completed.shape != (n,):
            raise ParameterError(f"completed: expected shape ({n},), got {completed.shape}")
    # motor: saturation, or tracking lost, for longer than the stated times
    saturated = np.abs(actuator_norm) >= c.saturation
    sat_run = _run_length(saturated.transpose(0, 2, 1))  # (n, r, T)
    saturation_time = (sat_run.max(axis=(1, 2)) if sat_run.size else np.zeros(n)) * dt
    starts = [_first_run(saturated[..., j], c.steps(c.motor_time, dt))
              for j in range(actuator_norm.shape[-1])]
    if tracking_excess is not None:
        lost = tracking_excess > c.tracking_tolerance
        starts += [_first_run(lost[..., j], c.steps(c.tracking_time, dt))
                   for j in range(tracking_excess.shape[-1])]
    if starts:
        events = np.stack(starts, axis=-1)  # saturation columns, then tracking columns
        motor_step = _earliest(events)
        first = np.argmin(np.where(events >= 0, events, np.iinfo(np.int64).max), axis=-1)
        motor_column = np.where(motor_step >= 0, first % actuator_norm.shape[-1], -1)
        motor_tracking = (motor_step >= 0) & (first >= actuator_norm.shape[-1])
    else:
        motor_step = motor_column = np.full(n, -1)
        motor_tracking = np.zeros(n, bool)
    # drop: not carried where the nominal run carries the object
    carried = carried_flags(contact_support, contact_gripper)
    # counted over the steps the nominal run carries it: a loss that goes on across the
    # nominal's own gap (a short free fall into the receiver at a hand-over) is one drop,
    # dated from its start (it had been dated after the gap, so that an empty wrist lagging
    # in between was taken for the cause)
    where = np.flatnonzero(np.asarray(nominal_carried, dtype=bool))
    drop_step = np.full(n, -1)
    if where.size:
        at = _last_run(~carried[:, where], c.steps(c.drop_time, dt))
        drop_step = np.where(at >= 0, where[np.maximum(at, 0)], -1)
    # slip: moved in the grip beyond the tolerance for longer than slip_time
    if slip is None:
        slip_step, max_slip = np.full(n, -1), np.zeros(n)
    else:
        slip_step = _first_run(slip > c.slip_tolerance, c.steps(c.slip_time, dt))
        max_slip = np.nan_to_num(slip, nan=0.0).max(axis=1) if t else np.zeros(n)
    # the final loss of stage 4 of an incomplete run (for its failure step)
    at4 = stage >= 4
    ever4 = at4.any(axis=1)
    last4 = t - 1 - np.argmax(at4[:, ::-1], axis=1)
    final_loss = np.where(ever4 & (last4 < t - 1), last4 + 1, -1)

    fall_step = (np.full(n, -1, np.int64) if object_height is None else fall_steps(
        contact_gripper, contact_support, nominal_carried, object_height, c.fall_height,
        speed=object_speed))
    # a fall onto a support fails a run whatever its end; another loss only one that does
    # not complete the task (a catch at the hand-over, an object set down early)
    fell = (fall_step >= 0) & completed
    drop_step = np.where(fell, fall_step, drop_step)
    drop_ok = (drop_step >= 0) & (~completed | fell)
    # a run that ends with the object still carried where the nominal run has let it go was
    # not dropped, whatever it touched on the way: it was never released (a Lite6's
    # high-friction cube, set on the table 70 ms before the nominal's and carried off
    # stuck to the fingers, was "dropped" at the set-down)
    if t and not nominal_carried[-1]:
        drop_ok &= ~(carried[:, -1] & ~fell)
    # nor one never lifted (by the task's own rule: a rise of lift_height): a cube too heavy
    # for a soft arm, gripped and dragged along the table 3 mm up, had been "dropped" (its
    # suggestions: grip differently) where it was never picked up (NOT_COMPLETED, or the
    # motor that could not lift it)
    if t:
        ever = (stage.max(axis=1) >= 2) if lifted is None else np.asarray(lifted, bool)
        drop_ok &= ever | fell
        # nor one whose object never leaves the grippers from the loss until the nominal run
        # lets it go (or the end): it was set down in the grip, not dropped (a held cube
        # sagging 1 mm onto a listed block; a cube set down a little early, still in the
        # fingers until the nominal's release); its slip, or the task's rule, names what
        # failed
        carrying = np.flatnonzero(np.asarray(nominal_carried, dtype=bool))
        end = int(carrying[-1]) if carrying.size else t - 1
        steps = np.arange(t)[None, :]
        window = (steps >= np.maximum(drop_step, 0)[:, None]) & (steps <= end)
        kept = (contact_gripper.any(axis=-1) | ~window).all(axis=1)
        drop_ok &= ~(kept & (drop_step >= 0)) | fell
    # a motor event after the object is lost is a consequence (the arms move unloaded, may
    # touch each other), not the cause
    motor_ok = (motor_step >= 0) & ~(drop_ok & (motor_step > drop_step))
    slip_ok = (slip_step >= 0) & (c.slip_is_failure | ~completed)
    conditions = [diverged, motor_ok, drop_ok, slip_ok, ~completed]
    codes = np.select(conditions, np.arange(len(_PRECEDENCE)), default=-1)
    outcome = tuple(Outcome.SUCCESS if k < 0 else _PRECEDENCE[k] for k in codes)
    event_steps = np.stack([np.where(diverged, diverged_step, -1),
                            np.where(motor_ok, motor_step, -1),
                            np.where(drop_ok, drop_step, -1),
                            np.where(slip_ok, slip_step, -1)], axis=-1)
    first = _earliest(event_steps)
    first = np.where(first < 0, np.where(~completed, final_loss, -1), first)
    return Classification(
        outcome=tuple(outcome), completed=completed, first_failure_step=first,
        slip_step=slip_step.astype(np.int64), drop_step=drop_step.astype(np.int64),
        motor_step=motor_step.astype(np.int64), max_slip=np.asarray(max_slip, dtype=float),
        saturation_time=np.asarray(saturation_time, dtype=float),
        motor_column=np.asarray(motor_column, dtype=np.int64),
        motor_tracking=np.asarray(motor_tracking, dtype=bool), dt=float(dt), criteria=c)


def _earliest(steps: np.ndarray) -> np.ndarray:
    """Earliest non-negative entry along the last axis, −1 where none, (n,)."""
    big = np.iinfo(np.int64).max
    masked = np.where(steps >= 0, steps, big).min(axis=-1)
    return np.where(masked == big, -1, masked)


def beyond_nominal(moved: np.ndarray, nominal_moved: np.ndarray) -> np.ndarray:
    """How far an object's displacement in a grip ``moved`` (..., 3) goes beyond the nominal
    run's own ``nominal_moved`` (..., 3) at the same step: its distance to the segment from
    0 to the nominal's displacement [m].

    A grip that slides less than a creeping nominal one, or the same way later, has gone no
    further than it (0); one that slides further, or another way, has. (The norm of the
    difference, before the twenty-ninth round, called a grip that held better than a
    creeping nominal one slipped: a UR5e's cylinder that moved 3 mm while the nominal one
    slid 20 mm.)"""
    moved = np.asarray(moved, dtype=np.float64)
    nominal_moved = np.asarray(nominal_moved, dtype=np.float64)
    length2 = np.sum(nominal_moved * nominal_moved, axis=-1)
    along = np.sum(moved * nominal_moved, axis=-1)
    share = np.divide(along, length2, out=np.zeros(np.broadcast(along, length2).shape),
                      where=length2 > 0)
    share = np.clip(share, 0.0, 1.0)
    return np.linalg.norm(moved - share[..., None] * nominal_moved, axis=-1)


def hold_starts(held: np.ndarray, segments: np.ndarray, formed: np.ndarray) -> np.ndarray:
    """Where each step's hold is measured from: per gripper, the first step of the step's
    hold (``segments``, :meth:`Twin.hold_segments`) that is ``held`` once the grasp has
    ``formed`` (:meth:`Twin.grasp_formed`), −1 where there is none; ``held`` (..., T, G)
    bool, ``segments`` and ``formed`` (T, G); returns (..., T, G) int. The anchor of
    :func:`grip_slip` (per sample), of the chains and of sparse evaluation (the nominal
    run's), which pass the touches as ``held`` (on the support or off it: fingers that
    slide along an object before it leaves its support have slipped)."""
    held, formed = np.asarray(held, dtype=bool), np.asarray(formed, dtype=bool)
    segments = np.asarray(segments)
    if held.ndim < 2 or segments.shape != held.shape[-2:] or formed.shape != segments.shape:
        raise ParameterError(
            f"hold_starts: expected held (..., T, G) and segments, formed (T, G), got "
            f"{held.shape}, {segments.shape} and {formed.shape}")
    held = held & formed
    out = np.full(held.shape, -1, np.int64)
    for j in np.unique(segments):
        inside = segments == j                                          # (T, G)
        mine = held & inside
        first = np.where(mine.any(axis=-2), np.argmax(mine, axis=-2), -1)  # (..., G)
        out = np.where(inside, first[..., None, :], out)
    return out


def grip_slip(position: np.ndarray, nominal_position: np.ndarray, held: np.ndarray,
              nominal_held: np.ndarray, *, counted: np.ndarray | None = None,
              projectors: np.ndarray | None = None,
              segments: np.ndarray | None = None,
              formed: np.ndarray | None = None,
              touching: np.ndarray | None = None,
              nominal_touching: np.ndarray | None = None) -> np.ndarray:
    """Displacement of the object in its holding grippers beyond the nominal run's.

    For gripper g, from the first step ``t0`` at which both the sample and the nominal run
    hold the object with g (with ``touching``: touch it, on its support or off it), the
    sample's displacement ``p(t) − p(t0)`` and the nominal's
    ``p_nom(t) − p_nom(t0)`` of the object's position in g's base frame, each projected by
    ``projectors[g]`` (to drop the fingers' closing axis), give the slip at t: how far the
    sample's goes beyond the nominal's (:func:`beyond_nominal`: its distance to the segment
    from 0 to the nominal's; a sample that slides less than a creeping nominal grip has not
    slipped). It counts where both runs hold the object with g and ``counted`` allows it; the
    result is the largest over the grippers. Where the nominal run regrasps (``segments``),
    each of its holds is measured from its own first such step; and only once its
    grasp has formed (``formed``): the object pushed into place by closing fingers has not
    slipped.

    Args:
        position: object position in each gripper's frame [m], (n, T, G, 3); or the
            positions of K points of the object (``Twin.grip_points``), (n, T, G, K, 3): then
            each point's displacement counts, and the farthest point's is the slip (a turn in
            the grip moves the object's ends while its centre stays).
        nominal_position: the same in the nominal run [m], (T, G, 3) or (T, G, K, 3).
        held: the sample holds the object with gripper g (touch, off the support),
            (n, T, G) bool.
        nominal_held: the same in the nominal run, (T, G) bool.
        counted: where a gripper's displacement counts, (T, G) bool; default everywhere.
            Brute force counts a gripper only while it holds the object alone in the nominal
            run: the object moves in a gripper that is letting go, which is the release, not
            slip (what slipped during a hand-over still shows once the receiver holds alone).
        projectors: per gripper, a (3, 3) projector applied to the displacement, (G, 3, 3);
            None for the identity.
        segments: which of the nominal gripper's holds each step belongs to
            (:meth:`Twin.hold_segments`), (T, G) int; default one hold.
        formed: where each gripper's grasp has formed (:meth:`Twin.grasp_formed`), (T, G)
            bool: a hold is measured from its first step held (or touched) by both
            there; default everywhere.
        touching: the sample touches the object with gripper g, on its support or off it,
            (n, T, G) bool; with ``nominal_touching`` (T, G), a hold is measured from its
            first step touched by both once the grasp has formed (fingers that slide along
            an object before it leaves its support have slipped); default ``held``.

    Returns:
        (n, T) displacement [m], 0 where it does not count.
    """
    position = np.asarray(position, dtype=np.float64)
    nominal_position = np.asarray(nominal_position, dtype=np.float64)
    if (position.ndim not in (4, 5) or position.shape[-1] != 3
            or position.shape[1:] != nominal_position.shape):
        raise ParameterError(
            f"position: expected (n, T, G, 3) or (n, T, G, K, 3) matching nominal_position "
            f"(T, G, 3) or (T, G, K, 3), got {position.shape} and {nominal_position.shape}")
    if position.ndim == 4:  # the object's position: one point
        position, nominal_position = position[..., None, :], nominal_position[..., None, :]
    n, t, g = position.shape[:3]
    both = np.asarray(held, dtype=bool) & np.asarray(nominal_held, dtype=bool)[None]
    if both.shape != (n, t, g):
        raise ParameterError(f"held: expected shape {(n, t, g)}, got {both.shape}")
    mask = both
    if counted is not None:
        counted = np.asarray(counted, dtype=bool)
        if counted.shape != (t, g):
            raise ParameterError(f"counted: expected shape {(t, g)}, got {counted.shape}")
        mask = both & counted[None]
    if segments is None:
        segments = np.zeros((t, g), np.int64)
    segments = np.asarray(segments)
    if segments.shape != (t, g):
        raise ParameterError(f"segments: expected shape {(t, g)}, got {segments.shape}")
    formed = np.ones((t, g), bool) if formed is None else np.asarray(formed, dtype=bool)
    if formed.shape != (t, g):
        raise ParameterError(f"formed: expected shape {(t, g)}, got {formed.shape}")
    # the anchor: the first step both touch the object with g once the grasp has formed,
    # on its support or off it (fingers that slide along a heavy object before it leaves
    # its support have slipped: measured from the lift-off, a Wonik Allegro's 0.85 kg ball
    # that slid in the hand while it still sat on its pedestal was "held")
    anchor = both
    if touching is not None:
        touching = np.asarray(touching, dtype=bool)
        nominal_touching = np.asarray(
            nominal_held if nominal_touching is None else nominal_touching, dtype=bool)
        if touching.shape != (n, t, g) or nominal_touching.shape != (t, g):
            raise ParameterError(
                f"touching, nominal_touching: expected shapes {(n, t, g)} and {(t, g)}, got "
                f"{touching.shape} and {nominal_touching.shape}")
        anchor = touching & nominal_touching[None]
    start = hold_starts(anchor, segments, formed)                   # (n, T, G)
    mask = mask & (start >= 0) & (np.arange(t)[None, :, None] >= start)
    t0 = np.maximum(start, 0)
    out = np.zeros((n, t))
    # only the steps where some sample's slip counts (a run's holds, not its approach)
    steps = np.flatnonzero(mask.any(axis=(0, 2)))
    if not g or not steps.size:
        return out
    rows = np.arange(n)[:, None, None]
    cols = np.arange(g)[None, None, :]
    t0 = t0[:, steps]
    moved = position[:, steps] - position[rows, t0, cols]
    nominal_moved = nominal_position[steps][None] - nominal_position[t0, cols]
    if projectors is not None:
        proj = np.swapaxes(np.asarray(projectors, dtype=np.float64), -1, -2)
        # each gripper's projector on its points' displacements (matmul: einsum was a tenth
        # of the demo audit's time here)
        moved = moved @ proj
        nominal_moved = nominal_moved @ proj
    disp = np.where(mask[:, steps], beyond_nominal(moved, nominal_moved).max(axis=-1), 0.0)
    out[:, steps] = disp.max(axis=-1)
    return out


# --------------------------------------------------------------------------
# brute force
# --------------------------------------------------------------------------


_PROBES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_PROBES_LOCK = threading.Lock()


def _probe_of(twin: Twin) -> _Probe:
    """The twin's :class:`_Probe`, compiled once per twin (its model is only read: each
    batch steps a copy of it)."""
    with _PROBES_LOCK:
        probe = _PROBES.get(twin)
        if probe is None:
            probe = _PROBES[twin] = _Probe(twin)
        return probe


class _Probe:
    """The twin's model with extra sensors for the brute force, and how to read them.

    The twin's own sensors come first and keep their addresses (the extra ones are appended),
    so ``Twin.signals`` reads the first ``twin.nsensordata`` values unchanged and the physics
    is the twin's: sensors do not act on the dynamics.
    """

    def __init__(self, twin: Twin):
        sc = twin.scenario
        base = twin.model
        anchors, projectors = grip_frames(base, sc)
        self.anchors = [int(a) for a in anchors]
        spec = sc.load_spec()  # critmoment's own copy: generated names, object friction priority
        twin.add_sensors(spec)  # the twin's sensors first, at the same addresses
        # per gripper, the object's position and orientation in its frame: where the
        # object's points (Twin.grip_points) are in the grip
        for (g, anchor), (kind, tag) in itertools.product(
                zip(sc.grippers, self.anchors, strict=False),
                ((mujoco.mjtSensor.mjSENS_FRAMEPOS, "pos"),
                 (mujoco.mjtSensor.mjSENS_FRAMEQUAT, "quat"))):
            s = spec.add_sensor()
            s.name = f"{_SENSOR_PREFIX}{tag}:{g.name}"
            s.type = kind
            # the bodies' own frames (XBODY: xpos/xmat), not their inertial frames (BODY:
            # xipos/ximat), in which the closing projector below is built; a gripper link
            # whose inertial frame is rotated (ACT's ViperX: 103 degrees) would otherwise
            # count the fingers' squeeze as slip and miss slip along another axis
            s.objtype = mujoco.mjtObj.mjOBJ_XBODY
            s.objname = sc.object_body
            s.reftype = mujoco.mjtObj.mjOBJ_XBODY
            s.refname = base.body(anchor).name
        self.motors = np.flatnonzero(twin.motors)  # the motor-checked actuators
        #: per column, the actuator's slide flag (its tracking tolerance is in metres)
        self.slide = np.asarray(twin.slide, bool)[self.motors]
        for a in self.motors:
            s = spec.add_sensor()
            s.name = f"{_SENSOR_PREFIX}q:{base.actuator(int(a)).name}"
            s.type = mujoco.mjtSensor.mjSENS_ACTUATORPOS
            s.objtype = mujoco.mjtObj.mjOBJ_ACTUATOR
            s.objname = base.actuator(int(a)).name
        # the actuator's length is gear × the joint's position: read back in joint units,
        # the lag is compared with the joint target (Twin.target_scale/offset) whatever
        # the gear or the servo's bias
        gear = base.actuator_gear[self.motors, 0]
        self.gear = np.where(gear == 0, 1.0, gear)
        self.target_scale = twin.target_scale[self.motors]
        self.target_offset = twin.target_offset[self.motors]
        self.model = spec.compile()
        twin.write_parameters(self.model, sc.box.nominal[None, :])
        nsd = twin.nsensordata
        ngrip = len(sc.grippers)
        #: per gripper, 3 position then 4 quaternion values
        self.pose = slice(nsd, nsd + 7 * ngrip)
        self.points = twin.grip_points
        self.q = slice(self.pose.stop, self.pose.stop + self.motors.size)
        self.projectors = projectors

    def grip_positions(self, sensordata: np.ndarray) -> np.ndarray:
        """The object's points in each gripper's frame, (c, T, G, K, 3) [m], from readings
        (c, T, nsensordata) of this probe's model."""
        c, t = sensordata.shape[:2]
        pose = sensordata[..., self.pose].reshape(c, t, -1, 7)
        w, x, y, z = np.moveaxis(pose[..., 3:], -1, 0)
        rot = np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                        2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                        2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
                       axis=-1).reshape(pose.shape[:-1] + (3, 3))
        return pose[..., None, :3] + self.points @ np.swapaxes(rot, -1, -2)


def grip_frames(model: mujoco.MjModel, scenario) -> tuple[np.ndarray, np.ndarray]:
    """Each gripper's base body and the projector that drops its fingers' closing axes.

    The base is the deepest body above every geom of the gripper; the projector (in the
    base's frame) removes the span of the slide joints between those geoms and the base,
    so that squeezing the object is not counted as slip. The ground truth and sparse
    evaluation measure slip in these frames alike.

    Args:
        model: the compiled model.
        scenario: the scenario (its grippers' geoms).

    Returns:
        (anchors (G,) int body ids, projectors (G, 3, 3)).
    """
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    anchors, projectors = [], []
    for gripper in scenario.grippers:
        bodies = [int(model.geom_bodyid[model.geom(name).id]) for name in gripper.geoms]
        anchor = common_ancestor(model, bodies)
        frame = data.xmat[anchor].reshape(3, 3)
        axes = []
        for chain in (body_chain(model, b) for b in bodies):
            for body in chain[:chain.index(anchor)]:
                first = int(model.body_jntadr[body])
                for j in range(first, first + int(model.body_jntnum[body])):
                    if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE:
                        axes.append(frame.T @ data.xaxis[j])
        anchors.append(anchor)
        projectors.append(act_info.closing_projector(axes))
    return np.array(anchors, dtype=np.int64), np.array(projectors).reshape(-1, 3, 3)


@dataclasses.dataclass(frozen=True, eq=False)
class NominalReference:
    """The nominal-parameter run that :func:`brute_force` classifies against, to reuse.

    Attributes:
        frames: what the classification reads from it.
        completed: it completes the task.
        n_steps: physics steps of the trajectory.
        nominal: the nominal parameter values, (k,).
        outcome: its own real outcome (classified against itself: a motor saturation, a
            divergence or the task's rule can fail it; a slip or a drop, measured against
            the nominal run, cannot).
        first_failure_step: the step of its earliest failure event, −1 for a success.
        motor_column: the motor-checked actuator of a motor failure (``Twin.motors``
            order), −1 otherwise.
        motor_tracking: that motor failure is a tracking loss, not a saturation.
        masks: where and from where its slip counts (:meth:`Twin.slip_masks`, from its
            readings: the grasp forms once the fingers stop).
    """

    frames: _Frames
    completed: bool
    n_steps: int
    nominal: np.ndarray
    outcome: Outcome = Outcome.SUCCESS
    first_failure_step: int = -1
    motor_column: int = -1
    motor_tracking: bool = False
    masks: SlipMasks | None = None


@dataclasses.dataclass(frozen=True, eq=False)
class BruteForce:
    """Real outcomes of full rollouts for parameter samples.

    Attributes:
        samples: the parameter values, (n, k), columns in ``parameter_names`` order.
        parameter_names: names of the k parameters.
        classification: the outcomes.
        diverged: the simulation diverged, (n,) bool.
        nominal_completed: the nominal-parameter run (the reference) completes the task.
        n_steps: physics steps per rollout.
        dt: physics step [s].
        seconds: wall time of the rollouts and their classification [s].
        reference: the nominal run, to pass to a later :func:`brute_force` of the same
            trajectory and twin (it then does not run again).
    """

    samples: np.ndarray
    parameter_names: tuple[str, ...]
    classification: Classification
    diverged: np.ndarray
    nominal_completed: bool
    n_steps: int
    dt: float
    seconds: float
    reference: NominalReference | None = dataclasses.field(default=None, repr=False)

    @property
    def outcome(self) -> tuple[Outcome, ...]:
        return self.classification.outcome

    @property
    def failed(self) -> np.ndarray:
        """(n,) bool: the real outcome is anything but SUCCESS."""
        return self.classification.failed


@entry_point
def brute_force(traj: Trajectory, *, twin: Twin, samples: np.ndarray,
                criteria: OutcomeCriteria = OutcomeCriteria(), chunk: int = 16,
                nthread: int = 0, reference: NominalReference | None = None) -> BruteForce:
    """Run the whole trajectory once per parameter sample and classify each real outcome.

    The samples run in chunks of at most ``chunk`` simulations through
    :func:`critmoment.recording.simulate` (``mujoco.batch.Batch.rollout``, ``nthread``
    threads), on the twin's model with sensors appended for the object's position in each
    gripper and the joints' positions; each chunk is classified and dropped before the next,
    so memory stays at about ``chunk × T × nsensordata × 8`` bytes. The nominal parameters run
    first, as the reference of the drop, slip and tracking criteria, unless ``reference``
    (``BruteForce.reference`` of an earlier call with the same trajectory and twin) gives it.

    Args:
        traj: the trajectory.
        twin: the twin.
        samples: parameter values, (n, k) in the box's column order.
        criteria: the outcome tolerances.
        chunk: most simulations per batch call.
        nthread: threads (0: all CPUs).
        reference: the nominal run from an earlier call, or None to run it.

    Returns:
        The :class:`BruteForce` result.

    Raises:
        ParameterError: bad samples, criteria, chunk, threads or reference.
        ResourceLimitError: the rollouts, one by one or all together, beyond the active
            :mod:`critmoment.budget` limits (``max_steps``, ``max_batch_steps``).
    """
    t_start = time.perf_counter()
    traj, twin, samples, criteria, chunk, nthread = _brute_force_inputs(
        traj, twin, samples, criteria, chunk, nthread)
    budget.check_validation(traj, twin, n_samples=samples.shape[0])
    return _brute_force(traj, twin=twin, samples=samples, criteria=criteria, chunk=chunk,
                        nthread=nthread, reference=reference, t_start=t_start)


def check_criteria(criteria: Any) -> OutcomeCriteria:
    """``criteria`` itself when it is an :class:`OutcomeCriteria`.

    Raises:
        ParameterError: anything else, with what to pass instead.
    """
    if not isinstance(criteria, OutcomeCriteria):
        raise ParameterError(f"criteria: expected an OutcomeCriteria "
                             f"(critmoment.groundtruth.OutcomeCriteria(slip_tolerance=..., "
                             f"...)), got {type(criteria).__name__} {criteria!r}")
    return criteria


def _brute_force_inputs(traj, twin, samples, criteria, chunk, nthread):
    """:func:`brute_force`'s arguments, checked at the boundary."""
    from critmoment.sparse import check_samples
    from critmoment.trajectory import check_trajectory
    from critmoment.twin import resolve_twin

    traj = check_trajectory(traj)
    twin = resolve_twin(None, twin)
    samples = check_samples(twin.scenario.box, samples)
    return (traj, twin, samples, check_criteria(criteria), _check_int("chunk", chunk, 1),
            budget.check_nthread(nthread))


def _brute_force(traj: Trajectory, *, twin: Twin, samples: np.ndarray,
                 criteria: OutcomeCriteria, chunk: int, nthread: int,
                 reference: NominalReference | None, t_start: float) -> BruteForce:
    """:func:`brute_force` on checked arguments, without the budget's check: for the audit's
    own verification rollouts, whose number :func:`critmoment.budget.check_audit` bounds
    before the audit starts."""
    box = twin.scenario.box
    probe = _probe_of(twin)
    controls = prepare_controls(twin, traj)
    state0 = initial_state(twin, traj)
    dt = float(twin.model.opt.timestep)
    if reference is not None and (reference.n_steps != controls.shape[0]
                                  or not np.array_equal(reference.nominal, box.nominal)):
        raise ParameterError(
            f"reference: expected the nominal run of this trajectory ({controls.shape[0]} "
            f"steps, nominal {box.nominal.tolist()}), got {reference.n_steps} steps, nominal "
            f"{np.asarray(reference.nominal).tolist()}")
    skip = 0 if reference is not None else 1
    everything = samples if reference is not None else np.vstack([box.nominal[None, :],
                                                                  samples])
    frames_ref = None if reference is None else reference.frames
    masks = None if reference is None else reference.masks
    parts, diverged = [], []
    for first, out, _mu in batched_rollouts(twin, state0, controls, everything,
                                            model=probe.model, chunk=chunk, nthread=nthread):
        budget.check_cancelled()
        rows = everything[first:first + out["sensordata"].shape[0]]
        frames = _Frames.read(twin, probe, out["sensordata"], twin.sample_limits(rows))
        if frames_ref is None:  # the nominal run is this first chunk's row 0
            frames_ref = frames.row(0)
            masks = twin.slip_masks(controls, frames_ref.contact_gripper,
                                    frames_ref.contact_support, out["sensordata"][0])
        if masks is None:  # a reference made without its readings
            masks = twin.slip_masks(controls, frames_ref.contact_gripper,
                                    frames_ref.contact_support)
        parts.append(_classify_frames(frames, frames_ref, controls, probe, dt, criteria,
                                      out["diverged"], out["diverged_step"], masks))
        diverged.append(out["diverged"])
    result = Classification.concatenate(parts)
    keep = slice(skip, None)
    classification = Classification(
        outcome=result.outcome[skip:], dt=dt, criteria=criteria,
        **{f.name: getattr(result, f.name)[keep] for f in dataclasses.fields(Classification)
           if f.name not in ("outcome", "dt", "criteria")})
    if reference is None:
        reference = NominalReference(frames=frames_ref, completed=bool(result.completed[0]),
                                     outcome=result.outcome[0],
                                     first_failure_step=int(result.first_failure_step[0]),
                                     motor_column=int(result.motor_column[0]),
                                     motor_tracking=bool(result.motor_tracking[0]),
                                     n_steps=int(controls.shape[0]),
                                     nominal=box.nominal.copy(), masks=masks)
    return BruteForce(samples=samples, parameter_names=box.names, classification=classification,
                      diverged=np.concatenate(diverged)[keep],
                      nominal_completed=reference.completed, n_steps=controls.shape[0],
                      dt=dt, seconds=time.perf_counter() - t_start, reference=reference)


def reference_from_recording(recording, twin: Twin,
                             criteria: OutcomeCriteria = OutcomeCriteria()) -> NominalReference:
    """The nominal run of :func:`brute_force`, read from the frequent rollout instead of run
    again: the recording is that run (the same model, initial state and controls; sensors do
    not act on the dynamics), so its sensor readings are the brute force's to the bit, and
    the extra sensors of :class:`_Probe` (position sensors: the object in each gripper's
    frame, the actuators' positions) are computed from its recorded positions, step k's
    readings from the state that starts step k, as ``mj_step`` reads them.

    Args:
        recording: the frequent rollout (:func:`critmoment.recording.rollout`) of the
            trajectory, at the box's nominal parameters.
        twin: its twin.
        criteria: the outcome tolerances (for the nominal run's own completion).

    Returns:
        The :class:`NominalReference`, to pass to :func:`brute_force`.

    Raises:
        ParameterError: the recording is not at the box's nominal parameters or has no
            steps.
    """
    box = twin.scenario.box
    nominal = np.asarray(recording.nominal, dtype=np.float64)
    if nominal.shape != box.nominal.shape or not np.array_equal(nominal, box.nominal):
        raise ParameterError(f"recording: expected a run at the box's nominal parameters "
                             f"{box.nominal.tolist()}, got {nominal.tolist()}")
    sd = np.asarray(recording.sensordata, dtype=np.float64)
    n = sd.shape[0]
    if n == 0 or sd.shape[1] != twin.nsensordata:
        raise ParameterError(f"recording: expected (T >= 1, {twin.nsensordata}) sensor "
                             f"readings, got {sd.shape}")
    probe = _probe_of(twin)
    model = probe.model
    data = mujoco.MjData(model)
    qpos = twin.qpos(np.asarray(recording.states, dtype=np.float64)[:n])
    extra = np.empty((n, model.nsensordata - twin.nsensordata))
    for k in range(n):
        data.qpos[:] = qpos[k]
        mujoco.mj_kinematics(model, data)
        mujoco.mj_comPos(model, data)
        mujoco.mj_tendon(model, data)
        mujoco.mj_transmission(model, data)
        mujoco.mj_sensorPos(model, data)
        extra[k] = data.sensordata[twin.nsensordata:]
    full = np.concatenate([sd, extra], axis=1)[None]
    frames = _Frames.read(twin, probe, full)
    controls = np.asarray(recording.controls, dtype=np.float64)
    dt = float(twin.model.opt.timestep)
    ref = frames.row(0)
    masks = twin.slip_masks(controls, ref.contact_gripper, ref.contact_support, sd)
    own = _classify_frames(frames, ref, controls, probe, dt, criteria, np.zeros(1, bool),
                           np.full(1, -1, np.int64), masks)
    return NominalReference(frames=ref, completed=bool(own.completed[0]), n_steps=n,
                            masks=masks,
                            nominal=box.nominal.copy(), outcome=own.outcome[0],
                            first_failure_step=int(own.first_failure_step[0]),
                            motor_column=int(own.motor_column[0]),
                            motor_tracking=bool(own.motor_tracking[0]))


@dataclasses.dataclass(frozen=True)
class _Frames:
    """What the classification reads from a chunk of full rollouts (leading (c, T))."""

    stage: np.ndarray
    contact_gripper: np.ndarray
    contact_support: np.ndarray
    height: np.ndarray
    speed: np.ndarray
    actuator_norm: np.ndarray
    position: np.ndarray
    q: np.ndarray
    success: np.ndarray
    #: the task's own lift rule per run (a rise of ``lift_height``, or carried from the start)
    lifted: np.ndarray

    @classmethod
    def read(cls, twin: Twin, probe: _Probe, sensordata: np.ndarray,
             limits: np.ndarray | None = None) -> _Frames:
        # the outcome reads contacts, positions and forces, not the contact loads of
        # Twin.signals (the audit's cost): those were two thirds of its time here
        sd = sensordata[..., :twin.nsensordata]
        gripper, support = twin.contact_flags(sd)
        pos, vel = sd[..., twin._pos_adr], sd[..., twin._vel_adr]
        c, t = sensordata.shape[:2]
        evidence = twin.task_evidence(gripper, support, pos, vel, base_axis=twin.base_axis(sd))
        # each run's own force limits where the box varies one (c, nu), else the twin's
        limits = twin.limits if limits is None else np.asarray(limits)[:, None]
        return cls(stage=twin.task.stage(gripper, support, pos), contact_gripper=gripper,
                   contact_support=support, height=pos @ np.asarray(twin.task.up),
                   speed=np.linalg.norm(vel, axis=-1),
                   actuator_norm=sd[..., twin._force_ids[probe.motors]]
                   / limits[..., probe.motors],
                   position=probe.grip_positions(sensordata),
                   q=sensordata[..., probe.q] / probe.gear, success=twin.task.success(evidence),
                   lifted=twin.task.lifted(evidence))

    def row(self, i: int) -> _Frames:
        return _Frames(**{f.name: getattr(self, f.name)[i] for f in dataclasses.fields(self)})

    @property
    def held(self) -> np.ndarray:
        return self.contact_gripper & ~self.contact_support[..., None]


def tracking_tolerances(criteria: OutcomeCriteria, slide: np.ndarray,
                        unit: float = 1.0) -> np.ndarray:
    """Per motor-checked actuator column, ``unit`` over its tracking tolerance (hinge:
    ``tracking_tolerance`` [rad]; slide: ``tracking_tolerance_slide`` [m]), (r,): with
    ``unit`` 1, a lag times it is the lag in tolerances."""
    slide = np.asarray(slide, bool)
    return unit / np.where(slide, criteria.tracking_tolerance_slide,
                           criteria.tracking_tolerance)


def _classify_frames(frames: _Frames, reference: _Frames, controls: np.ndarray, probe: _Probe,
                     dt: float, criteria: OutcomeCriteria, diverged: np.ndarray,
                     diverged_step: np.ndarray, masks: SlipMasks) -> Classification:
    """Classify the runs ``frames`` against the nominal ``reference``; ``masks``: where and
    from where a gripper's slip counts in the nominal run (:meth:`Twin.slip_masks`)."""
    target = controls[:, probe.motors] * probe.target_scale + probe.target_offset
    excess = np.abs(frames.q - target[None]) - np.abs(reference.q - target)[None]
    # a slide axis's lag [m] against its own tolerance, in the criteria's one comparison
    excess = excess * tracking_tolerances(criteria, probe.slide, criteria.tracking_tolerance)
    slip = grip_slip(frames.position, reference.position, frames.held, reference.held,
                     counted=masks.counted, projectors=probe.projectors,
                     segments=masks.segments, formed=masks.formed,
                     touching=frames.contact_gripper,
                     nominal_touching=reference.contact_gripper)
    nominal_carried = carried_flags(reference.contact_support, reference.contact_gripper)
    # the task's own physical success rule decides completion (critmoment.task)
    return classify(dt=dt, stage=frames.stage, contact_gripper=frames.contact_gripper,
                    contact_support=frames.contact_support, nominal_carried=nominal_carried,
                    actuator_norm=frames.actuator_norm, tracking_excess=excess, slip=slip,
                    diverged=diverged, diverged_step=diverged_step, criteria=criteria,
                    completed=frames.success, object_height=frames.height,
                    object_speed=frames.speed, lifted=frames.lifted)


def rerun_in_full(traj: Trajectory, *, twin: Twin, samples: np.ndarray, failed: np.ndarray,
                  cost: np.ndarray, unlifted: np.ndarray | None, verify: float,
                  chunk: int = 16, nthread: int = 0
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The audit's verification: the samples sparse evaluation cannot decide, decided by the
    real outcome of their own full rollout (:func:`brute_force`).

    Those are the samples that pass with a cost at or above ``verify × threshold`` (near the
    threshold, where a failure between the moments can hide) and the ``unlifted`` ones (they
    fail only where the object is squeezed off its support without a lift,
    ``SparseResult.failed_unlifted_only``).

    Args:
        traj: the trajectory.
        twin: the twin.
        samples: parameter values, (n, k).
        failed: the sparse prediction, (n,) bool.
        cost: each sample's highest sparse cost, (n,) (``SparseResult.worst_cost``).
        unlifted: the samples to re-run as unlifted, (n,) bool, or None for none.
        verify: the fraction of the threshold from which passing samples are re-run.
        chunk: most full rollouts per batch call.
        nthread: threads (0: all CPUs).

    Returns:
        The prediction with the re-run samples' outcomes, and which samples were re-run as
        near the threshold and as unlifted, each (n,) bool.
    """
    near = ~failed & (cost >= verify * twin.scenario.cost.threshold)
    unlifted = np.zeros_like(near) if unlifted is None else np.asarray(unlifted, dtype=bool)
    rerun = near | unlifted
    failed = np.array(failed, dtype=bool)
    if rerun.any():
        failed[rerun] = brute_force(traj, twin=twin, samples=samples[rerun], chunk=chunk,
                                    nthread=nthread).failed
    return failed, near, unlifted
