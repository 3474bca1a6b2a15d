"""Before the audit: can the twin reproduce the nominal motion, and does the trajectory fit?

:func:`check_feasibility` reads the nominal frequent rollout (a
:class:`~critmoment.recording.Recording`) and checks, for every actuator on a joint:

* **tracking**: the lag |q − target| of position-like actuators, where the target is what
  the actuator commands (``(gain·ctrl + biasprm[0]) / −biasprm[1]`` in actuator length,
  divided by the gear; ``ctrl`` itself for a ``<position>`` servo);
* **saturation**: how long |force| sits at its limit, the smallest of the scenario's
  ``[limits]``, the MJCF ``forcerange`` and the joint's ``actuatorfrcrange``;
* **static infeasibility**: joint ``frictionloss`` above what the actuator can ever exert
  (limit × gear) on a joint whose target moves.

Grippers (actuators of the action channels marked ``normalised``) legitimately lag and
saturate when they close on the object, so their lag and saturation are reported but never
fail the check. When the twin cannot follow, :class:`~critmoment.exceptions.InfeasibleTwinError`
says which joint, how far behind, for how long, from when, and the likely cause.

:func:`check_fit` looks for the other usual mistake, a trajectory that does not belong to the
scenario: the wrong action width (it names the bundled scenario of that width), gripper or
joint values in the wrong units, and a nominal run that never touches or never lifts the
object. :func:`preflight` runs both on a recording and emits the fit warnings.
"""

from __future__ import annotations

import dataclasses
import enum
import logging
import warnings
from collections.abc import Mapping

import mujoco
import numpy as np

from critmoment import actuators as act_info
from critmoment.exceptions import (
    CritmomentError,
    CritmomentWarning,
    InfeasibleTwinError,
    ParameterError,
    TrajectoryError,
)
from critmoment.recording import Recording
from critmoment.scenario import GENERATED, FeasibilityOptions
from critmoment.trajectory import Trajectory
from critmoment.twin import STATE_SPEC, Twin, carried_flags

__all__ = [
    "FeasibilityOptions",
    "JointFeasibility",
    "FeasibilityReport",
    "FitWarning",
    "check_feasibility",
    "check_fit",
    "preflight",
]

log = logging.getLogger(__name__)

#: task kinds whose success needs the object lifted (every kind critmoment knows today)
_LIFT_TASKS = ("handover", "pick_place", "pick_hold")
#: share of a lag stretch's largest lag that the servo's velocity damping must explain at
#: the target's speed for the message to name the damping as the likely cause
DAMPING_SHARE = 0.5
#: share of a saturated actuator's steps whose force changes sign from the step before,
#: from which the saturation is called a numerical oscillation (a stiff servo under an
#: explicit integrator), not a load
FLIP_SHARE = 0.25
#: the share of the lag tolerance a servo's dry-friction band (frictionloss / stiffness) must
#: reach for the message to name the joint's friction as the likely cause
FRICTION_BAND_SHARE = 0.5
#: the window over which the target's acceleration is read [s]: its velocity change over
#: about one action period, so that the kinks of linearly interpolated targets do not read
#: as accelerations of one physics step
ACCEL_WINDOW = 0.02
#: penetration of the object into another geom at the start that gets a fit warning [m]
START_PENETRATION = 0.002
#: fall of the object after its last touch by a gripper that gets a fit warning [m]
RELEASE_HEIGHT = 0.03


class FitWarning(CritmomentWarning):
    """A trajectory that probably does not belong to its scenario (see :func:`check_fit`)."""


class _Kind(enum.Enum):
    """How an actuator acts on its joint, as far as tracking is concerned (the values are
    those of :class:`critmoment.actuators.ActuatorKind` where both know the shape)."""

    POSITION = "position"   #: fixed gain, affine bias with biasprm[1] < 0: a position servo
    VELOCITY = "velocity"   #: affine bias on velocity only: tracks a velocity, not a position
    MOTOR = "motor"         #: no bias: a force/torque motor, ctrl is a force
    OTHER = "other"         #: another gain/bias, or a transmission other than a joint


def _classify(model: mujoco.MjModel, actuator: int) -> tuple[_Kind, str]:
    """The kind of actuator ``actuator`` and a note on why it is (not) tracked.

    Args:
        model: the compiled model.
        actuator: actuator id.

    Returns:
        (kind, note); the note is empty for a trackable position actuator on a joint.
    """
    if model.actuator_trntype[actuator] != mujoco.mjtTrn.mjTRN_JOINT:
        trn = mujoco.mjtTrn(int(model.actuator_trntype[actuator])).name
        return _Kind.OTHER, f"transmission {trn}: lag not checked (joint transmissions only)"
    gain = int(model.actuator_gaintype[actuator])
    bias = int(model.actuator_biastype[actuator])
    bp = model.actuator_biasprm[actuator]
    if bias == mujoco.mjtBias.mjBIAS_NONE:
        return _Kind.MOTOR, "motor (no bias): ctrl is a force, lag not checked"
    if gain != mujoco.mjtGain.mjGAIN_FIXED or bias != mujoco.mjtBias.mjBIAS_AFFINE:
        return _Kind.OTHER, "gain/bias not fixed/affine: lag not checked"
    if bp[1] < 0:
        if model.actuator_dyntype[actuator] != mujoco.mjtDyn.mjDYN_NONE:
            return _Kind.OTHER, ("position-like with activation dynamics: the target "
                                        "is the activation, lag not checked")
        return _Kind.POSITION, ""
    if bp[2] < 0:
        return _Kind.VELOCITY, "velocity servo: tracks a velocity, lag not checked"
    return _Kind.OTHER, "affine bias without a position term: lag not checked"


@dataclasses.dataclass(frozen=True)
class JointFeasibility:
    """Tracking and saturation of one actuator on its joint over the nominal run.

    Attributes:
        actuator: actuator name.
        joint: joint name.
        kind: the actuator's force law as far as tracking goes: "position" (fixed gain,
            affine bias with biasprm[1] < 0; lag tracked), "velocity", "motor" or "other"
            (lag not tracked, see ``note``).
        unit: the joint's unit, "rad" (hinge) or "m" (slide).
        gripper: the actuator belongs to a normalised (gripper) channel.
        max_lag: largest |q − target| [rad or m] (NaN when not tracked).
        max_lag_time: when it occurs [s] (NaN when not tracked).
        lag_duration: longest continuous stretch with the lag above tolerance [s]; where
            a contact holds the joint back over it, a shorter failing stretch that no
            contact explains, if any (the one the twin cannot follow).
        lag_start: start of that stretch [s] (None when there is none).
        lag_in_run: largest lag within that stretch [rad or m] (0 when none).
        saturation_duration: longest continuous stretch at the force limit [s] (chosen as
            ``lag_duration``'s).
        saturation_start: start of that stretch [s] (None when there is none).
        saturation_total: total time at the force limit [s].
        force_limit: the limit used, in actuator units [N·m or N] (inf when none).
        limit_source: "[limits]", "forcerange" or "actuatorfrcrange".
        frictionloss: the joint's frictionloss [N·m or N].
        target_span: range of the joint's target over the run [rad or m] (NaN when not
            tracked).
        note: why the lag is not tracked, or "".
        blocked_by: the contact (geom pair) that holds the joint back during its lag or
            saturation stretch, or "": the robot pushes against something (itself, the
            object, the support), which is a fact of the motion, not of the twin.
        jammed: that contact is between two of the robot's own bodies and touches already at
            the start: its collision geometry overlaps there (a defect of the model, which
            the twin cannot reproduce the motion through), not something the motion meets.
        damping_force: the joint's own viscous damping times its highest speed over the
            longest saturation [N·m or N, at the joint].
        saturation_speed: that speed [rad/s or m/s].
        target_speed: the target's highest speed over the lag stretch [rad/s or m/s]
            (0 when there is none).
        load_lag: the sag a position servo's stiffness gives under the largest force it
            exerts over the lag stretch (gravity, the object it holds): force / (stiffness ×
            gear) [rad or m] (0 when there is no stretch).
        damping_lag: the lag the servo's velocity damping alone gives at that speed, at
            steady state: (kv + joint damping / gear²) / kp × speed [rad or m] (0 when there
            is no stretch).
        friction_band: how far a position servo's error must grow before it overcomes the
            joint's dry friction, frictionloss / (kp × gear²) [rad or m] (0 for other
            actuators).
        spring_force: the joint's own spring (its ``stiffness`` times the distance from
            its ``springref``) at its largest over the longest saturation, else over the lag
            stretch [N·m or N, at the joint].
        force_flips: of the consecutive steps both at the force limit, the fraction whose
            force changes sign (a numerical oscillation between +limit and −limit, not a
            load).
        target_accel: the target's largest acceleration over the longest saturation or the
            lag stretch, its velocity change over :data:`ACCEL_WINDOW` [rad/s² or m/s²]
            (read, with the two below, only for a joint with a failing stretch; 0 else).
        inertial_force: the largest over that stretch of what following every servo's
            targets' acceleration takes at this joint on the robot's inertia, |M[dof, :] ·
            q̈_target| (armature included) [N·m or N, at the joint]: a motion too fast for
            the actuator, not a load it holds, where it takes most of the limit and the
            bias force does not.
        bias_force: the median over that stretch of the bias force at this joint (gravity,
            Coriolis, centrifugal; |qfrc_bias|) [N·m or N].
    """

    actuator: str
    joint: str
    kind: str
    unit: str
    gripper: bool
    max_lag: float
    max_lag_time: float
    lag_duration: float
    lag_start: float | None
    lag_in_run: float
    saturation_duration: float
    saturation_start: float | None
    saturation_total: float
    force_limit: float
    limit_source: str
    frictionloss: float
    target_span: float
    note: str = ""
    blocked_by: str = ""
    jammed: bool = False
    target_speed: float = 0.0
    damping_force: float = 0.0
    saturation_speed: float = 0.0
    force_flips: float = 0.0
    damping_lag: float = 0.0
    friction_band: float = 0.0
    load_lag: float = 0.0
    spring_force: float = 0.0
    target_accel: float = 0.0
    inertial_force: float = 0.0
    bias_force: float = 0.0

    def to_json(self) -> dict:
        """JSON-able dict (kind as its value, non-finite numbers as None)."""
        out = {}
        for f in dataclasses.fields(self):
            v = getattr(self, f.name)
            if isinstance(v, enum.Enum):
                v = v.value
            elif isinstance(v, float) and not np.isfinite(v):
                v = None
            out[f.name] = v
        return out


@dataclasses.dataclass(frozen=True)
class FeasibilityReport:
    """What :func:`check_feasibility` (and :func:`preflight`) found.

    Attributes:
        joints: one entry per actuator on a joint, in actuator order.
        problems: why the twin cannot reproduce the nominal motion, one line each (empty
            when feasible).
        notes: actuators not checked and why, one line each.
        warnings: lags and saturations beyond tolerance where a contact holds the joint
            back (see ``JointFeasibility.blocked_by``), one line each; not problems.
        fit_warnings: :func:`check_fit`'s warnings (filled by :func:`preflight`).
        options: the tolerances used.
        duration: length of the checked run [s].
    """

    joints: tuple[JointFeasibility, ...]
    problems: tuple[str, ...]
    notes: tuple[str, ...]
    options: FeasibilityOptions
    duration: float
    warnings: tuple[str, ...] = ()
    fit_warnings: tuple[str, ...] = ()

    @property
    def feasible(self) -> bool:
        return not self.problems

    def joint(self, name: str) -> JointFeasibility:
        """The entry of actuator or joint ``name``."""
        for j in self.joints:
            if name in (j.actuator, j.joint):
                return j
        raise ParameterError(f"no actuator or joint {name!r} in the feasibility report; known: "
                             f"{', '.join(j.actuator for j in self.joints)}")

    def to_json(self) -> dict:
        """The report's ``feasibility`` section."""
        return {"feasible": self.feasible, "problems": list(self.problems),
                "notes": list(self.notes), "warnings": list(self.warnings),
                "fit_warnings": list(self.fit_warnings),
                "duration": self.duration, "options": dataclasses.asdict(self.options),
                "joints": [j.to_json() for j in self.joints]}


#: failing stretches of one joint looked at for one that no contact explains
_STRETCHES = 6


def _runs(flags: np.ndarray) -> list[tuple[int, int]]:
    """(start, length) of each run of True in ``flags`` (T,), longest first (earliest first
    among equal lengths); [] when none."""
    if not flags.any():
        return []
    edges = np.flatnonzero(np.diff(np.concatenate([[0], flags.astype(np.int8), [0]])))
    starts, stops = edges[::2], edges[1::2]
    order = np.argsort(-(stops - starts), kind="stable")
    return [(int(starts[i]), int(stops[i] - starts[i])) for i in order]


def _overlapping(runs: list[tuple[int, int]], run: tuple[int, int]) -> tuple[int, int]:
    """The longest of ``runs`` that overlaps ``run`` (start, length), or (0, 0)."""
    start, length = run
    for s0, n0 in runs:
        if s0 < start + length and start < s0 + n0:
            return s0, n0
    return 0, 0


def _tracking_error(q: np.ndarray, target: np.ndarray, shift: int) -> np.ndarray:
    """|q(t) − target(t − d)| minimised over delays d of 0..``shift`` steps, (T,).

    A servo follows a moving target a little late (by about (kv + damping)/kp); a delayed
    copy of the motion is still the motion. What is left after the delay is a joint that
    sags, sticks or is blocked.
    """
    err = np.abs(q - target)
    if shift > 0 and target.size:
        padded = np.concatenate([np.full(shift, target[0]), target])
        for s in range(1, shift + 1):
            np.minimum(err, np.abs(q - padded[shift - s:shift - s + q.size]), out=err)
    return err


def _tracked(m: mujoco.MjModel, a: int, kind: _Kind) -> bool:
    """Actuator ``a`` is a position servo on a hinge or slide: its target is a position."""
    return kind is _Kind.POSITION and int(m.jnt_type[m.actuator_trnid[a, 0]]) in (
        int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))


def _servo_target(m: mujoco.MjModel, a: int, controls: np.ndarray
                  ) -> tuple[np.ndarray, np.ndarray]:
    """The joint position position servo ``a`` drives to at each step, (T,), within the
    joint's range, and where its control asks past that range, (T,) bool."""
    j = int(m.actuator_trnid[a, 0])
    gear = float(m.actuator_gear[a, 0]) or 1.0
    gain = m.actuator_gainprm[a, 0]
    b0, b1 = m.actuator_biasprm[a, :2]
    target = (gain * controls[:, a] + b0) / (-b1) / gear
    # a target past the joint's range is a push against a load (ADROIT's lift slide
    # commanded past its range to hold the 4.9 kg hand up), not a position to reach:
    # those steps are no lag
    past = np.zeros(target.shape[0], bool)
    if m.jnt_limited[j]:
        past = (target < m.jnt_range[j, 0]) | (target > m.jnt_range[j, 1])
        target = np.clip(target, *m.jnt_range[j])
    return target, past


def _target_accelerations(m: mujoco.MjModel, targets: Mapping[int, np.ndarray], n: int,
                          dt: float) -> np.ndarray:
    """The acceleration of each position servo's target (``targets``: by actuator, (T,))
    at its joint's dof, (T, nv), 0 elsewhere: the velocity change over
    :data:`ACCEL_WINDOW` around each step."""
    out = np.zeros((n, m.nv))
    w = max(1, int(round(ACCEL_WINDOW / dt)))
    if n <= 2 * w:
        return out
    for a, target in targets.items():
        dof = int(m.jnt_dofadr[m.actuator_trnid[a, 0]])
        out[w:n - w, dof] = (target[2 * w:] - 2.0 * target[w:n - w] + target[:n - 2 * w]) \
            / (w * dt) ** 2
    return out


def _gripper_actuators(twin: Twin) -> set[int]:
    """The actuators of a gripper: those on a normalised channel, and those the twin keeps
    out of the motor checks as fingers (on a joint below a gripper's base: a hand's
    fingers, each on a channel of its own, that close on the object and lag there by
    design; ADROIT's were refused as arm joints that could not follow)."""
    conv = twin.scenario.actions
    out: set[int] = set()
    for names, normalised in zip(conv.channels, conv.normalised, strict=True):
        if normalised:
            out.update(twin.model.actuator(a).id for a in names)
    out.update(int(i) for i in np.flatnonzero(twin.fingers))
    return out


def _force_limit(twin: Twin, a: int) -> tuple[float, str]:
    """The smallest force limit of actuator ``a`` in actuator units, and where it comes from."""
    m = twin.model
    # the scenario's limit is named as such only where its [limits] table sets it (else it
    # is the model's own, read from the attributes below); first, so that it wins a tie
    source = twin.scenario.limit_sources.get(twin.actuator_names[a], "scenario")
    candidates = [(float(twin.limits[a]), "[limits]")] if source == "scenario" else []
    own = act_info.range_limit(m.actuator_forcerange[a]) if m.actuator_forcelimited[a] else None
    joint = act_info.joint_force_limit(m, a)
    candidates += [(float(v), where) for v, where in ((own, "forcerange"),
                                                      (joint, "actuatorfrcrange"))
                   if v is not None]
    if not candidates:
        candidates.append((float(twin.limits[a]), "the model"))
    return min(candidates, key=lambda c: c[0])


def _unit(model: mujoco.MjModel, joint: int) -> str:
    return "m" if model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_SLIDE else "rad"


@dataclasses.dataclass(frozen=True, eq=False)
class _JointSignals:
    """One actuated joint's signals over the run, for :meth:`entry`: its lag (None where not
    tracked), its target, its position servo's bias gain (−kp, 0 when none) and, per step,
    the sign of its target less its position."""

    model: mujoco.MjModel
    states: np.ndarray
    qpos: np.ndarray
    force: np.ndarray
    dt: float
    actuator: int
    joint: int
    gear: float
    tol: float
    options: FeasibilityOptions
    lag: np.ndarray | None
    target: np.ndarray | None
    bias: float
    toward: np.ndarray | None
    target_accel: np.ndarray

    def _inertial(self, start: int, length: int) -> tuple[float, float, float]:
        """Over steps [start, start + length): the target's largest acceleration, the
        largest force the robot's inertia takes at this joint to follow every servo's
        targets, |M[dof, :] · q̈_target| (its own acceleration and the others' through the
        mass matrix), and the median bias force there, |qfrc_bias| (gravity, Coriolis and
        centrifugal); (0, 0, 0) without an accelerating target. The bias is a median: a
        shoulder at its limit for 2.5 s holding the arm up meets a brief peak of its
        targets' acceleration too (at most 200 steps of the stretch are read, and the
        acceleration's peaks)."""
        m, dof, acc = self.model, int(self.model.jnt_dofadr[self.joint]), self.target_accel
        lo, hi = max(0, start), min(acc.shape[0], start + length)
        if length <= 0 or hi <= lo or not acc[lo:hi].any():
            return 0.0, 0.0, 0.0
        part = acc[lo:hi]
        peaks = {lo + int(np.argmax(np.abs(part[:, dof]))),
                 lo + int(np.argmax(np.abs(part).sum(axis=1)))}
        steps = sorted(set(range(lo, hi, max(1, (hi - lo) // 200))) | peaks)
        data = mujoco.MjData(m)
        dense = np.zeros((m.nv, m.nv))
        inertial, bias = np.zeros(len(steps)), np.zeros(len(steps))
        for i, k in enumerate(steps):
            mujoco.mj_setState(m, data, self.states[min(k + 1, len(self.states) - 1)],
                               STATE_SPEC)
            mujoco.mj_forward(m, data)
            mujoco.mj_fullM(m, data, dense)
            inertial[i] = abs(float(dense[dof] @ acc[k]))
            bias[i] = abs(float(data.qfrc_bias[dof]))
        return float(np.abs(part[:, dof]).max()), float(inertial.max()), float(np.median(bias))

    def entry(self, base: JointFeasibility, lag_run: tuple[int, int],
              sat_run: tuple[int, int]) -> JointFeasibility:
        """``base`` with these (start, length) stretches of lag and saturation, and the
        contact that holds the joint back over its failing one, if any."""
        m, a, j, dt, gear, b1 = (self.model, self.actuator, self.joint, self.dt, self.gear,
                                 self.bias)
        n = self.force.shape[0]
        lag_start, lag_len = lag_run
        sat_start, sat_len = sat_run
        lag_in_run = speed = damping_lag = load_lag = 0.0
        if lag_len:
            lag_in_run = float(self.lag[lag_start:lag_start + lag_len].max())
        if lag_len and n > 1 and b1 < 0:
            part = self.target[lag_start:lag_start + lag_len + 1]
            speed = float(np.abs(np.diff(part)).max(initial=0.0)) / dt
            kv = max(0.0, -float(m.actuator_biasprm[a, 2]))
            damping = float(m.dof_damping[m.jnt_dofadr[j]])
            damping_lag = (kv + damping / gear ** 2) / (-b1) * speed
            exerted = np.abs(self.force[lag_start:lag_start + lag_len, a])
            load_lag = float(exerted.max(initial=0.0)) / (-b1 * abs(gear))
        damping_force = sat_speed = 0.0
        if sat_len and n > 1:
            # the joint's own viscous damping at its speed over the saturation, where the
            # actuator drives the motion (pushes the way the joint moves; a joint sagging
            # against its push is a load the damping only slows): a heavily damped joint
            # moved fast uses its actuator up on the damping alone
            qs = self.qpos[sat_start:sat_start + sat_len + 1, int(m.jnt_qposadr[j])]
            v = np.diff(qs) / dt
            push = self.force[sat_start:sat_start + v.size, a] * np.sign(gear)
            driving = np.sign(push) * np.sign(v) > 0
            sat_speed = float(np.abs(v[driving]).max(initial=0.0))
            damping_force = float(m.dof_damping[m.jnt_dofadr[j]]) * sat_speed
        spring_force = 0.0
        start, length = (sat_start, sat_len) if sat_len else (lag_start, lag_len)
        if length and m.jnt_stiffness[j] > 0:
            adr = int(m.jnt_qposadr[j])
            stretch = self.qpos[start:start + length + 1, adr] - m.qpos_spring[adr]
            spring_force = float(m.jnt_stiffness[j] * np.abs(stretch).max(initial=0.0))
        entry = dataclasses.replace(
            base, lag_duration=lag_len * dt, lag_start=lag_start * dt if lag_len else None,
            lag_in_run=lag_in_run, saturation_duration=sat_len * dt,
            saturation_start=sat_start * dt if sat_len else None, target_speed=speed,
            damping_lag=damping_lag, load_lag=load_lag, damping_force=damping_force,
            saturation_speed=sat_speed, spring_force=spring_force)
        failing = _failing_stretch(entry, self.tol, abs(gear), self.options)
        if failing is not None:
            # what the causes read, for a joint that has one to name only (a mass matrix
            # per step read: a gripper squeezing at its limit all through a hold has none)
            blocked, jammed = _blocking_contact(m, self.states, *failing, joint=j,
                                                toward=self.toward)
            # over the saturation and over the lag stretch (the saturation a lag follows
            # from may be another stretch than the longest)
            accel, inertial, bias_force = max(
                (self._inertial(*run) for run in (sat_run, lag_run)), key=lambda r: r[1])
            entry = dataclasses.replace(entry, blocked_by=blocked, jammed=jammed,
                                        target_accel=accel, inertial_force=inertial,
                                        bias_force=bias_force)
        return entry


def check_feasibility(recording: Recording, twin: Twin, *,
                      options: FeasibilityOptions | None = None,
                      raise_on_failure: bool = True,
                      observed: np.ndarray | None = None) -> FeasibilityReport:
    """Can the twin reproduce the nominal motion of ``recording``?

    Args:
        recording: the nominal frequent rollout of the trajectory.
        twin: its twin.
        options: tolerances; default the scenario's (``[feasibility]``).
        raise_on_failure: raise :class:`InfeasibleTwinError` on the first problem (else
            return the report with ``problems`` filled).
        observed: the controls whose servo targets are the joints' recorded or planned
            path (:func:`critmoment.recording.observed_controls` of a trajectory with
            ``observed``), (n_steps, nu), or None. A joint that follows that path is no
            lag, however far its target leads it (a feed-forward target on a soft servo).

    Returns:
        The report, one :class:`JointFeasibility` per actuator on a joint.

    Raises:
        InfeasibleTwinError: the twin cannot follow (friction above the force limit on a
            joint that must move, lag above tolerance or saturation for longer than allowed,
            outside the grippers); the message names the joint, the lag [rad or m], its
            duration [s], its start [s] and the likely cause.
    """
    from critmoment.recording import check_recording
    from critmoment.twin import resolve_twin

    check_recording(recording)
    twin = resolve_twin(None, twin)
    if options is None:
        options = twin.scenario.feasibility
    elif not isinstance(options, FeasibilityOptions):
        raise ParameterError(f"options: expected FeasibilityOptions or None, got "
                             f"{type(options).__name__} {options!r}")
    m = twin.model
    dt = float(recording.dt)
    n = recording.n_steps
    controls = np.asarray(recording.controls, dtype=np.float64)
    if controls.shape != (n, m.nu):
        raise ParameterError(f"recording: expected controls of shape ({n}, {m.nu}) for this "
                             f"twin, got {controls.shape}: recorded with another scenario?")
    if observed is not None:
        # (a run cut short, by a divergence, is checked over the steps it has)
        observed = np.asarray(observed, dtype=np.float64)[:n]
        if observed.shape != (n, m.nu):
            raise ParameterError(f"observed: expected controls of shape ({n}, {m.nu}) (one "
                                 f"row per step of the recording), got {observed.shape}")
    states = np.asarray(recording.states)
    qpos = twin.qpos(states)
    force = np.asarray(recording.signals.actuator_force)
    grippers = _gripper_actuators(twin)
    # every position servo's target, (T,) by actuator, and its acceleration at the dofs
    servo_targets = {a: _servo_target(m, a, controls) for a in range(m.nu)
                     if m.actuator_trntype[a] == mujoco.mjtTrn.mjTRN_JOINT
                     and _tracked(m, a, _classify(m, a)[0])}
    target_accel = _target_accelerations(
        m, {a: target for a, (target, _) in servo_targets.items()}, n, dt)
    joints, problems, notes, held = [], [], [], []
    for a in range(m.nu):
        name = m.actuator(a).name or f"actuator #{a}"
        if m.actuator_trntype[a] != mujoco.mjtTrn.mjTRN_JOINT:
            notes.append(f"{name}: {_classify(m, a)[1]}")
            continue
        j = int(m.actuator_trnid[a, 0])
        jname = m.joint(j).name or f"joint #{j}"
        unit = _unit(m, j)
        kind, note = _classify(m, a)
        if note:
            notes.append(f"{name}: {note}")
        gear = float(m.actuator_gear[a, 0]) or 1.0
        limit, source = _force_limit(twin, a)
        tol = options.lag_tolerance_slide if unit == "m" else options.lag_tolerance
        is_gripper = a in grippers
        max_lag = max_lag_time = span = float("nan")
        toward = None
        lag = target = None
        band = 0.0
        friction = float(m.dof_frictionloss[m.jnt_dofadr[j]])
        b1 = 0.0
        if a in servo_targets:
            b1 = m.actuator_biasprm[a, 1]
            target, past = servo_targets[a]
            q = qpos[1:n + 1, int(m.jnt_qposadr[j])]
            toward = np.sign(target[:q.size] - q)
            shift = int(round(options.delay / dt))
            lag = _tracking_error(q, target, shift)
            lag = np.where(past[:lag.size], 0.0, lag)
            if observed is not None:
                # the joint on its recorded or planned path is the motion, wherever its
                # target leads it
                path, _ = _servo_target(m, a, observed)
                lag = np.minimum(lag, _tracking_error(q, path, shift))
            k = int(np.argmax(lag))
            max_lag, max_lag_time = float(lag[k]), k * dt
            span = float(np.ptp(target)) if n else 0.0
            if b1 < 0:
                band = friction / (-b1 * gear ** 2)
        saturated = np.abs(force[:, a]) >= options.saturation_fraction * limit
        both = saturated[1:] & saturated[:-1]
        flips = both & (np.sign(force[1:, a]) != np.sign(force[:-1, a]))
        force_flips = float(flips.sum()) / max(1, int(both.sum()))
        lag_runs = [] if lag is None else _runs(lag > tol)
        sat_runs = _runs(saturated)

        sig = _JointSignals(model=m, states=states, qpos=qpos, force=force, dt=dt, actuator=a,
                            joint=j, gear=gear, tol=tol, options=options, lag=lag,
                            target=target, bias=float(b1), toward=toward,
                            target_accel=target_accel)
        base = JointFeasibility(
            actuator=name, joint=jname, kind=kind.value, unit=unit, gripper=is_gripper,
            max_lag=max_lag, max_lag_time=max_lag_time, lag_duration=0.0, lag_start=None,
            lag_in_run=0.0, saturation_duration=0.0, saturation_start=None,
            saturation_total=float(saturated.sum()) * dt, force_limit=limit,
            limit_source=source, frictionloss=friction, target_span=span, note=note,
            friction_band=band, force_flips=force_flips)
        none = (0, 0)
        entry = sig.entry(base, lag_runs[0] if lag_runs else none,
                          sat_runs[0] if sat_runs else none)
        if entry.blocked_by:
            # a contact holds the joint back over its longest failing stretch; a shorter
            # one that no contact explains is still a motion the twin cannot follow (a
            # servo too weak for its load elsewhere in the run), and it is what is said
            others = [(lr, _overlapping(sat_runs, lr)) for lr in lag_runs[1:_STRETCHES]
                      if lr[1] * dt > options.lag_duration]
            others += [(none, sr) for sr in sat_runs[:_STRETCHES]
                       if sr[1] * dt > options.saturation_duration]
            for lag_run, sat_run in others:
                alt = sig.entry(base, lag_run, sat_run)
                if (_failing_stretch(alt, tol, abs(gear), options) is not None
                        and not alt.blocked_by):
                    entry = alt
                    break
        joints.append(entry)
        found = _problems(entry, tol, abs(gear), options, m, j)
        if found and _clamp_only(twin, a, entry, tol, abs(gear), options):
            # a rated actuator held at a protective clamp under its rating while it tracks:
            # the ground truth reads saturation against the rating, and the motion is
            # reproduced (ALOHA's elbow clamped at 3.6 N·m, rated 15, lag 0.016 rad: every
            # sample's run succeeds); said, not refused
            held.append(
                f"actuator {name!r} (joint {jname!r}) is at its {entry.limit_source} "
                f"{entry.force_limit:g} {_force_unit(unit)} for {entry.saturation_duration:.3g} "
                f"s from t = {entry.saturation_start:.3f} s, under its rating "
                f"{float(twin.limits[a]):g} {_force_unit(unit)} in [limits]; it tracks its "
                f"targets (largest lag {entry.max_lag:.3g} {unit})")
            continue
        (held if entry.blocked_by and not entry.jammed else problems).extend(found)
    report = FeasibilityReport(joints=tuple(joints), problems=tuple(problems),
                               notes=tuple(notes), options=options, duration=n * dt,
                               warnings=tuple(held))
    if problems and raise_on_failure:
        raise InfeasibleTwinError(problems[0], report=report)
    return report


def _force_unit(unit: str) -> str:
    return "N" if unit == "m" else "N·m"


def _clamp_only(twin: Twin, a: int, e: JointFeasibility, tol: float, gear: float,
                opt: FeasibilityOptions) -> bool:
    """The joint's only problem is a saturation at a force limit tighter than the rating
    ``[limits]`` gives its actuator (a protective clamp, e.g. a force_limit parameter's
    nominal), while it tracks its targets: no lag stretch, no friction it cannot move."""
    rated = twin.scenario.limit_sources.get(twin.actuator_names[a], "scenario") == "scenario"
    return (rated and e.limit_source != "[limits]" and not _stuck(e, tol, gear, opt)
            and not e.lag_duration > opt.lag_duration
            and e.force_limit < float(twin.limits[a]))


def _stuck(e: JointFeasibility, tol: float, gear: float, opt: FeasibilityOptions) -> bool:
    """Friction above what the actuator can ever exert, on a joint that must move."""
    must_move = np.isnan(e.target_span) or e.target_span > opt.moving * tol
    return e.frictionloss > e.force_limit * gear and bool(must_move)


def _failing_stretch(e: JointFeasibility, tol: float, gear: float, opt: FeasibilityOptions
                     ) -> tuple[float, float] | None:
    """(start, duration) [s] of the lag or saturation stretch that fails the joint, if any."""
    if _stuck(e, tol, gear, opt) or not (opt.check_grippers or not e.gripper):
        return None
    if e.lag_duration > opt.lag_duration:
        return e.lag_start, e.lag_duration
    if e.saturation_duration > opt.saturation_duration:
        return e.saturation_start, e.saturation_duration
    return None


def _subtree(model: mujoco.MjModel, body: int) -> np.ndarray:
    """(nbody,) bool: the bodies ``body`` carries (itself included)."""
    inside = np.zeros(model.nbody, dtype=bool)
    for b in range(model.nbody):
        a = b
        while a > 0 and a != body:
            a = int(model.body_parentid[a])
        inside[b] = a == body
    return inside


def _blocking_contact(model: mujoco.MjModel, states: np.ndarray, start: float,
                      duration: float, *, joint: int, probes: int = 40,
                      toward: np.ndarray | None = None) -> tuple[str, bool]:
    """The contact that holds ``joint`` back over a stretch of the run, or "", and whether
    it jams the robot against itself: both its bodies are the robot's (in kinematic trees
    the actuators drive) and the pair touches already in the first state (a
    Menagerie Kinova Gen3's base and shoulder collision meshes overlap by 12 mm and hold
    its first joint; audited, every sample had failed as a motor overload).

    The stretch's states are replayed (positions and collisions only) at up to ``probes``
    steps. A contact between a body the joint carries and one it does not is an obstacle,
    unless the other body is a payload: a free body (the object) whose every contact is
    with the joint's bodies, which the joint carries like its own links. An obstacle
    present at at least half of the probed steps is named "geom1–geom2" (its most frequent
    pair): a gripper closed on the object is held by it, an arm carrying the object is not.
    With ``toward``, per step the sign of the joint's target less its position (n,), an
    obstacle holds the joint back only where the constraint forces on it push away from its
    target over the probed steps: a joint too weak for its load sags onto the table, which
    then pushes it back toward its target (the Panda's shoulder limited to 10 N·m rested on
    the table for 9.3 s, and the run had been audited as if the table held it back).
    """
    dt = float(model.opt.timestep)
    first, count = int(round(start / dt)), max(1, int(round(duration / dt)))
    steps = np.unique(np.linspace(first, first + count - 1, min(count, probes)).astype(int))
    carried = _subtree(model, int(model.jnt_bodyid[joint]))
    root = model.body_rootid
    free_root = np.zeros(model.nbody, dtype=bool)
    for b in range(1, model.nbody):
        jnt = model.body_jntadr[b]
        free_root[b] = (model.body_jntnum[b] > 0
                        and model.jnt_type[jnt] == mujoco.mjtJoint.mjJNT_FREE)
    data = mujoco.MjData(model)
    pairs: dict[tuple[int, int], int] = {}
    hits = 0
    push = 0.0  # the constraint forces on the joint, toward its target (+) or away (-)
    dof = int(model.jnt_dofadr[joint])
    for k in steps:
        mujoco.mj_setState(model, data, states[min(k + 1, states.shape[0] - 1)], STATE_SPEC)
        if toward is None:
            mujoco.mj_fwdPosition(model, data)
        else:
            mujoco.mj_forward(model, data)
            push += float(data.qfrc_constraint[dof]) * float(toward[min(k, toward.size - 1)])
        g1, g2 = _active_contacts(data)
        b1, b2 = model.geom_bodyid[g1], model.geom_bodyid[g2]
        across = carried[b1] != carried[b2]
        outside = np.where(carried[b1], b2, b1)
        for i in np.flatnonzero(across):
            r = root[outside[i]]
            if free_root[r]:
                # a free body touched only by the joint's bodies is its payload
                mine = root[b1] == r
                theirs = root[b2] == r
                partners = np.concatenate([b2[mine], b1[theirs]])
                if carried[partners].all():
                    across[i] = False
        hits += bool(across.any())
        for a, b in zip(g1[across], g2[across], strict=True):
            key = (int(min(a, b)), int(max(a, b)))
            pairs[key] = pairs.get(key, 0) + 1
    if not pairs or hits < 0.5 * steps.size or push > 0.0:
        return "", False
    a, b = max(pairs, key=pairs.get)
    return f"{_geom_name(model, a)}–{_geom_name(model, b)}", _jammed(model, data, states, a, b)


def _jammed(model: mujoco.MjModel, data: mujoco.MjData, states: np.ndarray, a: int,
            b: int) -> bool:
    """Geoms ``a`` and ``b`` belong to the robot (kinematic trees the actuators drive) and
    touch in the first recorded state. A tree with joints no actuator drives is a fixture
    (a hinged flap touching the pads at the start is something the motion meets)."""
    driven = np.zeros(model.nbody, dtype=bool)
    for act in range(model.nu):
        driven[act_info.moved_bodies(model, act, sites=True)] = True
    articulated = np.zeros(model.nbody, dtype=bool)
    articulated[model.body_rootid[np.flatnonzero(driven)]] = True
    articulated[0] = False
    roots = model.body_rootid[model.geom_bodyid[[a, b]]]
    if not articulated[roots].all():
        return False
    mujoco.mj_setState(model, data, states[0], STATE_SPEC)
    mujoco.mj_fwdPosition(model, data)
    g1, g2 = _active_contacts(data)
    return bool((((g1 == a) & (g2 == b)) | ((g1 == b) & (g2 == a))).any())


def _active_contacts(data: mujoco.MjData) -> tuple[np.ndarray, np.ndarray]:
    """The geom pairs of ``data``'s active contacts (as last computed): within the geoms'
    margin less their gap, where MuJoCo applies force, not only penetrating ones (Baxter's
    arm geoms have margin 1 mm)."""
    con, n = data.contact, data.ncon
    active = np.asarray(con.dist)[:n] < np.asarray(con.includemargin)[:n]
    return np.asarray(con.geom1)[:n][active], np.asarray(con.geom2)[:n][active]


def _geom_name(model: mujoco.MjModel, geom: int) -> str:
    # critmoment's own name for a geom the MJCF leaves unnamed (critmoment:geom:6) is not
    # in the user's file: the body it belongs to says where to look
    name = model.geom(geom).name
    if name and not name.startswith(GENERATED):
        return name
    body = model.body(int(model.geom_bodyid[geom])).name
    return f"geom #{geom} of body {body!r}"


def _problems(e: JointFeasibility, tol: float, gear: float, opt: FeasibilityOptions,
              model: mujoco.MjModel, joint: int) -> list[str]:
    """The problems of one joint, most telling first: friction, then lag, then saturation."""
    out = []
    fu = _force_unit(e.unit)
    reach = e.force_limit * gear
    if _stuck(e, tol, gear, opt):
        out.append(f"the twin cannot reproduce the nominal motion: joint {e.joint!r} (actuator "
                   f"{e.actuator!r}) frictionloss {e.frictionloss:g} {fu} > force limit "
                   f"{reach:g} {fu} ({e.limit_source}{f' × gear {gear:g}' if gear != 1 else ''}"
                   f"): the servo can never move this joint; check [limits] or the model's "
                   f"frictionloss")
        return out
    if not (opt.check_grippers or not e.gripper):
        return out
    if e.lag_duration > opt.lag_duration:
        if e.jammed:
            cause = _jam_cause(e)
        elif e.blocked_by:
            cause = (f"the contact {e.blocked_by} holds it back: the motion pushes the robot "
                     f"against itself, the object or the support")
        elif e.saturation_total > 0 and e.force_flips >= FLIP_SHARE:
            cause = _oscillation(e, fu)
        elif e.saturation_total > 0 and e.saturation_start is not None and _damped(e, gear):
            cause = _damping_cause(e, fu, gear, model, joint)
        elif e.saturation_total > 0 and e.saturation_start is not None and _sprung(e, gear):
            cause = _spring_cause(e, fu, gear, model, joint)
        elif e.saturation_total > 0 and e.saturation_start is not None and _hurried(e, gear):
            cause = _speed_cause(e, fu, gear)
        elif e.saturation_total > 0 and e.saturation_start is not None:
            cause = (f"the actuator is at its force limit {e.force_limit:g} {fu} "
                     f"({e.limit_source}) for {e.saturation_total:.3g} s in all: too weak "
                     f"for the load (gravity, the object); check [limits], the model's "
                     f"forcerange and gear{_explicit_hint(model)}")
        elif e.damping_lag >= DAMPING_SHARE * e.lag_in_run:
            cause = (f"the servo's velocity damping: at the target's speed of up to "
                     f"{e.target_speed:.3g} {e.unit}/s it trails by about (kv + joint damping) "
                     f"/ kp × speed = {e.damping_lag:.3g} {e.unit} at steady state; slow the "
                     f"motion down, or audit a twin whose servo gains match the robot's")
        elif e.friction_band >= FRICTION_BAND_SHARE * tol:
            cause = (f"the joint's dry friction: its frictionloss {e.frictionloss:g} {fu} "
                     f"holds it until the servo's error reaches frictionloss / stiffness = "
                     f"{e.friction_band:.3g} {e.unit}, so the servo stops short of its targets by up to "
                     f"that much; a twin whose joint friction and servo gains match the "
                     f"robot's (lower frictionloss or higher kp) tracks them")
        elif e.load_lag >= DAMPING_SHARE * e.lag_in_run:
            cause = (f"the load the servo holds (gravity, the object): under the force it "
                     f"gives there, its stiffness lets the joint sag by force / kp = "
                     f"{e.load_lag:.3g} {e.unit}; the robot's controller holds it closer "
                     f"(gravity compensation, stiffer gains): feed that load forward in the "
                     f"targets, or audit a twin whose servo gains match the robot's")
        elif model.jnt_limited[joint]:
            cause = ("the joint is blocked (a contact or its range) or the servo is too "
                     "soft (kp) for the motion; check the model's kp/kv and the trajectory's "
                     "speed")
        else:
            cause = ("the joint is blocked by a contact or the servo is too soft (kp) for "
                     "the motion; check the model's kp/kv and the trajectory's speed")
        out.append(
            f"the twin cannot reproduce the nominal motion: joint {e.joint!r} (actuator "
            f"{e.actuator!r}) lags its target by up to {e.lag_in_run:.3g} {e.unit} "
            f"(tolerance {tol:g} {e.unit}) for {e.lag_duration:.3g} s from t = "
            f"{e.lag_start:.3f} s; likely cause: {cause} (where the targets lead the joints "
            f"by design, a feed-forward offset or a soft servo's known lag: give the joints' "
            f"planned or recorded path as the trajectory's 'observed' (an npz key; ACT's "
            f"/observations/qpos and LeRobot's observation.state are read as it), and a "
            f"joint on that path is no lag; or the scenario's [feasibility] "
            f"lag_tolerance{'_slide' if e.unit == 'm' else ''} and delay set how far)")
    elif e.saturation_duration > opt.saturation_duration:
        explicit = _explicit_hint(model)
        cause = (_jam_cause(e) if e.jammed else
                 f"the contact {e.blocked_by} holds it back" if e.blocked_by else
                 _oscillation(e, fu) if e.force_flips >= FLIP_SHARE else
                 _damping_cause(e, fu, gear, model, joint) if _damped(e, gear) else
                 _spring_cause(e, fu, gear, model, joint) if _sprung(e, gear) else
                 _speed_cause(e, fu, gear) if _hurried(e, gear) else
                 # at its limit while it holds its target (lag within tolerance) under an
                 # explicit integrator: that integrator first (the RK4 Panda's base joint,
                 # no gravity load, sat at 87 N·m with a 0.01 rad lag; implicitfast never
                 # saturates it)
                 f"the model's {_explicit_name(model)} integrator, more likely than the "
                 f"load (the joint keeps within {tol:g} {e.unit} of its target at the "
                 f"limit): {_EXPLICIT}; else too weak for the load (check [limits], the "
                 f"model's forcerange and gear)"
                 if explicit and e.max_lag < tol else
                 "too weak for the load; check [limits], the model's forcerange and gear"
                 + explicit)
        out.append(
            f"the twin cannot reproduce the nominal motion: actuator {e.actuator!r} (joint "
            f"{e.joint!r}) is at (or above) its force limit {e.force_limit:g} {fu} ({e.limit_source}) "
            f"for {e.saturation_duration:.3g} s from t = {e.saturation_start:.3f} s (largest "
            f"lag {e.max_lag:.3g} {e.unit}); likely cause: {cause}")
    if e.blocked_by and not e.jammed:
        out = [msg.replace("the twin cannot reproduce the nominal motion: ",
                           "the nominal motion is held back by a contact: ") for msg in out]
    return out


def _jam_cause(e: JointFeasibility) -> str:
    return (f"the robot's own geoms {e.blocked_by} touch from the start and hold it back: "
            f"their collision geometry overlaps (MuJoCo's parent filter does not exclude a "
            f"pair whose parent is welded to the world); exclude the pair in the model "
            f"(<contact><exclude body1=... body2=.../></contact>) or fix the geoms")


def _damped(e: JointFeasibility, gear: float) -> bool:
    """The joint's own damping at its speed takes most of what the actuator can give."""
    return e.damping_force >= DAMPING_SHARE * e.force_limit * gear


def _damping_cause(e: JointFeasibility, fu: str, gear: float, model: mujoco.MjModel,
                   joint: int) -> str:
    return (f"the joint's own damping: moving at up to {e.saturation_speed:.3g} {e.unit}/s, "
            f"its damping {model.dof_damping[model.jnt_dofadr[joint]]:g} takes "
            f"{e.damping_force:.3g} {fu} of the {e.force_limit * gear:.3g} {fu} the actuator "
            f"can give; slow the motion there, or check the model's joint damping")


def _sprung(e: JointFeasibility, gear: float) -> bool:
    """The joint's own spring takes most of what the actuator can give."""
    return e.spring_force >= DAMPING_SHARE * e.force_limit * abs(gear)


def _spring_cause(e: JointFeasibility, fu: str, gear: float, model: mujoco.MjModel,
                  joint: int) -> str:
    adr = int(model.jnt_qposadr[joint])
    return (f"the joint's own spring: its stiffness {model.jnt_stiffness[joint]:g} {fu}/"
            f"{e.unit} pulls it towards its springref {model.qpos_spring[adr]:g} {e.unit} "
            f"with up to {e.spring_force:.3g} {fu} of the {e.force_limit * abs(gear):.3g} {fu} "
            f"the actuator can give; check the model's joint stiffness and springref (a "
            f"spring the robot does not have, or one its controller compensates)")


def _hurried(e: JointFeasibility, gear: float) -> bool:
    """Following the targets' acceleration takes most of what the actuator can give on the
    robot's inertia alone, where gravity and the other bias forces typically take less
    than that share (else the load is what the actuator cannot hold)."""
    reach = DAMPING_SHARE * e.force_limit * abs(gear)
    return e.inertial_force >= reach and e.bias_force < reach


def _speed_cause(e: JointFeasibility, fu: str, gear: float) -> str:
    return (f"the motion is too fast for the actuator: following its targets' acceleration "
            f"(up to {e.target_accel:.3g} {e.unit}/s²) takes up to {e.inertial_force:.3g} {fu} "
            f"at this joint on the robot's inertia alone (armature included; gravity and the "
            f"other bias forces {e.bias_force:.3g} {fu} typically), of the "
            f"{e.force_limit * abs(gear):.3g} {fu} the actuator can give; slow the motion "
            f"down (re-time the trajectory) or smooth its targets")


_EXPLICIT = ("it treats a stiff servo's velocity damping explicitly, which can saturate it "
             "(implicitfast does not)")


def _explicit_name(model: mujoco.MjModel) -> str:
    """"RK4" or "Euler" for an explicit integrator, else ""."""
    kind = int(model.opt.integrator)
    return ("RK4" if kind == int(mujoco.mjtIntegrator.mjINT_RK4) else
            "Euler" if kind == int(mujoco.mjtIntegrator.mjINT_EULER) else "")


def _explicit_hint(model: mujoco.MjModel) -> str:
    """Under an explicit integrator a stiff servo's velocity damping can itself drive the
    actuator to its limit; RK4 leaves the forces of its last stage in mjData, where a
    step-to-step oscillation does not show as one."""
    name = _explicit_name(model)
    return f"; or the model's {name} integrator: {_EXPLICIT}" if name else ""


def _oscillation(e: JointFeasibility, fu: str) -> str:
    """The cause of a saturation whose force flips between +limit and −limit."""
    return (f"a numerical oscillation, not a load: the actuator's force jumps between "
            f"+{e.force_limit:g} and −{e.force_limit:g} {fu} from one step to the next "
            f"({e.force_flips:.0%} of its steps at the limit); check the model's integrator "
            f"(implicitfast damps a stiff servo, Euler does not) and the servo's kp/kv for "
            f"the timestep")


# -- trajectory <-> scenario fit ------------------------------------------------------
def _bundled_widths(exclude: str) -> dict[str, int]:
    """Action width of each bundled scenario other than ``exclude`` (those that load)."""
    from critmoment.scenario import BUNDLED_SCENARIOS, load_scenario

    out = {}
    for name in BUNDLED_SCENARIOS:
        if name == exclude:
            continue
        try:
            out[name] = load_scenario(name).actions.width
        except CritmomentError as exc:  # a broken bundled scenario must not hide the hint
            log.debug("bundled scenario %s does not load: %s", name, exc)
    return out


def _check_width(trajectory: Trajectory, twin: Twin) -> None:
    sc = twin.scenario
    conv = sc.actions
    got = int(trajectory.n_channels)
    if got == conv.width:
        return
    fits = [name for name, w in _bundled_widths(sc.name).items() if w == got]
    hint = (f"bundled scenario {fits[0]!r} takes {got}: wrong --scenario? (--scenario "
            f"{fits[0]})" if fits else
            f"no bundled scenario takes {got}: pass the --scenario this trajectory was "
            f"recorded for")
    raise TrajectoryError(
        f"the trajectory has {got} action values per step, scenario {sc.name!r} expects "
        f"{conv.width} ({conv.name}: {', '.join(conv.labels)}); {hint}")


def _check_units(trajectory: Trajectory, twin: Twin) -> None:
    """Hard unit mismatches: gripper channels far outside 0..1, joint values in degrees."""
    actions = np.asarray(trajectory.actions, dtype=np.float64)
    conv = twin.scenario.actions
    lo, hi = twin.channel_lower, twin.channel_upper
    # every value within ±100: perhaps motor positions normalised to -100..100 (grippers
    # 0..100), as LeRobot's calibrated SO-100/SO-101 and Koch arms record them
    percent = (" or motor units normalised to -100..100 (grippers 0..100, as LeRobot's "
               "calibrated arms record them)" if actions.size and
               float(np.abs(actions).max()) <= 100.0 else "")
    for c, label in enumerate(conv.labels):
        col = actions[:, c]
        cmin, cmax = float(col.min()), float(col.max())
        if conv.normalised[c]:
            if cmax > 1.5 or cmin < -0.5:
                raise TrajectoryError(
                    f"channel {label!r} is a normalised gripper (0 closed .. 1 open), the "
                    f"trajectory's values span {cmin:.4g}..{cmax:.4g}: raw gripper units "
                    f"(metres, 0..255){percent}? normalise them, or this trajectory is for "
                    f"another scenario")
            own = _in_actuator_units(conv, c, cmin, cmax)
            if own is not None:
                raise TrajectoryError(
                    f"channel {label!r} is a normalised gripper (0 closed .. 1 open), the "
                    f"trajectory's values span {cmin:.4g}..{cmax:.4g}, its actuators' own "
                    f"controls from closed to open ({own}): the gripper in the actuator's "
                    f"units (metres?) rather than normalised; normalise it (0 closed .. 1 "
                    f"open)")
            continue
        hinge = np.isfinite(lo[c]) and np.isfinite(hi[c]) and hi[c] - lo[c] <= 2 * np.pi + 1e-6
        big = max(abs(cmin), abs(cmax))
        if hinge and big > 2 * np.pi + 0.5:
            # beyond two turns in degrees: encoder ticks (0..4095) or milliradians
            unit = ("degrees instead of radians" if big <= 720.0 else
                    "motor ticks (a 12-bit encoder's 0..4095), milliradians or degrees "
                    "instead of radians")
            raise TrajectoryError(
                f"channel {label!r} spans {cmin:.4g}..{cmax:.4g}, its joint range is "
                f"{lo[c]:.4g}..{hi[c]:.4g} rad: {unit}{percent}?")


def _in_actuator_units(conv, c: int, cmin: float, cmax: float) -> str | None:
    """Whether a normalised channel's values span its actuators' own controls from closed
    to open (``offsets`` to ``offsets + scales``) rather than 0..1: the controls in words
    when they do (and that span is not itself about 0..1), else None."""
    ends = [(float(o), float(o + s)) for s, o in zip(conv.scales[c], conv.offsets[c],
                                                      strict=True)]
    for a, b in ends:
        low, high = min(a, b), max(a, b)
        span = high - low
        if span <= 0 or (abs(low) < 0.1 and abs(high - 1.0) < 0.1):
            continue  # the actuator's own units are about 0..1: indistinguishable
        if span < 0.5 and cmax - cmin > 0.5 * span and \
                abs(cmin - low) <= 0.1 * span and abs(cmax - high) <= 0.1 * span:
            return f"{a:.4g}..{b:.4g}"
    return None


#: how far [m] an object may fall in the nominal run, touching neither its support nor a
#: gripper, before its start pose is an input error rather than a motion to audit
FREE_FALL = 1.0


def check_fit(trajectory: Trajectory, recording: Recording | None, twin: Twin, *,
              strict: bool = False) -> list[str]:
    """Does ``trajectory`` belong to the twin's scenario?

    With ``recording`` None only the static checks run (call it before the rollout, which
    would fail on a wrong width with a less telling message); with the nominal recording of
    the trajectory the run is checked too.

    Args:
        trajectory: the trajectory.
        recording: its nominal frequent rollout, or None.
        twin: the twin.
        strict: raise on the first warning as well.

    Returns:
        Warnings, one line each, each naming the likely mistake.

    Raises:
        TrajectoryError: a hard mismatch (action width not the scenario's, gripper values
            that are not normalised, joint targets in degrees, an object that falls through
            the world untouched), or with ``strict`` the first warning.
        ScenarioError: with ``recording``, a task no run of this length can meet
            (:func:`critmoment.recording.check_task_window`).
    """
    from critmoment.recording import check_task_window

    _check_width(trajectory, twin)
    _check_units(trajectory, twin)
    if recording is None:
        return []
    check_task_window(twin, trajectory)
    out: list[str] = []
    sig = recording.signals
    default = ""
    if trajectory.object_pose is None and trajectory.qpos0 is None:
        key = twin.scenario.keyframe
        default = ("; the trajectory gives none, so the model's default pose was used"
                   if key is None else
                   f"; the trajectory gives none, so keyframe {key!r}'s pose was used")
    touched = (np.asarray(sig.contact_support, bool).any()
               or np.asarray(sig.contact_gripper, bool).any())
    pos = np.asarray(sig.object_pos, dtype=np.float64)
    fall = float(pos[0, 2] - pos[:, 2].min()) if pos.size else 0.0
    if not touched and fall > FREE_FALL:
        # nothing to audit: every sample falls alike (a pose under the table, in mm)
        raise TrajectoryError(
            f"the object falls {fall:.3g} m in the nominal run, touching neither its support "
            f"nor a gripper (from z = {pos[0, 2]:.4g} m): its start pose is not on its "
            f"support (--object-pose{default}; under the table, or in mm?)")
    start = _data_at(twin, recording.states[0])
    depth, other = _start_penetration(twin, start)
    if depth > START_PENETRATION:
        out.append(f"the object starts {depth * 1e3:.3g} mm inside {other}: the model pushes "
                   f"it out at once (which reads as a lift-off); is the object pose right "
                   f"(--object-pose{default})?")
    unlisted = _unlisted_supports(twin, start)
    if unlisted:
        out.append(f"the object starts resting on {', '.join(repr(g) for g in unlisted)}, "
                   f"fixed geom(s) not in [support]: its lift-off from them is not seen as "
                   f"one, nor a drop back onto them; add them to [support] geoms (or their "
                   f"body to [support] bodies) if the object rests there")
    # a chunk that starts mid-carry (the object in a grip from the first step) need never
    # touch its support: a hand-over ends in the receiver's grip
    held_at_start = bool(np.asarray(sig.contact_gripper, bool)[:1].any())
    if not held_at_start:
        moved = _pretouch_motion(twin, recording)
        if moved is not None:
            out.append(moved)
    if not np.asarray(sig.contact_support, bool).any() and not held_at_start:
        out.append(f"the object never touches its support ([support] geoms) in the nominal "
                   f"run: is the object pose right (--object-pose{default}), or the "
                   f"[support] geoms?")
    dt = float(twin.model.opt.timestep)
    for at, height, again in _mid_run_drops(twin, recording):
        out.append(f"the nominal run drops the object {height * 100:.3g} cm onto its support "
                   f"at t = {at * dt:.2f} s (it leaves every gripper there and falls), and a "
                   f"gripper touches it again at t = {again * dt:.2f} s: a drop mid-task, "
                   f"which the task's rule does not see when the run still ends in success; "
                   f"the samples' falls are judged against this run, so is that the motion "
                   f"meant?")
    fall = _release_height(twin, recording)
    if fall > RELEASE_HEIGHT and recording.completed:
        out.append(f"the nominal run lets go of the object {fall * 100:.3g} cm above where it "
                   f"comes to rest: it falls there (a toss, not a place), which the task's "
                   f"rule still counts as done; is that the motion meant?")
    elif fall > RELEASE_HEIGHT:
        # a grip that loses its object mid-carry reads the same as a release from too high:
        # the run did not complete the task, so name both
        out.append(f"the object leaves the grippers {fall * 100:.3g} cm above where it comes "
                   f"to rest and falls there, and the nominal run does not complete the task: "
                   f"dropped from the grip (too weak or slippery for it at the nominal "
                   f"parameters?) or released too high?")
    touched = np.asarray(sig.contact_gripper, bool).any()
    if not touched:
        out.append(f"the nominal run never touches the object: is the object pose right "
                   f"(--object-pose{default}), or is this trajectory for another scenario?")
    elif _needs_lift(twin):
        carried = carried_flags(sig.contact_support, sig.contact_gripper)
        if not twin.lifted(carried, recording.states).any():
            out.append(f"the nominal run touches the object but never lifts it: too heavy or "
                       f"slippery at the nominal parameters, a grasp that does not close on "
                       f"it, or a wrong object pose (--object-pose{default})?")
    if not recording.completed:
        out += _clutter(twin, recording)
    else:
        out += _disturbed(twin, recording)
    out += _floating_base(twin, recording)
    if strict and out:
        raise TrajectoryError(out[0])
    return out


#: how far [m] and how much [deg] the object may move before a gripper first touches it: a
#: settled object on its support moves micrometres
PRETOUCH_MOVE = 0.002
PRETOUCH_TURN = 5.0


def _pretouch_motion(twin: Twin, recording: Recording) -> str | None:
    """The object's motion before any gripper first touches it (over the whole run where
    none does), in words, where it moves sideways or up by more than :data:`PRETOUCH_MOVE`
    or turns by more than :data:`PRETOUCH_TURN` (sinking into its support's contact margin
    is settling); else None. A mesh balanced on a vertex that the settling took
    for at rest toppled 1.0-1.6 s in, 9.8 mm and 29°, and runs that differed by 1 nm in its
    start toppled it differently (18 of 64 outcomes flipped); a cube on contacts too stiff
    or too springy for the time step left the table on its own, and the messages spoke of
    the grasp."""
    sig = recording.signals
    touch = np.asarray(sig.contact_gripper, bool).reshape(recording.n_steps, -1).any(axis=1)
    end = int(np.argmax(touch)) if touch.any() else touch.size
    if end < 2:
        return None
    pos = np.asarray(sig.object_pos, dtype=np.float64)[:end]
    # sideways or up: an object that only sinks into its support's contact margin (a
    # margin of 4 mm: 3.97 mm straight down, no turn) settles, it does not topple
    up = np.asarray(twin.scenario.task.up, dtype=np.float64)
    up = up / (np.linalg.norm(up) or 1.0)
    adr = twin.object_qposadr
    quat = twin.qpos(recording.states[1:end + 1])[:, adr + 3:adr + 7]
    carrier = _moving_support(twin, recording.states[0])
    carried_by = ""
    if carrier is not None:
        # on a support that moves (a tray on a mobile base): its motion with the support is
        # not the object's own; measured in the support body's frame
        pos, quat, up = _in_body_frame(twin, recording.states[:end], carrier, up)
        carried_by = f" relative to its moving support {_body_label(twin.model, carrier)}"
    rel = pos - pos[0]
    along = rel @ up
    # a contact margin holds the object up to that far from its support: rising into it is
    # settling too (a 4 mm margin lifted a settled cube 3.97 mm)
    model = twin.model
    near = list(np.flatnonzero(model.geom_bodyid == twin.object_body_id))
    near += [model.geom(g).id for g in twin.scenario.support_geoms]
    margin = float(model.geom_margin[near].max(initial=0.0)) if near else 0.0
    rise = np.maximum(along - margin, 0.0)
    shift = np.maximum(np.linalg.norm(rel - along[:, None] * up, axis=1), rise)
    quat = quat / np.linalg.norm(quat, axis=1, keepdims=True)
    turn = np.degrees(2.0 * np.arccos(np.clip(np.abs(quat @ quat[0]), 0.0, 1.0)))
    if not (shift.max() > PRETOUCH_MOVE or turn.max() > PRETOUCH_TURN):
        return None
    dt = float(recording.dt)
    first = int(np.argmax((shift > PRETOUCH_MOVE) | (turn > PRETOUCH_TURN)))
    when = (f"before any gripper touches it (at t = {end * dt:.2f} s)" if touch.any() else
            "and no gripper ever touches it")
    return (f"the object moves {shift.max() * 1e3:.3g} mm (sideways or up) and turns "
            f"{turn.max():.3g}°{carried_by} from "
            f"t = {first * dt:.2f} s {when}: it is not at rest at its start (balanced on an "
            f"edge or a vertex, contacts too stiff or springy for the time step) or something "
            f"else pushes it. Where it topples or bounces on its own, runs that differ by "
            f"rounding do so differently, and outcomes, the verdict and the safe region rest "
            f"on that noise; start it resting on a face, or check the object's contact "
            f"settings")


def _moving_support(twin: Twin, state: np.ndarray) -> int | None:
    """The body of a support geom the object rests on in ``state`` that a joint moves (a
    tray on a mobile base, a conveyor), or None when it rests on fixed ones."""
    model = twin.model
    data = _data_at(twin, state)
    supports = {model.geom(g).id for g in twin.scenario.support_geoms}
    for c in data.contact[:data.ncon]:
        g1, g2 = int(c.geom1), int(c.geom2)
        for mine, other in ((g1, g2), (g2, g1)):
            if int(model.geom_bodyid[mine]) == twin.object_body_id and other in supports:
                body = int(model.geom_bodyid[other])
                if any(model.body_jntnum[b] for b in act_info.body_chain(model, body)):
                    return body
    return None


def _in_body_frame(twin: Twin, states: np.ndarray, body: int, up: np.ndarray
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The object's position (T, 3) and orientation (T, 4) in ``body``'s frame at
    ``states`` (T, nstate), and ``up`` in that frame at the first."""
    model = twin.model
    data = mujoco.MjData(model)
    obj = twin.object_body_id
    n = states.shape[0]
    pos, quat, inv = np.empty((n, 3)), np.empty((n, 4)), np.empty(4)
    first = np.eye(3)
    for k in range(n):
        mujoco.mj_setState(model, data, np.asarray(states[k], dtype=float), STATE_SPEC)
        mujoco.mj_kinematics(model, data)
        frame = data.xmat[body].reshape(3, 3)
        first = frame if k == 0 else first
        pos[k] = frame.T @ (data.xpos[obj] - data.xpos[body])
        mujoco.mju_negQuat(inv, data.xquat[body])
        mujoco.mju_mulQuat(quat[k], inv, data.xquat[obj])
    return pos, quat, first.T @ up


#: physics steps between the nominal states scanned for contacts with the scene's other
#: bodies (a contact lasting a few ms is seen)
CLUTTER_STRIDE = 5
#: rise [m] of another free body held by a gripper that counts as lifting it
CLUTTER_LIFT = 0.01


def _clutter(twin: Twin, recording: Recording) -> list[str]:
    """What else in the scene a nominal run that fails its task touches: the object's
    contacts with other free bodies and with fixed geoms that are not its supports, and
    other free bodies the grippers lift (a cube stacked on the object, a neighbour a pad
    lands on). The audit's causes speak of the object's mass and friction; these name the
    scene's part in the failure. Contacts with the robot itself are the feasibility
    check's (``blocked_by``)."""
    model = twin.model
    touched, lifted, carried = _scan_clutter(twin, recording)
    out = []
    if touched:
        listed = ", ".join(f"{name} from t = {t:.2f} s" for name, t in
                           sorted(touched.items(), key=lambda item: item[1])[:4])
        out.append(f"the object touches {listed} in the nominal run, which does not complete "
                   f"the task: something in the object's way or under it (clutter, an "
                   f"obstacle, a geom missing from [support])? The failure causes speak of "
                   f"the object's mass and friction; the scene may be the cause")
    if carried:
        out.append(_carried_beside(model, twin.object_body_id, carried, lifted))
    lifted = {b: rise for b, rise in lifted.items() if b not in carried}
    if lifted:
        out.append(f"the grippers lift {_risen(model, lifted)}, another free body than the "
                   f"object {model.body(twin.object_body_id).name!r}, in the nominal run, "
                   f"which does not complete the task: does the grasp close on the wrong object "
                   f"(one stacked on it, a neighbour)?")
    return out


#: how far [m] and how much [deg] another free body may move, start to end, in a nominal
#: run that completes its task before the run is said to disturb it
DISTURB_SHIFT = 0.02
DISTURB_TURN = 20.0


def _disturbed(twin: Twin, recording: Recording) -> list[str]:
    """What a nominal run that completes its task does to the scene's other free bodies:
    one it moves or turns from start to end (a bottle knocked over on the way), one the
    grippers lift with the object (a slab carried off beside the cube). The task's rule
    sees neither, and the samples are judged against this run (their slip relative to its
    grip): a probe's run that toppled a bottle in every sample had been "completed" without
    a word, its safe region containing the nominal."""
    model = twin.model
    obj = twin.object_body_id
    others = _other_free_bodies(model, obj, _body_owners(model))
    if not others:
        return []
    _, lifted, carried = _scan_clutter(twin, recording)
    qpos = twin.qpos(recording.states[[0, -1]])
    moved = []
    for b in others:
        if b in lifted:
            continue  # carried off: said below
        a = int(model.jnt_qposadr[model.body_jntadr[b]])
        shift = float(np.linalg.norm(qpos[1, a:a + 3] - qpos[0, a:a + 3]))
        q0, q1 = qpos[0, a + 3:a + 7], qpos[1, a + 3:a + 7]
        turn = float(np.degrees(2 * np.arccos(np.clip(
            abs(q0 @ q1) / (np.linalg.norm(q0) * np.linalg.norm(q1)), 0.0, 1.0))))
        if shift > DISTURB_SHIFT or turn > DISTURB_TURN:
            moved.append(f"{_body_label(model, b)} {shift * 100:.3g} cm and turns it "
                         f"{turn:.0f}°")
    out = []
    if moved:
        out.append(f"the nominal run moves free body {'; '.join(moved)} (start to end): it "
                   f"completes its task but knocks over or pushes something in the scene, "
                   f"which the task's rule does not see, and the samples are judged against "
                   f"this run; is that the motion meant?")
    if carried:
        out.append(_carried_beside(model, obj, carried, lifted))
    lifted = {b: rise for b, rise in lifted.items() if b not in carried}
    if lifted:
        out.append(f"the grippers lift {_risen(model, lifted)}, another free body than the "
                   f"object {model.body(obj).name!r}, in the nominal run: the grasp closes on "
                   f"more than the object; is that the motion meant?")
    return out


def _other_free_bodies(model: mujoco.MjModel, obj: int, owner) -> list[int]:
    """The free bodies of the scene other than the object and the robot's own free base
    (``owner``: _body_owners')."""
    bases = set(act_info.robot_bases(model))
    return [b for b in range(1, model.nbody)
            if b != obj and owner[b] == ("free", b) and b not in bases]


#: a free robot base that tilts more than this [deg] in the nominal run, or falls more than
#: :data:`BASE_FALL` [m] at its start, is told of
BASE_TILT = 2.0
BASE_FALL = 0.01


def _floating_base(twin: Twin, recording: Recording) -> list[str]:
    """A free-floating robot base (``act_info.robot_bases``) that the nominal run tilts over
    :data:`BASE_TILT` or drops more than :data:`BASE_FALL` at its start, in words (a run
    that tilts it past ``[task] max_base_tilt`` fails its task). A probe's base, 5 cm above
    the floor without a start pose, fell onto its feet and was called scene clutter."""
    model = twin.model
    bases = act_info.robot_bases(model)
    if not bases:
        return []
    states = recording.states
    data = mujoco.MjData(model)
    up = np.asarray(twin.scenario.task.up, dtype=float)
    up = up / (np.linalg.norm(up) or 1.0)
    steps = np.unique(np.r_[np.arange(0, states.shape[0], CLUTTER_STRIDE), states.shape[0] - 1])
    axes = np.empty((steps.size, len(bases), 3))
    heights = np.empty((steps.size, len(bases)))
    for i, k in enumerate(steps):
        mujoco.mj_setState(model, data, np.asarray(states[k], dtype=float), STATE_SPEC)
        mujoco.mj_kinematics(model, data)
        for j, b in enumerate(bases):
            frame = data.xmat[b].reshape(3, 3)
            axes[i, j] = frame.T @ up if i == 0 else frame @ axes[0, j]
            heights[i, j] = data.xpos[b] @ up
    dt = float(recording.dt)
    early = steps * dt <= 0.5
    out = []
    allowed = float(twin.task.max_base_tilt)
    for j, b in enumerate(bases):
        tilt = np.degrees(np.arccos(np.clip(axes[:, j] @ up, -1.0, 1.0)))
        fall = float(heights[0, j] - heights[early, j].min())
        said = (f"the robot's base {_body_label(model, b)} is free-floating (a free joint that "
                f"carries the arm): a run that tilts it more than {allowed:g}° ([task] "
                f"max_base_tilt) fails its task")
        if fall > BASE_FALL:
            out.append(f"{said}; in the nominal run it falls {fall * 100:.3g} cm in its first "
                       f"0.5 s: its start pose is not on its contacts (give the robot's pose "
                       f"in the trajectory's qpos0 or a keyframe)")
        elif tilt.max() > BASE_TILT:
            at = int(steps[int(np.argmax(tilt))])
            out.append(f"{said}; in the nominal run it tilts {tilt.max():.3g}° (at t = "
                       f"{at * dt:.2f} s), and the samples' tilts are judged from their start")
    return out


def _body_label(model: mujoco.MjModel, b: int) -> str:
    return repr(model.body(b).name or f"body {b}")


def _risen(model: mujoco.MjModel, lifted: Mapping[int, float]) -> str:
    """Bodies and how high they rose, for a message."""
    return ", ".join(f"{_body_label(model, b)} ({rise * 100:.3g} cm)"
                     for b, rise in lifted.items())


def _scan_clutter(twin: Twin, recording: Recording
                  ) -> tuple[dict[str, float], dict[int, float], dict[int, list[str]]]:
    """Over the nominal states every ``CLUTTER_STRIDE`` steps: what the object touches
    besides its grippers, supports and the robot (name -> first time [s]), the other free
    bodies a gripper touches while they rise over ``CLUTTER_LIFT`` (body id -> highest rise
    [m]), and of those, the ones only grippers that never touch the object lift (body id ->
    those grippers' names: another arm carrying an object of its own)."""
    model = twin.model
    sc = twin.scenario
    grip, support = _role_geoms(twin)
    obj = twin.object_body_id
    owner = _body_owners(model)
    others = _other_free_bodies(model, obj, owner)
    adr = {b: int(model.jnt_qposadr[model.body_jntadr[b]]) for b in others}
    up = np.asarray(sc.task.up, dtype=float)
    states = recording.states
    steps = np.arange(0, states.shape[0], CLUTTER_STRIDE)
    data = mujoco.MjData(model)
    touched: dict[str, float] = {}  # what the object touched -> first time [s]
    lifted: dict[int, float] = {}   # other free body -> its highest rise while gripped
    start = {b: float(twin.qpos(states[:1])[0, adr[b]:adr[b] + 3] @ up) for b in others}
    dt = float(model.opt.timestep)
    gripper_of = {model.geom(g).id: gr.name for gr in sc.grippers for g in gr.geoms}
    holders: set[str] = set()            # grippers that touch the object
    lifters: dict[int, set[str]] = {}     # other free body -> grippers touching it risen
    for k in steps:
        twin.set_state(model, data, states[k])
        mujoco.mj_forward(model, data)
        if not data.ncon:
            continue
        for h in _object_partners(model, data, obj):
            if h in gripper_of:
                holders.add(gripper_of[h])
            kind, root = owner[int(model.geom_bodyid[h])]
            if h in grip or h in support or kind == "robot":
                continue
            name = (f"free body {model.body(root).name or root!r}" if kind == "free"
                    else f"fixed geom {_geom_name(model, h)!r}")
            touched.setdefault(name, k * dt)
        gripped: dict[int, set[str]] = {}
        for g1, g2 in np.asarray(data.contact.geom).reshape(-1, 2)[:data.ncon]:
            for g, h in ((int(g1), int(g2)), (int(g2), int(g1))):
                kind, root = owner[int(model.geom_bodyid[h])]
                if g in grip and kind == "free" and root != obj:
                    gripped.setdefault(root, set()).add(gripper_of[g])
        for b in set(gripped) & set(others):
            rise = float(data.qpos[adr[b]:adr[b] + 3] @ up) - start[b]
            if rise > CLUTTER_LIFT:
                lifted[b] = max(lifted.get(b, 0.0), rise)
                lifters.setdefault(b, set()).update(gripped[b])
    own = {b: sorted(names) for b, names in lifters.items() if not names & holders}
    return touched, lifted, own


def _carried_beside(model: mujoco.MjModel, obj: int, carried: Mapping[int, list[str]],
                    lifted: Mapping[int, float]) -> str:
    """The other free bodies grippers that never touch the object carry, in words: the
    task's rule judges the object alone, so their drops go unseen."""
    each = "; ".join(
        f"{'grippers' if len(carried[b]) > 1 else 'gripper'} {', '.join(map(repr, carried[b]))} "
        f"{'carry' if len(carried[b]) > 1 else 'carries'} free body "
        f"{_risen(model, {b: lifted[b]})}" for b in carried)
    names = [model.body(b).name for b in carried]
    return (f"{each} in the nominal run, beside the object {model.body(obj).name!r}: the "
            f"task's rule judges {model.body(obj).name!r} alone, so a run that drops "
            f"{', '.join(map(repr, names))} is not failed for it; give it a scenario of its own "
            f"([object] body = {names[0]!r}) to audit its grip")


def _unlisted_supports(twin: Twin, data: mujoco.MjData) -> list[str]:
    """The fixed geoms (on no moving body) the object touches in ``data`` (forwarded)
    that are neither [support] geoms nor a gripper's: a pedestal's top left out of the
    list."""
    model = twin.model
    grip, support = _role_geoms(twin)
    owner = _body_owners(model)
    found = []
    for h in _object_partners(model, data, twin.object_body_id):
        name = _geom_name(model, h)
        if (h not in grip and h not in support and owner[int(model.geom_bodyid[h])][0] == "fixed"
                and name not in found):
            found.append(name)
    return found


def _role_geoms(twin: Twin) -> tuple[set[int], set[int]]:
    """The ids of the grippers' geoms and of the [support] geoms."""
    model, sc = twin.model, twin.scenario
    return ({model.geom(g).id for gr in sc.grippers for g in gr.geoms},
            {model.geom(g).id for g in sc.support_geoms})


def _object_partners(model: mujoco.MjModel, data: mujoco.MjData, obj: int):
    """The geoms of other bodies in contact with body ``obj``'s in ``data``, one per
    contact."""
    for g1, g2 in np.asarray(data.contact.geom).reshape(-1, 2)[:data.ncon]:
        for g, h in ((int(g1), int(g2)), (int(g2), int(g1))):
            if model.geom_bodyid[g] == obj and model.geom_bodyid[h] != obj:
                yield h


def _data_at(twin: Twin, state: np.ndarray) -> mujoco.MjData:
    """The twin's model forwarded at integration state ``state`` (contacts found)."""
    data = mujoco.MjData(twin.model)
    twin.set_state(twin.model, data, state)
    mujoco.mj_forward(twin.model, data)
    return data


def _body_owners(model: mujoco.MjModel) -> list[tuple[str, int]]:
    """Per body, what moves it: ("free", root) below a free joint (the root body that
    carries it), ("fixed", 0) welded to the world all the way up, ("robot", -1) on a
    chain of hinges or slides."""
    out = [("fixed", 0)] * model.nbody
    for body in range(1, model.nbody):
        b = body
        while b > 0:
            first, num = model.body_jntadr[b], model.body_jntnum[b]
            if num:
                free = any(model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE
                           for j in range(first, first + num))
                out[body] = ("free", b) if free else ("robot", -1)
                break
            b = int(model.body_parentid[b])
    return out


def _start_penetration(twin: Twin, data: mujoco.MjData) -> tuple[float, str]:
    """The deepest penetration of the object's contacts in ``data`` (forwarded) [m] (0
    when none) and the geom it goes into."""
    model = twin.model
    if data.ncon == 0:
        return 0.0, ""
    geoms = np.asarray(data.contact.geom).reshape(-1, 2)[:data.ncon]
    dist = np.asarray(data.contact.dist)[:data.ncon]
    mine = model.geom_bodyid[geoms] == twin.object_body_id
    dist = np.where(mine[:, 0] != mine[:, 1], dist, np.inf)
    i = int(np.argmin(dist))
    if not dist[i] < 0:
        return 0.0, ""
    return -float(dist[i]), _geom_name(model, int(geoms[i, 1] if mine[i, 0] else geoms[i, 0]))


def _release_height(twin: Twin, recording: Recording) -> float:
    """How far the object falls after the last step a gripper touches it [m] (0 when it is
    never let go, or never touched): its height there over its height at the run's end."""
    touching = np.asarray(recording.signals.contact_gripper, bool).any(axis=-1)
    touched = np.flatnonzero(touching)
    if touched.size == 0 or touched[-1] >= touching.size - 1:
        return 0.0
    z = twin.object_height(recording.states[:touching.size])
    return float(z[touched[-1]] - z[-1])


def _mid_run_drops(twin: Twin, recording: Recording) -> list[tuple[int, float, int]]:
    """Where the nominal run lets its object fall onto a support and touches it again later
    (a drop mid-task, not the final release :func:`_release_height` measures): for each
    stretch out of every gripper that starts with the object held off its supports and
    ends on a support, having fallen more than ``RELEASE_HEIGHT``, (the first step out of
    the grippers, the fall [m], the step a gripper next touches it)."""
    from critmoment.groundtruth import resting

    sig = recording.signals
    touching = np.asarray(sig.contact_gripper, bool).any(axis=-1)
    support = np.asarray(sig.contact_support, bool)[:touching.size]
    n = touching.size
    # landed: on a support, or at rest on anything (a crate the scenario does not list)
    landing = resting(support, np.linalg.norm(np.asarray(sig.object_vel)[:n], axis=-1))
    if n < 2 or not touching.any():
        return []
    z = twin.object_height(recording.states[:n])
    out = []
    # each stretch out of every gripper: from a step after a touch to the next touch
    starts = np.flatnonzero(touching[:-1] & ~touching[1:]) + 1
    for r in starts:
        if support[r - 1]:
            continue  # let go while resting on a support: a place
        again = np.flatnonzero(touching[r:])
        if not again.size:
            continue  # the final release: _release_height's
        back = r + int(again[0])
        # come to rest below where it left the grip (a hand paused as it opens leaves the
        # object still for a moment, where it has not yet fallen)
        fallen = z[r - 1] - z[r:back]
        landed = np.flatnonzero(landing[r:back] & (fallen > RELEASE_HEIGHT))
        if landed.size:  # else caught before it landed (a hand-over's short free flight)
            out.append((int(r), float(fallen[int(landed[0])]), back))
    return out


def _needs_lift(twin: Twin) -> bool:
    task = getattr(twin.scenario, "task", None)
    kind = getattr(task, "kind", None)
    if kind is None:
        return True  # today's handover
    kind = getattr(kind, "value", kind)
    return str(kind) in _LIFT_TASKS


def preflight(trajectory: Trajectory, recording: Recording, twin: Twin, *,
              options: FeasibilityOptions | None = None) -> FeasibilityReport:
    """The checks the audit runs on its nominal rollout: feasibility, then fit.

    Feasibility comes first: a twin that cannot move its arms never touches the object
    either, and the fit warning would point at the wrong cause. Each fit warning is issued
    as a :class:`FitWarning` and kept in the report.

    Args:
        trajectory: the trajectory.
        recording: its nominal frequent rollout.
        twin: the twin.
        options: feasibility tolerances; default the scenario's (``[feasibility]``).

    Returns:
        The feasibility report with ``fit_warnings``.

    Raises:
        InfeasibleTwinError: see :func:`check_feasibility`.
        TrajectoryError: see :func:`check_fit`.
    """
    from critmoment.recording import observed_controls

    report = check_feasibility(recording, twin, options=options,
                               observed=observed_controls(twin, trajectory))
    fit = check_fit(trajectory, recording, twin)
    for msg in report.warnings + tuple(fit):
        warnings.warn(msg, FitWarning, stacklevel=2)
    return dataclasses.replace(report, fit_warnings=tuple(fit))

