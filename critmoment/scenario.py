"""Scenario: which model, object, grippers, limits, uncertainty box and cost.

A scenario is a TOML file beside an MJCF model (see ``docs/formats.md``). Every
field is validated on load, and every name (body, geom, actuator) is checked
against the compiled model, with the valid names listed when one is unknown.
"""

from __future__ import annotations

import dataclasses
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from critmoment.exceptions import InputFileError, ParameterError, ScenarioError
from critmoment.params import PARAMETER_KINDS, Parameter, Prior, UncertaintyBox

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

__all__ = [
    "CostParams",
    "Gripper",
    "ActionConvention",
    "Scenario",
    "load_scenario",
    "bundled_scenario_path",
    "BUNDLED_SCENARIOS",
]

#: scenarios shipped with critmoment, by name
BUNDLED_SCENARIOS = ("aloha_transfer_cube",)


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
            if not (np.isfinite(value) and value > 0):
                raise ScenarioError(f"[cost] {key}: expected a finite number > 0, got {value!r}")


@dataclasses.dataclass(frozen=True)
class Gripper:
    """A gripper: a name and the geoms that touch the object."""

    name: str
    geoms: tuple[str, ...]


@dataclasses.dataclass(frozen=True)
class ActionConvention:
    """How one action vector maps to actuator controls.

    Each channel drives one or more actuators: ``ctrl[a] = offset[a] + scale[a]·action[c]``.
    Channels marked ``normalised`` are bounded to [0, 1] (grippers); the others are joint
    targets bounded by their joint's range.

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


_ARM_JOINTS = ("waist", "shoulder", "elbow", "forearm_roll", "wrist_angle", "wrist_rotate")


def _aloha14(table: Mapping[str, Any]) -> ActionConvention:
    arms = table.get("arms", ["left", "right"])
    close = float(table.get("gripper_close", 0.01844))
    open_ = float(table.get("gripper_open", 0.05800))
    if not (isinstance(arms, list) and len(arms) == 2 and all(isinstance(a, str) for a in arms)):
        raise ScenarioError(f"[actions] arms: expected two arm prefixes, got {arms!r}")
    if not open_ > close:
        raise ScenarioError(
            f"[actions] expected gripper_open > gripper_close, got {open_} <= {close}")
    channels, scales, offsets, normalised, labels = [], [], [], [], []
    span = open_ - close
    for arm in arms:
        for joint in _ARM_JOINTS:
            channels.append((f"{arm}/{joint}",))
            scales.append((1.0,))
            offsets.append((0.0,))
            normalised.append(False)
            labels.append(f"{arm}/{joint}")
        channels.append((f"{arm}/left_finger", f"{arm}/right_finger"))
        scales.append((span, -span))
        offsets.append((close, -close))
        normalised.append(True)
        labels.append(f"{arm}/gripper")
    return ActionConvention("aloha14", tuple(channels), tuple(scales), tuple(offsets),
                            tuple(normalised), tuple(labels))


def _explicit(table: Mapping[str, Any]) -> ActionConvention:
    entries = table.get("channel")
    if not isinstance(entries, list) or not entries:
        raise ScenarioError(
            "[actions] convention = 'explicit' expects [[actions.channel]] tables with "
            "'actuators' (list), optional 'scales', 'offsets', 'normalised'")
    channels, scales, offsets, normalised, labels = [], [], [], [], []
    for i, entry in enumerate(entries):
        acts = entry.get("actuators")
        if not isinstance(acts, list) or not acts:
            raise ScenarioError(f"[[actions.channel]] #{i}: expected a list 'actuators', got {acts!r}")
        n = len(acts)
        sc = entry.get("scales", [1.0] * n)
        of = entry.get("offsets", [0.0] * n)
        if len(sc) != n or len(of) != n:
            raise ScenarioError(
                f"[[actions.channel]] #{i}: expected {n} scales and offsets, got {len(sc)}, {len(of)}")
        channels.append(tuple(acts))
        scales.append(tuple(float(s) for s in sc))
        offsets.append(tuple(float(o) for o in of))
        normalised.append(bool(entry.get("normalised", False)))
        labels.append(str(entry.get("label", acts[0])))
    return ActionConvention("explicit", tuple(channels), tuple(scales), tuple(offsets),
                            tuple(normalised), tuple(labels))


_CONVENTIONS = {"aloha14": _aloha14, "explicit": _explicit}


@dataclasses.dataclass(frozen=True)
class Scenario:
    """A validated scenario.

    Attributes:
        name: short name.
        path: the scenario file, or None when built in code.
        mjcf: the MJCF scene file.
        keyframe: keyframe name for the initial arm pose, or None for qpos0.
        object_body: the body whose safety is audited.
        object_geom: its collision geom.
        grippers: the grippers, in signal order.
        support_geoms: geoms of the support (table).
        actions: the action convention.
        fps: action rate [Hz] when the trajectory does not say.
        range_policy: "error", "clip" or "warn" for targets outside joint ranges.
        picker: gripper that lifts the object first (task stages 1–2).
        receiver: gripper that takes it over (stages 3–4).
        limits: force limit per actuator name [N·m or N].
        box: the uncertainty box.
        cost: cost constants.
        horizon: physics steps per sparse evaluation.
        description: free text.
    """

    name: str
    path: Path | None
    mjcf: Path
    keyframe: str | None
    object_body: str
    object_geom: str
    grippers: tuple[Gripper, ...]
    support_geoms: tuple[str, ...]
    actions: ActionConvention
    fps: float
    range_policy: str
    picker: str
    receiver: str
    limits: Mapping[str, float]
    box: UncertaintyBox
    cost: CostParams
    horizon: int = 1
    description: str = ""

    @property
    def gripper_names(self) -> tuple[str, ...]:
        return tuple(g.name for g in self.grippers)

    def replace(self, **changes) -> Scenario:
        """A copy with fields replaced (e.g. ``box=scenario.box.with_range(...)``)."""
        return dataclasses.replace(self, **changes)

    def load_model(self) -> mujoco.MjModel:
        """Compile the scenario's MJCF (without critmoment's sensors)."""
        try:
            return mujoco.MjModel.from_xml_path(str(self.mjcf))
        except ValueError as exc:
            raise ScenarioError(f"could not compile MJCF {self.mjcf}: {exc}") from exc

    def validate_names(self, model: mujoco.MjModel) -> None:
        """Check every name against ``model``; raise ScenarioError listing valid names."""
        def names(objtype, count):
            return [mujoco.mj_id2name(model, objtype, i) or "" for i in range(count)]

        bodies = names(mujoco.mjtObj.mjOBJ_BODY, model.nbody)
        geoms = names(mujoco.mjtObj.mjOBJ_GEOM, model.ngeom)
        actuators = names(mujoco.mjtObj.mjOBJ_ACTUATOR, model.nu)

        def need(name, pool, what, where):
            if name not in pool:
                raise ScenarioError(
                    f"{where}: unknown {what} {name!r}; valid names: "
                    + ", ".join(n for n in pool if n))

        need(self.object_body, bodies, "body", "[object] body")
        need(self.object_geom, geoms, "geom", "[object] geom")
        body = model.body(self.object_body)
        if body.jntnum[0] != 1 or model.jnt_type[body.jntadr[0]] != mujoco.mjtJoint.mjJNT_FREE:
            raise ScenarioError(
                f"[object] body: expected a body with one free joint, got {self.object_body!r} "
                f"with {body.jntnum[0]} joint(s)")
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
        for channel in self.actions.channels:
            for act in channel:
                need(act, actuators, "actuator", "[actions]")
        for act in self.limits:
            need(act, actuators, "actuator", "[limits]")
        if self.keyframe is not None and mujoco.mj_name2id(
                model, mujoco.mjtObj.mjOBJ_KEY, self.keyframe) < 0:
            keys = names(mujoco.mjtObj.mjOBJ_KEY, model.nkey)
            raise ScenarioError(
                f"[model] keyframe: unknown keyframe {self.keyframe!r}; valid: {keys}")
        for p in self.box.parameters:
            p.resolve(model)
        if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, self.object_geom) >= 0:
            obj = model.geom(self.object_geom)
            for p in self.box.parameters:
                if p.target == self.object_geom and p.fields == ("geom_friction",):
                    others = [i for i in range(model.ngeom)
                              if model.geom_bodyid[i] != obj.bodyid[0]
                              and model.geom_priority[i] >= obj.priority[0]
                              and model.geom_contype[i] | model.geom_conaffinity[i]]
                    if others:
                        raise ScenarioError(
                            f"friction parameter on geom {self.object_geom!r} needs that geom's "
                            f"priority above every geom it touches (MuJoCo mixes friction with "
                            f"max); expected priority > {model.geom_priority[others].max()}, "
                            f"got {obj.priority[0]}")


def _get(table: Mapping[str, Any], key: str, kind, where: str, default=...):
    if key not in table:
        if default is ...:
            raise ScenarioError(f"{where}: missing required key {key!r}")
        return default
    value = table[key]
    if not isinstance(value, kind) or isinstance(value, bool) and kind is not bool:
        raise ScenarioError(f"{where} {key}: expected {getattr(kind, '__name__', kind)}, "
                            f"got {value!r}")
    return value


def _number(table, key, where, default=...):
    return float(_get(table, key, (int, float), where, default))


def _parameter(name: str, spec: Mapping[str, Any]) -> Parameter:
    where = f"[uncertainty.{name}]"
    if not isinstance(spec, Mapping):
        raise ScenarioError(f"{where}: expected a table, got {spec!r}")
    kind = spec.get("kind", name)
    if kind not in PARAMETER_KINDS:
        raise ScenarioError(
            f"{where}: unknown parameter kind {kind!r}; known kinds: {', '.join(PARAMETER_KINDS)} "
            "(set kind = ... when the name is not a kind)")
    cls, target_key = PARAMETER_KINDS[kind]
    target = spec.get(target_key, spec.get("object"))
    if not isinstance(target, str):
        raise ScenarioError(f"{where}: expected {target_key} = \"<name>\", got {target!r}")
    rng = spec.get("range")
    if not (isinstance(rng, list) and len(rng) == 2
            and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in rng)):
        raise ScenarioError(f"{where} range: expected [low, high], got {rng!r}")
    nominal = _number(spec, "nominal", where)
    prior_name = spec.get("prior", "uniform")
    try:
        prior = Prior(prior_name)
    except ValueError:
        raise ScenarioError(
            f"{where} prior: expected one of {[p.value for p in Prior]}, got {prior_name!r}") from None
    try:
        return cls(name=name, target=target, low=float(rng[0]), high=float(rng[1]),
                   nominal=nominal, prior=prior)
    except ParameterError as exc:
        raise ScenarioError(f"{where}: {exc}") from exc


def _resolve_limits(raw: Mapping[str, Any], model: mujoco.MjModel) -> dict[str, float]:
    actuators = [model.actuator(i).name for i in range(model.nu)]
    limits: dict[str, float] = {}
    for key, value in raw.items():
        if not isinstance(value, (int, float)) or isinstance(value, bool) or not value > 0:
            raise ScenarioError(f"[limits] {key}: expected a force limit > 0, got {value!r}")
        matches = [a for a in actuators if a == key or a.rsplit("/", 1)[-1] == key]
        if not matches:
            raise ScenarioError(
                f"[limits] {key!r} matches no actuator; actuators: {', '.join(actuators)}")
        for a in matches:
            limits[a] = float(value)
    missing = [a for a in actuators if a not in limits]
    if missing:
        raise ScenarioError(f"[limits]: expected a force limit for every actuator, missing {missing}")
    return limits


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
        path = bundled_scenario_path(path)
    path = Path(path)
    if path.is_dir():
        path = path / "scenario.toml"
    if not path.is_file():
        raise InputFileError(
            f"scenario file not found: {path} (expected a scenario.toml, a folder with one, or "
            f"a bundled name: {', '.join(BUNDLED_SCENARIOS)})")
    try:
        raw = tomllib.loads(path.read_text())
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise ScenarioError(f"{path}: not valid TOML: {exc}") from exc
    return scenario_from_dict(raw, base=path.parent, path=path)


def scenario_from_dict(raw: Mapping[str, Any], *, base: Path, path: Path | None = None) -> Scenario:
    """Build a Scenario from the parsed TOML tables (paths relative to ``base``)."""
    known = {"name", "description", "model", "object", "grippers", "support", "actions", "task",
             "limits", "uncertainty", "cost", "sparse"}
    unknown = set(raw) - known
    if unknown:
        raise ScenarioError(f"unknown top-level keys {sorted(unknown)}; expected {sorted(known)}")
    model_t = _get(raw, "model", dict, "scenario")
    mjcf = base / _get(model_t, "mjcf", str, "[model]")
    if not mjcf.is_file():
        raise InputFileError(f"[model] mjcf: file not found: {mjcf}")
    object_t = _get(raw, "object", dict, "scenario")
    grippers_t = _get(raw, "grippers", dict, "scenario")
    if not grippers_t:
        raise ScenarioError("[grippers]: expected at least one [grippers.<name>] table")
    grippers = []
    for gname, gt in grippers_t.items():
        geoms = _get(gt, "geoms", list, f"[grippers.{gname}]")
        if not geoms or not all(isinstance(g, str) for g in geoms):
            raise ScenarioError(f"[grippers.{gname}] geoms: expected a list of geom names, got {geoms!r}")
        if len(set(geoms)) != len(geoms):
            raise ScenarioError(f"[grippers.{gname}] geoms: expected each geom once, got {geoms!r}")
        grippers.append(Gripper(gname, tuple(geoms)))
    support = _get(_get(raw, "support", dict, "scenario"), "geoms", list, "[support]")
    if not support or not all(isinstance(g, str) for g in support):
        raise ScenarioError(f"[support] geoms: expected a non-empty list of geom names, got {support!r}")
    actions_t = _get(raw, "actions", dict, "scenario")
    convention = actions_t.get("convention", "aloha14")
    if convention not in _CONVENTIONS:
        raise ScenarioError(
            f"[actions] convention: expected one of {sorted(_CONVENTIONS)}, got {convention!r}")
    actions = _CONVENTIONS[convention](actions_t)
    fps = _number(actions_t, "fps", "[actions]", 50.0)
    if not fps > 0:
        raise ScenarioError(f"[actions] fps: expected > 0, got {fps}")
    policy = actions_t.get("range_policy", "error")
    if policy not in ("error", "clip", "warn"):
        raise ScenarioError(f"[actions] range_policy: expected error, clip or warn, got {policy!r}")
    names = [g.name for g in grippers]
    task_t = raw.get("task", {})
    picker = task_t.get("picker", names[-1])
    receiver = task_t.get("receiver", names[0])
    for role, value in (("picker", picker), ("receiver", receiver)):
        if value not in names:
            raise ScenarioError(f"[task] {role}: expected one of the grippers {names}, got {value!r}")
    unc = _get(raw, "uncertainty", dict, "scenario")
    if not unc:
        raise ScenarioError("[uncertainty]: expected at least one parameter table")
    box = UncertaintyBox(tuple(_parameter(n, s) for n, s in unc.items()))
    cost_t = _get(raw, "cost", dict, "scenario", {})
    unknown_cost = set(cost_t) - {"A", "B", "alpha", "beta", "threshold"}
    if unknown_cost:
        raise ScenarioError(f"[cost]: unknown keys {sorted(unknown_cost)}")
    cost = CostParams(**{k: _number(cost_t, k, "[cost]") for k in cost_t})
    horizon = _get(_get(raw, "sparse", dict, "scenario", {}), "horizon", int, "[sparse]", 1)
    if horizon < 1:
        raise ScenarioError(f"[sparse] horizon: expected an integer >= 1, got {horizon}")
    try:
        model = mujoco.MjModel.from_xml_path(str(mjcf))
    except ValueError as exc:
        raise ScenarioError(f"could not compile MJCF {mjcf}: {exc}") from exc
    limits = _resolve_limits(_get(raw, "limits", dict, "scenario"), model)
    scenario = Scenario(
        name=str(raw.get("name", base.name)), path=path, mjcf=mjcf,
        keyframe=_get(model_t, "keyframe", str, "[model]", None), object_body=_get(object_t, "body", str, "[object]"),
        object_geom=_get(object_t, "geom", str, "[object]"), grippers=tuple(grippers),
        support_geoms=tuple(support), actions=actions, fps=fps, range_policy=policy,
        picker=picker, receiver=receiver, limits=limits, box=box, cost=cost, horizon=horizon,
        description=str(raw.get("description", "")))
    scenario.validate_names(model)
    return scenario
