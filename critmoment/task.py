"""Task definitions: what a trajectory must achieve with the object.

A :class:`Task` gives, in one place, everything that depends on *what the robot is
doing* rather than on the physics:

* the **stage** signal of each physics step (for the report and the moments),
* where the object **must be carried** (the grip's factor of safety counts there),
* the physical **success rule** of a whole run, from plain kinematics and contacts
  (object height, its distance to a goal, which gripper touches it, its speed),
* the words the report uses.

The audit, the verification rollouts, ``validate``'s ground truth and the report all
ask the scenario's task; nothing else hard-codes a task. New kinds are added by
subclassing :class:`Task` and registering the class in :data:`TASK_KINDS`, as
:data:`critmoment.params.PARAMETER_KINDS` does for parameters.

Kinds:

``handover``
    ACT's transfer-cube reward: 1 the picker touches the object, 2 and it is off the
    support, 3 the receiver touches it, 4 and it is off the support. Success: the
    receiver holds the object off every support at the end.
``pick_place``
    1 touched, 2 carried (touched, off the support), 3 placed (on a support within
    ``tolerance`` of the goal, still touched), 4 released (within ``tolerance`` of the
    goal, untouched). Success: the object was lifted at least ``lift_height`` above its
    start, and at the end lies within ``tolerance`` of the goal, released and at rest
    (speed below ``rest_speed``). A release onto a support at the goal is not a drop.
``pick_hold``
    1 touched, 2 held off the support. Success: lifted at least ``lift_height`` and still
    held off every support by the gripper at the end.

"Off the support" and "touched" are read over a final window of ``settle_time`` so that
contact chatter of a firm grasp (a contact flag that flickers for a step) does not
decide a run. A run that starts with the object already carried (touched by a gripper at
its first step and off every support over its first ``settle_time``: an action chunk
audited mid-carry) starts lifted: its object was lifted before the chunk began, and may only go down from there.
"""

from __future__ import annotations

import dataclasses
import warnings
from collections.abc import Mapping, Sequence
from typing import Any, ClassVar

import numpy as np

from critmoment.exceptions import CritmomentWarning, ScenarioError

__all__ = [
    "TaskEvidence",
    "Task",
    "HandoverTask",
    "PickPlaceTask",
    "PickHoldTask",
    "TASK_KINDS",
    "task_from_table",
]


#: a gripper whose last touch of the object came more than this before the end [s] ...
END_GAP = 0.01
#: ... while the object moves down faster than this [m/s] has let it fall: it does not hold
#: it at the end (a PiPER's cube that left its fingers 14 ms before the end, falling, was
#: "held" by a touch anywhere in the final window; a hold whose contact flickers at rest
#: still holds)
END_FALL_SPEED = 0.05


@dataclasses.dataclass(frozen=True)
class TaskEvidence:
    """What a run shows of the object, step by step, with leading shape (..., T).

    Attributes:
        contact_gripper: the object touches gripper g, (..., T, G) bool.
        contact_support: the object touches a support geom, (..., T) bool.
        object_pos: the object's position in the world [m], (..., T, 3).
        object_vel: the object's linear velocity in the world [m/s], (..., T, 3).
        dt: physics step [s].
        base_axis: the up axes of the robot's free-floating bases in the world, (..., T, B,
            3), or None (a robot fixed to the world, or a run that does not record them).
    """

    contact_gripper: np.ndarray
    contact_support: np.ndarray
    object_pos: np.ndarray
    object_vel: np.ndarray
    dt: float
    base_axis: np.ndarray | None = None

    def __post_init__(self):
        cg = np.asarray(self.contact_gripper, dtype=bool)
        cs = np.asarray(self.contact_support, dtype=bool)
        pos = np.asarray(self.object_pos, dtype=np.float64)
        vel = np.asarray(self.object_vel, dtype=np.float64)
        lead = cs.shape
        if cg.shape[:-1] != lead or pos.shape != lead + (3,) or vel.shape != lead + (3,):
            raise ScenarioError(
                f"task evidence: expected contact_gripper (..., T, G), contact_support (..., T), "
                f"object_pos and object_vel (..., T, 3) with one leading shape, got "
                f"{cg.shape}, {cs.shape}, {pos.shape}, {vel.shape}")
        if not (np.isfinite(self.dt) and self.dt > 0):
            raise ScenarioError(f"task evidence: expected a physics step dt > 0 s, got {self.dt}")
        object.__setattr__(self, "contact_gripper", cg)
        object.__setattr__(self, "contact_support", cs)
        object.__setattr__(self, "object_pos", pos)
        object.__setattr__(self, "object_vel", vel)
        if self.base_axis is not None:
            axis = np.asarray(self.base_axis, dtype=np.float64)
            if axis.ndim != len(lead) + 2 or axis.shape[:len(lead)] != lead or axis.shape[-1] != 3:
                raise ScenarioError(f"task evidence: expected base_axis (..., T, B, 3) with the "
                                    f"contacts' leading shape {lead}, got {axis.shape}")
            object.__setattr__(self, "base_axis", axis)

    @property
    def n_steps(self) -> int:
        return int(self.contact_support.shape[-1])

    def window(self, seconds: float) -> int:
        """Steps in a final window of ``seconds`` (at least 1, at most T)."""
        return int(min(max(1, round(seconds / self.dt)), max(1, self.n_steps)))


@dataclasses.dataclass(frozen=True)
class Task:
    """Base class of task kinds (see the module docstring).

    Attributes:
        grippers: names of the scenario's grippers, in signal order.
        lift_height: least rise of the object above its start that counts as a lift [m].
        settle_time: final window over which contacts are read for the success rule [s].
        up: the world's up direction, against gravity (set from the model when a scenario
            loads: a model with gravity along −y lifts along +y).
        max_base_tilt: how far a free-floating robot base may tilt from its start [deg]: a
            run that tips the robot further has failed its task, whatever the object does
            (a 5 kg cart that tipped 10-15° under a heavy cube and fell back had placed it).
    """

    grippers: tuple[str, ...]
    lift_height: float = 0.02
    settle_time: float = 0.05
    up: tuple[float, float, float] = dataclasses.field(default=(0.0, 0.0, 1.0),
                                                       metadata={"json": False})
    max_base_tilt: float = 5.0

    kind: ClassVar[str] = ""
    stage_names: ClassVar[tuple[str, ...]] = ()
    #: keys the scenario's [task] table may hold for this kind (besides ``kind``)
    keys: ClassVar[tuple[str, ...]] = ("lift_height", "settle_time", "max_base_tilt")

    def __post_init__(self):
        grippers = self.grippers
        if (isinstance(grippers, str) or not isinstance(grippers, (tuple, list)) or not grippers
                or not all(isinstance(g, str) and g for g in grippers)
                or len(set(grippers)) != len(grippers)):
            raise ScenarioError(f"[task] grippers: expected the names of the scenario's grippers "
                                f"(distinct non-empty strings), got {grippers!r}")
        object.__setattr__(self, "grippers", tuple(grippers))
        for key in ("lift_height", "settle_time", "max_base_tilt"):
            _set_real(self, key, lower=0.0, strict=False)
        up = _vector(self.up, "up")
        norm = float(np.linalg.norm(up))
        if not norm > 0:
            raise ScenarioError(f"[task] up: expected a non-zero direction (x, y, z), got {self.up!r}")
        object.__setattr__(self, "up", tuple(float(v) / norm + 0.0 for v in up))

    def _check_role(self, key: str) -> None:
        """The field ``key`` names one of :attr:`grippers`."""
        value = getattr(self, key)
        if not isinstance(value, str) or value not in self.grippers:
            raise ScenarioError(f"[task] {key}: expected one of the grippers "
                                f"{list(self.grippers)}, got {value!r}")

    # -- per step ------------------------------------------------------------------
    def stage(self, contact_gripper: np.ndarray, contact_support: np.ndarray,
              object_pos: np.ndarray) -> np.ndarray:
        """The task stage of each step, (...) int8, from (..., G), (...), (..., 3)."""
        raise NotImplementedError

    def must_carry(self, contact_gripper: np.ndarray, contact_support: np.ndarray) -> np.ndarray:
        """Where a gripper carries the object (off every support, touched), (...) bool.

        The grip's factor of safety counts only there.
        """
        return ~np.asarray(contact_support, bool) & np.asarray(contact_gripper, bool).any(axis=-1)

    @property
    def final_stage(self) -> int:
        """The stage a successful run ends in."""
        return len(self.stage_names) - 1

    # -- whole runs ---------------------------------------------------------------
    def success(self, ev: TaskEvidence) -> np.ndarray:
        """Whether each run achieved the task, (...) bool."""
        raise NotImplementedError

    def shortfalls(self, ev: TaskEvidence) -> list[str]:
        """What one run (evidence with no leading shape) lacks of :meth:`success`, each part
        of the rule it misses in words with the value measured; empty when it succeeds."""
        raise NotImplementedError

    def _rise(self, ev: TaskEvidence) -> np.ndarray:
        """The object's largest rise above its start along ``up`` [m], (...); 0 for a run
        with no step."""
        z = np.asarray(ev.object_pos) @ np.asarray(self.up, dtype=float)
        if z.shape[-1] == 0:
            return np.zeros(z.shape[:-1])
        return z.max(axis=-1) - z[..., 0]

    def _lift_shortfall(self, ev: TaskEvidence) -> list[str]:
        if bool(self.lifted(ev)):
            return []
        return [f"the object rose {float(self._rise(ev)) * 1e3:.0f} mm at most (a lift is "
                f"{self.lift_height * 1e3:.0f} mm)"]

    def _held_at_end(self, touch: np.ndarray, ev: TaskEvidence) -> np.ndarray:
        """The gripper whose contacts are ``touch`` (..., T) holds the object at the end,
        (...) bool: it touches it within the final ``settle_time``, and either at most
        :data:`END_GAP` before the end or with the object not falling (moving down slower
        than :data:`END_FALL_SPEED` at the last step)."""
        touch = np.asarray(touch, dtype=bool)
        recent = self._final(touch, ev, "any")
        if ev.n_steps == 0:
            return recent
        gap = np.argmax(touch[..., ::-1], axis=-1) * ev.dt  # since the last touch [s]
        return recent & ((gap <= END_GAP + 1e-12) | (self._falling(ev) < END_FALL_SPEED))

    def _falling(self, ev: TaskEvidence) -> np.ndarray:
        """How fast the object moves down at the last step [m/s], (...) (``up`` is a unit
        vector)."""
        return -(np.asarray(ev.object_vel)[..., -1, :] @ np.asarray(self.up, dtype=np.float64))

    def _base_tilt(self, ev: TaskEvidence) -> np.ndarray:
        """The largest tilt of a free-floating robot base from its first step [deg], (...);
        0 without one."""
        axis = ev.base_axis
        if axis is None or axis.shape[-2] == 0 or axis.shape[-3] == 0:
            return np.zeros(ev.contact_support.shape[:-1])
        cos = np.sum(axis * axis[..., :1, :, :], axis=-1) / np.maximum(
            np.linalg.norm(axis, axis=-1) * np.linalg.norm(axis[..., :1, :, :], axis=-1), 1e-12)
        return np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))).max(axis=(-2, -1))

    def upright(self, ev: TaskEvidence) -> np.ndarray:
        """No free-floating robot base tilts more than :attr:`max_base_tilt` from its
        start, (...) bool (true for a robot fixed to the world)."""
        return self._base_tilt(ev) <= self.max_base_tilt

    def _tip_shortfall(self, ev: TaskEvidence) -> list[str]:
        if bool(self.upright(ev)):
            return []
        return [f"the robot's free-floating base tilts {float(self._base_tilt(ev)):.3g}° (the "
                f"task allows {self.max_base_tilt:g}°, [task] max_base_tilt)"]

    def _end_shortfalls(self, ev: TaskEvidence, gripper: str | None, verb: str) -> list[str]:
        """``gripper`` must hold the object (:meth:`_held_at_end`), and no support touch it,
        over the final window."""
        out = []
        if gripper is not None:
            touch = ev.contact_gripper[..., self.grippers.index(gripper)]
            if not bool(self._held_at_end(touch, ev)):
                last = np.flatnonzero(touch)
                # the last touch, not a release: a receiver that only ever touched the
                # object with one finger had "let go" when the picker opened
                when = (f" (it last touched it at t = {(last[-1] + 1) * ev.dt:.2f} s)" if last.size
                        else " (it never touched it)")
                if last.size and bool(self._final(touch, ev, "any")):
                    when = (f" (it last touched it at t = {(last[-1] + 1) * ev.dt:.3f} s, and "
                            f"the object falls at {float(self._falling(ev)):.2g} m/s at the "
                            f"end)")
                out.append(f"{gripper} does not {verb} the object at the end{when}")
        if not bool(self._final(~ev.contact_support, ev, "all")):
            out.append("the object rests on its support at the end")
        return out

    def lifted(self, ev: TaskEvidence) -> np.ndarray:
        """The object rose at least ``lift_height`` above its start at some step, or the run
        starts with it already carried (:meth:`carried_at_start`), (...) bool."""
        if ev.n_steps == 0:
            return np.zeros(ev.contact_support.shape[:-1], dtype=bool)
        return (self._rise(ev) >= self.lift_height) | self.carried_at_start(ev)

    def carried_at_start(self, ev: TaskEvidence) -> np.ndarray:
        """The run starts with the object carried: touched by a gripper at the first step and
        off every support over the first ``settle_time`` (an action chunk that begins
        mid-carry), (...) bool."""
        w = ev.window(self.settle_time)
        touched = ev.contact_gripper[..., 0, :].any(axis=-1)
        return touched & ~ev.contact_support[..., :w].any(axis=-1)

    def _final(self, flags: np.ndarray, ev: TaskEvidence, how: str) -> np.ndarray:
        w = ev.window(self.settle_time)
        tail = np.asarray(flags)[..., -w:]
        return tail.any(axis=-1) if how == "any" else tail.all(axis=-1)

    def describe(self) -> str:
        """One sentence for the report."""
        raise NotImplementedError

    def to_json(self) -> dict[str, Any]:
        out: dict[str, Any] = {"kind": self.kind, "stages": list(self.stage_names),
                               "description": self.describe()}
        for f in dataclasses.fields(self):
            if not f.metadata.get("json", True):
                continue
            value = getattr(self, f.name)
            out[f.name] = list(value) if isinstance(value, tuple) else value
        return out

    # -- construction ------------------------------------------------------------
    @classmethod
    def from_table(cls, table: Mapping[str, Any], grippers: Sequence[str],
                   resolve_site=None) -> Task:
        """Build from the scenario's ``[task]`` table (``kind`` already checked)."""
        raise NotImplementedError


def _is_real(value: Any) -> bool:
    """A real number (Python or NumPy), not a bool (``True`` is 1 to Python, never to a
    scenario; the scenario's checks use this one too)."""
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(
        value, (bool, np.bool_))


def _set_real(task: Task, key: str, *, lower: float, strict: bool) -> None:
    """Check that the field ``key`` is a finite real number above ``lower`` (``>`` when
    ``strict``, else ``>=``) and store it as a float."""
    value = getattr(task, key)
    try:
        number = float(value) if _is_real(value) else float("nan")
    except OverflowError:
        number = float("nan")
    if not (np.isfinite(number) and (number > lower if strict else number >= lower)):
        raise ScenarioError(f"[task] {key}: expected a finite number {'>' if strict else '>='} "
                            f"{lower:g}, got {value!r}")
    object.__setattr__(task, key, number)


def _vector(value: Any, key: str) -> np.ndarray:
    """Three finite real numbers, (3,)."""
    try:
        ok = not isinstance(value, (str, bytes)) and len(value) == 3 and all(
            _is_real(v) for v in value)
        out = np.asarray([float(v) for v in value]) if ok else None
    except (TypeError, OverflowError):
        out = None
    if out is None or not np.isfinite(out).all():
        raise ScenarioError(f"[task] {key}: expected (x, y, z), three finite numbers in metres "
                            f"(world frame), got {value!r}")
    return out


def _number(table: Mapping[str, Any], key: str, default: float) -> float:
    value = table.get(key, default)
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not np.isfinite(value):
        raise ScenarioError(f"[task] {key}: expected a finite number, got {value!r}")
    return float(value)


def _gripper(table: Mapping[str, Any], key: str, grippers: Sequence[str], kind: str) -> str:
    if key not in table:
        if len(grippers) == 1:
            return grippers[0]
        raise ScenarioError(
            f"[task] {key}: kind {kind!r} with several grippers needs {key} = one of "
            f"{list(grippers)}, got none")
    value = table[key]
    if value not in grippers:
        raise ScenarioError(f"[task] {key}: expected one of the grippers {list(grippers)}, "
                            f"got {value!r}")
    return value


@dataclasses.dataclass(frozen=True)
class HandoverTask(Task):
    """ACT's transfer-cube task: the picker lifts the object, the receiver takes it over.

    Attributes:
        picker: the gripper that lifts the object first (stages 1–2).
        receiver: the gripper that holds it at the end (stages 3–4).
    """

    picker: str = ""
    receiver: str = ""

    kind: ClassVar[str] = "handover"
    stage_names: ClassVar[tuple[str, ...]] = (
        "untouched", "picker touches", "picker lifts", "receiver touches", "receiver holds")
    keys: ClassVar[tuple[str, ...]] = ("picker", "receiver", "lift_height", "settle_time",
                                       "max_base_tilt")

    def __post_init__(self):
        super().__post_init__()
        for role in ("picker", "receiver"):
            self._check_role(role)
        if self.picker == self.receiver:
            raise ScenarioError(
                f"[task] handover: expected two different grippers for picker and receiver, "
                f"got {self.picker!r} for both (a single-arm task is kind = \"pick_place\" or "
                f"\"pick_hold\")")

    def stage(self, contact_gripper, contact_support, object_pos):
        cg = np.asarray(contact_gripper, bool)
        off = ~np.asarray(contact_support, bool)
        pick = cg[..., self.grippers.index(self.picker)]
        recv = cg[..., self.grippers.index(self.receiver)]
        stage = np.zeros(off.shape, dtype=np.int8)
        stage[pick] = 1
        stage[pick & off] = 2
        stage[recv] = 3
        stage[recv & off] = 4
        return stage

    def success(self, ev):
        recv = ev.contact_gripper[..., self.grippers.index(self.receiver)]
        return (self._held_at_end(recv, ev) & self._final(~ev.contact_support, ev, "all")
                & self.upright(ev))

    def shortfalls(self, ev):
        return self._end_shortfalls(ev, self.receiver, "hold") + self._tip_shortfall(ev)

    def describe(self):
        return (f"hand-over: {self.picker} lifts the object off its support, {self.receiver} "
                f"takes it over and holds it off the support to the end")

    @classmethod
    def from_table(cls, table, grippers, resolve_site=None):
        if "lift_height" in table:
            # kept for files that set it, but nothing reads it: say so
            warnings.warn("[task] lift_height: a hand-over's success is the receiver holding "
                          "the object off every support at the end, which needs no lift "
                          "height; the value is not used", CritmomentWarning, stacklevel=3)
        return cls(grippers=tuple(grippers), picker=_gripper(table, "picker", grippers, cls.kind),
                   receiver=_gripper(table, "receiver", grippers, cls.kind),
                   lift_height=_number(table, "lift_height", 0.02),
                   settle_time=_number(table, "settle_time", 0.05),
                   max_base_tilt=_number(table, "max_base_tilt", 5.0))


@dataclasses.dataclass(frozen=True)
class PickPlaceTask(Task):
    """Pick the object up, carry it, place it at a goal and release it there.

    Attributes:
        gripper: the gripper that carries the object.
        goal: where the object's body frame (its origin, as object_pose gives it) must end [m], (3,).
        tolerance: largest distance of the object's body frame from the goal [m].
        rest_speed: largest speed of the object at the end [m/s].
    """

    gripper: str = ""
    goal: tuple[float, float, float] = (0.0, 0.0, 0.0)
    tolerance: float = 0.03
    rest_speed: float = 0.05

    kind: ClassVar[str] = "pick_place"
    stage_names: ClassVar[tuple[str, ...]] = ("untouched", "touched", "carried", "placed",
                                              "released")
    keys: ClassVar[tuple[str, ...]] = ("gripper", "goal", "goal_site", "tolerance",
                                       "rest_speed", "lift_height", "settle_time",
                                       "max_base_tilt")

    def __post_init__(self):
        super().__post_init__()
        self._check_role("gripper")
        object.__setattr__(self, "goal", tuple(float(v) for v in _vector(self.goal, "goal")))
        for key in ("tolerance", "rest_speed"):
            _set_real(self, key, lower=0.0, strict=True)

    def _at_goal(self, object_pos):
        return np.linalg.norm(np.asarray(object_pos) - np.asarray(self.goal), axis=-1) \
            <= self.tolerance

    def stage(self, contact_gripper, contact_support, object_pos):
        cg = np.asarray(contact_gripper, bool)
        on = np.asarray(contact_support, bool)
        touch = cg[..., self.grippers.index(self.gripper)]
        at_goal = self._at_goal(object_pos)
        stage = np.zeros(on.shape, dtype=np.int8)
        stage[touch] = 1
        stage[touch & ~on] = 2
        stage[touch & on & at_goal] = 3
        stage[~cg.any(axis=-1) & at_goal] = 4
        return stage

    def success(self, ev):
        touch = ev.contact_gripper.any(axis=-1)
        released = ~self._final(touch, ev, "any")
        at_goal = self._final(self._at_goal(ev.object_pos), ev, "all")
        speed = np.linalg.norm(ev.object_vel[..., -1, :], axis=-1) if ev.n_steps else 0.0
        return (self.lifted(ev) & at_goal & released & (speed <= self.rest_speed)
                & self.upright(ev))

    def shortfalls(self, ev):
        out = self._lift_shortfall(ev) + self._tip_shortfall(ev)
        if not bool(self._final(self._at_goal(ev.object_pos), ev, "all")):
            distance = np.linalg.norm(ev.object_pos - np.asarray(self.goal), axis=-1)
            at = np.flatnonzero(distance <= self.tolerance)
            since = (f"; it was within it until t = {(at[-1] + 1) * ev.dt:.2f} s" if at.size
                     else "")
            out.append(f"the object ends {distance[-1] * 1e3:.0f} mm from the goal (tolerance "
                       f"{self.tolerance * 1e3:.0f} mm{since})")
        touch = ev.contact_gripper.any(axis=-1)
        if bool(self._final(touch, ev, "any")):
            out.append("a gripper still touches the object at the end")
        speed = float(np.linalg.norm(ev.object_vel[-1])) if ev.n_steps else 0.0
        if speed > self.rest_speed:
            out.append(f"the object still moves at {speed:.3g} m/s at the end (at rest: "
                       f"{self.rest_speed:g} m/s)")
        return out

    def describe(self):
        g = ", ".join(f"{v:.3f}" for v in self.goal)
        return (f"pick and place: {self.gripper} lifts the object at least "
                f"{self.lift_height * 1e3:.0f} mm, places it within {self.tolerance * 1e3:.0f} mm "
                f"of ({g}) m and releases it at rest")

    @classmethod
    def from_table(cls, table, grippers, resolve_site=None):
        if ("goal" in table) == ("goal_site" in table):
            raise ScenarioError(
                "[task] pick_place: expected exactly one of goal = [x, y, z] (world [m]) or "
                f"goal_site = \"<site name>\", got {sorted(k for k in table if 'goal' in k)}")
        if "goal" in table:
            goal = table["goal"]
            if not (isinstance(goal, list) and len(goal) == 3 and all(
                    isinstance(v, (int, float)) and not isinstance(v, bool) and np.isfinite(v)
                    for v in goal)):
                raise ScenarioError(f"[task] goal: expected [x, y, z] in metres, got {goal!r}")
            goal = tuple(float(v) for v in goal)
        else:
            site = table["goal_site"]
            if not isinstance(site, str) or resolve_site is None:
                raise ScenarioError(f"[task] goal_site: expected a site name, got {site!r}")
            goal = tuple(float(v) for v in resolve_site(site))
        return cls(grippers=tuple(grippers), gripper=_gripper(table, "gripper", grippers, cls.kind),
                   goal=goal, tolerance=_number(table, "tolerance", 0.03),
                   rest_speed=_number(table, "rest_speed", 0.05),
                   lift_height=_number(table, "lift_height", 0.02),
                   settle_time=_number(table, "settle_time", 0.05),
                   max_base_tilt=_number(table, "max_base_tilt", 5.0))


@dataclasses.dataclass(frozen=True)
class PickHoldTask(Task):
    """Pick the object up and still hold it off its support at the end.

    Attributes:
        gripper: the gripper that holds the object.
    """

    gripper: str = ""

    kind: ClassVar[str] = "pick_hold"
    stage_names: ClassVar[tuple[str, ...]] = ("untouched", "touched", "held")
    keys: ClassVar[tuple[str, ...]] = ("gripper", "lift_height", "settle_time", "max_base_tilt")

    def __post_init__(self):
        super().__post_init__()
        self._check_role("gripper")

    def stage(self, contact_gripper, contact_support, object_pos):
        touch = np.asarray(contact_gripper, bool)[..., self.grippers.index(self.gripper)]
        off = ~np.asarray(contact_support, bool)
        stage = np.zeros(off.shape, dtype=np.int8)
        stage[touch] = 1
        stage[touch & off] = 2
        return stage

    def success(self, ev):
        touch = ev.contact_gripper[..., self.grippers.index(self.gripper)]
        return (self.lifted(ev) & self._held_at_end(touch, ev)
                & self._final(~ev.contact_support, ev, "all") & self.upright(ev))

    def shortfalls(self, ev):
        return (self._lift_shortfall(ev) + self._end_shortfalls(ev, self.gripper, "hold")
                + self._tip_shortfall(ev))

    def describe(self):
        return (f"pick and hold: {self.gripper} lifts the object at least "
                f"{self.lift_height * 1e3:.0f} mm and holds it off its support to the end")

    @classmethod
    def from_table(cls, table, grippers, resolve_site=None):
        return cls(grippers=tuple(grippers), gripper=_gripper(table, "gripper", grippers, cls.kind),
                   lift_height=_number(table, "lift_height", 0.02),
                   settle_time=_number(table, "settle_time", 0.05),
                   max_base_tilt=_number(table, "max_base_tilt", 5.0))


#: task kinds by name
TASK_KINDS: dict[str, type[Task]] = {
    HandoverTask.kind: HandoverTask,
    PickPlaceTask.kind: PickPlaceTask,
    PickHoldTask.kind: PickHoldTask,
}


def task_from_table(table: Any, grippers: Sequence[str], *, resolve_site=None) -> Task:
    """The task of a scenario's ``[task]`` table.

    Args:
        table: the parsed table (must hold ``kind``).
        grippers: the scenario's gripper names, in signal order.
        resolve_site: callable giving a site's world position [m] (3,) by name, for
            ``goal_site``.

    Raises:
        ScenarioError: no table, no or unknown kind, unknown keys, bad values.
    """
    from critmoment.scenario import unknown_keys_error

    kinds = ", ".join(TASK_KINDS)
    if not isinstance(table, Mapping):
        raise ScenarioError(f"[task]: expected a table with kind = one of {kinds}, got "
                            f"{table!r}")
    if "kind" not in table:
        raise ScenarioError(f"[task]: missing kind; expected kind = one of {kinds} (critmoment "
                            "never guesses the task)")
    kind = table["kind"]
    if not isinstance(kind, str) or kind not in TASK_KINDS:
        raise ScenarioError(f"[task] kind: expected one of {kinds}, got {kind!r}")
    cls = TASK_KINDS[kind]
    extra = set(table) - set(cls.keys) - {"kind"}
    if extra:
        raise unknown_keys_error("[task]", extra, ("kind",) + cls.keys)
    return cls.from_table(table, grippers, resolve_site)
