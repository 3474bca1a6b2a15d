"""Each sample's own history: chained segments, and a drift detector (measured: not selective).

Sparse evaluation restores the *nominal* state at every moment, so it cannot see what a
sample's own parameters did to its state between moments: a heavier cube carried sideways
shifts a few millimetres in a force-limited grip, an arm sags, and the shifted pads collide
at the hand-over although the nominal moments look safe. :func:`estimate_drift` measures,
at every audited moment where the nominal run holds the object with one gripper, how far
each sample's own state moves away from the nominal run over a short trace (``horizon``
steps from the restored state, the sample's parameters, the recorded controls): the
object's position in the holding gripper's frame (all three axes: an off-centre shift
between the fingers counts here, unlike slip) and the actuated joints' positions. The
drift and its rate at the trace's end are extrapolated linearly over the rest of that
gripper's hold in the nominal run; a sample whose predicted drift exceeds
``drift_tolerance`` (or its joint lag ``lag_tolerance``) is *escalated*: its own full
rollout should decide it, like the audit's verification of near-threshold samples.

The linear extrapolation is a heuristic, and measured it is not selective: on the bundled
twin a 25-step trace from the nominal state mostly sees the heavier cube settling in the
grip right after the restore, the same in every seed, so it escalates nearly every sample
predicted safe (``benchmarks/history_study.py``).

:func:`chained_failures` carries each sample's own state instead: from the nominal state at
the first moment it runs the recorded controls with the sample's parameters through every
later moment and applies the sparse decision there, from the state the sample reached. It
costs the stepping from the first to the last moment per sample (under half a full rollout
on the bundled demo), so it is meant for the samples the sparse sweep predicts safe.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import mujoco
import numpy as np
import scipy.ndimage

from critmoment import budget
from critmoment.exceptions import ParameterError
from critmoment.groundtruth import OutcomeCriteria, beyond_nominal, fall_steps, tracking_tolerances
from critmoment.sparse import SparseEvaluator, _object_in_grippers
from critmoment.task import TaskEvidence
from critmoment.twin import STATE_SPEC

__all__ = ["DriftEstimate", "estimate_drift", "ChainedResult", "chained_failures",
           "chain_start", "SustainedLevel", "NominalOnsets", "ONSET_MARGIN",
           "DRIFT_TOLERANCE", "LAG_TOLERANCE"]

#: predicted displacement of the object in its grip that escalates a sample [m]: half the
#: 3–5 mm off-centre shift that makes the bundled robot's pads collide at the hand-over
DRIFT_TOLERANCE = 0.002
#: predicted extra lag of an actuated joint that escalates a sample [rad]
LAG_TOLERANCE = 0.05


@dataclasses.dataclass(frozen=True, eq=False)
class DriftEstimate:
    """How far each sample's own state drifts from the nominal run, per moment.

    Attributes:
        steps: the moments traced, (m,) int64 (those where one gripper holds the object).
        samples: the parameter values, (n, k).
        horizon: steps of each trace.
        drift: object displacement in the holding gripper relative to the nominal run at the
            trace's end [m], (m, n).
        drift_rate: its rate of change over the trace's second half [m/s], (m, n).
        lag: largest actuated-joint position difference to the nominal run [rad or m],
            (m, n).
        lag_rate: its rate [rad/s], (m, n).
        remaining: time the gripper keeps holding alone in the nominal run after the
            trace [s], (m,).
        predicted_drift: drift + drift_rate × remaining [m], (m, n).
        predicted_lag: lag + lag_rate × remaining, (m, n).
        drift_tolerance: escalation limit of the predicted drift [m].
        lag_tolerance: escalation limit of the predicted lag.
    """

    steps: np.ndarray
    samples: np.ndarray
    horizon: int
    drift: np.ndarray
    drift_rate: np.ndarray
    lag: np.ndarray
    lag_rate: np.ndarray
    remaining: np.ndarray
    predicted_drift: np.ndarray
    predicted_lag: np.ndarray
    drift_tolerance: float
    lag_tolerance: float

    @property
    def escalate(self) -> np.ndarray:
        """(n,) bool: the sample's predicted drift or lag exceeds its tolerance at some
        moment: its own full rollout should decide it."""
        if self.steps.size == 0:
            return np.zeros(self.samples.shape[0], dtype=bool)
        bad = (self.predicted_drift > self.drift_tolerance) | (
            self.predicted_lag > self.lag_tolerance)
        return bad.any(axis=0)


def estimate_drift(evaluator: SparseEvaluator, steps: Any, samples: Any, *, horizon: int = 25,
                   drift_tolerance: float = DRIFT_TOLERANCE,
                   lag_tolerance: float = LAG_TOLERANCE) -> DriftEstimate:
    """Trace each sample from every moment where one gripper holds the object and predict
    its drift over the rest of that hold.

    Args:
        evaluator: the audit's sparse evaluator (its recording, twin and batches).
        steps: moments, physics step indices (m,) (moments where no gripper holds the
            object alone in the nominal run are skipped).
        samples: parameter values (n, k).
        horizon: steps of each trace (at least 4).
        drift_tolerance: predicted drift that escalates [m].
        lag_tolerance: predicted joint lag that escalates [rad].

    Returns:
        The :class:`DriftEstimate`; its ``escalate`` names the samples to roll out in full.
    """
    if isinstance(horizon, bool) or not isinstance(horizon, int) or horizon < 4:
        raise ParameterError(f"horizon: expected an integer >= 4 steps, got {horizon!r}")
    for name, value in (("drift_tolerance", drift_tolerance), ("lag_tolerance", lag_tolerance)):
        if not value > 0:
            raise ParameterError(f"{name}: expected a value > 0, got {value!r}")
    ev = evaluator
    samples = ev.check_samples(samples)
    steps = np.unique(np.asarray([int(s) for s in np.atleast_1d(steps)], dtype=np.int64))
    steps = steps[(steps >= 0) & (steps < ev.n_steps - 1)]
    twin = ev.twin
    model = twin.model
    dt = float(model.opt.timestep)
    alone = ev._alone
    holder = np.where(alone.any(axis=1), np.argmax(alone, axis=1), -1)
    traced = [int(k) for k in steps if holder[k] >= 0]
    rot = np.flatnonzero(twin.motors)
    joints = model.actuator_trnid[rot, 0]
    qadr = model.jnt_qposadr[joints]
    m, n = len(traced), samples.shape[0]
    out = {name: np.zeros((m, n)) for name in ("drift", "drift_rate", "lag", "lag_rate")}
    remaining = np.zeros(m)
    qpos_all = twin.qpos(ev._states)
    for i, k in enumerate(traced):
        g = int(holder[k])
        tr = ev.trace(k, samples, nstep=horizon)
        s = tr["xpos"].shape[1]
        rel = _object_in_grippers(tr["xpos"], tr["xmat"], twin.object_body_id,
                                  ev._anchors[g:g + 1])[:, :, 0]  # (n, s, 3)
        nominal = ev._nominal_positions(k, s)[:, g, 0]  # (s, 3): the object's origin
        disp = rel - nominal[None]
        half = max(1, s // 2)
        out["drift"][i] = np.linalg.norm(disp[:, -1], axis=-1)
        out["drift_rate"][i] = np.linalg.norm(disp[:, -1] - disp[:, -1 - half], axis=-1) / (
            half * dt)
        # qpos is recorded after the step's integration: the nominal states one step on
        q_nom = qpos_all[k + 1:k + 1 + s, qadr]  # (s, J)
        dq = np.abs(tr["qpos"][:, :, qadr] - q_nom[None])
        out["lag"][i] = dq[:, -1].max(axis=-1)
        out["lag_rate"][i] = np.abs(dq[:, -1] - dq[:, -1 - half]).max(axis=-1) / (half * dt)
        run = alone[k:, g]
        end = int(np.argmin(run)) if not run.all() else run.size
        remaining[i] = max(0, end - s) * dt
    predicted_drift = out["drift"] + out["drift_rate"] * remaining[:, None]
    predicted_lag = out["lag"] + out["lag_rate"] * remaining[:, None]
    return DriftEstimate(steps=np.array(traced, dtype=np.int64), samples=samples,
                         horizon=int(horizon), remaining=remaining,
                         predicted_drift=predicted_drift, predicted_lag=predicted_lag,
                         drift_tolerance=float(drift_tolerance),
                         lag_tolerance=float(lag_tolerance), **out)


@dataclasses.dataclass(frozen=True, eq=False)
class ChainedResult:
    """Each sample carried through the moments on its own state (:func:`chained_failures`).

    Attributes:
        steps: the moments evaluated, in time order, (m,) int64.
        samples: the parameter values, (n, k).
        failure: the sparse decision (``sparse.Failure`` values) at each moment from the
            sample's own state, (m, n) int8 (−1 where the sample had already failed).
        start: the step the chain starts from (the nominal state there).
        end: the step the chain stops at (the end of the run).
        stepped: physics steps each sample took at most.
        slip_step: first step of the first slip of the object in its holding gripper over
            the whole chain (the ground truth's rule, :func:`critmoment.groundtruth.grip_slip`
            with its tolerance and duration), −1 if none, (n,) int64.
        drop_step: first step at which the object, where the nominal run carries it, has
            been out of every gripper for longer than the ground truth's ``drop_time``, −1
            if none, (n,) int64. As in the ground truth a drop alone fails nothing: the
            sample steps on to the end (not decided at the later moments), where the task's
            rule decides it (``incomplete``), and so does the fall rule (``fall_step``).
        fall_step: for a sample that reached the end of the run, the ground truth's fall rule
            (:func:`critmoment.groundtruth.fall_steps`: where the nominal run carries the
            object, it lies on a support, or at rest on anything, touched by no gripper,
            having fallen more than ``fall_height`` since a gripper last touched it) over its
            whole run, the nominal run's steps before the start and its own after: the first
            step of the fall, −1 if none, (n,) int64. A fall fails the sample even when it
            completes the task (a cube dropped mid-carry and picked up again).
        max_slip: largest slip over the chain [m], (n,).
        motor_step: first step of a saturation of a rotational actuator (the ground truth's
            ``saturation`` of its force limit for longer than ``motor_time``) or of a lost
            tracking (further from its target than in the nominal run by more than
            ``tracking_tolerance`` for longer than ``tracking_time``), −1 if none, (n,) int64.
        motor_tracking: that first motor failure is a lost tracking, (n,) bool.
        diverged_step: the first step of the block between the moments in which the
            simulation diverged (MuJoCo raised or warned of instability, or a value went
            non-finite), −1 if none, (n,) int64; a divergence within a moment's window is
            that moment's ``Failure.DIVERGED``.
        incomplete: the sample passed every moment and the watch to the end of the run,
            but the task's success rule (:meth:`critmoment.task.Task.success`, over the
            nominal run's steps before the start and its own after) says it did not complete
            the task, (n,) bool (the ground truth's ``NOT_COMPLETED``).
        release: the first step after the nominal run's last carried one (the end of the
            run if it never carries the object; −1: unknown, every watched failure is late).
        closest: how close the sample came to failing a watched rule, (n,): per rule (slip,
            saturation, tracking), the highest level its quantity held for the rule's whole
            duration, as a fraction of the rule's limit (slip over ``slip_tolerance``,
            force over ``saturation`` of the limit, extra lag over
            ``tracking_tolerance``), the largest over the rules; at 1 or above the rule
            fires (:class:`SustainedLevel`).
    """

    steps: np.ndarray
    samples: np.ndarray
    failure: np.ndarray
    start: int
    stepped: int
    end: int = -1
    slip_step: np.ndarray | None = None
    drop_step: np.ndarray | None = None
    fall_step: np.ndarray | None = None
    max_slip: np.ndarray | None = None
    motor_step: np.ndarray | None = None
    motor_tracking: np.ndarray | None = None
    diverged_step: np.ndarray | None = None
    incomplete: np.ndarray | None = None
    release: int = -1
    closest: np.ndarray | None = None

    def near(self, fraction: float) -> np.ndarray:
        """(n,) bool: samples that pass their chain but held a watched quantity at or
        above ``fraction`` of its rule's limit for the rule's duration (``closest``): the
        chain starts from the nominal state and is the sample's own run only
        approximately, so a pass that close to a rule is decided, like a sparse pass near
        the cost threshold, by the sample's own full rollout.

        Raises:
            ParameterError: ``fraction`` is not a positive finite number.
        """
        if isinstance(fraction, bool) or not isinstance(fraction, (int, float, np.number)) \
                or not (np.isfinite(fraction) and fraction > 0):
            raise ParameterError(f"fraction: expected a positive finite fraction of a rule's "
                                 f"limit, got {fraction!r}")
        n = self.samples.shape[0]
        if self.closest is None:
            return np.zeros(n, bool)
        return ~self.failed & (self.closest >= fraction)

    @property
    def failed(self) -> np.ndarray:
        """(n,) bool: the sample fails at some moment of its own chain, or slips, loses
        the object or saturates a motor between them."""
        return (self.failure > 0).any(axis=0) | self.watched_failed

    @property
    def to_confirm(self) -> np.ndarray:
        """(n,) bool: failures the sample's own full rollout should decide, where the chain
        is the weaker evidence: a failure by a moment's sparse decision (its criteria are not
        the ground truth's: on its own path a force ratio can touch the cone without a real
        slip), a failure by the watch (its first) at or after the step the nominal run
        releases the object (``release``: from there the sample's path differs from the nominal one by
        where the object was set down, and a retreating finger's contact with it can turn on
        a micrometre), and a run that ends with the task incomplete without having dropped
        its object during the hold (a placement off the goal), and a fall onto a support
        (``fall_step``: whether the object lay on the support where the nominal run carries
        it turns on where the sample's own run set it down and picked it up again; without
        verification such a failure stands). A slip or a motor failure
        during the hold, and an incomplete task after a drop during the hold, stand: the
        chain measures them with the ground truth's own rules (started before the grasp,
        the chain's slip is the full rollout's to a micrometre)."""
        n = self.samples.shape[0]
        moment = (self.failure > 0).any(axis=0)
        # the watch's first failure, the one that stopped the sample (what its rules saw
        # after it, up to the end of that block of steps, depends on the block's length)
        first = np.full(n, np.iinfo(np.int64).max)
        for watched in (self.slip_step, self.motor_step, self.diverged_step):
            if watched is not None:
                first = np.where(watched >= 0, np.minimum(first, watched), first)
        late = (first < np.iinfo(np.int64).max) & (first >= self.release)
        incomplete = np.zeros(n, bool) if self.incomplete is None else self.incomplete
        dropped = (np.zeros(n, bool) if self.drop_step is None
                   else (self.drop_step >= 0) & (self.drop_step < self.release))
        fell = np.zeros(n, bool) if self.fall_step is None else self.fall_step >= 0
        return self.failed & (moment | late | (incomplete & ~dropped) | fell)

    def kinds(self) -> list[str | None]:
        """How each sample failed on its chain, the earliest event (None for a pass):
        ``groundtruth.Outcome`` values ("diverged", "motor", "slipped", "dropped",
        "not_completed") for the watch's rules and the task's ("tracking" for a motor
        failure that is a joint lagging its target, not a saturation), or "moment" for a failure
        of a moment's sparse decision on the sample's own state."""
        return [kind for kind, _ in self.first_failures()]

    def first_failures(self) -> list[tuple[str | None, int]]:
        """Per sample, (its :meth:`kinds` entry, the step of that earliest event): −1 for a
        pass, the chain's ``end`` for a task not completed."""
        n = self.samples.shape[0]
        failed = self.failed
        big = np.iinfo(np.int64).max
        events = [("diverged", self.diverged_step), ("motor", self.motor_step),
                  ("slipped", self.slip_step), ("dropped", self.drop_step),
                  ("dropped", self.fall_step)]
        steps = np.where(self.failure > 0, self.steps[:, None], big).min(axis=0) \
            if self.failure.size else np.full(n, big)
        out: list[tuple[str | None, int]] = []
        for i in range(n):
            if not failed[i]:
                out.append((None, -1))
                continue
            when = [(int(a[i]), name) for name, a in events if a is not None and a[i] >= 0]
            if steps[i] < big:
                when.append((int(steps[i]), "moment"))
            if when:
                step, kind = min(when)
                if kind == "motor" and self.motor_tracking is not None \
                        and self.motor_tracking[i]:
                    kind = "tracking"
                out.append((kind, step))
            else:
                out.append(("not_completed", int(self.end)))
        return out

    @property
    def watched_failed(self) -> np.ndarray:
        """(n,) bool: the watch (the ground truth's slip, saturation and tracking rules, and
        divergence) fails the sample somewhere along its chain, or it reaches the end of the
        run without completing the task (a drop fails it so) or having let its object fall
        onto a support (``fall_step``)."""
        out = np.zeros(self.samples.shape[0], bool)
        for watched in (self.slip_step, self.motor_step, self.diverged_step, self.fall_step):
            if watched is not None:
                out = out | (watched >= 0)
        if self.incomplete is not None:
            out = out | self.incomplete
        return out


class _Watch:
    """The ground truth's slip, drop and saturation rules, streamed over a chain's own
    states.

    Slip (as :func:`critmoment.groundtruth.grip_slip`): per gripper and nominal hold
    (``Twin.hold_segments``), from the first step of the hold at which both the sample and
    the nominal run hold the object with it once its grasp has formed
    (``Twin.grasp_formed``), the displacement of the object's points (``Twin.grip_points``)
    in the gripper's frame relative to the nominal run's, the closing axes projected out,
    the farthest point's, counted where the nominal run holds with that gripper alone; a slip is
    a run of more than ``slip_time`` above ``slip_tolerance``. Drop: the object touched
    by no gripper where the nominal run carries it, for longer than ``drop_time``.
    Saturation: a motor-checked actuator (``Twin.motors``) at ``saturation`` of its force
    limit for longer than ``motor_time``. Tracking: such an actuator further from its target
    than in the nominal run by more than ``tracking_tolerance`` for longer than ``tracking_time`` (both
    are the ground truth's MOTOR outcome).
    """

    def __init__(self, ev: SparseEvaluator, n: int, criteria: OutcomeCriteria,
                 start: int = 0, end: int | None = None, samples: np.ndarray | None = None):
        dt = float(ev.twin.model.opt.timestep)
        g = len(ev._anchors)
        self.ev = ev
        # the task's evidence of each sample's own run from start to end (the nominal
        # run's before it), for the task's success rule at the end
        end = ev.n_steps if end is None else end
        self.start = int(start)
        length = max(0, int(end) - self.start)
        ngrip = len(ev.twin.scenario.grippers)
        self.contact_gripper = np.zeros((n, length, ngrip), bool)
        self.contact_support = np.zeros((n, length), bool)
        # single precision: 0.1 µm on a metre, far below any task tolerance; half the memory
        self.object_pos = np.zeros((n, length, 3), np.float32)
        self.object_vel = np.zeros((n, length, 3), np.float32)
        # the robot's free-floating bases' up axes (Task.max_base_tilt), where it has any
        bases = len(ev.twin.robot_bases)
        self.base_axis = np.zeros((n, length, bases, 3), np.float32) if bases else None
        self.found = np.zeros((n, g), bool)
        k = len(ev._points)
        self.offset = np.zeros((n, g, k, 3))
        #: the nominal object's points in each grip where the sample's hold began
        self.grasp = np.zeros((n, g, k, 3))
        self.tolerance = float(criteria.slip_tolerance)
        self.fall_height = float(criteria.fall_height)
        self.slip_step = np.full(n, -1, np.int64)
        self.drop_step = np.full(n, -1, np.int64)
        self.motor_step = np.full(n, -1, np.int64)
        #: the first motor failure is a tracking loss (not a saturation)
        self.motor_tracking = np.zeros(n, bool)
        self.diverged_step = np.full(n, -1, np.int64)
        self.max_slip = np.zeros(n)
        twin = ev.twin
        motors = np.flatnonzero(twin.motors)
        self.force_adr = twin._force_ids[motors]
        # per sample where the box varies a force limit (n, r), else (r,)
        per_sample = None if samples is None else twin.sample_limits(samples)
        self.limits = (twin.limits[motors] if per_sample is None
                       else per_sample[:, motors])
        self.saturation = float(criteria.saturation)
        # tracking: each motor-checked actuator's joint position against the joint target
        # its control sets (Twin.target_scale/offset: a geared or offset servo's target is
        # not its ctrl), beyond the nominal run's own lag, both in joint units
        model = twin.model
        self.act = motors
        self.qadr = model.jnt_qposadr[model.actuator_trnid[motors, 0]]
        self.target_scale = twin.target_scale[motors]
        self.target_offset = twin.target_offset[motors]
        self.nominal_q = twin.qpos(ev._states)  # the nominal run's positions
        # per column [rad or m] (an arm's slide axis has its own tolerance)
        self.tracking_tolerance = 1.0 / tracking_tolerances(criteria, twin.slide[motors])
        # per rule: its running count of steps (n, columns), the steps it must last, and
        # where its first step goes (saturation and tracking are both the MOTOR outcome)
        self.rules = {
            "slip": (np.zeros((n, 1), np.int64), criteria.steps(criteria.slip_time, dt),
                     self.slip_step),
            "drop": (np.zeros((n, 1), np.int64), criteria.steps(criteria.drop_time, dt),
                     self.drop_step),
            "saturation": (np.zeros((n, motors.size), np.int64),
                           criteria.steps(criteria.motor_time, dt), self.motor_step),
            "tracking": (np.zeros((n, motors.size), np.int64),
                         criteria.steps(criteria.tracking_time, dt), self.motor_step)}
        # per rule, its quantity over its limit, as held for the rule's duration
        self.levels = {name: SustainedLevel(n, run.shape[1], need)
                       for name, (run, need, _) in self.rules.items() if name != "drop"}

    def failed(self) -> np.ndarray:
        """Failed by a rule that fails a run whatever its end (a drop does not: the task's
        rule at the end decides a run that lost its object)."""
        return (self.slip_step >= 0) | (self.motor_step >= 0) | (self.diverged_step >= 0)

    def __call__(self, k: int, ids: np.ndarray, sensordata: np.ndarray, xpos: np.ndarray,
                 xmat: np.ndarray, qpos: np.ndarray) -> None:
        ev = self.ev
        ids = np.asarray(ids, dtype=np.int64)
        c, s = xpos.shape[:2]
        if c == 0 or s == 0:
            return
        segments = ev._segments
        if s > 1 and ev._anchors.size:
            # a regrasp of the nominal run within the block: each hold from its own grasp
            cuts = np.flatnonzero((np.diff(segments[k:k + s], axis=0) != 0).any(axis=1)) + 1
            if cuts.size:
                edges = [0, *cuts.tolist(), s]
                for a, b in zip(edges[:-1], edges[1:], strict=False):
                    self(k + a, ids, sensordata[:, a:b], xpos[:, a:b], xmat[:, a:b],
                         qpos[:, a:b])
                return
        if k > self.start and ev._anchors.size:
            fresh = np.flatnonzero(segments[k] != segments[k - 1])
            if fresh.size:
                self.found[np.ix_(ids, fresh)] = False
        # a simulation that went non-finite without MuJoCo raising has diverged
        bad = ~(np.isfinite(sensordata).all(axis=-1) & np.isfinite(qpos).all(axis=-1))
        gone = bad.any(axis=1) & (self.diverged_step[ids] < 0)
        self.diverged_step[ids[gone]] = k + np.argmax(bad[gone], axis=1)
        touch, support = ev.twin.contact_flags(sensordata)          # (c, s, G), (c, s)
        rows = slice(k - self.start, k - self.start + s)
        self.contact_gripper[ids, rows] = touch
        self.contact_support[ids, rows] = support
        self.object_pos[ids, rows] = sensordata[..., ev.twin._pos_adr]
        self.object_vel[ids, rows] = sensordata[..., ev.twin._vel_adr]
        if self.base_axis is not None:
            self.base_axis[ids, rows] = ev.twin.base_axis(sensordata)
        held = touch & ~support[..., None]
        nominal_held = ev._held[k:k + s]                            # (s, G)
        both = held & nominal_held[None]
        slip = np.zeros((c, s))
        if ev._anchors.size:
            rel = _object_in_grippers(xpos, xmat, ev.twin.object_body_id, ev._anchors,
                                      ev._points)
            nominal = ev._nominal_positions(k, s)                   # (s, G, K, 3)
            diff = rel - nominal[None]                              # (c, s, G, K, 3)
            found = self.found[ids]
            # the hold's anchor: its first step touched by both once the grasp has formed
            # (grip_slip's)
            anchor = touch & ev._touching[k:k + s][None] & ev._formed[k:k + s][None]
            first = np.argmax(anchor, axis=1)                       # (c, G)
            new = ~found & anchor.any(axis=1)
            rows, cols = np.nonzero(new)
            offset, grasp = self.offset[ids], self.grasp[ids]
            offset[rows, cols] = diff[rows, first[rows, cols], cols]
            grasp[rows, cols] = nominal[first[rows, cols], cols]
            started = found[:, None, :] | (new[:, None, :] & (
                np.arange(s)[None, :, None] >= first[:, None, :]))
            # the sample's and the nominal's displacements since the hold began; the slip
            # is how far the sample's goes beyond the nominal's (grip_slip's rule)
            transposed = np.swapaxes(ev._projectors, -1, -2)       # per gripper, (G, 3, 3)
            nominal_moved = (nominal[None] - grasp[:, None]) @ transposed
            moved = (diff - offset[:, None]) @ transposed + nominal_moved
            counted = both & started & ev._counted[k:k + s][None]
            farthest = beyond_nominal(moved, nominal_moved).max(axis=-1)  # (c, s, G)
            slip = np.where(counted, farthest, 0.0).max(axis=-1)
            self.offset[ids], self.grasp[ids] = offset, grasp
            self.found[ids] = found | new
        self.max_slip[ids] = np.maximum(self.max_slip[ids], slip.max(axis=1))
        # lost: touched by no gripper where the nominal run carries it (fallen out of the
        # grip); an object set down on a support a little early, still in the grip (a
        # release at the goal), is not a drop, nor is one the grip cannot lift (the
        # moments' decisions see that)
        lost = ev._carried[k:k + s][None] & ~touch.any(axis=-1)
        over = slip > self.tolerance
        with np.errstate(invalid="ignore", divide="ignore"):
            limits = self.limits if self.limits.ndim == 1 else self.limits[ids][:, None]
            load = np.abs(sensordata[..., self.force_adr] / limits)
        saturated = load >= self.saturation
        target = (ev._controls[k:k + s][:, self.act] * self.target_scale
                  + self.target_offset)                                      # (s, r)
        nominal = self.nominal_q[k + 1:k + s + 1, self.qadr]
        q = qpos[..., self.qadr]                                             # (c, s, r)
        excess = np.abs(q - target[None]) - np.abs(nominal - target)[None]
        lagging = excess > self.tracking_tolerance
        flags = {"slip": over[..., None], "drop": lost[..., None], "saturation": saturated,
                 "tracking": lagging}                                 # each (c, s, columns)
        with np.errstate(invalid="ignore", divide="ignore"):
            ratios = {"slip": (slip / self.tolerance)[..., None],
                      "saturation": load / self.saturation,
                      "tracking": excess / self.tracking_tolerance}
        for name, level in self.levels.items():
            level.update(ids, np.nan_to_num(ratios[name], nan=np.inf))
        for name, (run, need, first_step) in self.rules.items():
            run[ids], first = _runs(run[ids], flags[name], need)
            at = k + first - need + 1
            hit = (first >= 0) & (first_step[ids] < 0)
            if name == "tracking":  # shares the motor step: the earlier of the two rules
                hit |= (first >= 0) & (at < first_step[ids])
                self.motor_tracking[ids[hit]] = True
            first_step[ids[hit]] = at[hit]


    def closest(self) -> np.ndarray:
        """(n,) the highest sustained level over the rules (``ChainedResult.closest``)."""
        return np.max([level.best for level in self.levels.values()], axis=0)

    def ends(self, rows: np.ndarray | None = None, *, block: int = 64
             ) -> tuple[np.ndarray, np.ndarray]:
        """The ground truth's rules over each sample's whole run, the nominal run's steps
        before the start and its own after, for ``rows`` (default: all; meaningful for the
        samples that reached the end), ``block`` samples at a time: the task's success rule,
        (r,) bool, and the fall rule (:func:`critmoment.groundtruth.fall_steps`), the first
        step of a fall or −1, (r,) int64."""
        ev = self.ev
        sig = ev.recording.signals
        k = self.start
        rows = (np.arange(self.contact_support.shape[0]) if rows is None
                else np.asarray(rows, dtype=np.int64))
        completed = np.zeros(rows.size, bool)
        fall = np.full(rows.size, -1, np.int64)
        up = np.asarray(ev.twin.task.up, dtype=np.float64)
        for lo in range(0, rows.size, block):
            ids = rows[lo:lo + block]

            def whole(nominal, own, ids=ids):
                before = np.broadcast_to(np.asarray(nominal)[:k],
                                         (ids.size,) + np.shape(nominal[:k]))
                return np.concatenate([before, own[ids]], axis=1)

            evidence = TaskEvidence(
                contact_gripper=whole(sig.contact_gripper, self.contact_gripper),
                contact_support=whole(sig.contact_support, self.contact_support),
                object_pos=whole(sig.object_pos, self.object_pos),
                object_vel=whole(sig.object_vel, self.object_vel),
                dt=float(ev.twin.model.opt.timestep),
                base_axis=None if self.base_axis is None else whole(
                    ev.twin.base_axis(ev.recording.sensordata), self.base_axis))
            completed[lo:lo + block] = np.asarray(ev.twin.task.success(evidence), dtype=bool)
            fall[lo:lo + block] = fall_steps(
                evidence.contact_gripper, evidence.contact_support, ev._carried,
                np.asarray(evidence.object_pos, dtype=np.float64) @ up, self.fall_height,
                speed=np.linalg.norm(evidence.object_vel, axis=-1))
        return completed, fall


class SustainedLevel:
    """The highest level each of n signals (with ``columns`` columns) held for ``need``
    consecutive steps, streamed over blocks of steps: per sample, the largest over columns
    and windows of ``need`` steps of the window's smallest value (a rule "above L for
    ``need`` steps" fires exactly where this level exceeds L).

    Each block's windows start in the previous blocks' last ``need − 1`` steps, which are
    carried over (as −inf before the first step, so a window is never shorter).
    """

    def __init__(self, n: int, columns: int, need: int):
        self.need = max(int(need), 1)
        self.best = np.full(n, -np.inf)
        self.tail = np.full((n, self.need - 1, columns), -np.inf)

    def update(self, ids: np.ndarray, values: np.ndarray) -> None:
        """Stream the values (c, s, columns) of the next s steps of samples ``ids``."""
        if values.shape[1] == 0:
            return
        joined = np.concatenate([self.tail[ids], values], axis=1)  # (c, need-1+s, cols)
        w = self.need
        # each window's min (van Herk's filter, linear in the steps); the ones whose window
        # lies inside the block are those from w // 2 to the end less w - w // 2 - 1
        mins = scipy.ndimage.minimum_filter1d(joined, w, axis=1, mode="nearest")
        inside = mins[:, w // 2:joined.shape[1] - w + w // 2 + 1]
        if inside.shape[1]:
            self.best[ids] = np.maximum(self.best[ids], inside.max(axis=(1, 2)))
        if self.need > 1:
            self.tail[ids] = joined[:, joined.shape[1] - (self.need - 1):]


def _release(ev: SparseEvaluator) -> int:
    """The first step after the nominal run's last carried step (the run's length if it
    never carries the object)."""
    carried = np.flatnonzero(ev._carried)
    return int(carried[-1]) + 1 if carried.size else int(ev.n_steps)


def _runs(run: np.ndarray, flags: np.ndarray, need: int) -> tuple[np.ndarray, np.ndarray]:
    """Streamed run lengths: ``run`` (c, r) steps each column has been on before this
    block, ``flags`` (c, s, r) whether it is on at each step of the block. Returns the run
    lengths after the block and, per simulation, the first step of the block at which some
    column's run reaches ``need`` (-1 if none), as counting step by step would."""
    c, s, _ = flags.shape
    if s == 0:
        return run, np.full(c, -1, np.int64)
    j = np.arange(s)[None, :, None]
    # the last step at or before j that was off (-1: on since the block began)
    last_off = np.maximum.accumulate(np.where(flags, -1, j), axis=1)
    length = np.where(last_off < 0, run[:, None, :] + j + 1, j - last_off)  # (c, s, r)
    reached = (length >= need).any(axis=2)                                    # (c, s)
    first = np.where(reached.any(axis=1), np.argmax(reached, axis=1), -1)
    return length[:, -1, :], first


#: how long before a parameter's onset the chain starts [s]: 2.5 contact time constants at
#: MuJoCo's default solref (0.02 s), time for the object to settle on its support under
#: the sample's own mass before anything touches it
ONSET_MARGIN = 0.05


class NominalOnsets:
    """The nominal run's contacts and actuator forces, as :meth:`Parameter.onset
    <critmoment.params.Parameter.onset>` asks for them (:class:`~critmoment.params.
    NominalContacts`).

    Contacts are found by collision detection on the recorded states, from the first step
    up to ``limit`` (steps past it count as never touching), once; each query is then a
    look-up.
    """

    def __init__(self, evaluator: SparseEvaluator, limit: int):
        twin = evaluator.twin
        model = twin.model
        sc = twin.scenario
        self.n_steps = evaluator.n_steps
        self.limit = int(min(max(limit, 0), self.n_steps))
        self.object_body = int(twin.object_body_id)
        self.object_geoms = frozenset(int(g) for g in np.flatnonzero(
            model.geom_bodyid == self.object_body))
        self.support_geoms = frozenset(int(model.geom(g).id) for g in sc.support_geoms)
        self._evaluator = evaluator
        self._ngeom = int(model.ngeom)
        self._pairs: tuple[np.ndarray, np.ndarray] | None = None

    def _scan(self) -> tuple[np.ndarray, np.ndarray]:
        """The touching geom pairs (p, 2) up to the limit, and the step of each (p,)."""
        if self._pairs is None:
            ev = self._evaluator
            model = ev.twin.model
            data = mujoco.MjData(model)
            pairs, at = [], []
            for k in range(self.limit + 1):
                mujoco.mj_setState(model, data, ev._states[k], STATE_SPEC)
                mujoco.mj_fwdPosition(model, data)
                n = data.ncon
                if n:
                    con = data.contact
                    touching = con.dist[:n] < con.includemargin[:n]
                    pairs.append(con.geom[:n][touching])
                    at.append(np.full(int(touching.sum()), k, np.int64))
            self._pairs = ((np.concatenate(pairs).astype(np.int64), np.concatenate(at))
                           if pairs else (np.zeros((0, 2), np.int64), np.zeros(0, np.int64)))
        return self._pairs

    def first_contact(self, geoms: frozenset[int], exclude: frozenset[int]) -> int:
        pairs, at = self._scan()
        own = np.zeros(self._ngeom, bool)
        own[list(geoms)] = True
        skip = own.copy()
        skip[list(exclude)] = True
        a, b = pairs[:, 0], pairs[:, 1]
        hit = (own[a] & ~skip[b]) | (own[b] & ~skip[a])
        return int(at[hit][0]) if hit.any() else self.n_steps

    def first_force(self, actuator: int, level: float) -> int:
        force = np.abs(self._evaluator.recording.signals.actuator_force[:, actuator])
        # the force read after step k acted from state k
        reached = np.flatnonzero(force >= level * (1.0 - 1e-9))
        return int(reached[0]) if reached.size else self.n_steps


def chain_start(evaluator: SparseEvaluator, steps: Any) -> int:
    """The step a sample's own history starts from: ``ONSET_MARGIN`` before the first step
    at which any uncertain parameter can change the motion (:meth:`Parameter.onset
    <critmoment.params.Parameter.onset>`: the object's mass and friction, once something
    other than its supports touches it; a force limit, once the nominal force reaches the range's
    low end; anything else, from the start), and no later than the first moment.

    Starting at the first moment, which change-point detection usually puts at the first
    touch, restores the nominal state in the middle of the contact's onset; measured on the
    iiwa + Robotiq 2F-140 (docs/real_models.md), the slip a chain measured from there
    varied between 5 and 10.3 mm with the start step, against 10.1–10.35 mm from before
    the touch, where the sample's state still equals the nominal one.

    Args:
        evaluator: the audit's sparse evaluator.
        steps: the audited moments (m,), at least one.

    Returns:
        The start step.
    """
    ev = evaluator
    first = int(np.min(ev.check_steps(steps)))
    known = ev._chain_starts.get(first)
    if known is not None:
        return known
    twin = ev.twin
    run = NominalOnsets(ev, first)
    onset = min((p.onset(i, run) for p, i in zip(twin.scenario.box.parameters,
                                                  twin._param_ids, strict=True)),
                default=0)
    margin = max(ev.horizon, int(np.ceil(ONSET_MARGIN / float(twin.model.opt.timestep))))
    start = ev._chain_starts[first] = int(max(0, min(first, onset - margin)))
    return start


#: fewest samples per part when a chain is shared out to Python threads
_SPLIT_LEAST = 2


def chained_failures(evaluator: SparseEvaluator, steps: Any, samples: Any, *,
                     start: int | None = 0,
                     criteria: OutcomeCriteria | None = None,
                     block: int = 400) -> ChainedResult:
    """Carry each sample's own state from one nominal state through every later moment.

    The simulations start from the recorded state at ``start`` (default 0, the run's own
    initial state: then a chain is the sample's own full run to the bit, as its brute-force
    rollout is; None: :func:`chain_start`, just before the parameters first act, cheaper but
    not bit-exact, since the object's mass already sets how it rests on its support: on a
    chaotic model, robosuite's Panda + Robotiq 2F-85 with an elliptic cone, seed 0, two
    samples that really fail by a joint-tracking loss after the release passed their chains
    from there and fail them from step 0; with hinge fingers out of the motor checks, the
    shipped Panda + Robotiq 2F-85 and iiwa + Robotiq 2F-140 of seed 1, whose nominal runs
    drop the cube, had 3 false safes from there and none from step 0), run the recorded
    controls with
    the sample's own parameters, and at each moment (in time order; one whose window
    overlaps the previous one's is skipped) are decided by the sparse decision over the
    horizon from the state they reached, not the nominal one. All along, from ``start`` to
    the end of the run, the object's slip in its holding gripper, its loss, the saturation
    and tracking of the arm's motors and the simulation's stability are watched with the
    ground truth's own rules and tolerances (``criteria``, default
    :class:`~critmoment.groundtruth.OutcomeCriteria`): between the moments the object creeps
    or shifts in a soft or force-limited grip, which no evaluation from a nominal state
    sees. A sample that reaches the end is decided by the task's success rule over its whole
    run. A sample stops at its first failure; a drop is not one by itself (as in the ground
    truth, it fails a run that does not complete the task): a sample that lost its object
    steps on to the end, undecided at the later moments. The cost is at most the stepping
    from ``start`` to the end, per sample.

    Args:
        evaluator: the audit's sparse evaluator.
        steps: moments, physics step indices (m,).
        samples: parameter values (n, k).
        start: the step the chain starts from (default 0; None: :func:`chain_start`).
        criteria: the slip and drop tolerances (default: the ground truth's).
        block: physics steps per batch call between the moments (default 400: a quarter
            of the calls, and of the hand-overs of Python's lock to the thread that makes
            them, that 100 took; a failed sample stops at the end of its block, a divergence
            MuJoCo warns of is dated to its block's first step).

    Returns:
        The :class:`ChainedResult`.

    Raises:
        ParameterError: bad steps, samples, criteria or block.
    """
    ev = evaluator
    samples = ev.check_samples(samples)
    steps = np.unique(ev.check_steps(steps))
    first = chain_start(ev, steps) if start is None else int(ev.check_steps([start])[0])
    steps = steps[steps >= first]
    criteria = OutcomeCriteria() if criteria is None else criteria
    if not isinstance(criteria, OutcomeCriteria):
        raise ParameterError(f"criteria: expected an OutcomeCriteria, got "
                             f"{type(criteria).__name__}")
    if isinstance(block, bool) or not isinstance(block, (int, np.integer)) or block < 1:
        raise ParameterError(f"block: expected an integer >= 1 (physics steps per batch "
                             f"call), got {block!r}")
    parts = ev._shared_out(samples.shape[0], _SPLIT_LEAST, lambda fork, rows: chained_failures(
        fork, steps, samples[rows], start=first, criteria=criteria, block=block))
    if parts is not None:
        # each sample's chain is its own: the result is the same as in one thread, and
        # while one thread watches its block's records in Python the other steps
        return _join_chains(parts, samples)
    h = ev.horizon
    # to the end of the run, as the ground truth watches it: after the release the arm
    # still retreats past an object its own history may have placed elsewhere, and a
    # simulation can still go unstable
    end = ev.n_steps
    n = samples.shape[0]
    watch = _Watch(ev, n, criteria, first, end, samples=samples)
    kept: list[int] = []  # a moment whose window overlaps the previous kept one is skipped
    for k in (int(s) for s in steps):
        if not kept or k >= kept[-1] + h:
            kept.append(k)
    failure = np.full((len(kept), n), -1, dtype=np.int8)
    stepped = 0
    for lo in range(0, n, ev.chunk):
        rows = np.arange(lo, min(n, lo + ev.chunk))
        stepped = max(stepped, _chain_chunk(ev, watch, samples[rows], rows, kept, first, end,
                                            block, failure))
    # a sample that reached the end of the run, the task's own success rule decides (the
    # ground truth's NOT_COMPLETED: placed off the goal, not released, still moving)
    reached = ~(failure > 0).any(axis=0) & ~watch.failed()
    incomplete = np.zeros(n, bool)
    fall_step = np.full(n, -1, np.int64)
    completed, fall_step[reached] = watch.ends(np.flatnonzero(reached))
    incomplete[reached] = ~completed
    return ChainedResult(steps=np.array(kept, dtype=np.int64), samples=samples,
                         failure=failure, start=first, stepped=stepped, end=end,
                         incomplete=incomplete, release=_release(ev),
                         slip_step=watch.slip_step, drop_step=watch.drop_step,
                         fall_step=fall_step,
                         max_slip=watch.max_slip, motor_step=watch.motor_step,
                         motor_tracking=watch.motor_tracking,
                         closest=watch.closest(),
                         diverged_step=watch.diverged_step)


def _join_chains(parts: list[ChainedResult], samples: np.ndarray) -> ChainedResult:
    """One :class:`ChainedResult` of the chains of consecutive parts of ``samples``."""
    head = parts[0]
    per_sample = {}
    for f in dataclasses.fields(ChainedResult):
        value = getattr(head, f.name)
        if f.name == "failure":
            per_sample[f.name] = np.concatenate([p.failure for p in parts], axis=1)
        elif f.name not in ("samples", "steps") and isinstance(value, np.ndarray):
            per_sample[f.name] = np.concatenate([getattr(p, f.name) for p in parts])
    return dataclasses.replace(head, samples=samples,
                               stepped=max(p.stepped for p in parts), **per_sample)


def _chain_chunk(ev: SparseEvaluator, watch: _Watch, samples: np.ndarray, rows: np.ndarray,
                 kept: list[int], first: int, end: int, block: int,
                 failure: np.ndarray) -> int:
    """Run one chunk of samples (``rows`` of the whole) along the chain; fill ``failure``
    and the watch; the steps taken."""
    batch, mu = ev._batch(samples)
    batch.state[:] = ev._start_row(first)
    alive = np.ones(rows.size, bool)
    raised = np.zeros(rows.size, bool)

    def watched(k, ids, sensordata, xpos, xmat, qpos):
        watch(k, rows[ids], sensordata, xpos, xmat, qpos)

    def step(k, nstep, ids):
        """Step the simulations ``ids`` ``nstep`` steps from k under the watch; a block in
        which MuJoCo raised or warned of an unstable step (as _simulate counts divergence)
        is where they diverged."""
        batch.warning[...] = 0
        ev._roll(batch, k, nstep, ids, raised, watched, measure_slip=False)
        gone = ids[(raised[ids] | (batch.warning[ids, :, 1] > 0).any(axis=1))
                   & (watch.diverged_step[rows[ids]] < 0)]
        watch.diverged_step[rows[gone]] = k

    current = taken = first
    for j, k in enumerate([*kept, None]):
        target = end if k is None else k
        while current < target and alive.any():
            budget.check_cancelled()
            nstep = min(block, target - current)
            step(current, nstep, np.flatnonzero(alive))
            current += nstep
            alive &= ~watch.failed()[rows]
        taken = max(taken, current)
        if k is None or not alive.any():
            break
        # a sample whose object is out of every gripper where the nominal run carries it
        # is not decided at the moments (its grip has nothing to hold): it steps on to the
        # end, where the task's rule decides it, as the ground truth counts a drop only in
        # a run that does not complete the task (the object can be caught again: a cube
        # that bounces between the grippers at a hand-over)
        lost = watch.drop_step[rows] >= 0
        run = np.flatnonzero(alive & ~lost)
        sim = ev._simulate(batch, k, run, mu, keep_state=False, restore=False, watch=watched)
        failure[j, rows[run]] = sim.failure[run]
        dropped = np.flatnonzero(alive & lost)
        if dropped.size:
            step(k, ev.horizon, dropped)
        current = k + ev.horizon
        taken = max(taken, current)
        alive[run[sim.failure[run] > 0]] = False
        alive &= ~watch.failed()[rows]
    return taken - first

