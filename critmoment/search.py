"""Worst-case search at critical moments: analytic bounds, CasADi, Optuna, verification.

Three views of the same question, "how bad can it get over the uncertainty box at this
moment?", each checked against the next:

1. **Analytic bounds** (:func:`analytic_bounds`). At a recorded moment the object is a
   payload rigidly held by a gripper, so the actuator forces the arm needs are affine in the
   object's mass, ``τ(m) = τ0 + m·y`` (Pinocchio inverse dynamics,
   :func:`critmoment.dynamics.payload_regressor`). The worst force over a mass interval is at
   an end point and the mass at which each joint reaches its force limit is closed-form. The
   grip needs friction ``m·|P⊥(a − g)|`` against ``μ·ΣFn`` available, which gives a
   closed-form contact factor of safety.
2. **CasADi** (:func:`analytic_worst_case`). The analytic cost
   ``C(m, μ) = A·exp(−α(FOS_c − 1)) + B·exp(−β(FOS_m − 1))`` as a smooth CasADi expression,
   maximised over the box by IPOPT from every corner; the failure boundary
   ``C(m, μ) = threshold`` from the exact closed form.
3. **Optuna** (:func:`search_worst_case`). The *simulated* cost (sparse evaluation) maximised
   by a seeded sampler with batched ask/tell.
4. **CasADi on the simulation** (:func:`surrogate_worst_case`). The simulated cost on a grid
   of the box (edges included), a B-spline interpolant of it as a CasADi function, IPOPT
   from the best grid points, each optimum re-simulated. Where the analytic model cannot say
   what happens beyond failure (the transient of a slipping grasp), this maximises the
   simulation itself.

:func:`verify` re-evaluates every worst case with sparse evaluation and reports how far the
analytic model is from the simulation; :func:`audit_moment` chains everything into the JSON
object that ``report.json`` carries per moment.

Modelling choices (see ``docs/search.md`` for the measurements behind them):

* **Attachment body.** The object is attached to the *gripper body*: the body carrying the
  gripper's pad geoms after stepping out of bodies moved by slide joints (the fingers). For the
  ViperX that is ``<arm>/gripper_link``. The fingers of a parallel gripper move symmetrically
  about it, and the wrench a payload puts on every rotational joint upstream is the same
  whether it is attached to a finger or to the gripper link (inverse dynamics passes the whole
  wrench up the chain), so only the fingers' own slide forces would differ, and those are not
  part of the motor factor of safety.
* **Acceleration.** ``q̈`` is MuJoCo's ``qacc`` after ``mj_forward`` at the restored state
  with step ``k``'s controls: the acceleration of the forces of step ``k``, the same solve
  whose sensor readings the recording holds (bit-identical). The finite difference
  ``(qvel[k+1] − qvel[k]) / dt`` is *not* that acceleration with ``implicitfast``: the
  velocity update solves ``(M − dt·∂f/∂v)·Δv = dt·f``, so damped joints (servo ``kv``, joint
  damping) move by 12–20 % less than ``qacc`` says (measured on the demo at lift-off, e.g.
  2.44 vs 2.10 rad/s² on the right wrist_rotate). The difference in inverse-dynamics force is
  ≤ 0.01 N·m there, small beside the limits; for the free object both agree exactly.
* **Required actuator force.** ``τ0`` is inverse dynamics with armature minus MuJoCo's
  passive forces (joint damping ``dof_damping·q̇``, and springs, gravity compensation and
  fluid forces where the model has them), divided by the transmission gear; dry joint friction (``frictionloss``,
  0.1 N·m on the ViperX) is left out because its sign is not known at a moment.
* **Grip.** The grip is modelled as ``ΣFn = pads × finger force limit`` (each pad presses with
  its finger's saturated force, the bundled demo's 5 N per finger) and Coulomb friction with
  the object's friction coefficient. Only the component of ``m(a − g)`` *perpendicular to the
  grasp axis* (the dominant contact normal) needs friction; the component along it is carried
  by the pads' normal forces (the finger servo, then the finger's joint limit). At the demo's
  hand-over the receiving gripper holds the cube with a vertical grasp axis, so the weight
  rests on the lower pad and friction is not what limits the grip.
* **Two grippers.** When both hold, the load sharing is unknown: the motor bound lets either
  arm carry the whole load (the worse of the two) and the contact bound takes the stronger
  single grasp (if one gripper alone can hold the object, both can); the moment is flagged.
* **Static vs step load.** The analytic force is what holds the payload once the servos have
  taken the load. Sparse evaluation changes the mass *suddenly* at the restored state, and an
  under-damped position servo overshoots a suddenly applied load (up to twice the static change
  for an undamped one). :attr:`AnalyticBounds.step_load_critical_mass` is the critical mass
  under that factor of 2; simulated critical masses fall between it and the static one.
"""

from __future__ import annotations

import contextlib
import dataclasses
import enum
import importlib.util
import math
import numbers
import threading
import warnings
from collections.abc import Generator, Mapping, Sequence
from typing import TYPE_CHECKING, Any

import mujoco
import numpy as np

from critmoment import dynamics as dyn
from critmoment.exceptions import ParameterError
from critmoment.params import FrictionParameter, MassParameter, Prior, UncertaintyBox
from critmoment.scenario import CostParams
from critmoment.twin import Twin

if TYPE_CHECKING:
    from critmoment.sparse import SparseResult

__all__ = [
    "SearchMethod",
    "GraspLoad",
    "AnalyticBounds",
    "analytic_bounds",
    "BoundaryPoint",
    "AnalyticWorstCase",
    "analytic_worst_case",
    "SearchTrial",
    "SearchResult",
    "search_worst_case",
    "run_searches",
    "SurrogateWorstCase",
    "surrogate_worst_case",
    "CheckedPoint",
    "Verification",
    "verify",
    "audit_moment",
    "audit_moments",
    "DEFAULT_SMOOTHING",
]

#: sharpness κ of the log-sum-exp smooth maximum of joint utilisations |τ_j|/τmax_j in the
#: CasADi model: the smooth value exceeds the true maximum by at most ln(n_terms)/κ
#: (≤ 0.013 for 12 terms), so the smooth motor FOS is at most ~1.3 % below the exact one
DEFAULT_SMOOTHING = 200.0
#: cost told to Optuna for a diverged sample (cost +inf): larger than any finite cost
_DIVERGED_COST = 1e6
#: |τ| is smoothed as sqrt(τ² + ε²) with ε this fraction of the joint's limit
_ABS_EPS = 1e-9
#: grid points per parameter scanned before Brent refines a boundary crossing
_SCAN = 2049


class SearchMethod(enum.Enum):
    """Optuna sampler of :func:`search_worst_case`."""

    TPE = "tpe"
    """Multivariate tree-structured Parzen estimator (seeded, constant liar for batches).
    The default: it models the mass–friction interaction from a few dozen trials, handles
    log-uniform ranges natively and needs nothing beyond Optuna."""
    CMAES = "cmaes"
    """CMA-ES (Optuna's ``CmaEsSampler``, one generation per batch); needs the ``cmaes``
    package."""


# --------------------------------------------------------------------------
# validation helpers
# --------------------------------------------------------------------------


#: the most trials, boundary points or grid points per parameter a search takes: Optuna keeps
#: every trial in memory and its TPE slows with each; more says nothing a finer moment set
#: would not (the audit's own bound, ``analysis.MAX_SEARCH_TRIALS``, is this)
MAX_TRIALS = 4096
#: the most IPOPT iterations per start
MAX_ITER = 100_000


def _check_int(name: str, value: Any, minimum: int, most: int | None = None) -> int:
    if (isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < minimum
            or (most is not None and value > most)):
        within = f">= {minimum}" if most is None else f"in [{minimum}, {most}]"
        raise ParameterError(f"{name}: expected an integer {within}, got {value!r}")
    return int(value)


def _check_positive(name: str, value: Any) -> float:
    if (isinstance(value, bool) or not isinstance(value, numbers.Real)
            or not math.isfinite(value) or value <= 0):
        raise ParameterError(f"{name}: expected a finite number > 0, got {value!r}")
    return float(value)


def _check_method(value: Any) -> SearchMethod:
    if isinstance(value, SearchMethod):
        return value
    try:
        return SearchMethod(value)
    except ValueError:
        raise ParameterError(
            f"method: expected one of {[m.value for m in SearchMethod]} (SearchMethod), "
            f"got {value!r}") from None


def _step_of(step: Any) -> int:
    """A physics step index from an int or an object with an int ``step`` (a Moment)."""
    value = getattr(step, "step", step)
    if isinstance(value, bool) or not isinstance(value, (numbers.Integral, np.integer)):
        raise ParameterError(f"step: expected an integer physics step index, got {step!r}")
    return int(value)


def _finite_or_none(x: float) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


def _rel(analytic: float, simulated: float) -> float:
    """Signed relative disagreement (analytic − simulated)/|simulated|; 0 if both are +inf."""
    a, s = float(analytic), float(simulated)
    if math.isnan(a) or math.isnan(s):
        return math.nan
    if math.isinf(a) or math.isinf(s):
        return 0.0 if a == s else math.copysign(math.inf, a - s)
    if s == 0.0:
        return 0.0 if a == 0.0 else math.copysign(math.inf, a)
    return (a - s) / abs(s)


# --------------------------------------------------------------------------
# analytic bounds
# --------------------------------------------------------------------------


@dataclasses.dataclass(frozen=True, eq=False)
class GraspLoad:
    """One gripper holding the object at a moment, as the analytic model sees it.

    Attributes:
        gripper: the gripper's name in the scenario.
        attach_body: the body the object is attached to (the gripper body, see the module
            docstring).
        pads: number of pad geoms of the gripper.
        normal_force: assumed total normal force of the grasp ΣFn [N]: pads × the finger
            actuators' force limit, or the caller's value.
        measured_normal_force: total normal force of the object's contacts with this
            gripper in the recorded step [N].
        grasp_axis: the dominant contact normal in the world frame, (3,) unit vector
            (sign arbitrary).
        demand_per_kg: |P⊥(a − g)|, the friction force each kg of object needs [N/kg]:
            the object's acceleration against gravity projected off the grasp axis.
        axial_per_kg: |n·(a − g)|, the part carried by the pads' normal forces [N/kg].
        y: actuator force per kg of object on each rotational actuator, (J,) [N·m/kg];
            non-zero only on the joints that move ``attach_body``.
    """

    gripper: str
    attach_body: str
    pads: int
    normal_force: float
    measured_normal_force: float
    grasp_axis: np.ndarray
    demand_per_kg: float
    axial_per_kg: float
    y: np.ndarray


@dataclasses.dataclass(frozen=True, eq=False)
class AnalyticBounds:
    """Closed-form motor and grip bounds at one moment over the uncertainty box.

    Forces are actuator forces [N·m] on the J rotational actuators (the ones the motor FOS
    covers). With H holding grippers, row h of ``y`` is the load if gripper h carries the
    whole object (see the module docstring for two grippers).

    Attributes:
        step: the moment, physics step index.
        time: its time [s].
        holding: grippers touching the object.
        on_support: the object touches its support (table) in the recorded step.
        grasps: one :class:`GraspLoad` per holding gripper, (H,).
        joints: names of the J rotational actuators.
        tau0: actuator force needed without the object, (J,) [N·m].
        y: actuator force per kg of object, (H, J) [N·m/kg].
        tau_max: force limits, (J,) [N·m].
        mass_range: (low, high) of the object's mass over the box [kg].
        mass_nominal: the nominal mass [kg].
        friction_range: (low, high) of the friction coefficient over the box.
        friction_nominal: the nominal friction coefficient.
        object_acc: the object's linear acceleration in the world [m/s²], (3,).
        gravity: gravity [m/s²], (3,).
        cost_params: the scenario's cost constants.
        parameter_names: the box's parameter names.
        parameter_nominal: their nominal values.
        mass_index: column of the object's mass in the box, or None.
        friction_index: column of the object's friction in the box, or None.
        critical_mass: per joint, the smallest mass ≥ 0 at which |τ| reaches the limit
            (worst over the holding grippers), (J,) [kg]; inf if never, 0 if already over.
        worst_torque: per joint, the largest |τ| over the mass range (at an end), (J,) [N·m].
        worst_mass: the mass at which it occurs, (J,) [kg].
        limiting_joint: the joint with the smallest critical mass, or None when no joint
            depends on the mass.
        motor_critical_mass: the smallest critical mass over the joints [kg] (FOS_m = 1).
        motor_critical_mass_threshold: the smallest mass at which the motor term alone
            reaches the cost threshold (FOS_m = 1 + ln(B/threshold)/β) [kg]; inf if never.
        step_load_critical_mass: the mass at which a suddenly applied load reaches a limit if
            the servo overshoots the static change by a factor 2 (undamped servo):
            ``|τ(m_nom) + 2(m − m_nom)·y| = τmax`` [kg].
        contact_critical_mass: mass at which the analytic contact FOS is 1 at nominal
            friction [kg]; inf when friction is not needed (or no grasp).
        contact_critical_mass_threshold: mass at which the contact term alone reaches the
            cost threshold at nominal friction (FOS_c = 1 + ln(A/threshold)/α) [kg]; inf if
            it never does.
        assumptions_hold: False when the object rests on the support, no gripper holds it,
            two grippers hold it, or the grasp force is unknown.
        notes: why the assumptions do not hold, and other caveats.
    """

    step: int
    time: float
    holding: tuple[str, ...]
    on_support: bool
    grasps: tuple[GraspLoad, ...]
    joints: tuple[str, ...]
    tau0: np.ndarray
    y: np.ndarray
    tau_max: np.ndarray
    mass_range: tuple[float, float]
    mass_nominal: float
    friction_range: tuple[float, float]
    friction_nominal: float
    object_acc: np.ndarray
    gravity: np.ndarray
    cost_params: CostParams
    parameter_names: tuple[str, ...]
    parameter_nominal: tuple[float, ...]
    mass_index: int | None
    friction_index: int | None
    critical_mass: np.ndarray
    worst_torque: np.ndarray
    worst_mass: np.ndarray
    limiting_joint: str | None
    motor_critical_mass: float
    motor_critical_mass_threshold: float
    step_load_critical_mass: float
    contact_critical_mass: float
    contact_critical_mass_threshold: float
    assumptions_hold: bool
    notes: tuple[str, ...]

    # -- parameters ----------------------------------------------------------------
    def parameters_at(self, mass: float, friction: float) -> dict[str, float]:
        """Every box parameter by name: the object's mass and friction set, the rest nominal."""
        values = {n: float(v) for n, v in zip(self.parameter_names, self.parameter_nominal, strict=False)}
        if self.mass_index is not None:
            values[self.parameter_names[self.mass_index]] = float(mass)
        if self.friction_index is not None:
            values[self.parameter_names[self.friction_index]] = float(friction)
        return values

    def point_of(self, parameters: Mapping[str, float] | np.ndarray) -> tuple[float, float]:
        """(mass, friction) of a parameter point (a name -> value mapping or a (k,) row)."""
        if isinstance(parameters, Mapping):
            row = [parameters.get(n, v) for n, v in zip(self.parameter_names,
                                                        self.parameter_nominal, strict=False)]
        else:
            row = np.asarray(parameters, dtype=np.float64).reshape(-1)
            if row.shape[0] != len(self.parameter_names):
                raise ParameterError(
                    f"expected a point of {len(self.parameter_names)} values "
                    f"{self.parameter_names}, got {row.shape[0]}")
        mass = float(row[self.mass_index]) if self.mass_index is not None else self.mass_nominal
        friction = (float(row[self.friction_index]) if self.friction_index is not None
                    else self.friction_nominal)
        return mass, friction

    # -- closed forms, vectorised ------------------------------------------------
    def torques(self, mass: np.ndarray | float) -> np.ndarray:
        """Needed actuator forces τ0 + m·y, (..., H, J) [N·m] (H ≥ 1; τ0 alone if no grasp)."""
        m = np.asarray(mass, dtype=np.float64)[..., None, None]
        y = self.y if self.y.shape[0] else np.zeros((1, self.tau0.shape[0]))
        return self.tau0 + m * y

    def fos_motor_joints(self, mass: np.ndarray | float) -> np.ndarray:
        """Motor FOS per joint τmax/|τ(m)|, worst over the holding grippers, (..., J)."""
        tau = np.abs(self.torques(mass))
        with np.errstate(divide="ignore"):
            ratio = np.where(tau > 0, self.tau_max / tau, np.inf)
        return ratio.min(axis=-2)

    def fos_motor(self, mass: np.ndarray | float) -> np.ndarray:
        """Analytic motor FOS min_j τmax_j/|τ0_j + m·y_j|, shape of ``mass``."""
        return self.fos_motor_joints(mass).min(axis=-1)

    def fos_contact(self, mass: np.ndarray | float, friction: np.ndarray | float
                    ) -> np.ndarray:
        """Analytic contact FOS μ·ΣFn/(m·|P⊥(a − g)|), broadcast shape of the inputs.

        With two grippers, the stronger single grasp; +inf without a grasp (or without a
        known grasp force) or without friction demand.
        """
        m, mu = np.broadcast_arrays(np.asarray(mass, dtype=np.float64),
                                    np.asarray(friction, dtype=np.float64))
        known = [g for g in self.grasps if math.isfinite(g.normal_force)]
        out = np.full(m.shape, -np.inf if known else np.inf)
        for g in known:
            with np.errstate(divide="ignore", invalid="ignore"):
                demand = m * g.demand_per_kg
                fos = np.where(demand > 0, mu * g.normal_force / demand, np.inf)
            out = np.maximum(out, fos)
        return out

    def cost(self, mass: np.ndarray | float, friction: np.ndarray | float) -> np.ndarray:
        """Analytic cost (eq. 15) of the closed-form factors of safety."""
        cp = self.cost_params
        with np.errstate(over="ignore"):
            c = cp.A * np.exp(-cp.alpha * (self.fos_contact(mass, friction) - 1.0))
            mm = cp.B * np.exp(-cp.beta * (self.fos_motor(mass) - 1.0))
        return c + np.broadcast_to(mm, np.shape(c))

    @property
    def min_fos_motor(self) -> float:
        """Smallest analytic motor FOS over the mass range (at an end of it)."""
        return float(self.fos_motor(np.array(self.mass_range)).min())

    @property
    def min_fos_contact(self) -> float:
        """Smallest analytic contact FOS over the box (heaviest, most slippery corner)."""
        return float(self.fos_contact(self.mass_range[1], self.friction_range[0]))

    def summary(self) -> dict:
        """JSON-able summary (the ``"analytic"`` object of ``report.json``; None = never)."""
        return {
            "step": self.step,
            "time": self.time,
            "holding": list(self.holding),
            "on_support": self.on_support,
            "critical_mass": {j: _finite_or_none(v)
                              for j, v in zip(self.joints, self.critical_mass, strict=False)},
            "worst_torque": {j: float(v) for j, v in zip(self.joints, self.worst_torque, strict=False)},
            "limiting_joint": self.limiting_joint,
            "motor_critical_mass": _finite_or_none(self.motor_critical_mass),
            "motor_critical_mass_threshold": _finite_or_none(self.motor_critical_mass_threshold),
            "step_load_critical_mass": _finite_or_none(self.step_load_critical_mass),
            "min_fos_motor": _finite_or_none(self.min_fos_motor),
            "min_fos_contact": _finite_or_none(self.min_fos_contact),
            "contact_critical_mass": _finite_or_none(self.contact_critical_mass),
            "contact_critical_mass_threshold": _finite_or_none(
                self.contact_critical_mass_threshold),
            "grasps": [{"gripper": g.gripper, "attach_body": g.attach_body,
                        "normal_force": _finite_or_none(g.normal_force),
                        "measured_normal_force": float(g.measured_normal_force),
                        "grasp_axis": [float(v) for v in g.grasp_axis],
                        "demand_per_kg": float(g.demand_per_kg)} for g in self.grasps],
            "assumptions_hold": self.assumptions_hold,
            "notes": list(self.notes),
        }


def _mass_and_friction(twin: Twin) -> tuple[int | None, int | None]:
    """Columns of the box's object-mass and object-friction parameters (None if absent)."""
    sc = twin.scenario
    mass_col = friction_col = None
    for j, p in enumerate(sc.box.parameters):
        if isinstance(p, MassParameter) and p.target == sc.object_body and mass_col is None:
            mass_col = j
        elif (isinstance(p, FrictionParameter) and p.target == sc.object_geom
              and friction_col is None):
            friction_col = j
    return mass_col, friction_col


def _gripper_body(model: mujoco.MjModel, pad_bodies: Sequence[int]) -> int:
    """The gripper body: step out of slide-jointed (finger) bodies, then the common ancestor."""
    def has_slide(b: int) -> bool:
        start, num = model.body_jntadr[b], model.body_jntnum[b]
        return any(model.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE
                   for j in range(start, start + num))

    def chain(b: int) -> list[int]:
        out = [b]
        while b != 0:
            b = int(model.body_parentid[b])
            out.append(b)
        return out

    bases = []
    for b in pad_bodies:
        b = int(b)
        while b != 0 and has_slide(b):
            b = int(model.body_parentid[b])
        bases.append(b)
    common = chain(bases[0])
    for b in bases[1:]:
        ancestors = set(chain(b))
        common = [c for c in common if c in ancestors]
    return common[0]


def _finger_limits(twin: Twin, pad_bodies: Sequence[int]) -> list[float]:
    """Force limits of the actuators on the slide joints that move the pad bodies."""
    model = twin.model
    limits = []
    for b in pad_bodies:
        b = int(b)
        while b != 0:
            start, num = model.body_jntadr[b], model.body_jntnum[b]
            slides = [j for j in range(start, start + num)
                      if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE]
            acts = [a for a in range(model.nu)
                    if model.actuator_trntype[a] == mujoco.mjtTrn.mjTRN_JOINT
                    and model.actuator_trnid[a, 0] in slides]
            if acts:
                lowest = twin.lowest_limits
                limits.extend(float(lowest[a]) for a in acts)
                break
            if not slides:
                break
            b = int(model.body_parentid[b])
    return limits


def _slide_axis(model: mujoco.MjModel, data: mujoco.MjData, pad_bodies: Sequence[int]
                ) -> np.ndarray:
    """World axis (3,) of the first slide joint moving a pad body; the world z if none."""
    for b in pad_bodies:
        start, num = model.body_jntadr[b], model.body_jntnum[b]
        for j in range(start, start + num):
            if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE:
                return np.array(data.xaxis[j], dtype=np.float64)
    return np.array([0.0, 0.0, 1.0])


def _contacts_with(model: mujoco.MjModel, data: mujoco.MjData, obj_geom: int,
                   geoms: set[int]) -> tuple[float, np.ndarray | None]:
    """Total normal force [N] of the object's contacts with ``geoms``, dominant normal (3,)."""
    force = np.zeros(6)
    total = 0.0
    scatter = np.zeros((3, 3))
    for i in range(data.ncon):
        con = data.contact[i]
        pair = (int(con.geom1), int(con.geom2))
        if obj_geom not in pair or not ({pair[0], pair[1]} - {obj_geom}) & geoms:
            continue
        if con.efc_address < 0:
            continue
        mujoco.mj_contactForce(model, data, i, force)
        fn = max(float(force[0]), 0.0)
        normal = np.asarray(con.frame[:3], dtype=np.float64)
        total += fn
        scatter += fn * np.outer(normal, normal)
    if total <= 0:
        return 0.0, None
    w, v = np.linalg.eigh(scatter)
    return total, v[:, int(np.argmax(w))]


def analytic_bounds(recording, twin: Twin, step: Any, *,
                    pin_model: dyn.PinocchioModel | None = None,
                    normal_force: float | None = None) -> AnalyticBounds:
    """Closed-form motor and grip bounds at one recorded moment.

    Restores the recorded integration state before ``step`` with that step's controls,
    solves the forward dynamics once (``mj_forward``: the recorded sensor readings of the
    step, bit for bit), finds the grippers that touch the object, attaches the object's
    inertia (unit inertia per kg, at its recorded pose) to each holding gripper's body and
    computes ``τ(m) = τ0 + m·y`` on the rotational actuators with Pinocchio.

    Args:
        recording: the frequent rollout (``states`` (T + 1, nstate), ``controls`` (T, nu),
            ``dt``), recorded with ``twin``.
        twin: the twin.
        step: physics step index in [0, T − 1], or an object with an int ``step``.
        pin_model: the Pinocchio model of ``twin.model`` (built when None; cheap).
        normal_force: total normal force of a grasp ΣFn [N]; default pads × the finger
            actuators' force limit.

    Returns:
        The :class:`AnalyticBounds`.

    Raises:
        ParameterError: step out of range, or a bad ``normal_force``.
    """
    model = twin.model
    states = np.asarray(recording.states, dtype=np.float64)
    controls = np.asarray(recording.controls, dtype=np.float64)
    k = _step_of(step)
    n_steps = controls.shape[0]
    if not 0 <= k < n_steps:
        raise ParameterError(
            f"step: expected a physics step in [0, {n_steps - 1}] (recording of {n_steps} "
            f"steps), got {k}")
    if normal_force is not None:
        normal_force = _check_positive("normal_force", normal_force)
    pm = pin_model if pin_model is not None else dyn.from_mujoco(model)
    sc = twin.scenario
    cp = sc.cost

    data = mujoco.MjData(model)
    twin.set_state(model, data, states[k])
    data.ctrl[:] = controls[k]
    mujoco.mj_forward(model, data)
    sig = twin.signals(data.sensordata.copy())
    on_support = bool(sig.contact_support)
    touching = np.asarray(sig.contact_gripper, dtype=bool)
    holding = tuple(g.name for g, t in zip(sc.grippers, touching, strict=False) if t)
    acc = np.asarray(sig.object_acc, dtype=np.float64)
    gravity = np.array(model.opt.gravity, dtype=np.float64)

    # the box: the object's mass and friction (others stay at nominal)
    mass_col, friction_col = _mass_and_friction(twin)
    box = sc.box
    ob = twin.object_body_id
    if mass_col is None:
        m_lo = m_hi = m_nom = float(model.body_mass[ob])
    else:
        m_lo, m_hi, m_nom = box.low[mass_col], box.high[mass_col], box.nominal[mass_col]
    if friction_col is None:
        f_lo = f_hi = f_nom = twin.object_friction()
    else:
        f_lo, f_hi, f_nom = (box.low[friction_col], box.high[friction_col],
                             box.nominal[friction_col])

    # rotational actuators -> dofs, limits, gears
    rot = np.flatnonzero(twin.motors)
    joints = tuple(twin.actuator_names[a] for a in rot)
    dofs = model.jnt_dofadr[model.actuator_trnid[rot, 0]]
    gear = model.actuator_gear[rot, 0]
    tau_max = twin.lowest_limits[rot]  # a force-limit parameter at its range's low end

    unit_inertia = np.diag(model.body_inertia[ob] / model.body_mass[ob])
    pose = np.empty(7)
    pose[:3] = data.xipos[ob]
    mujoco.mju_mat2Quat(pose[3:], data.ximat[ob])

    notes: list[str] = []
    grasps: list[GraspLoad] = []
    tau0_full = None
    obj_geom = twin.object_geom_id
    for g, touch in zip(sc.grippers, touching, strict=False):
        if not touch:
            continue
        geom_ids = [model.geom(name).id for name in g.geoms]
        pad_bodies = [int(model.geom_bodyid[i]) for i in geom_ids]
        body = _gripper_body(model, pad_bodies)
        tau0_g, y_g = dyn.payload_regressor(
            pm, data.qpos, data.qvel, data.qacc, attach_body=body,
            payload_pose_world=pose, unit_inertia=unit_inertia, include_armature=True)
        tau0_full = tau0_g
        measured, axis = _contacts_with(model, data, obj_geom, set(geom_ids))
        if axis is None:
            # touching without force: fall back on a finger's slide axis (or the world z)
            axis = _slide_axis(model, data, pad_bodies)
        fingers = _finger_limits(twin, pad_bodies)
        # one pad force per finger body that a slide actuator drives (a gripper given by
        # body also holds the palm's geoms, which press with no force of their own)
        n_fingers = len({b for b in pad_bodies if _finger_limits(twin, [b])})
        if normal_force is not None:
            fn = normal_force
        elif fingers:
            fn = n_fingers * max(fingers)
        elif measured > 0:
            fn = float(measured)
            notes.append(
                f"gripper {g.name!r}: its fingers are not driven by slide actuators (a tendon, "
                "linkage or hinge jaw), so the actuator's force limit gives no pad force; the "
                f"grip bound uses the recorded grasp force {measured:.3g} N")
        else:
            fn = math.nan
            notes.append(f"gripper {g.name!r}: no slide actuator moves its pads (a tendon, "
                         "linkage or hinge jaw) and the recording shows no grasp force here, so "
                         "the grasp force is unknown; pass normal_force to bound the grip")
        rel = acc - gravity
        axial = float(abs(axis @ rel))
        perp = float(np.linalg.norm(rel - axis * (axis @ rel)))
        grasps.append(GraspLoad(
            gripper=g.name, attach_body=model.body(body).name, pads=max(n_fingers, 1),
            normal_force=float(fn), measured_normal_force=float(measured),
            grasp_axis=axis, demand_per_kg=perp, axial_per_kg=axial,
            y=y_g[dofs] / gear))
        if math.isfinite(fn) and measured < 0.9 * fn:
            notes.append(
                f"gripper {g.name!r}: recorded grasp force {measured:.3g} N is below the assumed "
                f"{fn:.3g} N (pads × finger force limit): the contact bound is optimistic here")
        if axial > 0.5 * np.linalg.norm(rel):
            angle = math.degrees(math.acos(min(1.0, axial / np.linalg.norm(rel))))
            notes.append(
                f"gripper {g.name!r}: the grasp axis is {angle:.0f}° from the load direction: "
                "the pads' normal forces (finger servo, then the finger's joint limit) carry "
                "most of the load, friction only the rest")
    if tau0_full is None:
        qfrc = pm.rnea(data.qpos, data.qvel, data.qacc, include_armature=True)
        tau0_full = qfrc
    # minus MuJoCo's passive forces (joint damping, springs, gravity compensation, fluid)
    tau0 = (tau0_full[dofs] - dyn.unactuated_force(model, data)[dofs]) / gear
    y = (np.stack([g.y for g in grasps]) if grasps else np.zeros((0, rot.size)))

    if not holding:
        notes.append("no gripper touches the object: nothing carries it, no payload bound")
    if on_support:
        notes.append("the object touches its support: the grip does not carry the whole "
                     "weight; the bounds assume it does (as right after lift-off)")
    if len(holding) > 1:
        notes.append(f"{len(holding)} grippers hold the object ({', '.join(holding)}): load "
                     "sharing is unknown; the motor bound lets either arm carry the whole "
                     "load, the contact bound takes the stronger single grasp")
    if friction_col is None:
        notes.append("the box has no friction parameter of the object: friction fixed at "
                     f"{f_nom:g}")
    others = [p.name for j, p in enumerate(box.parameters) if j not in (mass_col, friction_col)]
    if others:
        notes.append(f"the analytic model holds {', '.join(others)} at nominal")
    # a free-floating robot standing on its contacts: inverse dynamics of the floating chain
    # puts its weight (and the payload's) into the unactuated free joint, not into the legs
    standing = dyn.standing_actuators(model, data, twin)
    standing = [twin.actuator_names[a] for a in rot if a in standing]
    if standing:
        notes.append(f"the robot's free-floating base stands on its contacts through "
                     f"{', '.join(standing)}: their load includes its weight, which the "
                     f"bound leaves out (not bounded)")
    assumptions_hold = (bool(holding) and not on_support and len(holding) == 1
                        and all(math.isfinite(g.normal_force) for g in grasps)
                        and not standing)

    # per joint: critical mass (worst over grippers), worst |τ| over the mass range
    y_rows = y if y.shape[0] else np.zeros((1, rot.size))
    crit = dyn.critical_mass(tau0[None], y_rows, tau_max[None]).min(axis=0)
    ends = np.array([m_lo, m_hi])
    tau_ends = np.abs(tau0[None, None] + ends[:, None, None] * y_rows[None])  # (2, H, J)
    per_end = tau_ends.max(axis=1)  # (2, J)
    worst_torque = per_end.max(axis=0)
    worst_mass = ends[np.argmax(per_end, axis=0)]
    depends = np.abs(y_rows).max(axis=0) > 0
    limiting = None
    motor_crit = math.inf
    if depends.any() and np.isfinite(crit[depends]).any():
        j = int(np.flatnonzero(depends)[np.argmin(crit[depends])])
        limiting, motor_crit = joints[j], float(crit[j])
    fos_m_star = 1.0 + math.log(cp.B / cp.threshold) / cp.beta if cp.B > cp.threshold else None
    if fos_m_star is None:
        motor_thr = math.inf
    else:
        motor_thr = float(dyn.critical_mass(tau0[None], y_rows,
                                            tau_max[None] / fos_m_star).min())
    step_load = float(dyn.critical_mass(tau0[None] - m_nom * y_rows, 2.0 * y_rows,
                                        tau_max[None]).min())
    # contact: the stronger single grasp at nominal friction
    fos_c_star = 1.0 + math.log(cp.A / cp.threshold) / cp.alpha if cp.A > cp.threshold else None
    contact_crit = contact_thr = math.inf
    finite = [g for g in grasps if math.isfinite(g.normal_force)]
    if finite and len(finite) == len(grasps):
        caps = [f_nom * g.normal_force / g.demand_per_kg if g.demand_per_kg > 0 else math.inf
                for g in grasps]
        contact_crit = float(max(caps))
        if fos_c_star is not None:
            contact_thr = contact_crit / fos_c_star
    return AnalyticBounds(
        step=k, time=float(k * getattr(recording, "dt", model.opt.timestep)),
        holding=holding, on_support=on_support, grasps=tuple(grasps), joints=joints,
        tau0=tau0, y=y, tau_max=tau_max, mass_range=(float(m_lo), float(m_hi)),
        mass_nominal=float(m_nom), friction_range=(float(f_lo), float(f_hi)),
        friction_nominal=float(f_nom), object_acc=acc, gravity=gravity, cost_params=cp,
        parameter_names=box.names, parameter_nominal=tuple(float(v) for v in box.nominal),
        mass_index=mass_col, friction_index=friction_col,
        critical_mass=crit, worst_torque=worst_torque, worst_mass=worst_mass,
        limiting_joint=limiting, motor_critical_mass=motor_crit,
        motor_critical_mass_threshold=motor_thr, step_load_critical_mass=step_load,
        contact_critical_mass=contact_crit, contact_critical_mass_threshold=contact_thr,
        assumptions_hold=assumptions_hold, notes=tuple(notes))


# --------------------------------------------------------------------------
# CasADi: worst case of the analytic cost and its failure boundary
# --------------------------------------------------------------------------


@dataclasses.dataclass(frozen=True)
class BoundaryPoint:
    """The failure boundary of the analytic cost at one friction value.

    Attributes:
        friction: the friction coefficient.
        critical_mass: the smallest mass in the range where the analytic cost exceeds the
            threshold [kg], or None when it never does.
        fails_everywhere: the whole mass range fails at this friction.
    """

    friction: float
    critical_mass: float | None
    fails_everywhere: bool = False


@dataclasses.dataclass(frozen=True)
class AnalyticWorstCase:
    """The worst case of the analytic cost over the box (CasADi + IPOPT) and its boundary.

    Attributes:
        step: the moment.
        parameters: the worst case, every box parameter by name (the ones the analytic model
            does not know at nominal).
        cost: exact analytic cost there (not the smoothed one the optimiser saw).
        fos_motor: exact analytic motor FOS there.
        fos_contact: exact analytic contact FOS there.
        dominant: "contact" or "motor", the larger cost term.
        fails: cost > threshold.
        starts: number of IPOPT starts (box corners, nominal, centre).
        solver_status: IPOPT's return status per start.
        boundary: the failure boundary, one :class:`BoundaryPoint` per friction value.
        critical_mass_nominal_friction: where the analytic cost crosses the threshold along
            mass at nominal friction [kg] (None if it never does).
        critical_friction_nominal_mass: the largest friction at which the analytic cost
            exceeds the threshold at nominal mass (fails below it), or None.
        smoothing: κ of the smooth maximum used by the optimiser.
        bounds: the analytic bounds the model was built from.
    """

    step: int
    parameters: Mapping[str, float]
    cost: float
    fos_motor: float
    fos_contact: float
    dominant: str
    fails: bool
    starts: int
    solver_status: tuple[str, ...]
    boundary: tuple[BoundaryPoint, ...]
    critical_mass_nominal_friction: float | None
    critical_friction_nominal_mass: float | None
    smoothing: float
    bounds: AnalyticBounds = dataclasses.field(repr=False, compare=False)

    def summary(self) -> dict:
        """JSON-able summary."""
        return {
            "parameters": dict(self.parameters), "cost": float(self.cost),
            "fos_motor": _finite_or_none(self.fos_motor),
            "fos_contact": _finite_or_none(self.fos_contact), "dominant": self.dominant,
            "fails": self.fails, "solver_status": list(self.solver_status),
            "critical_mass_nominal_friction": self.critical_mass_nominal_friction,
            "critical_friction_nominal_mass": self.critical_friction_nominal_mass,
            "boundary": [{"friction": b.friction, "critical_mass": b.critical_mass,
                          "fails_everywhere": b.fails_everywhere} for b in self.boundary],
        }


def _smooth_cost(bounds: AnalyticBounds, kappa: float):
    """CasADi function (m, μ) -> smooth analytic cost, and the symbols."""
    import casadi as ca

    cp = bounds.cost_params
    m = ca.SX.sym("m")
    mu = ca.SX.sym("mu")
    finite = np.isfinite(bounds.tau_max) & (bounds.tau_max > 0)
    tau0, tmax = bounds.tau0[finite], bounds.tau_max[finite]
    rows = bounds.y[:, finite] if bounds.y.shape[0] else np.zeros((1, int(finite.sum())))
    terms = []
    for row in rows:
        for t0, yj, tm in zip(tau0, row, tmax, strict=False):
            tau = t0 + m * yj
            terms.append(ca.sqrt(tau * tau + (_ABS_EPS * tm) ** 2) / tm)
    cost = 0
    if terms:
        u_motor = ca.logsumexp(kappa * ca.vertcat(*terms)) / kappa
        cost = cost + cp.B * ca.exp(-cp.beta * (1.0 / u_motor - 1.0))
    grips = [g for g in bounds.grasps if math.isfinite(g.normal_force) and g.demand_per_kg > 0]
    if grips and len(grips) == len(bounds.grasps):
        util = [m * g.demand_per_kg / (mu * g.normal_force) for g in grips]
        u_contact = (util[0] if len(util) == 1
                     else -ca.logsumexp(-kappa * ca.vertcat(*util)) / kappa)
        cost = cost + cp.A * ca.exp(-cp.alpha * (1.0 / u_contact - 1.0))
    return m, mu, cost


def _first_crossings(f, lo: float, hi: float, threshold: float, rows: int, *,
                     from_high: bool = False, split: int = 15
                     ) -> list[tuple[float | None, bool]]:
    """Per row r, the first x in [lo, hi] (scanning up, or down with ``from_high``) where
    f(x)[r] > threshold; ``f`` maps x (rows, p) to the values (rows, p).

    A scan of ``_SCAN`` points brackets each crossing; every bracket is then refined at
    once, ``split`` interior points per round, to 1e-12 relative. Returns, per row, (the
    crossing, the bracket's failing end: f exceeds the threshold there; or None if f never
    exceeds it; fails at the scan's start).
    """
    if hi <= lo:
        bad = f(np.full((rows, 1), lo))[:, 0] > threshold
        return [(lo if b else None, False) for b in bad]
    xs = np.linspace(lo, hi, _SCAN)
    if from_high:
        xs = xs[::-1]
    bad = f(np.tile(xs, (rows, 1))) > threshold
    first = np.argmax(bad, axis=1)
    inside = bad.any(axis=1) & (first > 0)
    a = xs[np.maximum(first - 1, 0)]  # the passing end of each bracket
    b = xs[first]                     # the failing end
    fractions = np.arange(1, split + 1) / (split + 1)
    open_ = inside.copy()
    at = np.arange(rows)
    while open_.any():
        pts = a[:, None] + (b - a)[:, None] * fractions[None]        # (rows, split)
        fails = f(pts) > threshold
        q = np.where(fails.any(axis=1), np.argmax(fails, axis=1), split)
        new_a = np.where(q > 0, pts[at, np.maximum(q - 1, 0)], a)
        new_b = np.where(q < split, pts[at, np.minimum(q, split - 1)], b)
        a, b = np.where(open_, new_a, a), np.where(open_, new_b, b)
        open_ &= np.abs(b - a) > 1e-12 * np.maximum(1.0, np.abs(b))
    out = []
    for r in range(rows):
        if not bad[r].any():
            out.append((None, False))
        elif first[r] == 0:
            out.append((float(xs[0]), True))
        else:
            out.append((float(b[r]), False))  # its failing end: f(x) > threshold there
    return out


def _solve(solver, **args) -> tuple[dict, str]:
    """One CasADi/IPOPT solve and its return status, interruptible: IPOPT runs Python's
    signal handlers between iterations, and CasADi swallows the KeyboardInterrupt they
    raise (the solve returns "NonIpopt_Exception_Thrown"), so a Ctrl-C or a SIGTERM there
    went on to a whole report and exit 1. The signal is noted and raised after the solve."""
    import signal

    noted: list[int] = []
    previous: dict[int, Any] = {}

    def note(signum, frame):
        noted.append(signum)
        handler = previous[signum]
        if callable(handler):
            handler(signum, frame)
        raise KeyboardInterrupt

    if threading.current_thread() is threading.main_thread():
        for sig in (signal.SIGINT, signal.SIGTERM):
            handler = signal.getsignal(sig)
            if callable(handler):  # a Python handler (Ctrl-C's, the CLI's SIGTERM)
                try:
                    signal.signal(sig, note)
                except (ValueError, OSError):
                    continue
                previous[sig] = handler
    try:
        sol = solver(**args)
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)
    if noted:
        raise KeyboardInterrupt
    return sol, str(solver.stats()["return_status"])


def analytic_worst_case(bounds: AnalyticBounds, *, smoothing: float = DEFAULT_SMOOTHING,
                        n_boundary: int = 9, max_iter: int = 200,
                        grid: int = 33) -> AnalyticWorstCase:
    """Maximise the analytic cost over the box with IPOPT and trace its failure boundary.

    The smooth model: |τ| ≈ sqrt(τ² + ε²), the motor FOS is the reciprocal of a log-sum-exp
    smooth maximum of the joint utilisations |τ_j|/τmax_j (sharpness ``smoothing``; it never
    exceeds the true FOS and is within ln(n)/κ of its reciprocal), the contact FOS is exact
    (one grasp) or a smooth maximum over grasps. The exact closed form is first evaluated
    on a ``grid`` × ``grid`` lattice of the box (one vectorised call); IPOPT starts from its
    highest point and from the nominal point; the answer is the candidate (the box corners,
    the nominal point, the centre, the lattice's highest point, IPOPT's solutions) whose
    *exact* closed-form cost is highest. The boundary C(m, μ) = threshold is solved on the
    exact closed form: for each of ``n_boundary`` friction values a scan of the mass range
    brackets the first crossing and a vectorised multi-point bisection refines every
    bracket at once to 1e-12 relative (a 1-D root of a closed form: bracketing cannot miss
    it, where a local optimiser could stop at the wrong side of a kink of the exact
    minimum).

    Args:
        bounds: from :func:`analytic_bounds`.
        smoothing: κ of the smooth maximum (> 0).
        n_boundary: friction values of the boundary (>= 1), evenly spaced over the range.
        max_iter: IPOPT iteration limit per start.
        grid: lattice points per parameter of the exact cost that seed IPOPT (>= 2).

    Returns:
        The :class:`AnalyticWorstCase`.
    """
    import casadi as ca

    smoothing = _check_positive("smoothing", smoothing)
    n_boundary = _check_int("n_boundary", n_boundary, 1, MAX_TRIALS)
    max_iter = _check_int("max_iter", max_iter, 1, MAX_ITER)
    grid = _check_int("grid", grid, 2, 1025)
    (m_lo, m_hi), (f_lo, f_hi) = bounds.mass_range, bounds.friction_range
    lo, hi = np.array([m_lo, f_lo]), np.array([m_hi, f_hi])
    span = np.where(hi > lo, hi - lo, 1.0)
    m, mu, cost = _smooth_cost(bounds, smoothing)
    u = ca.SX.sym("u", 2)  # unit-box coordinates: IPOPT sees well-scaled variables
    x = lo + span * u
    objective = -ca.substitute(ca.substitute(ca.SX(cost), m, x[0]), mu, x[1])
    solver = ca.nlpsol("worst", "ipopt", {"x": u, "f": objective},
                       {"ipopt.print_level": 0, "print_time": False, "ipopt.sb": "yes",
                        "show_eval_warnings": False, "ipopt.max_iter": max_iter,
                        "ipopt.tol": 1e-10})
    ub = np.where(hi > lo, 1.0, 0.0)
    nominal = (np.array([bounds.mass_nominal, bounds.friction_nominal]) - lo) / span
    # the corners, the nominal point and the centre are candidates, first, so that a flat
    # cost (nothing depends on the parameters) reports the heaviest, most slippery corner
    # rather than where IPOPT happened to stop; then the exact cost's highest lattice point
    points = [np.array(c, dtype=float) for c in ((1, 0), (1, 1), (0, 0), (0, 1))]
    points += [nominal, np.full(2, 0.5)]
    lattice = np.stack(np.meshgrid(np.linspace(0.0, 1.0, grid), np.linspace(0.0, 1.0, grid),
                                   indexing="ij"), axis=-1).reshape(-1, 2) * ub
    on_lattice = lo + span * lattice
    with np.errstate(invalid="ignore"):
        exact_lattice = np.nan_to_num(bounds.cost(on_lattice[:, 0], on_lattice[:, 1]),
                                      nan=-np.inf)
    top = lattice[int(np.argmax(exact_lattice))]
    points.append(top)
    candidates = [lo + span * np.minimum(s, ub) for s in points]
    starts = [top, nominal]
    status = []
    for s in starts:
        sol, state = _solve(solver, x0=np.minimum(s, ub), lbx=np.zeros(2), ubx=ub)
        status.append(state)
        candidates.append(lo + span * np.clip(np.asarray(sol["x"]).reshape(-1), 0.0, ub))
    candidates = np.array(candidates)
    exact = bounds.cost(candidates[:, 0], candidates[:, 1])
    best = candidates[int(np.argmax(exact))]
    m_w, f_w = float(best[0]), float(best[1])

    cp = bounds.cost_params
    fos_m = float(bounds.fos_motor(m_w))
    fos_c = float(bounds.fos_contact(m_w, f_w))
    # both factors of safety are >= 0, so neither exponent exceeds α or β
    term_c = cp.A * math.exp(-cp.alpha * (fos_c - 1.0)) if math.isfinite(fos_c) else 0.0
    term_m = cp.B * math.exp(-cp.beta * (fos_m - 1.0)) if math.isfinite(fos_m) else 0.0
    total = term_c + term_m

    frictions = (np.linspace(f_lo, f_hi, n_boundary) if n_boundary > 1
                 else np.array([bounds.friction_nominal]))
    # the boundary's mass crossings, and last the one at the nominal friction
    at_friction = np.append(frictions, bounds.friction_nominal)[:, None]
    crossings = _first_crossings(lambda ms: bounds.cost(ms, at_friction), m_lo, m_hi,
                                 cp.threshold, at_friction.shape[0])
    boundary = [BoundaryPoint(friction=float(f), critical_mass=crit, fails_everywhere=everywhere)
                for f, (crit, everywhere) in zip(frictions, crossings[:-1], strict=True)]
    crit_m = crossings[-1][0]
    (crit_f, _), = _first_crossings(lambda fs: bounds.cost(bounds.mass_nominal, fs), f_lo,
                                    f_hi, cp.threshold, 1, from_high=True)
    return AnalyticWorstCase(
        step=bounds.step, parameters=bounds.parameters_at(m_w, f_w), cost=total,
        fos_motor=fos_m, fos_contact=fos_c,
        dominant="contact" if term_c > term_m else "motor", fails=total > cp.threshold,
        starts=len(starts), solver_status=tuple(status), boundary=tuple(boundary),
        critical_mass_nominal_friction=crit_m, critical_friction_nominal_mass=crit_f,
        smoothing=smoothing, bounds=bounds)




# --------------------------------------------------------------------------
# Optuna: worst case of the simulated cost
# --------------------------------------------------------------------------


@dataclasses.dataclass(frozen=True)
class SearchTrial:
    """One simulated evaluation of the search.

    Attributes:
        number: the trial's index (0-based, in evaluation order).
        batch: the batch (one ``evaluate`` call) it ran in.
        parameters: its parameter values by name.
        cost: the simulated cost, maximum over the moments (+inf if diverged).
        cost_per_moment: the cost at each moment, in ``SearchResult.steps`` order.
        enqueued: a box corner or the nominal point, enqueued before sampling.
    """

    number: int
    batch: int
    parameters: Mapping[str, float]
    cost: float
    cost_per_moment: tuple[float, ...]
    enqueued: bool


@dataclasses.dataclass(frozen=True)
class SearchResult:
    """The worst case of the simulated cost found by Optuna.

    Attributes:
        method: the sampler.
        steps: the moments searched over (the objective is the maximum cost over them).
        evaluations: parameter samples evaluated (each at every moment).
        worst_case: the most severe sample, parameter values by name.
        worst_cost: its cost (maximum over the moments; +inf if it diverged).
        worst_cost_per_moment: its cost at each moment.
        evaluations_to_worst: how many samples it took to first reach ``worst_cost``.
        stopped_early: the search stopped before its budget (``stop_reason`` says why).
        ceiling: the largest cost the simulation can give (see :func:`search_worst_case`),
            or None when ``stop_at_ceiling`` was off.
        seed: the sampler's seed.
        history: every trial, in evaluation order.
        stop_reason: "ceiling" (the cost reached its ceiling), "patience" (no higher cost
            in ``patience`` batches) or None (the budget ran out).
    """

    method: SearchMethod
    steps: tuple[int, ...]
    evaluations: int
    worst_case: Mapping[str, float]
    worst_cost: float
    worst_cost_per_moment: tuple[float, ...]
    evaluations_to_worst: int
    stopped_early: bool
    ceiling: float | None
    seed: int
    history: tuple[SearchTrial, ...]
    stop_reason: str | None = None

    def summary(self) -> dict:
        """JSON-able summary (the ``"search"`` object of ``report.json``)."""
        return {
            "method": self.method.value, "steps": list(self.steps),
            "evaluations": self.evaluations, "worst_case": dict(self.worst_case),
            "worst_cost": _finite_or_none(self.worst_cost),
            "diverged": math.isinf(self.worst_cost),
            "worst_cost_per_moment": [_finite_or_none(c) for c in self.worst_cost_per_moment],
            "evaluations_to_worst": self.evaluations_to_worst,
            "stopped_early": self.stopped_early, "stop_reason": self.stop_reason,
            "seed": self.seed,
        }


def _cost_ceiling(twin: Twin) -> float:
    """The largest cost the simulation can give: A·e^α + B (or B·e^β).

    The grasp's contact FOS is ≥ 0 (0 when a carried object is dropped), so the contact
    term never exceeds A·e^α. The motor FOS is ≥ 1 when every rotational actuator is
    force-limited within its scenario limit (as in the bundled scenario), so the motor term
    never exceeds B; otherwise only FOS ≥ 0 holds and the bound is B·e^β.
    """
    model, cp = twin.model, twin.scenario.cost
    rot = np.flatnonzero(twin.motors)
    limited = model.actuator_forcelimited[rot].astype(bool)
    reach = np.abs(model.actuator_forcerange[rot]).max(axis=1)
    bounded = limited.all() and (reach <= np.asarray(twin.limits)[rot] * (1 + 1e-12)).all()
    return float(cp.A * math.exp(cp.alpha) + (cp.B if bounded else cp.B * math.exp(cp.beta)))


_SOLVERS_LOADED = False


def load_solvers() -> None:
    """Imports the solvers the search uses, whole, with SIGINT and the stop signals held
    back (main thread): CasADi, and Optuna with the modules a study loads on its first
    trials. An interrupt that landed in one of those lazy imports mid-audit left Optuna
    half-imported, and every later audit in that process failed (``AttributeError: module
    'optuna.pruners' has no attribute '_filter_study'``). Once per process."""
    global _SOLVERS_LOADED
    if _SOLVERS_LOADED:
        return
    from critmoment._signals import signals_held

    with signals_held():
        import casadi  # noqa: F401
        import optuna
        from optuna.distributions import FloatDistribution

        with _quiet_optuna():
            study = optuna.create_study(direction="maximize",
                                        sampler=_sampler(optuna, SearchMethod.TPE, 0, 2))
            dist = {"x": FloatDistribution(0.0, 1.0)}
            for _ in range(7):  # pairs asked together, as the search does, past TPE's
                trials = [study.ask(dist), study.ask(dist)]  # random start-up trials
                for trial in trials:
                    study.tell(trial, trial.params["x"])
        _SOLVERS_LOADED = True


@contextlib.contextmanager
def _quiet_optuna():
    """Optuna at WARNING and its experimental warnings muted, restored afterwards."""
    import optuna

    previous = optuna.logging.get_verbosity()
    optuna.logging.set_verbosity(optuna.logging.WARNING)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", optuna.exceptions.ExperimentalWarning)
            yield optuna
    finally:
        optuna.logging.set_verbosity(previous)


def _sampler(optuna, method: SearchMethod, seed: int, batch_size: int):
    if method is SearchMethod.TPE:
        return optuna.samplers.TPESampler(seed=seed, multivariate=True, constant_liar=True)
    return optuna.samplers.CmaEsSampler(seed=seed, popsize=max(2, batch_size),
                                        warn_independent_sampling=False)


def _search_box(evaluator, box: UncertaintyBox | None) -> UncertaintyBox:
    """The box to search: the evaluator's, or one with the same parameters."""
    base: UncertaintyBox = evaluator.box
    box = base if box is None else box
    if not isinstance(box, UncertaintyBox) or box.names != base.names:
        raise ParameterError(
            f"box: expected an UncertaintyBox with parameters {base.names} (the evaluator's), "
            f"got {getattr(box, 'names', box)!r}")
    return box


#: relative rise of the highest cost that counts as progress for ``patience``
PATIENCE_RTOL = 0.01


def search_worst_case(evaluator, steps: Any, box: UncertaintyBox | None = None, *,
                      method: SearchMethod = SearchMethod.TPE, n_trials: int = 48,
                      batch_size: int = 8, seed: int = 0, enqueue_corners: bool = True,
                      stop_at_ceiling: bool = True, patience: int | None = None
                      ) -> SearchResult:
    """Search the box for the parameters that maximise the simulated cost.

    Ask/tell with Optuna: each batch of ``batch_size`` asked trials is evaluated in one
    ``evaluator.evaluate(steps, samples)`` call (sparse evaluation at every moment), and the
    objective of a sample is its largest cost over the moments (a diverged sample counts as
    the worst possible). Before sampling, the box corners and the nominal point are enqueued:
    the cost of this task is monotone in mass and friction at most moments, so its worst case
    is usually a corner, found in the first batch.

    The default sampler is multivariate TPE: it models the mass–friction interaction from a
    few dozen trials, handles log-uniform priors natively, is deterministic with a seed and
    needs no extra package; ``constant_liar`` makes the trials of one batch differ. CMA-ES
    (one generation per batch) needs ``cmaes`` and a few generations to move its mean.

    Stopping early: the simulated cost has a ceiling. The grasp's contact FOS is ≥ 0 (it is
    0 when a carried object is dropped), so the contact term is at most A·e^α; when every
    rotational actuator is force-limited within its scenario limit (the bundled scenario) the
    motor FOS is ≥ 1 and the motor term at most B (else B·e^β). The search stops once a
    sample reaches the ceiling (a dropped object with a saturated motor, or a diverged
    simulation): nothing can be more severe. Below the ceiling every trial of the budget
    runs; the simulated cost is not monotone beyond failure (at lift-off a grippier cube
    is dropped later and loads the arm longer), so its worst case need not be a corner.
    With ``patience`` the search also stops after that many batches in a row that do not
    raise the highest cost by more than :data:`PATIENCE_RTOL` (the audit's default; the
    budget is then a cap).

    Args:
        evaluator: a :class:`~critmoment.sparse.SparseEvaluator` (its horizon applies).
        steps: the moments, physics step indices (m,).
        box: the box to search (same parameter names as the evaluator's; ranges may be
            narrower); default the evaluator's.
        method: TPE (default) or CMAES.
        n_trials: samples to evaluate at most (>= 1).
        batch_size: samples per ``evaluate`` call (>= 1).
        seed: sampler seed (>= 0); the same seed gives the same result.
        enqueue_corners: evaluate the box corners and the nominal point first.
        stop_at_ceiling: stop once the cost reaches its ceiling (see above).
        patience: stop after this many batches (>= 1) without a higher cost (by more than
            :data:`PATIENCE_RTOL`), or None to run the whole budget below the ceiling.

    Returns:
        The :class:`SearchResult`.

    Raises:
        ParameterError: bad steps, options or box; CMAES without the ``cmaes`` package.
    """
    return run_searches(evaluator, [_search(
        evaluator, steps, box, method=method, n_trials=n_trials, batch_size=batch_size,
        seed=seed, enqueue_corners=enqueue_corners, stop_at_ceiling=stop_at_ceiling,
        patience=patience)])[0]


def _search(evaluator, steps: Any, box: UncertaintyBox | None, *, method: SearchMethod,
            n_trials: int, batch_size: int, seed: int, enqueue_corners: bool,
            stop_at_ceiling: bool, patience: int | None
            ) -> Generator[tuple[np.ndarray, np.ndarray], SparseResult, SearchResult]:
    """:func:`search_worst_case` as a generator: it yields each batch of asked samples as
    (steps, samples) to evaluate, is sent their :class:`SparseResult`, and returns the
    :class:`SearchResult` (:func:`run_searches` drives it)."""
    method = _check_method(method)
    n_trials = _check_int("n_trials", n_trials, 1, MAX_TRIALS)
    batch_size = _check_int("batch_size", batch_size, 1, MAX_TRIALS)
    seed = _check_int("seed", seed, 0)
    steps_arr = evaluator.check_steps(steps)
    box = _search_box(evaluator, box)
    if method is SearchMethod.CMAES and importlib.util.find_spec("cmaes") is None:
        raise ParameterError(
            "method CMAES: expected the 'cmaes' package to be importable (pip install cmaes), "
            "got none; use SearchMethod.TPE")
    ceiling = _cost_ceiling(evaluator.twin) if stop_at_ceiling else None
    patience = None if patience is None else _check_int("patience", patience, 1)

    names = box.names
    import optuna
    from optuna.distributions import FloatDistribution

    # Optuna is quiet in the caller's _quiet_optuna (searches run interleaved)
    dists = {p.name: FloatDistribution(p.low, p.high, log=p.prior is Prior.LOGUNIFORM)
             for p in box.parameters}
    study = optuna.create_study(direction="maximize",
                                sampler=_sampler(optuna, method, seed, batch_size))
    queued = []
    if enqueue_corners:
        for row in np.vstack([box.corners(), box.nominal[None]]):
            if not any(np.array_equal(row, q) for q in queued):
                queued.append(row)
        queued = queued[:n_trials]
        for row in queued:
            study.enqueue_trial({n: float(v) for n, v in zip(names, row, strict=False)})
    history: list[SearchTrial] = []
    stopped: str | None = None
    batch = 0
    best, since = -np.inf, 0
    while len(history) < n_trials and not stopped:
        size = min(batch_size, n_trials - len(history))
        trials = [study.ask(dists) for _ in range(size)]
        samples = np.array([[t.params[n] for n in names] for t in trials], dtype=np.float64)
        samples = np.clip(samples, box.low, box.high)
        res = yield steps_arr, samples
        per_moment = res.cost  # (m, size)
        costs = per_moment.max(axis=0)
        for i, t in enumerate(trials):
            value = float(costs[i])
            study.tell(t, min(value, _DIVERGED_COST))
            history.append(SearchTrial(
                number=len(history), batch=batch,
                parameters={n: float(v) for n, v in zip(names, samples[i], strict=False)}, cost=value,
                cost_per_moment=tuple(float(c) for c in per_moment[:, i]),
                enqueued=len(history) < len(queued)))
        batch += 1
        top = max(h.cost for h in history)
        progress = batch == 1 or top > best + PATIENCE_RTOL * abs(best)
        since = 0 if progress else since + 1
        best = top
        if len(history) < n_trials:
            if ceiling is not None and best >= ceiling * (1 - 1e-12):
                stopped = "ceiling"
            elif patience is not None and since >= patience:
                stopped = "patience"
    costs = np.array([h.cost for h in history])
    first = int(np.argmax(costs))  # argmax returns the first of equal maxima
    worst = history[first]
    return SearchResult(
        method=method, steps=tuple(int(s) for s in steps_arr), evaluations=len(history),
        worst_case=dict(worst.parameters), worst_cost=worst.cost,
        worst_cost_per_moment=worst.cost_per_moment, evaluations_to_worst=first + 1,
        stopped_early=stopped is not None, ceiling=ceiling, seed=seed, history=tuple(history),
        stop_reason=stopped)


def run_searches(evaluator, searches: Sequence[Generator]) -> list[SearchResult]:
    """Run Optuna searches side by side: each round, the batches that every search still
    running asks for are evaluated together (``evaluator.evaluate_many``: one batch call
    for the searches of all moments, not one per search). Each search asks and is told
    exactly as alone, so its result is the same.

    Args:
        evaluator: the sparse evaluator.
        searches: :func:`_search` generators.

    Returns:
        Their :class:`SearchResult`, in order.
    """
    results: list[SearchResult | None] = [None] * len(searches)
    pending: dict[int, tuple[np.ndarray, np.ndarray]] = {}

    def advance(i, value=None):
        try:
            pending[i] = searches[i].send(value)
        except StopIteration as stop:
            pending.pop(i, None)
            results[i] = stop.value

    with _quiet_optuna():
        for i in range(len(searches)):
            advance(i)
        while pending:
            order = list(pending)
            answers = evaluator.evaluate_many([pending[i] for i in order], settle=False)
            for i, res in zip(order, answers, strict=True):
                advance(i, res)
    return results


# --------------------------------------------------------------------------
# CasADi on the simulated cost: grid, B-spline surrogate, IPOPT
# --------------------------------------------------------------------------


@dataclasses.dataclass(frozen=True)
class SurrogateWorstCase:
    """The worst case of the simulated cost found through a CasADi surrogate.

    Attributes:
        steps: the moments (the objective is the maximum cost over them).
        parameters: the most severe point simulated, parameter values by name.
        cost: its simulated cost (+inf if it diverged).
        source: "grid" (a grid point) or "ipopt" (an optimum of the surrogate).
        grid: grid points per parameter.
        grid_cost: the highest simulated cost on the grid.
        candidates: the surrogate optima, parameter values by name, in start order.
        candidate_costs: their simulated costs.
        solver_status: IPOPT's return status per start.
        evaluations: simulated samples (grid + candidates).
    """

    steps: tuple[int, ...]
    parameters: Mapping[str, float]
    cost: float
    source: str
    grid: int
    grid_cost: float
    candidates: tuple[Mapping[str, float], ...]
    candidate_costs: tuple[float, ...]
    solver_status: tuple[str, ...]
    evaluations: int

    def summary(self) -> dict:
        """JSON-able summary."""
        return {"steps": list(self.steps), "parameters": dict(self.parameters),
                "cost": _finite_or_none(self.cost), "source": self.source, "grid": self.grid,
                "grid_cost": _finite_or_none(self.grid_cost), "evaluations": self.evaluations,
                "solver_status": list(self.solver_status)}


def surrogate_worst_case(evaluator, steps: Any, box: UncertaintyBox | None = None, *,
                         grid: int = 9, starts: int = 4, max_iter: int = 100
                         ) -> SurrogateWorstCase:
    """Maximise the simulated cost with IPOPT on a B-spline surrogate of it.

    The box's unit cube (prior quantiles, so a log-uniform parameter is spaced evenly in its
    logarithm) gets ``grid`` points per parameter, ends included, and one sparse evaluation
    of all of them. The costs become a cubic B-spline interpolant (``casadi.interpolant``),
    which IPOPT maximises within the unit cube from the ``starts`` best grid points; each
    optimum is simulated, and the answer is the most severe point simulated, grid or optimum.

    Why a grid: the simulated worst case often lies on the box's boundary (at lift-off the
    grippiest cube is held longest and loads the arm most, so the worst case sits on the
    friction range's upper end), where a Sobol sample never lands and a grid does.

    Args:
        evaluator: a :class:`~critmoment.sparse.SparseEvaluator` (its horizon applies).
        steps: the moments, physics step indices (m,).
        box: the box (the evaluator's parameters; ranges may be narrower); default the
            evaluator's.
        grid: points per parameter (>= 3); grid**k evaluations, at most 4096.
        starts: IPOPT starts (>= 1), from the best grid points.
        max_iter: IPOPT iteration limit per start.

    Returns:
        The :class:`SurrogateWorstCase`.

    Raises:
        ParameterError: bad steps, options or box, or a grid of more than 4096 points.
    """
    import casadi as ca

    grid = _check_int("grid", grid, 3)
    starts = _check_int("starts", starts, 1, MAX_TRIALS)
    max_iter = _check_int("max_iter", max_iter, 1, MAX_ITER)
    steps_arr = evaluator.check_steps(steps)
    box = _search_box(evaluator, box)
    if grid ** box.ndim > 4096:
        raise ParameterError(
            f"grid: {grid}**{box.ndim} = {grid ** box.ndim} points, expected at most 4096; "
            "use a coarser grid or search_worst_case (Optuna) for this many parameters")
    axis = np.linspace(0.0, 1.0, grid)
    mesh = np.meshgrid(*[axis] * box.ndim, indexing="ij")
    unit = np.stack([g.reshape(-1) for g in mesh], axis=1)
    points = np.clip(box.from_unit(unit), box.low, box.high)  # ends exact despite rounding
    cost = evaluator.evaluate(steps_arr, points, settle=False).cost.max(axis=0)
    order = np.argsort(-np.where(np.isnan(cost), -np.inf, cost), kind="stable")
    g_best = int(order[0])
    names = box.names

    def named(row):
        return {n: float(v) for n, v in zip(names, row, strict=False)}

    cand_unit, status = [], []
    if np.isfinite(cost[g_best]):  # a diverged grid point (+inf) is already the worst
        # casadi wants the values with the first axis fastest (Fortran order)
        values = cost.reshape((grid,) * box.ndim).ravel(order="F")
        spline = ca.interpolant("cost", "bspline", [axis] * box.ndim, values)
        x = ca.MX.sym("u", box.ndim)
        solver = ca.nlpsol("surrogate", "ipopt", {"x": x, "f": -spline(x)},
                           {"ipopt.print_level": 0, "print_time": False, "ipopt.sb": "yes",
                            "show_eval_warnings": False, "ipopt.max_iter": max_iter})
        for i in order[:starts]:
            sol, state = _solve(solver, x0=unit[i], lbx=np.zeros(box.ndim),
                                ubx=np.ones(box.ndim))
            status.append(state)
            cand_unit.append(np.clip(np.asarray(sol["x"]).reshape(-1), 0.0, 1.0))
    cand_points = (np.clip(box.from_unit(np.array(cand_unit)), box.low, box.high) if cand_unit
                   else np.zeros((0, box.ndim)))
    cand_cost = (evaluator.evaluate(steps_arr, cand_points, settle=False).cost.max(axis=0) if cand_unit
                 else np.zeros(0))
    best_point, best_cost, source = points[g_best], float(cost[g_best]), "grid"
    if cand_cost.size and float(np.max(cand_cost)) > best_cost:
        i = int(np.argmax(cand_cost))
        best_point, best_cost, source = cand_points[i], float(cand_cost[i]), "ipopt"
    return SurrogateWorstCase(
        steps=tuple(int(s) for s in steps_arr), parameters=named(best_point), cost=best_cost,
        source=source, grid=grid, grid_cost=float(cost[g_best]),
        candidates=tuple(named(r) for r in cand_points),
        candidate_costs=tuple(float(c) for c in cand_cost), solver_status=tuple(status),
        evaluations=int(points.shape[0] + cand_points.shape[0]))


# --------------------------------------------------------------------------
# verification by sparse evaluation
# --------------------------------------------------------------------------


@dataclasses.dataclass(frozen=True)
class CheckedPoint:
    """One parameter point, analytic model against sparse evaluation.

    Disagreements are signed and relative, ``(analytic − simulated)/|simulated|`` (0 when
    both are +inf, ±inf when only one is): a positive FOS disagreement means the analytic
    model is optimistic.

    Attributes:
        source: where the point comes from: "analytic" (CasADi worst case), "search"
            (Optuna worst case), "nominal", or "analytic_boundary" (the analytic critical
            mass at nominal friction).
        parameters: the parameter values by name.
        analytic_cost: cost of the analytic model.
        analytic_fos_motor: analytic motor FOS.
        analytic_fos_contact: analytic contact FOS.
        simulated_cost: cost of the sparse evaluation (+inf if diverged).
        simulated_fos_motor: simulated motor FOS.
        simulated_fos_contact: simulated contact FOS of the grasp (``fos_grasp``).
        simulated_diverged: the simulation diverged.
        cost_disagreement: relative disagreement of the costs.
        fos_motor_disagreement: relative disagreement of the motor FOS.
        fos_contact_disagreement: relative disagreement of the contact FOS.
        analytic_fails: the analytic cost exceeds the threshold.
        simulated_fails: the simulated cost exceeds the threshold (or it diverged).

    Beyond failure the two are not on one scale: the simulation clamps actuator forces at
    their range (FOS_m → 1) and a slipping contact sits on its friction cone (FOS_c → 1, or
    0 once the object is dropped), while the analytic FOS keep falling below 1. Compare
    factors of safety where both pass; where they fail, compare ``agree``.
    """

    source: str
    parameters: Mapping[str, float]
    analytic_cost: float
    analytic_fos_motor: float
    analytic_fos_contact: float
    simulated_cost: float
    simulated_fos_motor: float
    simulated_fos_contact: float
    simulated_diverged: bool
    cost_disagreement: float
    fos_motor_disagreement: float
    fos_contact_disagreement: float
    analytic_fails: bool
    simulated_fails: bool

    @property
    def agree(self) -> bool:
        """The analytic model and the simulation classify the point alike (fail or pass)."""
        return self.analytic_fails == self.simulated_fails

    def summary(self) -> dict:
        """JSON-able summary (non-finite numbers as None)."""
        out: dict[str, Any] = {"source": self.source, "parameters": dict(self.parameters)}
        for f in ("analytic_cost", "analytic_fos_motor", "analytic_fos_contact",
                  "simulated_cost", "simulated_fos_motor", "simulated_fos_contact",
                  "cost_disagreement", "fos_motor_disagreement", "fos_contact_disagreement"):
            out[f] = _finite_or_none(getattr(self, f))
        out["simulated_diverged"] = self.simulated_diverged
        out["analytic_fails"] = self.analytic_fails
        out["simulated_fails"] = self.simulated_fails
        out["agree"] = self.agree
        return out


@dataclasses.dataclass(frozen=True)
class Verification:
    """Every worst case found at a moment, re-evaluated by sparse evaluation.

    Attributes:
        step: the moment.
        horizon: the evaluator's horizon [steps].
        threshold: the cost threshold.
        points: the checked points.
        most_severe: the source whose point has the highest simulated cost.
        assumptions_hold: the analytic model's assumptions hold at this moment.
        notes: the analytic model's notes and what the comparison showed.
    """

    step: int
    horizon: int
    threshold: float
    points: tuple[CheckedPoint, ...]
    most_severe: str
    assumptions_hold: bool
    notes: tuple[str, ...]

    def point(self, source: str) -> CheckedPoint:
        """The checked point of ``source``."""
        for p in self.points:
            if p.source == source:
                return p
        raise ParameterError(f"no checked point from {source!r}; have "
                             f"{[p.source for p in self.points]}")

    def summary(self) -> dict:
        """JSON-able summary."""
        return {"step": self.step, "horizon": self.horizon, "threshold": self.threshold,
                "points": [p.summary() for p in self.points], "most_severe": self.most_severe,
                "assumptions_hold": self.assumptions_hold, "notes": list(self.notes)}


def verify(evaluator, step: Any, analytic: AnalyticWorstCase | AnalyticBounds,
           search: SearchResult | None = None, *, include_nominal: bool = True
           ) -> Verification:
    """Re-evaluate the worst cases found at a moment by sparse evaluation.

    Checks the CasADi worst case (when ``analytic`` is an :class:`AnalyticWorstCase`), the
    analytic critical mass at nominal friction, the Optuna worst case and the nominal point,
    all in one ``evaluate`` call, and compares the analytic model's FOS and cost with the
    simulated ones at the same parameters.

    With a horizon of one step the simulated motor FOS of position servos does not depend on
    the payload (their force is a function of the restored state) and soft contacts have not
    taken the full load yet: the comparison then says more about the horizon than about the
    model, and a note says so.

    Args:
        evaluator: the sparse evaluator (its horizon applies).
        step: the moment (physics step, or an object with an int ``step``).
        analytic: the analytic worst case (or only the bounds) at this moment.
        search: the Optuna result to check too, or None.
        include_nominal: also check the nominal point.

    Returns:
        The :class:`Verification`.

    Raises:
        ParameterError: bad step, or analytic bounds of another step.
    """
    k, bounds, points, samples = _points_to_verify(evaluator, step, analytic, search,
                                                   include_nominal)
    res = evaluator.evaluate([k], samples, settle=False)
    return _verification(evaluator, k, bounds, points, res)


def _points_to_verify(evaluator, step: Any, analytic: AnalyticWorstCase | AnalyticBounds,
                      search: SearchResult | None, include_nominal: bool):
    """:func:`verify`'s checks and points: (step, bounds, [(source, parameters)], samples
    (p, k))."""
    k = _step_of(step)
    evaluator.check_steps([k])
    if isinstance(analytic, AnalyticWorstCase):
        bounds, worst = analytic.bounds, analytic
    elif isinstance(analytic, AnalyticBounds):
        bounds, worst = analytic, None
    else:
        raise ParameterError(
            f"analytic: expected AnalyticWorstCase or AnalyticBounds, got "
            f"{type(analytic).__name__}")
    if bounds.step != k:
        raise ParameterError(
            f"analytic: expected the bounds of step {k}, got those of step {bounds.step}")
    box = evaluator.box
    if box.names != bounds.parameter_names:
        raise ParameterError(f"analytic: expected parameters {box.names}, got "
                             f"{bounds.parameter_names}")
    points: list[tuple[str, dict[str, float]]] = []
    if worst is not None:
        points.append(("analytic", dict(worst.parameters)))
        if worst.critical_mass_nominal_friction is not None:
            points.append(("analytic_boundary", bounds.parameters_at(
                worst.critical_mass_nominal_friction, bounds.friction_nominal)))
    if search is not None:
        points.append(("search", {n: float(search.worst_case.get(n, v))
                                  for n, v in zip(box.names, box.nominal, strict=False)}))
    if include_nominal:
        points.append(("nominal", {n: float(v) for n, v in zip(box.names, box.nominal, strict=False)}))
    if not points:
        raise ParameterError("verify: expected at least one point to check (an "
                             "AnalyticWorstCase, a SearchResult or include_nominal=True)")
    samples = np.array([[p[n] for n in box.names] for _, p in points], dtype=np.float64)
    return k, bounds, points, samples


def _verification(evaluator, k: int, bounds: AnalyticBounds,
                  points: list[tuple[str, dict[str, float]]], res: SparseResult
                  ) -> Verification:
    """:func:`verify`'s comparison of the analytic model with the sparse evaluation ``res``
    of ``points`` at moment k."""
    checked = []
    for i, (source, params) in enumerate(points):
        m, f = bounds.point_of(params)
        a_cost = float(bounds.cost(m, f))
        a_fm = float(bounds.fos_motor(m))
        a_fc = float(bounds.fos_contact(m, f))
        s_cost = float(res.cost[0, i])
        s_fm = float(res.fos_motor[0, i])
        s_fc = float(res.fos_grasp[0, i])
        checked.append(CheckedPoint(
            source=source, parameters=params, analytic_cost=a_cost, analytic_fos_motor=a_fm,
            analytic_fos_contact=a_fc, simulated_cost=s_cost, simulated_fos_motor=s_fm,
            simulated_fos_contact=s_fc, simulated_diverged=bool(res.diverged[0, i]),
            cost_disagreement=_rel(a_cost, s_cost), fos_motor_disagreement=_rel(a_fm, s_fm),
            fos_contact_disagreement=_rel(a_fc, s_fc),
            analytic_fails=a_cost > bounds.cost_params.threshold,
            simulated_fails=bool(res.failed[0, i])))
    notes = list(bounds.notes)
    masses = np.array([bounds.point_of(p)[0] for _, p in points])
    fm = res.fos_motor[0][~res.diverged[0]]
    fm = fm[np.isfinite(fm)]  # no force limit: an infinite FOS says nothing of the mass
    if np.ptp(masses) > 0 and fm.size > 1 and np.ptp(fm) == 0:
        notes.append(
            f"the simulated motor FOS did not change with the mass over the horizon of "
            f"{evaluator.horizon} step(s): position servos answer a load only as the arm "
            "sags; compare motor FOS at a horizon of ~100 steps")
    if res.diverged.any():
        notes.append("a checked point diverged in simulation (counted as cost +inf)")
    most = max(checked, key=lambda c: c.simulated_cost)
    return Verification(step=k, horizon=int(evaluator.horizon),
                        threshold=float(bounds.cost_params.threshold), points=tuple(checked),
                        most_severe=most.source, assumptions_hold=bounds.assumptions_hold,
                        notes=tuple(notes))


def audit_moment(evaluator, step: Any, *, pin_model: dyn.PinocchioModel | None = None,
                 method: SearchMethod = SearchMethod.TPE, n_trials: int = 48,
                 batch_size: int = 8, seed: int = 0, smoothing: float = DEFAULT_SMOOTHING,
                 patience: int | None = None) -> dict:
    """Analytic bounds, CasADi and Optuna worst cases and their verification at one moment.

    Args:
        evaluator: the sparse evaluator of the recording (``evaluator.recording`` and
            ``evaluator.twin`` give the moment's state).
        step: the moment (physics step, or an object with an int ``step``).
        pin_model: the Pinocchio model of the twin's model (built when None).
        method: the Optuna sampler.
        n_trials: Optuna's budget of samples.
        batch_size: samples per sparse-evaluation call.
        seed: the sampler's seed.
        smoothing: κ of the CasADi model's smooth maximum.
        patience: Optuna stops after this many batches without a higher cost (None: the
            whole budget).

    Returns:
        A JSON-able dict: ``step``, ``time``, ``horizon``, ``analytic`` (critical masses per
        joint, limiting joint, minimum factors of safety, contact critical masses,
        assumptions, notes, and the CasADi ``worst_case``), ``search`` (method, evaluations,
        worst case, worst cost) and ``verification``. Non-finite numbers are None (a
        critical mass of None: the limit is never reached).
    """
    return audit_moments(evaluator, [step], pin_model=pin_model, method=method,
                         n_trials=n_trials, batch_size=batch_size, seed=seed,
                         smoothing=smoothing, patience=patience)[0]


def audit_moments(evaluator, steps: Sequence[Any], *,
                  pin_model: dyn.PinocchioModel | None = None,
                  method: SearchMethod = SearchMethod.TPE, n_trials: int = 48,
                  batch_size: int = 8, seed: int = 0, smoothing: float = DEFAULT_SMOOTHING,
                  patience: int | None = None) -> list[dict]:
    """:func:`audit_moment` at each of several moments, their searches side by side
    (:func:`run_searches`) and their verifications in one ``evaluate_many`` call: the same
    results as one call per moment, in fewer and fuller batches."""
    ks = [_step_of(step) for step in steps]
    evaluator.check_steps(ks)
    if pin_model is None and ks:
        pin_model = dyn.from_mujoco(evaluator.twin.model)
    bounds = [analytic_bounds(evaluator.recording, evaluator.twin, k, pin_model=pin_model)
              for k in ks]
    worsts = [analytic_worst_case(b, smoothing=smoothing) for b in bounds]
    found = run_searches(evaluator, [_search(
        evaluator, [k], None, method=method, n_trials=n_trials, batch_size=batch_size,
        seed=seed, enqueue_corners=True, stop_at_ceiling=True, patience=patience)
        for k in ks])
    checks = [_points_to_verify(evaluator, k, w, f, True)
              for k, w, f in zip(ks, worsts, found, strict=True)]
    answers = evaluator.evaluate_many([([k], samples) for k, _, _, samples in checks],
                                     settle=False)
    out = []
    for (k, b, points, _), worst, f, res in zip(checks, worsts, found, answers, strict=True):
        analytic = b.summary()
        analytic["worst_case"] = worst.summary()
        out.append({"step": k, "time": b.time, "horizon": int(evaluator.horizon),
                    "analytic": analytic, "search": f.summary(),
                    "verification": _verification(evaluator, k, b, points, res).summary()})
    return out
