"""Scenario: which model, object, grippers, task, limits, uncertainty box and cost.

A scenario is a TOML file beside an MJCF model (see ``docs/formats.md``). The schema is
strict: every table and key is checked (an unknown key is an error that lists the valid
keys, with a "did you mean"), every value's type, and every name (body, geom, actuator,
joint, tendon, keyframe) against the compiled model, with the valid names listed when one
is unknown.

Models load as they ship. critmoment compiles its own copy through ``mujoco.MjSpec``
(:func:`prepare_spec`) and, in that copy only:

* names unnamed geoms ``critmoment:geom:<i>`` (``i`` = the geom's id) and unnamed
  actuators after the joint or tendon they drive, so grippers given by body and actuators
  addressed by their joint work on models whose elements carry no names;
* raises the ``priority`` of the object's geoms above every other geom when the box varies
  the object's friction, so that the object's friction governs its contacts (MuJoCo mixes
  two geoms' friction with ``max`` unless one has the higher priority). The pads' own
  friction then no longer acts on the object's contacts; it still acts on every other
  contact of the pads;
* makes the torque motors that ``[servos]`` names joint-position servos (:class:`Servos`):
  the joint controller the real robot runs around a torque-controlled model's motors;
* compiles a body whose centre of mass the box moves (``com_offset``) as not ``simple``:
  MuJoCo treats a body whose inertial frame is its own as simple, and refuses a centre of
  mass moved off that frame at run time (``mj_setConstGroups``: "sameframe no longer
  holds").
"""

from __future__ import annotations

import dataclasses
import difflib
import hashlib
import math
import os
import re
import sys
import warnings
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from critmoment import actuators as act_info
from critmoment.exceptions import (
    CritmomentWarning,
    InputFileError,
    ParameterError,
    ScenarioError,
)
from critmoment.params import (
    PARAMETER_KINDS,
    ComOffsetParameter,
    ForceLimitParameter,
    FrictionParameter,
    MassParameter,
    Parameter,
    Prior,
    UncertaintyBox,
)
from critmoment.task import Task, task_from_table
from critmoment.task import _is_real as _is_number

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

__all__ = [
    "CostParams",
    "Gripper",
    "ActionConvention",
    "SparseSettings",
    "FeasibilityOptions",
    "Scenario",
    "load_scenario",
    "scenario_from_dict",
    "prepare_spec",
    "ServoGains",
    "Servos",
    "bundled_scenario_path",
    "BUNDLED_SCENARIOS",
    "unknown_keys_error",
    "compile_spec",
    "ScenarioWarning",
]


class ScenarioWarning(CritmomentWarning):
    """A scenario that loads but probably does not say what was meant."""


#: scenarios shipped with critmoment, by name
BUNDLED_SCENARIOS = ("aloha_transfer_cube", "panda_pick_place")

#: prefix of the names critmoment gives unnamed model elements in its own copy
GENERATED = "critmoment:"


def _models_dir() -> Path:
    """Folder of the bundled models, installed (critmoment.models) or in a checkout."""
    try:
        from importlib import resources

        path = Path(str(resources.files("critmoment.models")))
        if (path / BUNDLED_SCENARIOS[0]).is_dir():
            return path
    except (ModuleNotFoundError, TypeError):
        pass
    return Path(__file__).resolve().parent.parent / "models"


def bundled_scenario_path(name: str = "aloha_transfer_cube") -> Path:
    """Path of a bundled scenario's ``scenario.toml``."""
    if name not in BUNDLED_SCENARIOS:
        raise ScenarioError(
            f"unknown bundled scenario {name!r}; available: {', '.join(BUNDLED_SCENARIOS)}")
    return _models_dir() / name / "scenario.toml"


# ---------------------------------------------------------------------------
# strict schema helpers
# ---------------------------------------------------------------------------


def unknown_keys_error(where: str, extra: Iterable[str], valid: Sequence[str]) -> ScenarioError:
    """A ScenarioError for keys ``extra`` of table ``where``, with the valid keys and a
    "did you mean" for each key close to a valid one."""
    parts = []
    for key in sorted(extra):
        close = difflib.get_close_matches(key, list(valid), n=1, cutoff=0.6)
        parts.append(f"{key!r}" + (f" (did you mean {close[0]!r}?)" if close else ""))
    return ScenarioError(f"{where}: unknown key{'s' if len(parts) > 1 else ''} "
                         f"{', '.join(parts)}; valid keys: {', '.join(valid)}")


def _keys(table: Mapping[str, Any], where: str, valid: Sequence[str]) -> None:
    extra = set(table) - set(valid)
    if extra:
        raise unknown_keys_error(where, extra, valid)


def _type_name(kind) -> str:
    if isinstance(kind, tuple):
        return " or ".join(_type_name(k) for k in kind)
    return {dict: "a table", list: "a list", str: "a string", int: "an integer",
            float: "a number", bool: "true or false"}.get(kind, getattr(kind, "__name__", kind))


def _get(table: Mapping[str, Any], key: str, kind, where: str, default=...):
    if key not in table:
        if default is ...:
            raise ScenarioError(f"{where}: missing required key {key!r}")
        return default
    value = table[key]
    bad_bool = isinstance(value, bool) and kind is not bool and not (
        isinstance(kind, tuple) and bool in kind)
    if not isinstance(value, kind) or bad_bool:
        raise ScenarioError(f"{where} {key}: expected {_type_name(kind)}, got {value!r}")
    return value


def _number(table, key, where, default=..., *, positive: bool = False) -> float:
    value = _get(table, key, (int, float), where, default)
    if value is None:
        return value
    value = float(value)
    if not math.isfinite(value) or (positive and not value > 0):
        raise ScenarioError(f"{where} {key}: expected a finite number{' > 0' if positive else ''}"
                            f", got {value!r}")
    return value


def _names(table, key, where, default=...) -> tuple[str, ...] | None:
    value = _get(table, key, list, where, default)
    if value is None:
        return None
    if not value or not all(isinstance(v, str) for v in value):
        raise ScenarioError(f"{where} {key}: expected a non-empty list of names, got {value!r}")
    if len(set(value)) != len(value):
        raise ScenarioError(f"{where} {key}: expected each name once, got {value!r}")
    return tuple(value)


# ---------------------------------------------------------------------------
# the scenario's parts
# ---------------------------------------------------------------------------


#: a sliding friction coefficient above this is warned of as no real material's
PLAUSIBLE_FRICTION = 10.0
#: the largest exponent α, β of the cost (exp(50) ≈ 5e21: a step already)
MAX_COST_EXPONENT = 50.0
#: where each cost term alone should reach the threshold, as a factor of safety: outside
#: it the weights call a comfortable margin a failure, or a limit well passed safe
FOS_BAND = (0.5, 2.0)


@dataclasses.dataclass(frozen=True)
class CostParams:
    """Constants of the cost C = A·exp(−α(FOS_c − 1)) + B·exp(−β(FOS_m − 1)) (thesis eq. 15)."""

    A: float = 0.8
    B: float = 1.0
    alpha: float = 0.7
    beta: float = 2.0
    threshold: float = 0.9

    def __post_init__(self):
        for key in ("A", "B", "alpha", "beta", "threshold"):
            value = getattr(self, key)
            if not _is_number(value) or not (np.isfinite(value) and value > 0):
                raise ScenarioError(f"[cost] {key}: expected a finite number > 0, got {value!r}")
        for key in ("alpha", "beta"):
            value = getattr(self, key)
            if value > MAX_COST_EXPONENT:
                raise ScenarioError(
                    f"[cost] {key}: expected at most {MAX_COST_EXPONENT:g} (the sharpness of "
                    f"the cost's exponential in the factor of safety; above it the cost is a "
                    f"step and its largest value, at a factor of safety 0, overflows), got "
                    f"{value!r}")
        largest = self.A * math.exp(self.alpha) + self.B * math.exp(self.beta)
        if not self.threshold < largest:
            raise ScenarioError(
                f"[cost] threshold: expected below the largest cost the formula gives, "
                f"A·exp(α) + B·exp(β) = {largest:.4g} (both factors of safety at 0), got "
                f"{self.threshold!r}: no grip and no motor could ever fail")
        for name, weight, rate, term in (("A", self.A, self.alpha, "contact"),
                                         ("B", self.B, self.beta, "motor")):
            fos = self.failing_fos(term)
            if not FOS_BAND[0] <= fos <= FOS_BAND[1]:
                warnings.warn(
                    f"[cost]: the {term} term alone reaches the threshold {self.threshold:g} "
                    f"at a {term} factor of safety of {fos:.3g} ({name} = {weight:g}, "
                    f"{'α' if term == 'contact' else 'β'} = {rate:g}): "
                    + (f"a {term} with {fos:.3g}× margin counts as failing"
                       if fos > FOS_BAND[1] else
                       f"a {term} well past its limit still passes")
                    + f"; expected it between {FOS_BAND[0]:g} and {FOS_BAND[1]:g} (1 is the "
                      f"limit itself: the friction cone, the force limit)",
                    ScenarioWarning, stacklevel=3)

    def failing_fos(self, term: str) -> float:
        """The factor of safety at which the ``term`` ("contact" or "motor") alone reaches
        the threshold: 1 + ln(weight / threshold) / rate."""
        weight, rate = (self.A, self.alpha) if term == "contact" else (self.B, self.beta)
        return 1.0 + math.log(weight / self.threshold) / rate


@dataclasses.dataclass(frozen=True)
class Gripper:
    """A gripper: a name and the geoms that may touch the object.

    Attributes:
        name: the gripper's name in the scenario.
        geoms: its collision geoms (generated names for geoms the MJCF leaves unnamed).
        body: the body whose subtree's collision geoms make up the gripper, when given by
            body; else None.
    """

    name: str
    geoms: tuple[str, ...]
    body: str | None = None


@dataclasses.dataclass(frozen=True)
class ActionConvention:
    """How one action vector maps to actuator controls.

    Each channel drives one or more actuators: ``ctrl[a] = offset[a] + scale[a]·action[c]``.
    Channels marked ``normalised`` are bounded to [0, 1] (grippers: 0 closed, 1 open);
    the others are joint targets bounded by their joint's range.

    Attributes:
        name: the convention's name (``"aloha14"`` or ``"explicit"``).
        channels: per channel, the actuator names it drives.
        scales: per channel, the scale of each actuator.
        offsets: per channel, the offset of each actuator.
        normalised: per channel, whether it is a normalised [0, 1] channel.
        labels: a readable name per channel.
    """

    name: str
    channels: tuple[tuple[str, ...], ...]
    scales: tuple[tuple[float, ...], ...]
    offsets: tuple[tuple[float, ...], ...]
    normalised: tuple[bool, ...]
    labels: tuple[str, ...]

    @property
    def width(self) -> int:
        return len(self.channels)


@dataclasses.dataclass(frozen=True)
class SparseSettings:
    """The ``[sparse]`` table: how sparse evaluation measures a moment.

    Attributes:
        horizon: physics steps per sparse evaluation.
        persistence: how long a contact-FOS excursion must last to count as a failure [s]
            (shorter excursions are contact chatter).
        slip_tolerance: largest motion of the object in the holding gripper over the
            horizon that is not slip [m].
        creep_horizon: physics steps over which creep (slow slip) is measured, 0 for off.
    """

    horizon: int = 1
    persistence: float = 0.02
    slip_tolerance: float = 0.005
    creep_horizon: int = 0

    def __post_init__(self):
        if isinstance(self.horizon, bool) or not isinstance(self.horizon, int) or self.horizon < 1:
            raise ScenarioError(f"[sparse] horizon: expected an integer >= 1, got {self.horizon!r}")
        if (isinstance(self.creep_horizon, bool) or not isinstance(self.creep_horizon, int)
                or self.creep_horizon < 0):
            raise ScenarioError(
                f"[sparse] creep_horizon: expected an integer >= 0, got {self.creep_horizon!r}")
        if not (_is_number(self.persistence) and math.isfinite(self.persistence)
                and self.persistence >= 0):
            raise ScenarioError(
                f"[sparse] persistence: expected a time >= 0 s, got {self.persistence!r}")
        if not (_is_number(self.slip_tolerance) and math.isfinite(self.slip_tolerance)
                and self.slip_tolerance > 0):
            raise ScenarioError(
                f"[sparse] slip_tolerance: expected a distance > 0 m, got {self.slip_tolerance!r}")


@dataclasses.dataclass(frozen=True)
class FeasibilityOptions:
    """Tolerances of :func:`critmoment.feasibility.check_feasibility`, the scenario's
    ``[feasibility]`` table (every key optional).

    The defaults leave a wide margin over the bundled scenario's families (largest arm lag
    about 0.02 rad, no arm actuator at its limit; ``docs/method.md``, "Feasibility and fit
    checks").

    Attributes:
        lag_tolerance: largest tolerated lag of a hinge joint [rad].
        lag_tolerance_slide: largest tolerated lag of a slide joint [m].
        lag_duration: a lag above tolerance fails when it lasts longer than this [s].
        delay: the lag is the position error left after allowing the joint to follow its
            target this late [s] (a PD servo follows a ramp about (kv + damping)/kp late).
        saturation_fraction: |force| ≥ this fraction of the limit counts as saturated.
        saturation_duration: a saturation fails when it lasts longer than this [s].
        moving: a joint must move when its target spans more than this fraction of its
            lag tolerance; only such joints fail the friction check.
        check_grippers: also fail on the lag and saturation of gripper actuators
            (the normalised action channels); off by default, since a gripper closed on
            the object is blocked by it.
    """

    lag_tolerance: float = 0.1
    lag_tolerance_slide: float = 0.01
    lag_duration: float = 0.1
    delay: float = 0.1
    saturation_fraction: float = 0.99
    saturation_duration: float = 0.1
    moving: float = 0.1
    check_grippers: bool = False

    def __post_init__(self):
        # (name, may be 0, unit)
        for name, zero, unit in (("lag_tolerance", False, ""),
                                 ("lag_tolerance_slide", False, ""),
                                 ("lag_duration", False, " s"), ("delay", True, " s"),
                                 ("saturation_duration", False, " s"), ("moving", False, ""),
                                 ("saturation_fraction", False, "")):
            value = getattr(self, name)
            if not (_is_number(value) and math.isfinite(value)
                    and (value >= 0 if zero else value > 0)):
                raise ScenarioError(f"[feasibility] {name}: expected a finite number "
                                    f"{'>= 0' if zero else '> 0'}{unit}, got {value!r}")
        if not self.saturation_fraction <= 1:
            raise ScenarioError(f"[feasibility] saturation_fraction: expected in (0, 1], "
                                f"got {self.saturation_fraction!r}")
        if not isinstance(self.check_grippers, (bool, np.bool_)):
            raise ScenarioError(f"[feasibility] check_grippers: expected true or false, got "
                                f"{self.check_grippers!r}")


_ARM_JOINTS = ("waist", "shoulder", "elbow", "forearm_roll", "wrist_angle", "wrist_rotate")


def _aloha14(table: Mapping[str, Any], resolve) -> ActionConvention:
    _keys(table, "[actions]", ("convention", "fps", "range_policy", "arms", "gripper_close",
                                "gripper_open"))
    arms = _get(table, "arms", list, "[actions]", ["left", "right"])
    close = _number(table, "gripper_close", "[actions]", 0.01844)
    open_ = _number(table, "gripper_open", "[actions]", 0.05800)
    if not (len(arms) == 2 and all(isinstance(a, str) for a in arms)):
        raise ScenarioError(f"[actions] arms: expected two arm prefixes, got {arms!r}")
    if not open_ > close:
        raise ScenarioError(
            f"[actions] expected gripper_open > gripper_close, got {open_} <= {close}")
    channels, scales, offsets, normalised, labels = [], [], [], [], []
    span = open_ - close
    for arm in arms:
        for joint in _ARM_JOINTS:
            channels.append((resolve(f"{arm}/{joint}", "[actions]"),))
            scales.append((1.0,))
            offsets.append((0.0,))
            normalised.append(False)
            labels.append(f"{arm}/{joint}")
        channels.append((resolve(f"{arm}/left_finger", "[actions]"),
                         resolve(f"{arm}/right_finger", "[actions]")))
        scales.append((span, -span))
        offsets.append((close, -close))
        normalised.append(True)
        labels.append(f"{arm}/gripper")
    return ActionConvention("aloha14", tuple(channels), tuple(scales), tuple(offsets),
                            tuple(normalised), tuple(labels))


_CHANNEL_KEYS = ("actuators", "scales", "offsets", "normalised", "closed", "open", "label")


def _explicit(table: Mapping[str, Any], resolve, model=None, grippers=(), keyframe=None
              ) -> ActionConvention:
    _keys(table, "[actions]", ("convention", "fps", "range_policy", "channel"))
    entries = table.get("channel")
    if not isinstance(entries, list) or not entries or not all(
            isinstance(e, Mapping) for e in entries):
        raise ScenarioError(
            "[actions] convention = 'explicit' expects [[actions.channel]] tables with "
            "'actuators' (list), optional 'scales', 'offsets', 'normalised', 'closed', 'open', "
            f"'label'; got {entries!r}")
    channels, scales, offsets, normalised, labels = [], [], [], [], []
    for i, entry in enumerate(entries):
        where = f"[[actions.channel]] table {i + 1} of {len(entries)}"
        _keys(entry, where, _CHANNEL_KEYS)
        names = _names(entry, "actuators", where)
        acts = tuple(resolve(a, where) for a in names)
        n = len(acts)
        norm = _get(entry, "normalised", bool, where, False)
        has_affine = "scales" in entry or "offsets" in entry
        has_ends = "closed" in entry or "open" in entry
        if has_affine and has_ends:
            raise ScenarioError(f"{where}: expected scales/offsets or closed/open, not both")
        if has_ends and not norm:
            raise ScenarioError(f"{where}: closed/open are for normalised gripper channels; "
                                "set normalised = true")
        if norm and not has_affine:
            sc, of = _gripper_ends(entry, acts, where, model, grippers, keyframe)
        else:
            sc = _get(entry, "scales", list, where, [1.0] * n)
            of = _get(entry, "offsets", list, where, [0.0] * n)
            if len(sc) != n or len(of) != n:
                raise ScenarioError(
                    f"{where}: expected {n} scales and offsets, got {len(sc)}, {len(of)}")
            for key, values in (("scales", sc), ("offsets", of)):
                if not all(isinstance(v, (int, float)) and not isinstance(v, bool)
                           and math.isfinite(v) for v in values):
                    raise ScenarioError(f"{where} {key}: expected finite numbers, got {values!r}")
            if any(v == 0 for v in sc):
                raise ScenarioError(f"{where} scales: expected non-zero scales, got {sc!r}")
        channels.append(acts)
        scales.append(tuple(float(s) for s in sc))
        offsets.append(tuple(float(o) for o in of))
        normalised.append(norm)
        labels.append(str(_get(entry, "label", str, where, names[0])))
    return ActionConvention("explicit", tuple(channels), tuple(scales), tuple(offsets),
                            tuple(normalised), tuple(labels))


def _gripper_ends(entry, acts, where, model, grippers, keyframe):
    """Scales and offsets of a normalised gripper channel from its closed/open controls.

    ``closed``/``open`` are control values (one number for every actuator, or a list).
    When neither is given, the channel spans its actuators' ``ctrlrange`` and the end that
    brings the gripper's geoms closer together is "closed" (measured by
    :func:`critmoment.actuators.gripper_gap` on the compiled model).
    """
    n = len(acts)
    ids = [model.actuator(a).id for a in acts]

    def ends(key):
        value = entry[key]
        values = value if isinstance(value, list) else [value] * n
        if len(values) != n or not all(isinstance(v, (int, float)) and not isinstance(v, bool)
                                       and math.isfinite(v) for v in values):
            raise ScenarioError(f"{where} {key}: expected one finite control value, or a list "
                                f"of one per actuator ({n}: {list(acts)}), got {value!r}")
        return [float(v) for v in values]

    if "closed" in entry or "open" in entry:
        if not ("closed" in entry and "open" in entry):
            raise ScenarioError(f"{where}: expected both closed and open control values")
        closed, open_ = ends("closed"), ends("open")
    else:
        if not all(model.actuator_ctrllimited[i] for i in ids):
            raise ScenarioError(
                f"{where}: a normalised channel on actuators without a ctrlrange needs "
                "closed = ... and open = ... control values (or scales/offsets)")
        geoms = _channel_gripper_geoms(model, ids, grippers)
        if geoms is None:
            raise ScenarioError(
                f"{where}: cannot tell which end of the control range closes the gripper "
                "(no gripper's geoms move with it); give closed = ... and open = ...")
        try:
            closed, open_ = act_info.closing_ends(model, ids, geoms, keyframe=keyframe)
        except ValueError as exc:
            raise ScenarioError(f"{where}: cannot tell closed from open ({exc}); give "
                                "closed = ... and open = ...") from None
    same = [model.actuator(i).name for i, c, o in zip(ids, closed, open_, strict=True)
            if c == o]
    if same:
        raise ScenarioError(f"{where}: expected closed != open for every actuator, got the "
                            f"same value for {', '.join(repr(n) for n in same)} (closed "
                            f"{closed}, open {open_}); an actuator that does not open or close "
                            f"the gripper belongs in a channel of its own")
    return [o - c for c, o in zip(closed, open_, strict=True)], closed


def channel_gripper(model, act_ids, grippers) -> int | None:
    """The index of the gripper whose geoms move with actuators ``act_ids``, or None."""
    for i, g in enumerate(grippers):
        ids = [model.geom(name).id for name in g.geoms]
        if len(ids) >= 2 and act_info.moves_geoms(model, act_ids, ids):
            return i
    return None


def _channel_gripper_geoms(model, act_ids, grippers):
    """Geom ids of the gripper whose geoms move with actuators ``act_ids``, or None."""
    i = channel_gripper(model, act_ids, grippers)
    return None if i is None else [model.geom(name).id for name in grippers[i].geoms]


_CONVENTIONS = {"aloha14": _aloha14, "explicit": _explicit}


@dataclasses.dataclass(frozen=True)
class ServoGains:
    """A joint-position servo's gains in joint units: torque (or force) =
    ``kp`` (target - q) - ``kv`` q̇ [N·m/rad and N·m·s/rad on a hinge; N/m and N·s/m on a
    slide]."""

    kp: float
    kv: float


@dataclasses.dataclass(frozen=True)
class Servos:
    """``[servos]``: the model's torque motors driven as joint-position servos, the joint
    controller a torque-controlled robot runs (robosuite's arms, gym-hil's Panda ship torque
    motors; their policies' joint targets go through such a controller).

    Each converted motor (a ``motor`` on a hinge or slide joint) keeps its joint, gear and
    force bound: its actuator becomes ``kp``/``kv`` in joint units, its control the joint's
    target (the joint's range, in radians or metres), and its force range the force the
    motor could give (its control range times its gain, within its own force range). Its
    motor FOS is measured against that bound, as for any servo.

    Attributes:
        default: gains for every torque motor on a joint not in ``gains``, or None (then
            only those in ``gains`` are converted).
        gains: per actuator name.
    """

    default: ServoGains | None = None
    gains: Mapping[str, ServoGains] = dataclasses.field(default_factory=dict)

    def __bool__(self) -> bool:
        return self.default is not None or bool(self.gains)


@dataclasses.dataclass(frozen=True)
class Scenario:
    """A validated scenario.

    Attributes:
        name: short name.
        path: the scenario file, or None when built in code.
        mjcf: the MJCF scene file.
        keyframe: keyframe name (or index, for an unnamed one) of the initial pose, or None
            for the model's qpos0.
        object_body: the body whose safety is audited.
        object_geom: its collision geom.
        grippers: the grippers, in signal order.
        support_geoms: geoms of the supports (table, bin, floor).
        actions: the action convention.
        fps: action rate [Hz] when the trajectory does not say.
        range_policy: "error", "clip" or "warn" for targets outside joint ranges.
        task: what the trajectory must achieve (:mod:`critmoment.task`).
        limits: force limit per actuator name [N·m or N]; ``inf`` for an actuator with no
            limit in the scenario or the MJCF (listed in ``unlimited``).
        box: the uncertainty box.
        cost: cost constants.
        sparse: sparse-evaluation settings.
        limit_sources: per actuator, where its limit comes from ("scenario", "mjcf" or
            "none").
        description: free text.
        settle: an object that starts touching nothing falls onto its support before the
            audit's clock starts (``[object] settle``, default true).
        servos: torque motors driven as joint-position servos (``[servos]``).
        feasibility: the tolerances of the check that the twin reproduces the nominal
            motion (``[feasibility]``).
    """

    name: str
    path: Path | None
    mjcf: Path
    keyframe: str | int | None
    object_body: str
    object_geom: str
    grippers: tuple[Gripper, ...]
    support_geoms: tuple[str, ...]
    actions: ActionConvention
    fps: float
    range_policy: str
    task: Task
    limits: Mapping[str, float]
    box: UncertaintyBox
    cost: CostParams
    sparse: SparseSettings = SparseSettings()
    limit_sources: Mapping[str, str] = dataclasses.field(default_factory=dict)
    description: str = ""
    settle: bool = True
    servos: Servos = Servos()
    feasibility: FeasibilityOptions = FeasibilityOptions()
    #: ``[actions] fps`` was given (else ``fps`` is the 50 Hz default)
    fps_given: bool = False
    #: the SHA-256 of the scenario file's bytes as parsed (:func:`load_scenario`), for the
    #: report's manifest; None for a scenario built in code
    sha256: str | None = dataclasses.field(default=None, compare=False)

    def __post_init__(self):
        # load_scenario builds these checked; a Scenario built or replaced in code gets the
        # same structure checked here (names against the model: Twin, validate_names)
        def bad(field: str, expected: str, got: Any) -> ScenarioError:
            return ScenarioError(f"Scenario {field}: expected {expected}, got "
                                 f"{type(got).__name__} {got!r}"[:400])

        for field in ("name", "object_body", "object_geom"):
            value = getattr(self, field)
            if not isinstance(value, str) or (field != "name" and not value):
                raise bad(field, "a non-empty string", value)
        if not isinstance(self.mjcf, (str, os.PathLike)):
            raise bad("mjcf", "the path of the MJCF scene", self.mjcf)
        object.__setattr__(self, "mjcf", Path(self.mjcf))
        grippers = self.grippers
        if not isinstance(grippers, (tuple, list)) or not grippers or not all(
                isinstance(g, Gripper) and g.geoms for g in grippers):
            raise bad("grippers", "at least one Gripper with its geoms", grippers)
        if len({g.name for g in grippers}) != len(grippers):
            raise bad("grippers", "grippers of different names", [g.name for g in grippers])
        object.__setattr__(self, "grippers", tuple(grippers))
        support = self.support_geoms
        if (isinstance(support, str) or not isinstance(support, (tuple, list)) or not support
                or not all(isinstance(g, str) and g for g in support)):
            raise bad("support_geoms", "the names of the supports' geoms (table, bin, floor): "
                      "without them lift-off, place and drop cannot be told", support)
        object.__setattr__(self, "support_geoms", tuple(support))
        for field, kind in (("actions", ActionConvention), ("task", Task),
                            ("box", UncertaintyBox), ("cost", CostParams),
                            ("sparse", SparseSettings), ("servos", Servos),
                            ("feasibility", FeasibilityOptions)):
            if not isinstance(getattr(self, field), kind):
                raise bad(field, f"a {kind.__name__}", getattr(self, field))
        self._bind_task()
        key = self.keyframe
        if not (key is None or (isinstance(key, (int, np.integer)) and not isinstance(
                key, (bool, np.bool_))) or (isinstance(key, str) and key)):
            raise bad("keyframe", "a keyframe name, an index of an unnamed one, or None", key)
        if not (_is_number(self.fps) and math.isfinite(self.fps) and self.fps > 0):
            raise bad("fps", "an action rate > 0 Hz", self.fps)
        if self.range_policy not in ("error", "clip", "warn"):
            raise bad("range_policy", "one of 'error', 'clip', 'warn'", self.range_policy)
        for field in ("settle", "fps_given"):
            if not isinstance(getattr(self, field), bool):
                raise bad(field, "True or False", getattr(self, field))
        if not isinstance(self.limits, Mapping):
            raise bad("limits", "a mapping of actuator name to force limit", self.limits)
        for actuator, value in self.limits.items():
            if not (isinstance(actuator, str) and _is_number(value) and value > 0):
                raise ScenarioError(
                    f"Scenario limits: expected a force limit > 0 (N or N·m; inf for none) per "
                    f"actuator name, got {actuator!r}: {value!r}")

    def _bind_task(self) -> None:
        """Give the task the scenario's gripper order: a task reads the contact signals by
        column, in :attr:`gripper_names` order, and names its roles (picker, receiver,
        gripper) by name. A task built in code with its grippers in another order (or a
        scenario whose grippers were reordered by :meth:`replace`) would read one gripper's
        contacts for another's role; a task naming a gripper the scenario lacks is refused."""
        missing = [m for m in ("stage", "success", "shortfalls", "describe")
                   if getattr(type(self.task), m) is getattr(Task, m)]
        if missing:
            raise ScenarioError(
                f"Scenario task: expected a task of a kind (HandoverTask, PickPlaceTask, "
                f"PickHoldTask, or a Task subclass that implements stage, success, shortfalls "
                f"and describe), got {type(self.task).__name__} without {', '.join(missing)}")
        names = self.gripper_names
        if self.task.grippers == names:
            return
        unknown = [g for g in self.task.grippers if g not in names]
        if unknown:
            raise ScenarioError(
                f"Scenario task: expected grippers of the scenario {list(names)}, got "
                f"{list(self.task.grippers)} ({', '.join(map(repr, unknown))} not among them)")
        object.__setattr__(self, "task", dataclasses.replace(self.task, grippers=names))

    @property
    def gripper_names(self) -> tuple[str, ...]:
        return tuple(g.name for g in self.grippers)

    @property
    def horizon(self) -> int:
        """Physics steps per sparse evaluation (``sparse.horizon``)."""
        return self.sparse.horizon

    @property
    def unlimited(self) -> tuple[str, ...]:
        """Actuators without a force limit (neither the scenario nor the MJCF gives one)."""
        return tuple(a for a, v in self.limits.items() if not math.isfinite(v))

    def content_sha256(self) -> str:
        """SHA-256 of what an audit reads from the scenario: every field but its file's
        path, its file hash and its description, with the MJCF by file name (the report's
        ``model_sha256`` hashes the compiled model). A scenario changed in code
        (:meth:`replace`) hashes differently from the file it was read from."""
        skip = {"path", "sha256", "description", "mjcf"}
        parts = [(f.name, getattr(self, f.name)) for f in dataclasses.fields(self)
                 if f.name not in skip]
        parts.append(("mjcf", self.mjcf.name))
        return hashlib.sha256(repr(parts).encode()).hexdigest()

    def replace(self, **changes) -> Scenario:
        """A copy with fields replaced (e.g. ``box=scenario.box.with_range(...)``)."""
        fields = {f.name for f in dataclasses.fields(self)}
        unknown = sorted(set(changes) - fields - {"horizon"})
        if unknown:
            raise unknown_keys_error("Scenario.replace", unknown, sorted(fields | {"horizon"}))
        if "horizon" in changes:
            changes["sparse"] = dataclasses.replace(
                changes.get("sparse", self.sparse), horizon=changes.pop("horizon"))
        return dataclasses.replace(self, **changes)

    def load_spec(self) -> mujoco.MjSpec:
        """The scenario's MJCF as critmoment's own MjSpec (see :func:`prepare_spec`)."""
        return prepare_spec(self.mjcf, object_body=self.object_body, servos=self.servos,
                            **_spec_targets(self.box))

    def load_model(self) -> mujoco.MjModel:
        """Compile the scenario's MJCF (without critmoment's sensors)."""
        return compile_spec(self.load_spec(), self.mjcf)

    def keyframe_id(self, model: mujoco.MjModel) -> int | None:
        """Id of the keyframe, or None."""
        if self.keyframe is None:
            return None
        if isinstance(self.keyframe, int):
            return self.keyframe
        return model.key(self.keyframe).id

    def _check_roles(self, model: mujoco.MjModel) -> None:
        """The object, the grippers and the supports are different geoms: a gripper or a
        support made of the object's own geoms would make every grip check vacuous."""
        obj = model.body(self.object_body).id

        def of_object(geom: str) -> bool:
            body = int(model.geom_bodyid[model.geom(geom).id])
            while body > 0:
                if body == obj:
                    return True
                body = int(model.body_parentid[body])
            return False

        for g in self.grippers:
            mine = [geom for geom in g.geoms if of_object(geom)]
            if mine:
                raise ScenarioError(
                    f"[grippers.{g.name}]: geoms {mine} belong to the object body "
                    f"{self.object_body!r}; expected the gripper's own finger/pad geoms (a "
                    f"body = \"...\" above the fingers, not the object)")
        mine = [geom for geom in self.support_geoms if of_object(geom)]
        if mine:
            raise ScenarioError(f"[support]: geoms {mine} belong to the object body "
                                f"{self.object_body!r}; expected the table, bin or floor geoms")
        support = set(self.support_geoms)
        for g in self.grippers:
            both = sorted(support.intersection(g.geoms))
            if both:
                raise ScenarioError(f"[grippers.{g.name}] and [support]: geoms {both} are in "
                                    f"both; expected a geom to be either a gripper's or a "
                                    f"support's")
        for i, a in enumerate(self.grippers):
            for b in self.grippers[i + 1:]:
                both = sorted(set(a.geoms).intersection(b.geoms))
                if both:
                    raise ScenarioError(f"[grippers.{a.name}] and [grippers.{b.name}]: geoms "
                                        f"{both} are in both; expected each gripper's own geoms")

    def undriven_actuators(self, model: mujoco.MjModel) -> tuple[str, ...]:
        """Actuators of ``model`` that no action channel drives (their control stays 0)."""
        driven = {a for channel in self.actions.channels for a in channel}
        return tuple(name for i in range(model.nu)
                     if (name := mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, i)
                         or "") not in driven)

    def validate_names(self, model: mujoco.MjModel) -> None:
        """Check every name against ``model``; raise ScenarioError listing valid names."""
        def names(objtype, count):
            return [mujoco.mj_id2name(model, objtype, i) or "" for i in range(count)]

        bodies = names(mujoco.mjtObj.mjOBJ_BODY, model.nbody)
        geoms = names(mujoco.mjtObj.mjOBJ_GEOM, model.ngeom)
        actuators = names(mujoco.mjtObj.mjOBJ_ACTUATOR, model.nu)

        def need(name, pool, what, where):
            if name not in pool:
                raise ScenarioError(f"{where}: unknown {what} {name!r}; valid names: "
                                    + _listing(pool))

        _check_options(model)
        need(self.object_body, bodies, "body", "[object] body")
        need(self.object_geom, geoms, "geom", "[object] geom")
        body = model.body(self.object_body)
        if body.jntnum[0] != 1 or model.jnt_type[body.jntadr[0]] != mujoco.mjtJoint.mjJNT_FREE:
            free = [model.body(model.jnt_bodyid[j]).name for j in range(model.njnt)
                    if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
            raise ScenarioError(
                f"[object] body: expected a body with one free joint, got {self.object_body!r} "
                f"with {body.jntnum[0]} joint(s); free bodies: {_listing(free)}")
        parts = act_info.parts_below(model, body.id)
        if parts:
            raise ScenarioError(act_info.object_parts_message(model, body.id, parts))
        held = object_equalities(model, body.id)
        if held:
            raise ScenarioError(held_object_message("[object] body", self.object_body, held))
        owner = model.geom_bodyid[model.geom(self.object_geom).id]
        if owner != body.id:
            raise ScenarioError(
                f"[object] geom: {self.object_geom!r} belongs to body {model.body(owner).name!r}, "
                f"expected a geom of [object] body {self.object_body!r}")
        for g in self.grippers:
            for geom in g.geoms:
                need(geom, geoms, "geom", f"[grippers.{g.name}] geoms")
        for geom in self.support_geoms:
            need(geom, geoms, "geom", "[support] geoms")
        self._check_roles(model)
        for g in self.grippers:
            why = cannot_touch(model, [model.geom(geom).id for geom in g.geoms], body.id)
            if why:
                raise ScenarioError(
                    f"[grippers.{g.name}]: none of its geoms can touch the object "
                    f"{self.object_body!r}: {why}; expected a gripper whose pads collide with "
                    f"the object (the grip's audit would be vacuous)")
        if self.support_geoms:
            why = cannot_touch(model, [model.geom(geom).id for geom in self.support_geoms],
                                body.id)
            if why:
                raise ScenarioError(
                    f"[support] geoms: none of {list(self.support_geoms)} can touch the object "
                    f"{self.object_body!r}: {why} (a default class of an included file may "
                    f"set them); expected supports the object rests on (it falls through "
                    f"them)")
        seen: dict[str, str] = {}
        for c, (label, channel) in enumerate(zip(self.actions.labels, self.actions.channels,
                                                 strict=True)):
            for a in channel:
                need(a, actuators, "actuator", "[actions]")
                if a in seen:
                    raise ScenarioError(
                        f"[actions]: actuator {a!r} is driven by two channels ({seen[a]} and "
                        f"#{c} {label!r}); expected each actuator in at most one channel (a "
                        f"repeated name usually means another actuator was meant)")
                seen[a] = f"#{c} {label!r}"
        for a in self.limits:
            need(a, actuators, "actuator", "[limits]")
        if self.keyframe is not None:
            if isinstance(self.keyframe, int):
                if not 0 <= self.keyframe < model.nkey:
                    raise ScenarioError(f"[model] keyframe: expected an index in [0, {model.nkey})"
                                        f", got {self.keyframe}")
            elif mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, self.keyframe) < 0:
                keys = names(mujoco.mjtObj.mjOBJ_KEY, model.nkey)
                raise ScenarioError(
                    f"[model] keyframe: unknown keyframe {self.keyframe!r}; valid: "
                    f"{_listing(keys)} or an index 0..{model.nkey - 1}")
        written: dict[tuple, str] = {}
        obj = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, self.object_body)
        reach = _body_reach(model, obj)
        if reach is not None and self.sparse.slip_tolerance >= 2.0 * reach:
            raise ScenarioError(
                f"[sparse] slip_tolerance: {self.sparse.slip_tolerance:g} m, but the object "
                f"{self.object_body!r} is at most {2.0 * reach:.3g} m across; expected a "
                f"motion in the grip well under the object's size (default 0.005 m): a slip "
                f"that large has carried the object out of the grip, so none would count")
        for p in self.box.parameters:
            try:
                index = p.resolve(model)
            except ScenarioError as exc:
                raise ScenarioError(f"[uncertainty.{p.name}]: {exc}") from None
            _check_effect(p, index, model, object_body=obj)
            # one parameter per quantity: a second would overwrite the first in every
            # simulation (the friction of any of the object's geoms is the object's)
            key = (p.fields, "object" if isinstance(p, FrictionParameter)
                   and obj >= 0 and model.geom_bodyid[index] == obj else index)
            if key in written:
                raise ScenarioError(
                    f"[uncertainty.{p.name}] and [uncertainty.{written[key]}]: both vary "
                    f"{p.fields[0].split('_', 1)[1]} of {p.target!r}"
                    f"{' (the object)' if key[1] == 'object' else ''}; expected one "
                    f"parameter per quantity (the second would overwrite the first)")
            written[key] = p.name


#: <option> <flag .../> settings under which no grasp or no servo can act at all
_NO_GRASP_FLAGS = (("contact", mujoco.mjtDisableBit.mjDSBL_CONTACT, "no contact is made: no "
                    "gripper can hold the object and nothing supports it"),
                   ("constraint", mujoco.mjtDisableBit.mjDSBL_CONSTRAINT, "no contact, joint "
                    "limit or equality acts: no gripper can hold the object"),
                   ("actuation", mujoco.mjtDisableBit.mjDSBL_ACTUATION, "no actuator acts: "
                    "the robot cannot follow any trajectory"))


def _check_options(model: mujoco.MjModel) -> None:
    """Simulation options under which no grasp or no motion can happen at all (contacts,
    constraints or actuation disabled): an audit would blame every sample on the model."""
    for name, bit, why in _NO_GRASP_FLAGS:
        if model.opt.disableflags & int(bit):
            raise ScenarioError(f"<option> <flag {name}=\"disable\"/>: {why}; expected a model "
                                f"with {name} enabled")


def _listing(pool: Sequence[str], limit: int = 40) -> str:
    shown = [n for n in pool if n and not n.startswith(GENERATED)]
    more = len(shown) - limit
    return (", ".join(shown[:limit]) + (f", ... ({more} more)" if more > 0 else "")) or "(none)"


def _with_units(box: UncertaintyBox, model: mujoco.MjModel) -> UncertaintyBox:
    """The box with each force limit's unit read from the model (N·m on a hinge)."""
    out = []
    for p in box.parameters:
        if isinstance(p, ForceLimitParameter):
            try:
                p = p.with_units(model)
            except ScenarioError as exc:
                raise ScenarioError(f"[uncertainty.{p.name}]: {exc}") from None
        out.append(p)
    return UncertaintyBox(tuple(out))


def _spec_targets(box: UncertaintyBox) -> dict[str, tuple[str, ...]]:
    """:func:`prepare_spec`'s keywords for the box: the geoms whose friction it varies and
    the bodies whose centre of mass it moves."""
    return {"friction_geoms": tuple(p.target for p in box.parameters
                                    if isinstance(p, FrictionParameter)),
            "com_bodies": tuple(p.target for p in box.parameters
                                if isinstance(p, ComOffsetParameter))}


def _check_effect(p: Parameter, index: int, model: mujoco.MjModel, *,
                  object_body: int = -1) -> None:
    """A parameter must change what it claims to change on the compiled model.

    A friction on a geom the object can touch (a pad) must govern its contacts with the
    object (a higher priority than the object's geoms there); its contacts with anything
    else do not matter to the grip (both pads of one priority touch each other: that
    contact is not the grip's). A friction on any other geom must govern its contacts."""
    if isinstance(p, FrictionParameter):
        partners = act_info.dynamic_partners(model, index)
        on_object = [i for i in partners if model.geom_bodyid[i] == object_body]
        rivals = [i for i in (on_object or partners)
                  if model.geom_priority[i] >= model.geom_priority[index]]
        if model.opt.enableflags & mujoco.mjtEnableBit.mjENBL_OVERRIDE:
            raise ScenarioError(
                f"[uncertainty.{p.name}]: the model enables the contact override (<option> "
                f"<flag override=\"enable\"/>), which gives every contact the friction "
                f"o_friction = {model.opt.o_friction[0]:g}: the friction of geom {p.target!r} "
                "changes nothing; disable the override or drop the friction parameter")
        if not act_info.collision_geoms(model)[index]:
            raise ScenarioError(
                f"[uncertainty.{p.name}]: geom {p.target!r} takes part in no contact "
                "(contype = conaffinity = 0 and no explicit <pair>): its friction changes "
                "nothing")
        # with the highest priority its condim is its contacts'; a pair sets its own
        dynamic = bool(model.geom_contype[index] or model.geom_conaffinity[index])
        pairs = act_info.geom_pairs(model, [index])
        if not rivals and not ((dynamic and model.geom_condim[index] > 1)
                               or (model.pair_dim[pairs] > 1).any()):
            raise ScenarioError(
                f"[uncertainty.{p.name}]: geom {p.target!r} makes frictionless contacts "
                f"(condim 1{' in its explicit pairs too' if pairs.size else ''}): its "
                "friction changes nothing; set condim = 3 (or 4, 6) on it, or drop the "
                "friction parameter")
        if rivals:
            which = "its contacts with the object" if on_object else "its contacts"
            raise ScenarioError(
                f"[uncertainty.{p.name}]: the friction of geom {p.target!r} never governs "
                f"{which}: {len(rivals)} geom(s) it can touch there have priority >= its "
                f"{model.geom_priority[index]} (MuJoCo mixes friction with max), so its costs "
                "would not change over the range; vary the object's friction (critmoment gives "
                "the object's geoms priority) or raise this geom's priority in the MJCF")
    elif isinstance(p, (MassParameter, ComOffsetParameter)) and model.body_weldid[index] == 0:
        raise ScenarioError(
            f"[uncertainty.{p.name}]: body {p.target!r} is fixed to the world (no joint "
            "between it and the world), so its mass or centre of mass changes nothing; "
            "name a body that moves (the object, or a link of the arm)")
    elif isinstance(p, (MassParameter, ComOffsetParameter)) and not model.body_mass[index] > 0:
        why, which = (("its inertia cannot scale with a mass",
                       "inertial or geoms with density") if isinstance(p, MassParameter) else
                      ("moving its centre of mass changes nothing",
                       "the object, or a link of the arm"))
        raise ScenarioError(
            f"[uncertainty.{p.name}]: body {p.target!r} has no mass in the MJCF "
            f"({model.body_mass[index]:g} kg), so {why}; name a body with mass ({which})")
    elif isinstance(p, ComOffsetParameter) and (reach := _body_reach(model, index)) is not None:
        span = _com_span(model, index)
        if span is None:
            # a centre of mass in no geom (a frame, two separate parts): within their reach
            ipos = model.body_ipos[index]
            far = [v for v in (p.low, p.high)
                   if np.linalg.norm(ipos + np.array([v, 0.0, 0.0])) > reach]
            where = f"they lie within {reach:.3g} m of its frame"
        else:
            far = [v for v in (p.low, p.high) if not span[0] - 1e-9 <= v <= span[1] + 1e-9]
            where = (f"along its x axis through its centre of mass they span offsets "
                     f"{span[0]:.3g} to {span[1]:.3g} m")
        if far:
            raise ScenarioError(
                f"[uncertainty.{p.name}]: an offset of {far[0]:g} m along x puts the centre of "
                f"mass of body {p.target!r} outside every geom it has ({where}); expected a "
                f"range within the body, whose centre of mass lies inside its matter (is the "
                f"range in mm?)")
    elif isinstance(p, ForceLimitParameter) and not model.actuator_forcelimited[index]:
        raise ScenarioError(
            f"[uncertainty.{p.name}]: actuator {p.target!r} has no forcerange in the MJCF "
            "(forcelimited false), so a force limit parameter would change nothing; add "
            "forcerange/forcelimited to the actuator")


def _body_reach(model: mujoco.MjModel, body: int) -> float | None:
    """The radius about a body's frame that holds all its own geoms (their bounding
    spheres), or None for a body without geoms."""
    geoms = np.flatnonzero(model.geom_bodyid == body)
    if geoms.size == 0:
        return None
    return float(np.max(np.linalg.norm(model.geom_pos[geoms], axis=1)
                        + model.geom_rbound[geoms]))


def _inside_geom(model: mujoco.MjModel, geom: int, points: np.ndarray) -> np.ndarray:
    """Whether each point (n, 3), in its body's frame, lies inside the geom (its exact
    shape for MuJoCo's primitives, a mesh's convex hull, which is what MuJoCo collides,
    the bounding box for another shape or a flat mesh)."""
    rot = np.zeros(9)
    mujoco.mju_quat2Mat(rot, model.geom_quat[geom])
    local = (points - model.geom_pos[geom]) @ rot.reshape(3, 3)  # into the geom's frame
    size, kind = model.geom_size[geom], int(model.geom_type[geom])
    tol = 1e-9
    if kind == mujoco.mjtGeom.mjGEOM_SPHERE:
        return np.linalg.norm(local, axis=1) <= size[0] + tol
    if kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
        axial = np.clip(local[:, 2], -size[1], size[1])
        return np.linalg.norm(local - np.outer(axial, [0, 0, 1]), axis=1) <= size[0] + tol
    if kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
        return ((np.linalg.norm(local[:, :2], axis=1) <= size[0] + tol)
                & (np.abs(local[:, 2]) <= size[1] + tol))
    if kind == mujoco.mjtGeom.mjGEOM_ELLIPSOID:
        return (np.sum((local / size) ** 2, axis=1) <= 1.0 + tol)
    if kind == mujoco.mjtGeom.mjGEOM_BOX:
        return (np.abs(local) <= size + tol).all(axis=1)
    if kind == mujoco.mjtGeom.mjGEOM_MESH and model.geom_dataid[geom] >= 0:
        hull = _mesh_hull(model, int(model.geom_dataid[geom]))
        if hull is not None:  # facets n·x + d ≤ 0 inside, in the geom's frame
            return (local @ hull[:, :3].T + hull[:, 3] <= tol).all(axis=1)
    box = model.geom_aabb[geom]  # centre (3), half sizes (3), in the geom's frame
    return (np.abs(local - box[:3]) <= box[3:] + tol).all(axis=1)


def _mesh_hull(model: mujoco.MjModel, mesh: int) -> np.ndarray | None:
    """The facets (f, 4) of a mesh's convex hull in its geom's frame (MuJoCo's compiled
    vertices are there), or None where qhull finds no volume (a flat mesh)."""
    from scipy.spatial import ConvexHull, QhullError

    start, count = int(model.mesh_vertadr[mesh]), int(model.mesh_vertnum[mesh])
    vert = np.asarray(model.mesh_vert[start:start + count], dtype=np.float64)
    if count < 4:
        return None
    try:
        return ConvexHull(vert).equations
    except (QhullError, ValueError):
        return None


def _com_span(model: mujoco.MjModel, body: int) -> tuple[float, float] | None:
    """The offsets along a body's x axis from its centre of mass that stay inside its own
    geoms, (low, high) [m], without leaving them; None for a body without geoms or whose
    centre of mass lies in none (a rigid body's centre of mass lies inside its matter)."""
    geoms = np.flatnonzero(model.geom_bodyid == body)
    # the body's matter is what it collides with, where it has such geoms (a large visual
    # mesh beside a small collision box is no matter)
    solid = geoms[(model.geom_contype[geoms] != 0) | (model.geom_conaffinity[geoms] != 0)]
    geoms = solid if solid.size else geoms
    if geoms.size == 0:
        return None
    ipos = model.body_ipos[body]
    reach = float(np.max(np.linalg.norm(model.geom_pos[geoms] - ipos, axis=1)
                         + model.geom_rbound[geoms]))
    offsets = np.linspace(-reach, reach, 4001)
    points = ipos + np.outer(offsets, [1.0, 0.0, 0.0])
    inside = np.zeros(offsets.size, bool)
    for g in geoms:
        inside |= _inside_geom(model, int(g), points)
    centre = offsets.size // 2
    if not inside[centre]:
        return None
    def within(v: float) -> bool:
        point = (ipos + np.array([v, 0.0, 0.0]))[None]
        return any(_inside_geom(model, int(g), point)[0] for g in geoms)

    def edge(i_in: int, i_out: int) -> float:  # bisected between an inside and an outside
        a, b = float(offsets[i_in]), float(offsets[i_out])
        for _ in range(40):
            a, b = ((a + b) / 2, b) if within((a + b) / 2) else (a, (a + b) / 2)
        return a

    outside = np.flatnonzero(~inside)
    below, above = outside[outside < centre], outside[outside > centre]
    low = edge(int(below[-1]) + 1, int(below[-1])) if below.size else float(offsets[0])
    high = edge(int(above[0]) - 1, int(above[0])) if above.size else float(offsets[-1])
    return low, high


# ---------------------------------------------------------------------------
# critmoment's own copy of the model
# ---------------------------------------------------------------------------


def _motor_on_joint(spec: mujoco.MjSpec, a) -> bool:
    """A plain torque motor (fixed gain, no bias, no dynamics, no plugin) on a hinge or
    slide joint."""
    if a.trntype != mujoco.mjtTrn.mjTRN_JOINT or a.gaintype != mujoco.mjtGain.mjGAIN_FIXED:
        return False
    if a.plugin.active:  # the plugin's force comes on top of any gain and bias
        return False
    if a.biastype != mujoco.mjtBias.mjBIAS_NONE or a.dyntype != mujoco.mjtDyn.mjDYN_NONE:
        return False
    joint = spec.joint(a.target)
    return joint is not None and joint.type in (mujoco.mjtJoint.mjJNT_HINGE,
                                                mujoco.mjtJoint.mjJNT_SLIDE)


def _limited(flag, low: float, high: float, auto: bool) -> bool:
    if flag == mujoco.mjtLimited.mjLIMITED_TRUE:
        return True
    return flag == mujoco.mjtLimited.mjLIMITED_AUTO and auto and low < high


def _make_servos(spec: mujoco.MjSpec, servos: Servos) -> None:
    """Turn the torque motors ``servos`` names into joint-position servos (see
    :class:`Servos`)."""
    motors = {a.name: a for a in spec.actuators if _motor_on_joint(spec, a)}
    for name in servos.gains:
        if name not in motors:
            kinds = {a.name: a for a in spec.actuators}
            what = ("is not a torque motor on a hinge or slide joint (a servo already, or "
                    "another transmission)" if name in kinds else "is no actuator of the model")
            if name in kinds and kinds[name].plugin.active:
                what = f"is a plugin actuator ({act_info.PLUGIN_ADVICE})"
            raise ScenarioError(
                f"[servos.{name}]: expected a torque motor on a joint, but {name!r} {what}; "
                f"the model's torque motors on joints: {_listing(sorted(motors)) or '(none)'}")
    if servos.default is not None and not motors:
        warnings.warn("[servos]: default kp, kv given, but the model has no torque motor on a "
                      "joint to drive as a servo; they change nothing", ScenarioWarning,
                      stacklevel=3)
    auto = bool(spec.compiler.autolimits)
    for name, a in motors.items():
        gains = servos.gains.get(name, servos.default)
        if gains is None:
            continue
        joint = spec.joint(a.target)
        g = float(a.gear[0])
        if not g:
            raise ScenarioError(f"[servos]: actuator {name!r} has gear 0; it moves nothing")
        # the force the motor can give: its control range times its gain, within its own
        # force range
        bounds = act_info.motor_force_range(
            a.ctrlrange, float(a.gainprm[0]), a.forcerange,
            ctrl_limited=_limited(a.ctrllimited, *a.ctrlrange, auto),
            force_limited=_limited(a.forcelimited, *a.forcerange, auto))
        # torque = g F with F = (kp/g) target - (kp/g²) length - (kv/g²) length rate, the
        # length being g q: kp and kv act on the joint, the control is the joint's target
        a.gainprm = np.zeros_like(a.gainprm)
        a.biasprm = np.zeros_like(a.biasprm)
        a.gainprm[0] = gains.kp / g
        a.biasprm[1] = -gains.kp / g ** 2
        a.biasprm[2] = -gains.kv / g ** 2
        a.biastype = mujoco.mjtBias.mjBIAS_AFFINE
        low, high = (float(v) for v in joint.range)
        if _limited(joint.limited, low, high, auto):
            scale = (math.pi / 180.0 if spec.compiler.degree
                     and joint.type == mujoco.mjtJoint.mjJNT_HINGE else 1.0)
            a.ctrlrange = np.array([low, high]) * scale  # (a servo's ctrlrange is not converted)
            a.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
        else:
            a.ctrllimited = mujoco.mjtLimited.mjLIMITED_FALSE
        if bounds is not None:
            a.forcerange = bounds
            a.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
        else:
            a.forcelimited = mujoco.mjtLimited.mjLIMITED_FALSE


def cannot_touch(model: mujoco.MjModel, geoms: Sequence[int], body: int) -> str:
    """Why no geom of ``geoms`` can ever collide with a geom of ``body`` (MuJoCo's collision
    filter, as :func:`critmoment.actuators.grip_contacts` reads it), in words; "" when one
    can, or ``body`` has no geom that collides with anything (refused elsewhere)."""
    if not len(geoms) or not act_info.collision_geoms(model)[model.geom_bodyid == body].any():
        return ""
    if act_info.grip_contacts(model, body, geoms):
        return ""
    excluded = set(model.exclude_signature.tolist())
    pads = {int(model.geom_bodyid[g]) for g in geoms}
    shut = {b for b in pads if (min(b, body) << 16) + max(b, body) in excluded}
    out = []
    if shut:
        out.append(f"<contact><exclude> between the object and "
                   f"{', '.join(sorted(repr(model.body(b).name) for b in shut))}")
    if shut != pads:
        out.append("their contype/conaffinity bits and the object's share no bit")
    return " and ".join(out)


def object_equalities(model: mujoco.MjModel, body: int) -> list[str]:
    """The equality constraints active at the start (``eq_active0``) that tie ``body`` to
    another body or to the world (``weld`` and ``connect``, between bodies or their sites),
    each in words ("equality 'grasp' (a weld to body 'hand')"): a grasp made by a weld, as
    teleoperation and learning environments make it."""
    out = []
    kinds = {int(mujoco.mjtEq.mjEQ_WELD): "a weld", int(mujoco.mjtEq.mjEQ_CONNECT): "a connect"}
    for e in range(model.neq):
        kind = kinds.get(int(model.eq_type[e]))
        if kind is None or not model.eq_active0[e]:
            continue
        ends = []
        for obj in (int(model.eq_obj1id[e]), int(model.eq_obj2id[e])):
            if int(model.eq_objtype[e]) == int(mujoco.mjtObj.mjOBJ_SITE):
                obj = int(model.site_bodyid[obj])
            ends.append(obj)
        if body not in ends:
            continue
        other = ends[1] if ends[0] == body else ends[0]
        to = "the world" if other == 0 else f"body {model.body(other).name!r}"
        name = model.equality(e).name
        out.append(f"equality {name!r} ({kind} to {to})" if name
                   else f"equality #{e} ({kind} to {to})")
    return out


def held_object_message(where: str, name: str, held: Sequence[str]) -> str:
    """Why an object that :func:`object_equalities` ties to something is refused."""
    return (f"{where}: {name!r} is held by {'; '.join(held)}, active from the start: an "
            f"object constrained so cannot slip or drop, and the audit of its grip would pass "
            f"whatever the mass or friction; set active=\"false\" on the equality "
            f"(critmoment never switches it on) or remove it")


def prepare_spec(mjcf: str | Path, *, object_body: str | None = None,
                 friction_geoms: Sequence[str] = (), com_bodies: Sequence[str] = (),
                 servos: Servos | None = None,
                 what: str = "[model] mjcf") -> mujoco.MjSpec:
    """The MJCF as an MjSpec, made ready for critmoment (see the module docstring).

    Args:
        mjcf: the MJCF file.
        object_body: the object's body; when ``friction_geoms`` names any of its geoms,
            the object's geoms get a priority above every other geom.
        friction_geoms: geoms whose friction the uncertainty box varies.
        com_bodies: bodies whose centre of mass the uncertainty box moves (compiled as not
            simple).
        servos: torque motors to drive as joint-position servos (``[servos]``), or None.
        what: where the path came from, for messages.

    Raises:
        InputFileError: the file is missing or unreadable.
        ScenarioError: the MJCF does not parse or compile.
    """
    mjcf = Path(mjcf)
    if not mjcf.is_file():
        where = "" if mjcf.is_absolute() else f" (looked for {mjcf.absolute()})"
        raise InputFileError(f"{what}: {_not_a_file(mjcf)}: {mjcf}{where}")
    if mjcf.suffix.lower() in (".toml", ".npz", ".hdf5", ".h5", ".parquet", ".json"):
        raise ScenarioError(f"{what}: expected an MJCF model file (.xml), got {mjcf} (a "
                            f"{mjcf.suffix} file); a scenario goes to --scenario, a "
                            f"trajectory to rollout/analyze/validate")
    _check_mjcf_text(mjcf, what)
    try:
        # an absolute path: from a relative one, MuJoCo (4.0) resolves the meshes of a file
        # <include>d beside it against the relative folder twice, and fails to open them.
        # Through the user's links, as MuJoCo reads the path: a scene linked into a robot's
        # folder includes that folder's files (resolved, it had included the files beside
        # the link's target, another robot's), and a Hugging Face cache's extensionless blob
        # behind a scene.xml link is read as XML
        spec = mujoco.MjSpec.from_file(os.path.abspath(mjcf))
    except Exception as exc:  # MuJoCo raises ValueError, OSError or its own errors
        raise ScenarioError(f"could not read MJCF {mjcf}: {exc}") from exc
    try:
        return _prepared(spec, object_body, friction_geoms, com_bodies, servos)
    except UnicodeDecodeError as exc:  # a name MuJoCo keeps but Python cannot read
        raise ScenarioError(_not_utf8(mjcf, exc.object)) from exc


#: the first bytes of a compiled MuJoCo model (``mj_saveModel``'s format id, 54321, as a
#: little-endian int)
_MJB_MAGIC = (54321).to_bytes(4, "little")


def _check_mjcf_text(mjcf: Path, what: str) -> None:
    """Refuse a file that cannot be an MJCF (or URDF) text: a compiled ``.mjb`` model, or
    one that does not start with ``<`` (after a byte-order mark and white space)."""
    try:
        with open(mjcf, "rb") as f:
            head = f.read(4096)
    except OSError as exc:
        raise InputFileError(f"{what}: could not read {mjcf}: {exc}") from exc
    if head.startswith(_MJB_MAGIC) or mjcf.suffix.lower() == ".mjb":
        raise ScenarioError(f"{what}: {mjcf} is a compiled MuJoCo model (MJB); critmoment "
                            f"needs the MJCF (XML) source it was compiled from (it edits the "
                            f"model through MjSpec, which an MJB cannot give)")
    text = head.removeprefix(b"\xef\xbb\xbf").lstrip()
    if text and not text.startswith(b"<"):
        raise ScenarioError(f"{what}: expected an MJCF model file (XML text starting with "
                            f"'<'), got {mjcf}, which starts with {head[:16]!r}")


def _not_utf8(mjcf: Path, text: bytes) -> str:
    bad = next((part for part in bytes(text).split(b"\0") if not _is_utf8(part)), text)
    return (f"could not read MJCF {mjcf}: the name {bytes(bad)!r} is not UTF-8 text; "
            f"MuJoCo's names must be (save the file, and any file it includes, as UTF-8)")


def _is_utf8(raw: bytes) -> bool:
    try:
        raw.decode("utf-8")
    except UnicodeDecodeError:
        return False
    return True


def _prepared(spec: mujoco.MjSpec, object_body, friction_geoms, com_bodies, servos
              ) -> mujoco.MjSpec:
    geoms = list(spec.geoms)
    taken = {g.name for g in geoms}
    for i, g in enumerate(geoms):
        if not g.name:
            name = f"{GENERATED}geom:{i}"
            while name in taken:
                name += "_"
            g.name = name
            taken.add(name)
    used = {a.name for a in spec.actuators if a.name}
    for i, a in enumerate(spec.actuators):
        if not a.name:
            name = a.target or f"{GENERATED}actuator:{i}"
            if name in used:
                name = f"{GENERATED}actuator:{i}"
            a.name = name
            used.add(name)
    if object_body is not None and friction_geoms:
        body = spec.body(object_body)
        if body is not None:
            own = _rigid_geoms(body)
            if any(g.name in friction_geoms for g in own):
                _govern_object_friction(spec, own)
    for name in com_bodies:
        body = spec.body(name)
        if body is not None:
            body.simple = 0
    if servos:
        _make_servos(spec, servos)
    return spec


def _govern_object_friction(spec: mujoco.MjSpec, own: list) -> None:
    """Make the object's friction the friction of every contact it makes, and change nothing
    else about those contacts.

    Where the object's geoms already set every parameter of their contacts (they have the
    highest priority, or their partners' parameters equal theirs), they get a priority above
    every other geom. Otherwise raising it would also hand the object's condim, solref and
    solimp to contacts whose own are different (a stiff fingertip's solref 0.004 became the
    object's 0.02): each contact the object can make becomes an explicit ``<pair>`` with the
    parameters MuJoCo gives it (:func:`critmoment.actuators.contact_parameters`), whose
    sliding friction the friction parameter then writes."""
    try:
        model = spec.compile()
    except Exception:  # noqa: BLE001 - the caller's compile reports it, with the names
        return
    ids = [model.geom(g.name).id for g in own]
    combos, same = [], True
    for g in ids:
        if not (model.geom_contype[g] or model.geom_conaffinity[g]):
            continue
        fr = model.geom_friction[g]
        for x in act_info.dynamic_partners(model, g):
            mixed = act_info.contact_parameters(model, g, x)
            combos.append((g, x, mixed))
            same &= (mixed.condim == int(model.geom_condim[g])
                     and mixed.friction == (fr[0], fr[0], fr[1], fr[2], fr[2])
                     and mixed.solref == tuple(model.geom_solref[g])
                     and mixed.solimp == tuple(model.geom_solimp[g]))
    if same:
        top = max((g.priority for g in spec.geoms), default=0)
        for g in own:
            g.priority = top + 1
        return
    for g, x, mixed in combos:
        spec.add_pair(name=f"{GENERATED}pair:{model.geom(g).name}:{model.geom(x).name}",
                      geomname1=model.geom(g).name, geomname2=model.geom(x).name,
                      condim=mixed.condim, friction=list(mixed.friction),
                      solref=list(mixed.solref), solimp=list(mixed.solimp),
                      margin=mixed.margin, gap=mixed.gap)


def _rigid_geoms(body) -> list:
    """The geoms of a spec body and of the bodies below it with no joint of their own (parts
    fixed to it, which ``<compiler fusestatic="true"/>`` merges into it)."""
    out = list(body.geoms)
    for child in body.bodies:
        if not child.joints:
            out += _rigid_geoms(child)
    return out


def compile_spec(spec: mujoco.MjSpec, mjcf: Path) -> mujoco.MjModel:
    """Compile a spec from :func:`prepare_spec`; a ScenarioError says what failed, and
    which element of the model a generated name (``critmoment:geom:3``) stands for."""
    try:
        model = spec.compile()
    except Exception as exc:
        text = str(exc).strip()
        hint = ""
        found = re.search(rf"{re.escape(GENERATED)}(geom|actuator):(\d+)", text)
        if found:
            hint = (f" ({found.group(0)!r} is critmoment's name for the model's unnamed "
                    f"{found.group(1)} #{found.group(2)}, in the order of the MJCF)")
        raise ScenarioError(f"could not compile MJCF {mjcf}: {text}{hint}") from exc
    if not _is_utf8(bytes(model.names)):
        raise ScenarioError(_not_utf8(mjcf, bytes(model.names)))
    return model


# ---------------------------------------------------------------------------
# loading
# ---------------------------------------------------------------------------


def _parameter(name: str, spec: Any) -> Parameter:
    where = f"[uncertainty.{name}]"
    if not isinstance(spec, Mapping):
        raise ScenarioError(f"{where}: expected a table, got {spec!r}")
    kind = spec.get("kind", name)
    if not isinstance(kind, str) or kind not in PARAMETER_KINDS:
        raise ScenarioError(
            f"{where}: unknown parameter kind {kind!r}; known kinds: {', '.join(PARAMETER_KINDS)} "
            "(set kind = ... when the name is not a kind)")
    cls, target_key = PARAMETER_KINDS[kind]
    _keys(spec, where, ("kind", target_key, "object", "range", "nominal", "prior"))
    if target_key != "object" and target_key in spec and "object" in spec:
        raise ScenarioError(f"{where}: expected one of {target_key} = ... and object = ..., got "
                            f"both ({spec[target_key]!r}, {spec['object']!r})")
    target = spec.get(target_key, spec.get("object"))
    if not isinstance(target, str):
        raise ScenarioError(f"{where}: expected {target_key} = \"<name>\", got {target!r}")
    rng = spec.get("range")
    if not (isinstance(rng, list) and len(rng) == 2
            and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in rng)):
        # (a force limit's unit is read from the model later: a property here)
        unit = cls.unit if isinstance(cls.unit, str) else "N·m or N"
        raise ScenarioError(f"{where} range: expected [low, high], two plain numbers in the "
                            f"parameter's unit ({unit or 'a coefficient'}; no unit text), got "
                            f"{rng!r}")
    nominal = _number(spec, "nominal", where)
    prior_name = spec.get("prior", "uniform")
    try:
        prior = Prior(prior_name)
    except (ValueError, TypeError):
        raise ScenarioError(
            f"{where} prior: expected one of {[p.value for p in Prior]}, got {prior_name!r}") from None
    try:
        param = cls(name=name, target=target, low=float(rng[0]), high=float(rng[1]),
                    nominal=nominal, prior=prior)
    except ParameterError as exc:
        raise ScenarioError(f"{where}: {exc}") from exc
    if isinstance(param, FrictionParameter) and param.high > PLAUSIBLE_FRICTION:
        warnings.warn(f"{where} range: a sliding friction coefficient up to {param.high:g} is "
                      f"far beyond real materials (rubber on rough surfaces reaches about 1-2); "
                      f"is the range in other units?", ScenarioWarning, stacklevel=3)
    return param


class _ActuatorResolver:
    """Finds an actuator by name, by the part of its name after "/", or by the joint or
    tendon it drives (for models whose actuators carry no names)."""

    def __init__(self, model: mujoco.MjModel):
        self.model = model
        self.infos = act_info.describe_all(model)
        self.names = [i.name for i in self.infos]

    def matches(self, key: str) -> list[int]:
        exact = [i.index for i in self.infos if i.name == key]
        if exact:
            return exact
        return [i.index for i in self.infos
                if i.name.rsplit("/", 1)[-1] == key or i.target == key
                or (i.target and i.target.rsplit("/", 1)[-1] == key)]

    def one(self, key: str, where: str) -> str:
        found = self.matches(key)
        if len(found) == 1:
            return self.names[found[0]]
        if not found:
            raise ScenarioError(
                f"{where}: {key!r} matches no actuator (by name, or by the joint/tendon it "
                f"drives); actuators: {self.listing()}")
        raise ScenarioError(f"{where}: {key!r} matches {len(found)} actuators "
                            f"{[self.names[i] for i in found]}; use the full name")

    def listing(self) -> str:
        return ", ".join(f"{i.name} ({i.kind.value} on {i.transmission} {i.target})"
                         for i in self.infos) or "(none)"


def _resolve_limits(raw: Mapping[str, Any], resolver: _ActuatorResolver
                    ) -> tuple[dict[str, float], dict[str, str]]:
    model = resolver.model
    limits: dict[str, float] = {}
    sources: dict[str, str] = {}
    set_by: dict[str, str] = {}  # actuator -> the [limits] key that set it
    for i in range(model.nu):
        value = act_info.force_limit(model, i)
        limits[resolver.names[i]] = math.inf if value is None else value
        sources[resolver.names[i]] = "none" if value is None else "mjcf"
    for key, value in raw.items():
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not (
                math.isfinite(value) and value > 0):
            raise ScenarioError(f"[limits] {key}: expected a finite force limit > 0 [N·m or N], "
                                f"got {value!r}")
        matches = resolver.matches(key)
        if not matches:
            raise ScenarioError(
                f"[limits] {key!r} matches no actuator (by name, or by the joint/tendon it "
                f"drives); actuators: {resolver.listing()}")
        for i in matches:
            name = resolver.names[i]
            earlier = set_by.get(name)
            if earlier is not None and float(raw[earlier]) != float(value):
                raise ScenarioError(
                    f"[limits] {earlier!r} = {raw[earlier]!r} and {key!r} = {value!r} both "
                    f"set actuator {name!r}; expected one limit per actuator (use full "
                    f"names)")
            set_by[name] = key
            limits[name] = float(value)
            sources[name] = "scenario"
    _warn_limits_over_model(model, {resolver.names.index(name): (key, limits[name])
                                    for name, key in set_by.items()})
    return limits, sources


def _warn_limits_over_model(model: mujoco.MjModel, given: Mapping[int, tuple[str, float]]
                            ) -> None:
    """Warn, once, where [limits] values (``given``: actuator -> its key and value) exceed
    the force the model lets the actuator give (its ``forcerange``, its joint's
    ``actuatorfrcrange`` over the gear): it can never reach them, so its saturation check
    cannot fail however heavy the load, and a rating copied in joint units onto a geared
    actuator reads ``gear`` times too high."""
    over, geared = [], []
    for i, (key, value) in sorted(given.items()):
        physical = act_info.force_limit(model, i)
        if physical is None or value <= 1.01 * physical:
            continue
        over.append(f"{key} = {value:g} (actuator {model.actuator(i).name!r} gives at most "
                    f"{physical:.4g})")
        gear = abs(float(model.actuator_gear[i, 0])) or 1.0
        if gear != 1.0:
            geared.append(f"{model.actuator(i).name!r} gear {gear:g}: {value:g} / {gear:g} = "
                          f"{value / gear:.4g}")
    if not over:
        return
    warnings.warn(
        f"[limits] {'; '.join(over)}: above what the model's forcerange / the joint's "
        f"actuatorfrcrange lets the actuator give; MuJoCo clamps its force there, so its "
        f"motor FOS stays above the ratio and a load it cannot hold shows only as a "
        f"tracking loss"
        + (f". [limits] is in the actuator's own units (force before the gear), so a joint "
           f"rating R is R / gear there ({'; '.join(geared)})" if geared else ""),
        ScenarioWarning, stacklevel=4)


def _check_channel_kinds(actions: ActionConvention, resolver: _ActuatorResolver) -> None:
    """A joint-position channel must drive position-like actuators."""
    for c, acts in enumerate(actions.channels):
        for a in acts:
            info = resolver.infos[resolver.names.index(a)]
            if not info.kind.tracks_position and not actions.normalised[c]:
                kind = info.kind.value
                command = {"motor": "torque", "intvelocity": "velocity",
                           "plugin": "plugin's"}.get(kind, "velocity or other")
                raise ScenarioError(
                    f"[actions] channel {actions.labels[c]!r}: actuator {a!r} is "
                    f"{'an' if kind[0] in 'aeiou' else 'a'} {kind} actuator (ctrl is a "
                    f"{command} command), but the action convention gives joint-position targets; "
                    + ("drive the torque motor as a joint servo with [servos] kp, kv (the "
                       "robot's joint controller; `critmoment init` writes them)"
                       if kind == "motor" else
                       act_info.PLUGIN_ADVICE if kind == "plugin" else
                       "audit a position-controlled model, or convert the actions to this "
                       "actuator's controls"))


def _check_gripper_controls(actions: ActionConvention, model: mujoco.MjModel) -> None:
    """A gripper channel's closed and open controls must lie near its actuators' control
    range: far outside it (by more than the range's width) they are in other units (mm for
    m, degrees for radians) or of the wrong sign, and MuJoCo would clamp them silently."""
    for c, acts in enumerate(actions.channels):
        if not actions.normalised[c]:
            continue
        for a, scale, offset in zip(acts, actions.scales[c], actions.offsets[c], strict=True):
            i = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_ACTUATOR, a)
            if i < 0 or not model.actuator_ctrllimited[i]:
                continue
            lo, hi = (float(v) for v in model.actuator_ctrlrange[i])
            width = hi - lo
            for end, value in (("closed (action 0)", offset), ("open (action 1)",
                                                               offset + scale)):
                if not lo - width <= value <= hi + width:
                    raise ScenarioError(
                        f"[actions] channel {actions.labels[c]!r}: the {end} control of "
                        f"actuator {a!r} is {value:g}, far outside its ctrlrange [{lo:g}, "
                        f"{hi:g}]; expected values in the actuator's own units (the model's "
                        f"ctrlrange: m or rad for a position servo), not mm, degrees or "
                        f"another sign")
            ends = sorted((offset, offset + scale))
            clamped = [min(max(v, lo), hi) for v in ends]
            if width > 0 and clamped[0] == clamped[1]:
                # both ends beyond the same end of the range: MuJoCo clamps both to it, and
                # the gripper never moves (it never closes, or never opens)
                raise ScenarioError(
                    f"[actions] channel {actions.labels[c]!r}: actuator {a!r}'s closed and "
                    f"open controls ({offset:g}, {offset + scale:g}) both lie beyond the "
                    f"same end of its ctrlrange [{lo:g}, {hi:g}]; MuJoCo clamps both to "
                    f"{clamped[0]:g} and the gripper never moves; expected controls within "
                    f"its ctrlrange (scales and offsets in the actuator's own units)")


def _gripper_from_table(gname: str, gt: Any, model: mujoco.MjModel) -> Gripper:
    where = f"[grippers.{gname}]"
    if not isinstance(gt, Mapping):
        raise ScenarioError(f"{where}: expected a table with geoms = [...] or body = \"...\", "
                            f"got {gt!r}")
    _keys(gt, where, ("geoms", "body"))
    if ("geoms" in gt) == ("body" in gt):
        raise ScenarioError(f"{where}: expected exactly one of geoms = [names] or body = "
                            f"\"<body>\" (every collision geom of its subtree)")
    if "geoms" in gt:
        return Gripper(gname, _names(gt, "geoms", where))
    body = _get(gt, "body", str, where)
    return Gripper(gname, _subtree_geoms(model, body, where), body=body)


def _reach(model: mujoco.MjModel, data: mujoco.MjData, geom: int
           ) -> tuple[np.ndarray, float] | None:
    """A fixed world point and a bound on how far any point of ``geom`` can get from it, over
    every joint value: the sum along its kinematic chain of the bodies' offsets, each hinge or
    ball joint's anchor offset twice, each slide joint's travel. None where the chain has a
    free joint, an unlimited slide or a mocap body (no such bound)."""
    chain, b = [], int(model.geom_bodyid[geom])
    while b != 0:
        chain.append(b)
        b = int(model.body_parentid[b])
    moving = [i for i, b in enumerate(chain) if model.body_jntnum[b]]
    if not moving or any(model.body_mocapid[b] >= 0 for b in chain):
        return None
    top = moving[-1]  # the highest body with joints: its parent is fixed in the world
    bound = float(np.linalg.norm(model.geom_pos[geom]) + model.geom_rbound[geom])
    for i, b in enumerate(chain[:top + 1]):
        if i < top:
            bound += float(np.linalg.norm(model.body_pos[b]))
        for j in range(model.body_jntadr[b], model.body_jntadr[b] + model.body_jntnum[b]):
            kind = model.jnt_type[j]
            if kind == mujoco.mjtJoint.mjJNT_FREE:
                return None
            if kind == mujoco.mjtJoint.mjJNT_SLIDE:
                if not model.jnt_limited[j]:
                    return None
                q0 = model.qpos0[model.jnt_qposadr[j]]
                bound += float(np.max(np.abs(model.jnt_range[j] - q0)))
            else:
                bound += 2.0 * float(np.linalg.norm(model.jnt_pos[j]))
    parent = int(model.body_parentid[chain[top]])
    anchor = data.xpos[parent] + data.xmat[parent].reshape(3, 3) @ model.body_pos[chain[top]]
    return anchor, bound


def _carry_reach(model: mujoco.MjModel, gripper: Gripper, object_body: str,
                 key_id: int | None) -> tuple[list[tuple[np.ndarray, float]], np.ndarray] | None:
    """Where ``gripper`` can bring the object's centre at any joint values: per gripper geom
    a fixed point and a radius around it (:func:`_reach` plus how far the object's centre
    can be from a geom touching it), and the object's start position; None where some geom
    has no such bound."""
    data = mujoco.MjData(model)
    if key_id is not None:
        mujoco.mj_resetDataKeyframe(model, data, key_id)
    mujoco.mj_kinematics(model, data)
    obj = model.body(object_body).id
    extent = _body_reach(model, obj) or 0.0
    balls = []
    for name in gripper.geoms:
        reach = _reach(model, data, model.geom(name).id)
        if reach is None:
            return None
        balls.append((reach[0], reach[1] + extent))
    return balls, data.xpos[obj].copy()


def _down(model: mujoco.MjModel) -> np.ndarray:
    gravity = np.asarray(model.opt.gravity, dtype=float)
    norm = float(np.linalg.norm(gravity))
    return gravity / norm if norm > 0 else np.array([0.0, 0.0, -1.0])


def _check_goal_site_fixed(model: mujoco.MjModel, site: int) -> None:
    """The goal is read once, at the start pose: a goal site on a body that joints move (an
    arm's link, the gripper) is an error; on a free body (a loose bin) a warning.

    Raises:
        ScenarioError: naming the site, its body and the joint that moves it.
    """
    name = model.site(site).name
    b = int(model.site_bodyid[site])
    while b:
        for j in range(model.body_jntadr[b], model.body_jntadr[b] + model.body_jntnum[b]):
            if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE:
                warnings.warn(
                    f"[task] goal_site: site {name!r} is on the free body "
                    f"{model.body(b).name!r}; the goal is its position at the start pose and "
                    f"does not follow the body if it moves", ScenarioWarning, stacklevel=2)
                return
            raise ScenarioError(
                f"[task] goal_site: site {name!r} is on body "
                f"{model.body(int(model.site_bodyid[site])).name!r}, which joint "
                f"{model.joint(j).name or j!r} moves; expected a site fixed in the world (the "
                f"goal is read once, at the start pose), or give goal = [x, y, z]")
        if model.body_mocapid[b] >= 0:
            raise ScenarioError(
                f"[task] goal_site: site {name!r} is on the mocap body {model.body(b).name!r}, "
                f"which moves; expected a site fixed in the world, or give goal = [x, y, z]")
        b = int(model.body_parentid[b])


def _nearest_reach(model: mujoco.MjModel, balls: Sequence[tuple[np.ndarray, float]],
                   point: np.ndarray, *, slack: float, factor: float = 1.0
                   ) -> tuple[float, np.ndarray, float]:
    """Of :func:`_carry_reach`'s balls (anchor, radius), the one ``point`` is nearest to
    reaching: (gap beyond ``factor`` × (radius + slack), its anchor, radius + slack). A
    point above a ball counts as reached where it lies over it: an object let go there
    falls into it (a goal in a bin below the arm)."""
    down = _down(model) if np.linalg.norm(model.opt.gravity) > 0 else np.zeros(3)
    best = None
    for anchor, radius in balls:
        lift = max(0.0, float(np.dot(point - anchor, down)))
        gap = float(np.linalg.norm(point - lift * down - anchor)) - factor * (radius + slack)
        if best is None or gap < best[0]:
            best = (gap, anchor, radius + slack)
    return best


def _check_goal_reach(model: mujoco.MjModel, goal: Sequence[float], gripper: Gripper,
                      object_body: str, key_id: int | None, *, slack: float) -> None:
    """A pick-and-place goal the carrying gripper cannot bring the object to, at any joint
    values, is an error (a goal in millimetres, or in another frame), not a task that every
    sample fails.

    Raises:
        ScenarioError: naming the goal, the arm's fixed base point and both distances.
    """
    carry = _carry_reach(model, gripper, object_body, key_id)
    if carry is None:
        return
    goal = np.asarray(goal, dtype=float)
    best = _nearest_reach(model, carry[0], goal, slack=slack)
    if best[0] <= 0.0:
        return
    _, anchor, farthest = best
    raise ScenarioError(
        f"[task] goal: ({', '.join(f'{v:g}' for v in goal)}) m is "
        f"{np.linalg.norm(goal - anchor):.3g} m from ({', '.join(f'{v:.3f}' for v in anchor)})"
        f" m, the fixed base of the arm that carries gripper {gripper.name!r}; at any joint "
        f"values that arm brings the object at most {farthest:.3g} m from there; expected a "
        f"goal in world coordinates, in metres, that the arm can reach")


def start_out_of_reach(model: mujoco.MjModel, scenario: Scenario, position: np.ndarray,
                       *, slack: float = 0.05, factor: float = 10.0) -> str | None:
    """Why no gripper of ``scenario`` can ever touch an object whose centre starts at
    ``position``, more than ``factor`` times as far from every arm's base as the arm
    reaches (a pose in millimetres or centimetres), or None. An object merely out of reach
    (set aside on purpose, a motion audited without it) is the nominal run's "never touches
    the object" warning, not an error; nor where some gripper's reach has no bound. An
    object above a gripper's reach may fall into it, as a goal above a bin may
    (:func:`_check_goal_reach`)."""
    key_id = scenario.keyframe_id(model)
    position = np.asarray(position, dtype=float)
    balls = []
    for gripper in scenario.grippers:
        carry = _carry_reach(model, gripper, scenario.object_body, key_id)
        if carry is None:
            return None
        balls += carry[0]
    best = _nearest_reach(model, balls, position, slack=slack, factor=factor)
    if best[0] <= 0.0:
        return None
    _, anchor, farthest = best
    return (f"the object starts at ({', '.join(f'{v:g}' for v in position)}) m, "
            f"{np.linalg.norm(position - anchor):.3g} m from ({', '.join(f'{v:.3f}' for v in anchor)})"
            f" m, the fixed base of the nearest arm, which at any joint values reaches at most "
            f"{farthest:.3g} m from there: no gripper can ever touch it, by far; expected the "
            f"object's start pose in world coordinates, in metres (is it in mm?)")


def _check_lift_reach(model: mujoco.MjModel, lift_height: float, gripper: Gripper,
                      object_body: str, key_id: int | None) -> None:
    """A ``lift_height`` above the highest point the carrying arm can raise the object's
    centre to (from its start pose) can never be met: an error, not a task every sample
    fails.

    Raises:
        ScenarioError: naming both heights.
    """
    carry = _carry_reach(model, gripper, object_body, key_id)
    if carry is None:
        return
    up = -_down(model)
    start = float(np.dot(carry[1], up))
    highest = max(float(np.dot(anchor, up)) + radius for anchor, radius in carry[0])
    if start + lift_height > highest:
        raise ScenarioError(
            f"[task] lift_height: {lift_height:g} m above the object's start, but at any joint "
            f"values the arm that carries gripper {gripper.name!r} raises it at most "
            f"{max(0.0, highest - start):.3g} m; expected a height in metres the arm can reach "
            f"(default 0.02)")


def _not_a_file(path: Path) -> str:
    """Why ``path`` cannot be read as a file, in words."""
    if path.is_dir():
        return "expected a file, got a folder"
    if path.exists():
        return "expected a regular file, got a special file (a device, FIFO or socket)"
    return "file not found"


def _subtree_geoms(model: mujoco.MjModel, body: str, where: str) -> tuple[str, ...]:
    bid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, body)
    if bid < 0:
        names = [model.body(i).name for i in range(model.nbody)]
        raise ScenarioError(f"{where} body: unknown body {body!r}; valid names: {_listing(names)}")
    inside = []
    colliding = act_info.collision_geoms(model)
    for g in range(model.ngeom):
        b = int(model.geom_bodyid[g])
        while b not in (0, bid):
            b = int(model.body_parentid[b])
        if b == bid and colliding[g]:
            inside.append(model.geom(g).name)
    if not inside:
        raise ScenarioError(f"{where} body: {body!r} has no collision geom in its subtree")
    return tuple(inside)


def _object_geom(object_t: Mapping[str, Any], model: mujoco.MjModel, body: str) -> str:
    if "geom" in object_t:
        return _get(object_t, "geom", str, "[object]")
    bid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, body)
    if bid < 0:
        return ""  # validate_names reports the unknown body
    colliding = act_info.collision_geoms(model)
    own = [model.geom(g).name for g in range(model.ngeom)
           if model.geom_bodyid[g] == bid and colliding[g]]
    if len(own) != 1:
        raise ScenarioError(f"[object] geom: body {body!r} has {len(own)} collision geoms "
                            f"{own}; say which with geom = \"...\"")
    return own[0]


def load_scenario(path: str | Path | None = None) -> Scenario:
    """Load and validate a scenario.

    Args:
        path: a ``scenario.toml``, a folder holding one, a bundled scenario's name, or None
            for the bundled ``aloha_transfer_cube``.

    Returns:
        The validated scenario.
    """
    if path is None:
        path = bundled_scenario_path()
    elif isinstance(path, str) and path in BUNDLED_SCENARIOS:
        bundled = bundled_scenario_path(path)
        local = Path(path)
        if local.exists() and local.resolve() != bundled.resolve() \
                and local.resolve() != bundled.resolve().parent:
            # a copy of a bundled scenario made to edit it, under the same name: the
            # bundled one had been loaded and the edits silently not audited
            warnings.warn(f"scenario {path!r}: names both a bundled scenario and "
                          f"{str(local.resolve())!r} here; loading the latter (give "
                          f"{str(bundled)!r} for the bundled one)", ScenarioWarning,
                          stacklevel=2)
        else:
            path = bundled
    elif not isinstance(path, (str, os.PathLike)) or not os.fspath(path).strip():
        raise ScenarioError(f"scenario: expected a scenario.toml, its folder or a bundled "
                            f"scenario's name ({', '.join(BUNDLED_SCENARIOS)}), got "
                            f"{type(path).__name__} {path!r}")
    path = Path(path)
    try:
        if path.is_dir():
            path = path / "scenario.toml"
        if not path.is_file():
            close = [b for b in BUNDLED_SCENARIOS if str(path) and str(path) in b] or \
                difflib.get_close_matches(str(path), BUNDLED_SCENARIOS, n=1, cutoff=0.6)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            raise InputFileError(
                f"scenario {_not_a_file(path)}: {path} (expected a scenario.toml, a folder with one, "
                f"or a bundled name: {', '.join(BUNDLED_SCENARIOS)}){hint}")
        data = path.read_bytes()
        text = data.decode("utf-8-sig")  # (a byte-order mark some editors write)
    except OSError as exc:
        raise InputFileError(f"{path}: cannot read the scenario file ({exc.strerror or exc})"
                             ) from exc
    except UnicodeDecodeError as exc:
        raise ScenarioError(f"{path}: expected a UTF-8 TOML file, got bytes that are not UTF-8 "
                            f"({exc.reason} at byte {exc.start})") from exc
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        hint = ("; this is an MJCF model: a scenario is a scenario.toml naming it (critmoment "
                "init MODEL.xml --object BODY --task KIND writes one)"
                if text.lstrip().startswith("<") else "")
        raise ScenarioError(f"{path}: not valid TOML: {exc}{hint}") from exc
    # the manifest names the bytes parsed here, not what the file holds at report time
    return dataclasses.replace(scenario_from_dict(raw, base=path.parent, path=path),
                               sha256=hashlib.sha256(data).hexdigest())


_TOP = ("name", "description", "model", "object", "grippers", "support", "actions", "task",
        "limits", "uncertainty", "cost", "sparse", "servos", "feasibility")


def _servos(raw: Mapping[str, Any]) -> Servos:
    """``[servos]``: ``kp``/``kv`` for every torque motor on a joint, and/or
    ``[servos.<actuator>]`` tables with their own."""
    table = _get(raw, "servos", dict, "scenario", {})

    def gains(t: Mapping[str, Any], where: str) -> ServoGains:
        _keys(t, where, ("kp", "kv"))
        kp = _number(t, "kp", where, positive=True)
        kv = _number(t, "kv", where)
        if kv < 0:
            raise ScenarioError(f"{where} kv: expected a damping >= 0, got {kv!r}")
        return ServoGains(kp=kp, kv=kv)

    per = {k: v for k, v in table.items() if isinstance(v, Mapping)}
    flat = {k: v for k, v in table.items() if k not in per}
    default = None
    if flat:
        _keys(flat, "[servos]", ("kp", "kv"))
        if "kp" not in flat or "kv" not in flat:
            raise ScenarioError("[servos]: expected both kp and kv (the default gains of every "
                                "torque motor on a joint), or [servos.<actuator>] tables only")
        default = gains(flat, "[servos]")
    return Servos(default=default,
                  gains={k: gains(v, f"[servos.{k}]") for k, v in per.items()})


def scenario_from_dict(raw: Mapping[str, Any], *, base: Path, path: Path | None = None) -> Scenario:
    """Build a Scenario from the parsed TOML tables (paths relative to ``base``)."""
    _keys(raw, "scenario", _TOP)
    model_t = _get(raw, "model", dict, "scenario")
    _keys(model_t, "[model]", ("mjcf", "keyframe"))
    given = _get(model_t, "mjcf", str, "[model]")
    mjcf = base / given
    if not mjcf.exists() and path is not None and path.is_symlink():
        # a linked scenario.toml: its model lies beside the file the link points to
        real = path.resolve().parent / given
        if real.exists():
            mjcf = real
    keyframe = _get(model_t, "keyframe", (str, int), "[model]", None)
    object_t = _get(raw, "object", dict, "scenario")
    _keys(object_t, "[object]", ("body", "geom", "settle"))
    object_body = _get(object_t, "body", str, "[object]")

    unc = _get(raw, "uncertainty", dict, "scenario")
    if not unc:
        raise ScenarioError("[uncertainty]: expected at least one parameter table")
    box = UncertaintyBox(tuple(_parameter(n, s) for n, s in unc.items()))

    servos = _servos(raw)
    spec = prepare_spec(mjcf, object_body=object_body, servos=servos, **_spec_targets(box))
    model = compile_spec(spec, mjcf)
    box = _with_units(box, model)
    object_geom = _object_geom(object_t, model, object_body)
    key_id = None
    if isinstance(keyframe, int) and 0 <= keyframe < model.nkey:
        key_id = keyframe
    elif isinstance(keyframe, str) and mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY,
                                                         keyframe) >= 0:
        key_id = model.key(keyframe).id

    grippers_t = _get(raw, "grippers", dict, "scenario")
    if not grippers_t:
        raise ScenarioError("[grippers]: expected at least one [grippers.<name>] table")
    grippers = tuple(_gripper_from_table(n, t, model) for n, t in grippers_t.items())
    support_t = _get(raw, "support", dict, "scenario")
    _keys(support_t, "[support]", ("geoms", "bodies"))
    support = list(_names(support_t, "geoms", "[support]", None) or ())
    for body in _names(support_t, "bodies", "[support]", None) or ():
        support.extend(g for g in _subtree_geoms(model, body, "[support] bodies")
                       if g not in support)
    if not support:
        raise ScenarioError("[support]: expected geoms = [names] and/or bodies = [names] of the "
                            "supports (table, bin, floor)")
    # check geom names before the actuator probes use them
    geom_names = {model.geom(i).name for i in range(model.ngeom)}
    for g in grippers:
        for geom in g.geoms:
            if geom not in geom_names:
                raise ScenarioError(f"[grippers.{g.name}] geoms: unknown geom {geom!r}; valid "
                                    f"names: {_listing(sorted(geom_names))}")

    resolver = _ActuatorResolver(model)
    actions_t = _get(raw, "actions", dict, "scenario")
    convention = actions_t.get("convention", "aloha14")
    if not isinstance(convention, str) or convention not in _CONVENTIONS:
        raise ScenarioError(
            f"[actions] convention: expected one of {sorted(_CONVENTIONS)}, got {convention!r}")
    if convention == "explicit":
        actions = _explicit(actions_t, resolver.one, model, grippers, key_id)
    else:
        actions = _aloha14(actions_t, resolver.one)
    _check_channel_kinds(actions, resolver)
    _check_gripper_controls(actions, model)
    fps = _number(actions_t, "fps", "[actions]", 50.0, positive=True)
    policy = _get(actions_t, "range_policy", str, "[actions]", "error")
    if policy not in ("error", "clip", "warn"):
        raise ScenarioError(f"[actions] range_policy: expected error, clip or warn, got {policy!r}")

    def site_position(name):
        sid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SITE, name)
        if sid < 0:
            sites = [model.site(i).name for i in range(model.nsite)]
            raise ScenarioError(f"[task] goal_site: unknown site {name!r}; valid: {_listing(sites)}")
        _check_goal_site_fixed(model, sid)
        data = mujoco.MjData(model)
        if key_id is not None:
            mujoco.mj_resetDataKeyframe(model, data, key_id)
        mujoco.mj_kinematics(model, data)
        return data.site_xpos[sid].copy()

    if "task" not in raw:
        raise ScenarioError("scenario: missing [task] table; expected kind = one of handover, "
                            "pick_place, pick_hold (critmoment never guesses the task)")
    task = task_from_table(raw["task"], [g.name for g in grippers], resolve_site=site_position)
    task = dataclasses.replace(task, up=tuple(float(v) + 0.0 for v in -_down(model)))
    if task.kind in ("pick_place", "pick_hold"):  # (a hand-over's success needs no lift)
        holder = next(g for g in grippers if g.name == task.gripper)
        _check_lift_reach(model, task.lift_height, holder, object_body, key_id)
        if task.kind == "pick_place":
            _check_goal_reach(model, task.goal, holder, object_body, key_id,
                              slack=task.tolerance)

    limits_t = _get(raw, "limits", dict, "scenario", {})
    limits, sources = _resolve_limits(limits_t, resolver)
    cost_t = _get(raw, "cost", dict, "scenario", {})
    _keys(cost_t, "[cost]", ("A", "B", "alpha", "beta", "threshold"))
    cost = CostParams(**{k: _number(cost_t, k, "[cost]") for k in cost_t})
    sparse_t = _get(raw, "sparse", dict, "scenario", {})
    _keys(sparse_t, "[sparse]", ("horizon", "persistence", "slip_tolerance", "creep_horizon"))
    sparse = SparseSettings(
        horizon=_get(sparse_t, "horizon", int, "[sparse]", 1),
        persistence=_number(sparse_t, "persistence", "[sparse]", 0.02),
        slip_tolerance=_number(sparse_t, "slip_tolerance", "[sparse]", 0.005),
        creep_horizon=_get(sparse_t, "creep_horizon", int, "[sparse]", 0))
    feas_t = _get(raw, "feasibility", dict, "scenario", {})
    _keys(feas_t, "[feasibility]", tuple(f.name for f in dataclasses.fields(FeasibilityOptions)))
    feasibility = FeasibilityOptions(**{
        k: (_get(feas_t, k, bool, "[feasibility]") if k == "check_grippers"
            else _number(feas_t, k, "[feasibility]")) for k in feas_t})
    scenario = Scenario(
        name=str(_get(raw, "name", str, "scenario", base.name)), path=path, mjcf=mjcf,
        keyframe=keyframe, object_body=object_body, object_geom=object_geom,
        grippers=grippers, support_geoms=tuple(support), actions=actions, fps=fps,
        fps_given="fps" in actions_t, range_policy=policy, task=task, limits=limits, box=box, cost=cost, sparse=sparse,
        limit_sources=sources, description=str(_get(raw, "description", str, "scenario", "")),
        settle=_get(object_t, "settle", bool, "[object]", True), servos=servos,
        feasibility=feasibility)
    scenario.validate_names(model)
    for p in box.parameters:
        if isinstance(p, MassParameter):
            in_mjcf = float(model.body_mass[p.resolve(model)])
            if in_mjcf > 0 and p.low >= 100.0 * in_mjcf:
                warnings.warn(
                    f"[uncertainty.{p.name}] range: {p.low:g}..{p.high:g} kg, at least 100 "
                    f"times the body's {in_mjcf:g} kg in the MJCF; is the range in grams? "
                    f"(expected kg)", ScenarioWarning, stacklevel=2)
    idle = scenario.undriven_actuators(model)
    if idle:
        warnings.warn(
            f"[actions]: no channel drives actuator(s) {list(idle)}: their control stays 0 "
            f"for the whole trajectory (a position actuator then pulls its joint to 0); add "
            f"them to [[actions.channel]] if the policy commands them", ScenarioWarning,
            stacklevel=2)
    return scenario
