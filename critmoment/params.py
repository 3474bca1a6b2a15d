"""Uncertain physical parameters and the uncertainty box.

A parameter knows which MuJoCo model fields it changes and how to write a value
into them. The same ``write`` serves a single ``MjModel`` (arrays of shape
``(1, ...)`` viewed from the model) and a ``mujoco.batch.Batch`` (expanded
per-simulation arrays ``(nsim, ...)``), so sparse evaluation, full rollouts and
the analytic model all change the physics in exactly one way.

New kinds of parameters (centre-of-mass offset, gripper force limit, ...) are
added by subclassing :class:`Parameter` and registering the class in
:data:`PARAMETER_KINDS`.
"""

from __future__ import annotations

import dataclasses
import enum
import math
from collections.abc import Mapping
from typing import Any, ClassVar, Protocol

import mujoco
import numpy as np

from critmoment.exceptions import ParameterError, ScenarioError

__all__ = [
    "Prior",
    "Parameter",
    "MassParameter",
    "FrictionParameter",
    "ComOffsetParameter",
    "ForceLimitParameter",
    "PARAMETER_KINDS",
    "NominalContacts",
    "UncertaintyBox",
]


class Prior(enum.Enum):
    """Prior distribution of a parameter over its range."""

    UNIFORM = "uniform"
    LOGUNIFORM = "loguniform"


@dataclasses.dataclass(frozen=True)
class Parameter:
    """One uncertain scalar of the physics.

    Attributes:
        name: the parameter's name in the scenario (``"mass"``, ``"friction"``).
        target: the MuJoCo object it acts on (body, geom or actuator name).
        low: lower end of the range, in the parameter's unit.
        high: upper end of the range.
        nominal: the value the trajectory was planned for.
        prior: distribution over [low, high] used for P(success).
    """

    name: str
    target: str
    low: float
    high: float
    nominal: float
    prior: Prior = Prior.UNIFORM

    #: MjModel fields this parameter writes.
    fields: ClassVar[tuple[str, ...]] = ()
    #: whether mj_setConst must run after writing (mass, inertia).
    needs_set_const: ClassVar[bool] = False
    #: unit shown in reports.
    unit: ClassVar[str] = ""
    #: the smallest admissible value (exclusive), e.g. 0 for a mass.
    minimum: ClassVar[float] = -np.inf

    def __post_init__(self):
        for field in ("name", "target"):
            value = getattr(self, field)
            if not isinstance(value, str) or not value:
                raise ParameterError(
                    f"parameter {field}: expected a non-empty string, got {value!r}")
        for field in ("low", "high", "nominal"):
            value = getattr(self, field)
            if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float,
                                                                             np.number)):
                raise ParameterError(
                    f"parameter {self.name!r} {field}: expected a number, got {value!r}")
            try:
                object.__setattr__(self, field, float(value))
            except OverflowError:  # an int past float's range: as refused as inf
                object.__setattr__(self, field, math.inf if value > 0 else -math.inf)
        if not isinstance(self.prior, Prior):
            try:
                object.__setattr__(self, "prior", Prior(self.prior))
            except (ValueError, TypeError):
                raise ParameterError(
                    f"parameter {self.name!r} prior: expected one of "
                    f"{[p.value for p in Prior]} (or critmoment.params.Prior), got "
                    f"{self.prior!r}") from None
        values = (self.low, self.high, self.nominal)
        if not all(np.isfinite(v) for v in values):
            raise ParameterError(
                f"parameter {self.name!r}: expected finite range and nominal, got "
                f"range [{self.low}, {self.high}], nominal {self.nominal}")
        if not self.low < self.high:
            raise ParameterError(
                f"parameter {self.name!r}: expected range low < high, got [{self.low}, {self.high}]")
        if not self.low <= self.nominal <= self.high:
            raise ParameterError(
                f"parameter {self.name!r}: expected nominal inside the range "
                f"[{self.low}, {self.high}], got {self.nominal}")
        if self.low <= self.minimum:
            raise ParameterError(
                f"parameter {self.name!r}: expected values > "
                f"{self.minimum}{' ' + self.unit if self.unit else ''}, "
                f"got range [{self.low}, {self.high}]")
        if self.prior is Prior.LOGUNIFORM and self.low <= 0:
            raise ParameterError(
                f"parameter {self.name!r}: a log-uniform prior needs low > 0, got {self.low}")

    # -- binding to a model -------------------------------------------------
    def resolve(self, model: mujoco.MjModel) -> int:
        """Return the id of ``target`` in ``model``; raise ScenarioError listing valid names."""
        raise NotImplementedError

    def write(self, index: int, base, arrays: Mapping[str, np.ndarray],
              values: np.ndarray) -> None:
        """Write ``values`` (n,) into the per-simulation ``arrays`` (n, ...) of ``fields``.

        Args:
            index: the target's id, from :meth:`resolve`.
            base: an object whose ``fields`` attributes hold the model's own (unmodified)
                values, which the parameter scales or offsets from.
            arrays: per-simulation arrays (n, ...) for each of ``fields``, written in place.
            values: the parameter's values, (n,).
        """
        raise NotImplementedError

    def onset(self, index: int, run: NominalContacts) -> int:
        """The first step of the nominal run at which this parameter can change the motion.

        Up to that step a sample's state equals the nominal run's, so its own history can
        start from the recorded state there (:func:`critmoment.history.chain_start`). The
        default, 0, is always right: the parameter acts from the start.

        Args:
            index: the target's id, from :meth:`resolve`.
            run: the nominal run's contacts and actuator forces.
        """
        return 0

    def check(self, values: np.ndarray) -> np.ndarray:
        """Return ``values`` as float64 (n,), raising ParameterError if any is not admissible."""
        values = np.asarray(values, dtype=np.float64).reshape(-1)
        bad = ~np.isfinite(values) | (values <= self.minimum)
        if bad.any():
            raise ParameterError(
                f"parameter {self.name!r}: expected finite values > {self.minimum} {self.unit}, "
                f"got {values[bad][:5].tolist()}")
        return values


def _brief(value: Any, limit: int = 80) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[:limit - 3] + "..."


class NominalContacts(Protocol):
    """What :meth:`Parameter.onset` may ask of the nominal run (implemented by
    :class:`critmoment.history.NominalOnsets`)."""

    #: the object's body id, and the geom ids of its body and of its supports
    object_body: int
    object_geoms: frozenset[int]
    support_geoms: frozenset[int]

    def first_contact(self, geoms: frozenset[int], exclude: frozenset[int]) -> int:
        """First step at which one of ``geoms`` touches a geom outside ``geoms`` and
        ``exclude`` (the run's length if never)."""

    def first_force(self, actuator: int, level: float) -> int:
        """First step at which the actuator's force magnitude reaches ``level`` (the run's
        length if never)."""


def _object_onset(run: NominalContacts, geoms: frozenset[int]) -> int:
    """A parameter of the object acts once something other than its supports touches it
    (resting on a support, its mass and friction do not move anything else)."""
    return run.first_contact(geoms, run.support_geoms)


def _resolve(model: mujoco.MjModel, objtype: mujoco.mjtObj, name: str, what: str) -> int:
    idx = mujoco.mj_name2id(model, objtype, name)
    if idx < 0:
        count = {mujoco.mjtObj.mjOBJ_BODY: model.nbody, mujoco.mjtObj.mjOBJ_GEOM: model.ngeom,
                 mujoco.mjtObj.mjOBJ_ACTUATOR: model.nu}[objtype]
        names = [mujoco.mj_id2name(model, objtype, i) for i in range(count)]
        raise ScenarioError(
            f"unknown {what} {name!r}; the model has: "
            + ", ".join(n for n in names if n))
    return idx


@dataclasses.dataclass(frozen=True)
class MassParameter(Parameter):
    """Mass of a body [kg]; its inertia scales with it (same shape, same density)."""

    fields: ClassVar[tuple[str, ...]] = ("body_mass", "body_inertia")
    needs_set_const: ClassVar[bool] = True
    unit: ClassVar[str] = "kg"
    minimum: ClassVar[float] = 0.0

    def resolve(self, model):
        return _resolve(model, mujoco.mjtObj.mjOBJ_BODY, self.target, "body")

    def onset(self, index, run):
        return _object_onset(run, run.object_geoms) if index == run.object_body else 0

    def write(self, index, base, arrays, values):
        scale = values / base.body_mass[index]
        arrays["body_mass"][:, index] = values
        arrays["body_inertia"][:, index] = base.body_inertia[index] * scale[:, None]


#: MuJoCo's smallest friction coefficient (mjMINMU): a contact's friction is raised to it
MIN_FRICTION = 1e-5


@dataclasses.dataclass(frozen=True)
class FrictionParameter(Parameter):
    """Sliding friction coefficient of a geom's contacts.

    MuJoCo mixes the friction of two geoms with ``max``, so the target geom must
    have a higher ``priority`` than everything it touches: then its own friction
    is the contact's. The twin checks that when it binds the scenario.
    """

    fields: ClassVar[tuple[str, ...]] = ("geom_friction",)
    unit: ClassVar[str] = ""
    minimum: ClassVar[float] = 0.0

    def __post_init__(self):
        super().__post_init__()
        if self.low < MIN_FRICTION:
            raise ParameterError(
                f"parameter {self.name!r}: expected a friction coefficient >= {MIN_FRICTION:g} "
                f"(MuJoCo raises any smaller one to that, mjMINMU), got range "
                f"[{self.low:g}, {self.high:g}]")

    def resolve(self, model):
        return _resolve(model, mujoco.mjtObj.mjOBJ_GEOM, self.target, "geom")

    def onset(self, index, run):
        # the object's own geom: once something other than a support touches it; any other
        # geom (a finger pad): its first contact with anything
        if index in run.object_geoms:
            return _object_onset(run, frozenset({index}))
        return run.first_contact(frozenset({index}), frozenset())

    def write(self, index, base, arrays, values):
        arrays["geom_friction"][:, index, 0] = values


@dataclasses.dataclass(frozen=True)
class ComOffsetParameter(Parameter):
    """Offset of a body's centre of mass along its local x axis [m]."""

    fields: ClassVar[tuple[str, ...]] = ("body_ipos",)
    needs_set_const: ClassVar[bool] = True
    unit: ClassVar[str] = "m"

    def resolve(self, model):
        return _resolve(model, mujoco.mjtObj.mjOBJ_BODY, self.target, "body")

    # onset: the default, from the start. Unlike its mass, an object's centre of mass can
    # move it on its support before anything touches it (an offset past its footprint tips
    # it over), so no later step is safe to assume

    def write(self, index, base, arrays, values):
        arrays["body_ipos"][:, index] = base.body_ipos[index]
        arrays["body_ipos"][:, index, 0] += values


@dataclasses.dataclass(frozen=True)
class ForceLimitParameter(Parameter):
    """Symmetric force limit of an actuator [N or N·m] (e.g. the gripper's grip force).

    ``torque``: the actuator drives a hinge joint, so its force is a torque (N·m); ``gear``:
    its gear, where the limit (in the actuator's units, before the gear) is not the joint's
    (a value v then means v × gear at the joint). Both set by :func:`with_units` once the
    model is known.
    """

    fields: ClassVar[tuple[str, ...]] = ("actuator_forcerange",)
    minimum: ClassVar[float] = 0.0
    torque: bool = False
    gear: float = 1.0

    @property
    def unit(self) -> str:  # type: ignore[override]
        unit = "N·m" if self.torque else "N"
        return unit if self.gear == 1.0 else f"×{self.gear:g} {unit}"

    def with_units(self, model: mujoco.MjModel) -> ForceLimitParameter:
        """This parameter with its unit read from ``model``: N·m for an actuator on a hinge
        (or ball) joint, N otherwise."""
        a = self.resolve(model)
        on_joint = int(model.actuator_trntype[a]) in (int(mujoco.mjtTrn.mjTRN_JOINT),
                                                      int(mujoco.mjtTrn.mjTRN_JOINTINPARENT))
        kind = int(model.jnt_type[model.actuator_trnid[a, 0]]) if on_joint else -1
        torque = kind in (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_BALL))
        gear = abs(float(model.actuator_gear[a, 0])) if on_joint else 1.0
        return dataclasses.replace(self, torque=torque, gear=gear or 1.0)

    def resolve(self, model):
        return _resolve(model, mujoco.mjtObj.mjOBJ_ACTUATOR, self.target, "actuator")

    def onset(self, index, run):
        # a limit clamps only a force that reaches it: where the nominal force stays below
        # the range's low end, no value of the range changes it
        return run.first_force(index, self.low)

    def write(self, index, base, arrays, values):
        arrays["actuator_forcerange"][:, index, 0] = -values
        arrays["actuator_forcerange"][:, index, 1] = values


#: scenario key ``kind`` (or the parameter's name) -> class, and the key naming its target
PARAMETER_KINDS: dict[str, tuple[type[Parameter], str]] = {
    "mass": (MassParameter, "body"),
    "friction": (FrictionParameter, "geom"),
    "com_offset": (ComOffsetParameter, "body"),
    "force_limit": (ForceLimitParameter, "actuator"),
}


def kind_of(parameter: Parameter) -> str:
    """The scenario's ``kind`` of a parameter (``"com_offset"``, ...): the key of
    :data:`PARAMETER_KINDS` whose class it is."""
    for kind, (cls, _) in PARAMETER_KINDS.items():
        if type(parameter) is cls:
            return kind
    return type(parameter).__name__


@dataclasses.dataclass(frozen=True)
class UncertaintyBox:
    """The box of uncertain parameters, in a fixed order.

    Attributes:
        parameters: the parameters; column j of every sample array is parameters[j].
    """

    parameters: tuple[Parameter, ...]

    def __post_init__(self):
        params = self.parameters
        if isinstance(params, Parameter) or not isinstance(params, (tuple, list)):
            raise ParameterError(f"UncertaintyBox parameters: expected a tuple of Parameter, "
                                 f"got {type(params).__name__}")
        bad = [type(p).__name__ for p in params if not isinstance(p, Parameter)]
        if bad or not params:
            raise ParameterError(
                f"UncertaintyBox parameters: expected at least one critmoment Parameter "
                f"(MassParameter, FrictionParameter, ...), got {bad or 'none'}")
        abstract = [p.name for p in params if type(p).resolve is Parameter.resolve]
        if abstract:
            raise ParameterError(
                f"UncertaintyBox parameters: expected parameters of a kind ("
                f"{', '.join(c.__name__ for c, _ in PARAMETER_KINDS.values())}, or a subclass "
                f"that implements resolve and write), got the base Parameter for {abstract}")
        object.__setattr__(self, "parameters", tuple(params))
        names = [p.name for p in self.parameters]
        if len(set(names)) != len(names):
            raise ParameterError(f"parameter names must be unique, got {names}")

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.parameters)

    @property
    def ndim(self) -> int:
        return len(self.parameters)

    @property
    def low(self) -> np.ndarray:
        return np.array([p.low for p in self.parameters])

    @property
    def high(self) -> np.ndarray:
        return np.array([p.high for p in self.parameters])

    @property
    def nominal(self) -> np.ndarray:
        return np.array([p.nominal for p in self.parameters])

    def index(self, name: str) -> int:
        """Column of parameter ``name``."""
        try:
            return self.names.index(name)
        except ValueError:
            raise ParameterError(
                f"unknown parameter {name!r}; the box has {', '.join(self.names)}") from None

    def check_samples(self, samples: Any, *, what: str = "samples") -> np.ndarray:
        """Validate a (n, k) sample array (k = ndim); return it as float64 C-contiguous.

        Raises:
            ParameterError: not numeric (strings, None, objects, ragged rows), the wrong
                shape, or values a parameter does not admit.
        """
        expected = f"a real array of shape (n, {self.ndim}) for parameters {list(self.names)}"
        if samples is None or isinstance(samples, (str, bytes, Mapping)):
            raise ParameterError(f"{what}: expected {expected}, got {type(samples).__name__} "
                                 f"{_brief(samples)}")
        try:
            arr = np.asarray(samples)
        except (TypeError, ValueError) as exc:  # ragged rows
            raise ParameterError(f"{what}: expected {expected}, got {type(samples).__name__} "
                                 f"that numpy cannot make an array of ({exc})") from None
        if arr.dtype == bool or arr.dtype.kind not in "iuf":
            raise ParameterError(f"{what}: expected {expected}, got dtype {arr.dtype} "
                                 f"{_brief(samples)}")
        samples = arr.astype(np.float64, copy=False)
        if samples.ndim == 1 and self.ndim == 1:
            samples = samples[:, None]
        if samples.ndim != 2 or samples.shape[1] != self.ndim:
            raise ParameterError(
                f"expected samples of shape (n, {self.ndim}) for parameters {self.names}, "
                f"got shape {samples.shape}")
        for j, p in enumerate(self.parameters):
            p.check(samples[:, j])
        return np.ascontiguousarray(samples)

    def from_unit(self, u: np.ndarray) -> np.ndarray:
        """Map points of the unit cube (n, k) to the box through each prior's inverse CDF."""
        u = np.asarray(u, dtype=np.float64)
        out = np.empty_like(u)
        for j, p in enumerate(self.parameters):
            if p.prior is Prior.LOGUNIFORM:
                out[:, j] = np.exp(np.log(p.low) + u[:, j] * (np.log(p.high) - np.log(p.low)))
            else:
                out[:, j] = p.low + u[:, j] * (p.high - p.low)
        return out

    def to_unit(self, x: np.ndarray) -> np.ndarray:
        """Inverse of :meth:`from_unit`."""
        x = np.asarray(x, dtype=np.float64)
        out = np.empty_like(x)
        for j, p in enumerate(self.parameters):
            if p.prior is Prior.LOGUNIFORM:
                out[:, j] = (np.log(x[:, j]) - np.log(p.low)) / (np.log(p.high) - np.log(p.low))
            else:
                out[:, j] = (x[:, j] - p.low) / (p.high - p.low)
        return out

    def corners(self) -> np.ndarray:
        """The 2**k corners of the box, (2**k, k), plus nothing else."""
        grids = np.meshgrid(*[[p.low, p.high] for p in self.parameters], indexing="ij")
        return np.stack([g.reshape(-1) for g in grids], axis=1)

    def with_range(self, name: str, low: float, high: float,
                   nominal: float | None = None) -> UncertaintyBox:
        """A copy with parameter ``name``'s range (and optionally nominal) replaced."""
        j = self.index(name)
        p = self.parameters[j]
        nominal = p.nominal if nominal is None else nominal
        params = list(self.parameters)
        params[j] = dataclasses.replace(p, low=low, high=high, nominal=nominal)
        return UncertaintyBox(tuple(params))
