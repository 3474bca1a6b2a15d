"""The digital twin: a scenario's MuJoCo model with critmoment's sensors.

:class:`Twin` compiles the scenario's MJCF through ``mujoco.MjSpec`` and adds
the sensors every safety signal is read from, so that a plain ``MjData``, a
``mujoco.batch.Batch`` and ``mujoco.rollout`` all deliver the signals as
``sensordata``:

* a ``contact`` sensor (data = found, force) per object/gripper-geom pair with
  :data:`CONTACT_SLOTS` slots, and one per object/support-geom pair;
* ``framelinacc`` of the object body (MuJoCo reports it with gravity removed
  like an accelerometer; :meth:`Twin.signals` adds gravity back);
* ``actuatorfrc`` of every actuator.

The twin keeps the immutable nominal model apart from mutable data, maps
action vectors to controls, and writes uncertain parameters into a model or a
batch in exactly one way (:meth:`Twin.write_parameters`).
"""

from __future__ import annotations

import contextlib
import contextvars
import copy
import dataclasses
import functools
import hashlib
import math
import os
import threading
import types
import warnings
from collections.abc import Iterator, Mapping
from typing import NamedTuple

import mujoco
import numpy as np

from critmoment import actuators as act_info
from critmoment import safety
from critmoment.exceptions import (
    CritmomentWarning,
    ParameterError,
    ScenarioError,
    TrajectoryError,
)
from critmoment.params import ForceLimitParameter, FrictionParameter
from critmoment.scenario import GENERATED, Scenario, channel_gripper
from critmoment.task import TaskEvidence

__all__ = ["CONTACT_SLOTS", "STATE_SPEC", "Signals", "SlipMasks", "Twin", "carried_flags",
           "grip_points", "lifted_flags", "LIFT_RISE"]

#: how far [m] the object must rise in a carried run for the run to count as a lift
LIFT_RISE = 0.002

#: how far a gripper's command must open past its tightest in a hold, as a fraction of its
#: channel's closed-to-open range, for the hold to be letting go (the release): the object
#: moves in a gripper that opens, which is not slip
RELEASE_OPENING = 0.1
#: longest gap [s] in a gripper's contact with the object that does not end its hold (the
#: contacts of a loosening grip flicker)
HOLD_GAP = 0.05
#: a grasp has formed once the gripper's command has done all but GRASP_CLOSING of its
#: closing (from its widest opening before the first touch to the tightest it reaches within
#: GRASP_FORMING [s] of the touch) and its tightest value so far no longer drops by
#: GRASP_RATE (of its range) within GRASP_SETTLE [s]; slip counts from there
#: (Twin.grasp_formed)
GRASP_CLOSING = 0.05
GRASP_RATE = 0.01
GRASP_SETTLE = 0.05
GRASP_FORMING = 1.0
#: ... and once its fingers have stopped: none of the gripper's geoms moves more than
#: FINGERS_STILL [m] relative to the others within GRASP_SETTLE (slow finger servos go
#: on pushing the object into place after their command is done: a Wonik Allegro's, for
#: about 100 ms)
FINGERS_STILL = 1e-3
#: contact slots read per object/geom pair; MuJoCo's box-box collider makes at most 8
CONTACT_SLOTS = 8
#: the state saved in recordings: enough to restore a step bit-exactly (warmstart included)
STATE_SPEC = mujoco.mjtState.mjSTATE_INTEGRATION


@dataclasses.dataclass(frozen=True)
class Signals:
    """Safety signals, each with the same leading shape (...) (time, samples or both).

    Attributes:
        object_acc: object's linear acceleration in the world frame [m/s²], (..., 3).
        actuator_force: actuator forces [N·m or N], (..., nu).
        actuator_norm: actuator_force / force limit, (..., nu).
        fos_contact: contact FOS per gripper, (..., G); +inf without contact.
        fos_grasp: contact FOS of the grasp, eq. 12 over the contacts of all grippers,
            where the object must be carried (off its support); +inf on the support, 0 when
            it must be carried but no gripper touches it (falling), (...). This is the
            contact FOS the cost uses.
        fos_motor: motor FOS over the motor-checked actuators (``Twin.motors``: the arm's
            hinges and slides, not a gripper's fingers), (...).
        motor_argmax: index (into the actuators) of the limiting actuator, (...).
        cost: cost (eq. 15) of fos_grasp and fos_motor, (...).
        contact_support: object touches the support, (...) bool.
        contact_gripper: object touches gripper g, (..., G) bool.
        stage: the task's stage (:meth:`critmoment.task.Task.stage`), (...) int8.
        object_pos: the object's position in the world [m], (..., 3).
        object_vel: the object's linear velocity in the world [m/s], (..., 3).
    """

    object_acc: np.ndarray
    actuator_force: np.ndarray
    actuator_norm: np.ndarray
    fos_contact: np.ndarray
    fos_grasp: np.ndarray
    fos_motor: np.ndarray
    motor_argmax: np.ndarray
    cost: np.ndarray
    contact_support: np.ndarray
    contact_gripper: np.ndarray
    stage: np.ndarray
    object_pos: np.ndarray
    object_vel: np.ndarray


def carried_flags(contact_support: np.ndarray, contact_gripper: np.ndarray) -> np.ndarray:
    """Where the object is carried: off its support and touched by a gripper.

    Args:
        contact_support: object touches a support geom, (...) bool.
        contact_gripper: object touches each gripper, (..., n_grippers) bool.

    Returns:
        (...) bool. Sparse evaluation gates the grasp FOS with the nominal run's flags.
    """
    return ~np.asarray(contact_support, bool) & np.asarray(contact_gripper, bool).any(axis=-1)


def lifted_flags(carried: np.ndarray, height: np.ndarray, rise: float = LIFT_RISE
                 ) -> np.ndarray:
    """The carried steps that belong to a real lift.

    A run of consecutive carried steps counts as a lift when the object rises more than
    ``rise`` above its height at the run's start; a squeeze that tips the object off its
    support without raising it (a few steps, under a millimetre) does not. A run carried
    from the first step on counts as a lift too: the object was lifted before the
    trajectory began (an action chunk that starts mid-carry) and may only go down.

    Args:
        carried: (T,) bool, from :func:`carried_flags`.
        height: the object's height at the same steps, (T,) [m].
        rise: the least rise of a lift [m].

    Returns:
        (T,) bool, a subset of ``carried``.
    """
    carried = np.asarray(carried, dtype=bool)
    height = np.asarray(height, dtype=np.float64)
    if carried.ndim != 1 or height.shape != carried.shape:
        raise ParameterError(
            f"lifted_flags: expected carried and height of the same shape (T,), got "
            f"{carried.shape} and {height.shape}")
    out = carried.copy()
    edges = np.flatnonzero(np.diff(np.concatenate([[False], carried, [False]]).astype(np.int8)))
    for start, stop in zip(edges[::2], edges[1::2], strict=True):
        if start > 0 and height[start:stop].max() - height[start] <= rise:
            out[start:stop] = False
    return out


def model_digest(model: mujoco.MjModel) -> str:
    """SHA-256 of a compiled model's binary MJB form: every number and name it simulates
    with, whatever files it came from (includes and meshes too, not what lies beside them)."""
    buffer = np.zeros(mujoco.mj_sizeModel(model), dtype=np.uint8)
    mujoco.mj_saveModel(model, None, buffer)
    return hashlib.sha256(buffer.tobytes()).hexdigest()


#: the most points :func:`grip_points` keeps before it falls back to their bounding box
MAX_GRIP_POINTS = 32


def grip_points(model: mujoco.MjModel, body: int) -> np.ndarray:
    """Points of a body whose displacement in a grip is its slip, in the body's frame, (K, 3)
    [m]: the origin first, then, per collision geom of the body, the points that fix the
    geom's pose up to its own symmetry (a sphere's centre; a capsule's or cylinder's axis
    ends; an ellipsoid's axis ends, but a spheroid's only on its own axis; a box's, mesh's or
    other shape's bounding-box corners).

    The object's position alone misses a turn in the grip: a plank or a tool held off its
    centre of mass pivots about the fingers' axis while the point between them stays put, and
    is placed turned or dropped. Measured at these points, a pivot counts by how far it moves
    the object's farthest part (30 degrees of a 12 cm plank: 3 cm), while a sphere's spin, or
    a cylinder's about its own axis, moves none of them. More than :data:`MAX_GRIP_POINTS`
    (a compound of many geoms) become the eight corners of their bounding box.
    """
    colliding = act_info.collision_geoms(model)
    pts = [np.zeros(3)]
    types = mujoco.mjtGeom
    for g in np.flatnonzero((model.geom_bodyid == body) & colliding):
        kind = int(model.geom_type[g])
        size = model.geom_size[g]
        if kind == types.mjGEOM_PLANE or kind == types.mjGEOM_HFIELD:
            continue
        if kind == types.mjGEOM_SPHERE:
            local = np.zeros((1, 3))
        elif kind in (types.mjGEOM_CAPSULE, types.mjGEOM_CYLINDER):
            local = np.array([[0.0, 0.0, size[1]], [0.0, 0.0, -size[1]]])
        elif kind == types.mjGEOM_ELLIPSOID:
            # the ends of the axes that a turn about another can move: none of a sphere's,
            # the odd one out of a spheroid's (a spin about it changes nothing)
            same = np.isclose(size[:, None], size[None, :], rtol=1e-9, atol=0.0).sum(axis=1)
            axes = np.diag(size)[same == 1] if (same < 3).any() else np.zeros((0, 3))
            local = np.concatenate([np.zeros((1, 3)), axes, -axes])
        else:
            centre, half = model.geom_aabb[g, :3], model.geom_aabb[g, 3:]
            if kind == types.mjGEOM_BOX:
                centre, half = np.zeros(3), size[:3]
            signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)],
                             dtype=np.float64)
            local = centre + signs * half
        rot = np.empty(9)
        mujoco.mju_quat2Mat(rot, model.geom_quat[g])
        pts.extend(model.geom_pos[g] + local @ rot.reshape(3, 3).T)
    out = np.unique(np.round(np.array(pts), 12), axis=0)
    out = np.concatenate([np.zeros((1, 3)), out[np.any(out != 0.0, axis=1)]])
    if len(out) > MAX_GRIP_POINTS + 1:
        lo, hi = out.min(axis=0), out.max(axis=0)
        corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                            for z in (lo[2], hi[2])])
        out = np.concatenate([np.zeros((1, 3)), corners])
    return out


def state_slice(model: mujoco.MjModel, component: mujoco.mjtState | int) -> slice:
    """Where a state component (``mjSTATE_QPOS``, ``mjSTATE_QVEL``, ...) sits in a
    :data:`STATE_SPEC` row of ``model``.

    Raises:
        ParameterError: the component is not part of ``STATE_SPEC``.
    """
    offset = 0
    for bit in range(mujoco.mjtState.mjNSTATE):
        part = 1 << bit
        if not int(STATE_SPEC) & part:
            continue
        size = mujoco.mj_stateSize(model, part)
        if part == int(component):
            return slice(offset, offset + size)
        offset += size
    raise ParameterError(f"state component {component} is not part of {STATE_SPEC}")


def _sensor_name(*parts: str) -> str:
    return "critmoment:" + ":".join(parts)


def _channel_range(model: mujoco.MjModel, a: int, scale: float, offset: float
                   ) -> tuple[float, float]:
    """The channel values that actuator ``a``, driven at ``offset + scale·value``, takes
    as given: within its ``ctrlrange`` where it is limited (MuJoCo clamps the control
    there, whatever the transmission: a Shadow Hand's tendon finger commanded to 3.5 of
    its 0..3.1415 was clamped without a word, and its fist let the ball drop), and for a
    joint actuator, with its joint target in the joint's range, mapped back through the
    servo's own target (:func:`critmoment.actuators.position_target`: a servo geared 2:1
    holds its joint at ctrl / 2), or through ctrl itself for an actuator that tracks no
    position; unbounded where neither limits it."""
    lo, hi = -np.inf, np.inf
    if scale != 0 and model.actuator_ctrllimited[a]:
        ends = sorted((float(c) - offset) / scale for c in model.actuator_ctrlrange[a])
        lo, hi = ends[0], ends[1]
    if int(model.actuator_trntype[a]) not in (int(mujoco.mjtTrn.mjTRN_JOINT),
                                              int(mujoco.mjtTrn.mjTRN_JOINTINPARENT)):
        return lo, hi
    joint = model.actuator_trnid[a, 0]
    if not model.jnt_limited[joint]:
        return lo, hi
    q0 = act_info.position_target(model, a, offset)
    q1 = act_info.position_target(model, a, offset + scale)
    if q0 is None or q1 is None or q1 == q0:
        q0, q1 = offset, offset + scale
    ends = sorted((float(v) - q0) / (q1 - q0) for v in model.jnt_range[joint])
    return max(lo, ends[0]), min(hi, ends[1])


def _empty_channel(model: mujoco.MjModel, label: str, c: int, acts) -> str:
    """Why channel ``c`` can take no value: each of its actuators' ``ctrlrange`` and its
    joint's compiled range (a ``ctrlrange`` written in degrees under ``angle="degree"``,
    which MuJoCo never converts, left no target the joint could reach)."""
    parts = []
    for a in acts:
        a = int(a)
        limits = []
        if model.actuator_ctrllimited[a]:
            limits.append("ctrlrange " + " ".join(f"{v:.6g}" for v in model.actuator_ctrlrange[a]))
        if int(model.actuator_trntype[a]) in (int(mujoco.mjtTrn.mjTRN_JOINT),
                                              int(mujoco.mjtTrn.mjTRN_JOINTINPARENT)):
            j = int(model.actuator_trnid[a, 0])
            if model.jnt_limited[j]:
                limits.append(f"joint {model.joint(j).name!r} range "
                              + " ".join(f"{v:.6g}" for v in model.jnt_range[j]) + " compiled")
        parts.append(f"actuator {model.actuator(a).name!r}"
                     + (f" ({'; '.join(limits)})" if limits else " (unlimited)"))
    return (f"[actions] channel {label!r} (index {c}): expected its actuators' ctrlrange and "
            f"joint range to share some values, got none in common: {'; '.join(parts)}. A "
            f"ctrlrange is never converted from degrees (MuJoCo compiles joint ranges to "
            f"radians, not controls): write it in radians, or fix the channel's scales/offsets")


def _fingers_still(fingers: np.ndarray, start: int, end: int, w: int) -> int:
    """The first step from ``start`` (before ``end``) at which no finger position of
    ``fingers`` (T, P, 3) moves more than ``FINGERS_STILL`` within the next ``w`` steps;
    ``start`` itself where there is none (fingers that never stop, say a grip that follows
    an object sliding out: the command's moment stands)."""
    t = fingers.shape[0]
    if fingers.shape[1] == 0 or start >= end:
        return start
    for k in range(start, end):
        ahead = fingers[k:min(t, k + w + 1)] - fingers[k]
        if float(np.max(np.einsum("tpi,tpi->tp", ahead, ahead))) <= FINGERS_STILL ** 2:
            return k
    return start


def _release_start(u: np.ndarray) -> int | None:
    """Where a hold's release starts, an index into its commanded opening ``u`` (0 closed,
    1 open), or None where the hold does not end in one: the hold ends opened by
    ``RELEASE_OPENING`` past the tightest command before (the last such stretch reaching the
    end), and the release is that stretch's last rise through halfway from the tightest to
    the largest opening in it."""
    if u.size == 0:
        return None
    low = np.minimum.accumulate(u)
    opened = u > low + RELEASE_OPENING
    if not opened[-1]:
        return None
    closed = np.flatnonzero(~opened)
    first = int(closed[-1]) + 1 if closed.size else 0
    base = float(low[first])
    half = base + 0.5 * (float(u[first:].max()) - base)
    under = np.flatnonzero(u[first:] <= half)
    return first + (int(under[-1]) + 1 if under.size else 0)


class SlipMasks(NamedTuple):
    """Where and from where the nominal run's slip is measured (:meth:`Twin.slip_masks`),
    each (T, G)."""

    counted: np.ndarray  # bool: the gripper holds alone, not in its release (slip_counted)
    segments: np.ndarray  # int: which of the gripper's holds (hold_segments)
    formed: np.ndarray  # bool: its grasp has formed (grasp_formed)
    letting: np.ndarray  # bool: the gripper lets its object go (letting_go)


class Twin:
    """A scenario bound to its compiled model.

    Args:
        scenario: the validated scenario (or, loaded with
            :func:`~critmoment.scenario.load_scenario`, a path to a scenario.toml or its
            folder, a bundled scenario's name, or None for the bundled default).

    Attributes:
        scenario: the scenario.
        model: the compiled model with sensors, nominal parameters applied. Treat as
            read-only; use :meth:`copy_model` for a model to modify.
    """

    def __init__(self, scenario: Scenario | str | os.PathLike | None = None):
        from critmoment.scenario import Scenario as _Scenario
        from critmoment.scenario import load_scenario

        if scenario is None or isinstance(scenario, (str, os.PathLike)):
            scenario = load_scenario(scenario)  # a path, a bundled name, None: the default
        elif not isinstance(scenario, _Scenario):
            raise ScenarioError(
                f"Twin: expected a Scenario (critmoment.load_scenario), a path to a "
                f"scenario.toml or its folder, a bundled scenario's name or None, got "
                f"{type(scenario).__name__} {scenario!r}")
        self.scenario = scenario
        spec = scenario.load_spec()
        self.add_sensors(spec)
        try:
            model = spec.compile()
        except ValueError as exc:
            raise ScenarioError(f"could not compile {scenario.mjcf} with sensors: {exc}") from exc
        self.model = model
        #: SHA-256 of the model as compiled (:func:`model_digest`), taken before any audit
        #: changes a parameter in it
        self.model_sha256 = model_digest(model)
        #: object start positions already checked against the arms' reach
        self._starts_checked: set[tuple[float, ...]] = set()
        scenario.validate_names(model)
        self._index(model)
        self._param_ids = [p.resolve(model) for p in scenario.box.parameters]
        #: (column, actuator) of each force-limit parameter whose value is that actuator's
        #: limit in the motor checks as in the physics (its forcerange): the actuator's
        #: capability, uncertain. Where ``[limits]`` states the actuator's rated limit, the
        #: parameter is a protective clamp and the checks divide by the rating
        sources = scenario.limit_sources
        self._limit_columns = tuple(
            (j, int(i)) for j, (p, i) in enumerate(zip(scenario.box.parameters,
                                                       self._param_ids, strict=True))
            if isinstance(p, ForceLimitParameter)
            and sources.get(model.actuator(int(i)).name) != "scenario")
        for j, a in self._limit_columns:
            self.limits[a] = float(scenario.box.nominal[j])
        #: per parameter, the ids it writes: the friction of one of the object's geoms is the
        #: object's friction, written to every collision geom of its body
        self._param_targets = [self._targets(p, i, model)
                               for p, i in zip(scenario.box.parameters, self._param_ids,
                                               strict=True)]
        #: per parameter, the explicit <pair>s its geoms take part in: MuJoCo uses a pair's
        #: own friction instead of the geoms', so a friction parameter writes theirs too
        self._param_pairs = [
            act_info.geom_pairs(model, t) if isinstance(p, FrictionParameter)
            else np.zeros(0, dtype=int)
            for p, t in zip(scenario.box.parameters, self._param_targets, strict=True)]
        pads = [model.geom(name).id for grip in scenario.grippers for name in grip.geoms]
        self._warn_replaced_pairs(model, set(pads))
        self._grip_sources = act_info.grip_friction_sources(model, self.object_body_id, pads)
        condims = act_info.grip_condims(model, self.object_body_id, pads)
        if condims and max(condims) == 1:
            warnings.warn(
                f"every contact of the object {scenario.object_body!r} with the grippers' "
                f"geoms is frictionless (condim 1, from the geoms' priority or an explicit "
                f"<pair>): only the grip's shape can hold it, and a friction parameter does "
                f"not act on the grip", CritmomentWarning, stacklevel=2)
        # parameters scale from the MJCF's own values, whatever nominal values are applied
        self._original = types.SimpleNamespace(
            **{f: getattr(model, f).copy() for f in self.parameter_fields()})
        self.write_parameters(model, scenario.box.nominal[None, :])
        self._check_box_ends()

    # -- construction ---------------------------------------------------------
    def _check_box_ends(self) -> None:
        """Each parameter at each end of its range (the others nominal) must give a model
        MuJoCo can simulate: a mass of 1e-12 kg makes the inertia singular
        (``mjWARN_INERTIA``) and every evaluation diverge, which is a range that makes no
        sense rather than a verdict.

        Raises:
            ScenarioError: naming the parameter, the end and MuJoCo's warning.
        """
        box = self.scenario.box

        def warnings_at(sample: np.ndarray) -> set[str]:
            model = self.copy_model()
            self.write_parameters(model, sample[None])
            data = mujoco.MjData(model)
            with quiet_mujoco_log():
                mujoco.mj_forward(model, data)
            return {mujoco.mjtWarning(i).name for i in range(len(data.warning))
                    if data.warning[i].number}

        nominal = warnings_at(box.nominal)  # the model's own, whatever the parameters
        for j, p in enumerate(box.parameters):
            for end, value in (("low", p.low), ("high", p.high)):
                sample = box.nominal.copy()
                sample[j] = value
                found = sorted(warnings_at(sample) - nominal)
                if found:
                    unit = f" {p.unit}" if p.unit else ""
                    raise ScenarioError(
                        f"[uncertainty.{p.name}]: at the {end} end of its range, {value:g}"
                        f"{unit}, MuJoCo cannot simulate the model ({', '.join(found)}: "
                        f"{'a body too light for its inertia to be resolved' if 'mjWARN_INERTIA' in found else 'an unstable state'}"
                        f" at the start); expected a range the simulation holds")

    def _warn_replaced_pairs(self, model: mujoco.MjModel, pads: set[int]) -> None:
        """Warn where the friction parameter's nominal replaces the friction the model's own
        grip contacts have: an explicit pair's in the MJCF, or the one MuJoCo's rule gives
        a contact critmoment made a pair of (``critmoment:pair:``)."""
        box = self.scenario.box
        for p, pairs, nominal in zip(box.parameters, self._param_pairs, box.nominal,
                                     strict=True):
            grip = [i for i in pairs
                    if {int(model.pair_geom1[i]), int(model.pair_geom2[i])} & pads]
            aniso = [int(i) for i in pairs if int(model.pair_dim[i]) > 1
                     and not np.isclose(model.pair_friction[i, 0], model.pair_friction[i, 1])]
            if aniso:
                i = aniso[0]
                warnings.warn(
                    f"[uncertainty.{p.name}]: explicit <pair> "
                    f"{model.geom(int(model.pair_geom1[i])).name}–"
                    f"{model.geom(int(model.pair_geom2[i])).name} has anisotropic sliding "
                    f"friction ({model.pair_friction[i, 0]:g}, {model.pair_friction[i, 1]:g})"
                    f"{f' (and {len(aniso) - 1} more pairs)' if len(aniso) > 1 else ''}; the "
                    f"parameter sets both directions to one value, so the audited contacts "
                    f"are isotropic", CritmomentWarning, stacklevel=4)
            shown = grip or list(pairs)
            own = model.pair_friction[shown, 0]
            if not shown or np.allclose(own, nominal):
                continue
            made = all(model.pair(int(i)).name.startswith(GENERATED) for i in shown)
            values = sorted({round(float(f), 6) for f in own})
            # the ones the nominal changes, named geoms first
            differ = [i for i, f in zip(shown, own, strict=True) if not np.isclose(f, nominal)]
            shown = sorted(differ, key=lambda i: (
                model.geom(int(model.pair_geom1[i])).name.startswith(GENERATED)
                + model.geom(int(model.pair_geom2[i])).name.startswith(GENERATED), i))
            own = model.pair_friction[shown, 0]
            each = ", ".join(
                f"{model.geom(int(model.pair_geom1[i])).name}–"
                f"{model.geom(int(model.pair_geom2[i])).name} {f:g}"
                for i, f in zip(shown[:4], own[:4], strict=True))
            more = f" and {len(shown) - 4} more" if len(shown) > 4 else ""
            source = ("by MuJoCo's rule for the two geoms (the gripper's have the higher "
                      "priority, or the larger friction)" if made else
                      "from explicit <pair>s in the MJCF")
            warnings.warn(
                f"[uncertainty.{p.name}]: the model's {'grip ' if grip else ''}contacts have "
                f"sliding friction {', '.join(f'{v:g}' for v in values)} ({each}{more}), "
                f"{source}; the parameter sets them, so the audited runs use its nominal "
                f"{nominal:g} there (set the nominal to the model's value to audit the model "
                f"as it is)", CritmomentWarning, stacklevel=4)

    def grip_friction(self, geom_friction: np.ndarray | None = None,
                      pair_friction: np.ndarray | None = None) -> np.ndarray:
        """The sliding friction of the object's grip contacts, per simulation: the lowest
        over the contacts an object geom and a gripper geom can make (MuJoCo's own rule for
        each: an explicit pair's friction, else the higher-priority geom's, else the larger).

        Args:
            geom_friction: per-simulation ``geom_friction`` (n, ngeom, 3); default the
                nominal model's.
            pair_friction: per-simulation ``pair_friction`` (n, npair, 5); default the
                nominal model's.

        Returns:
            (n,) friction coefficients.
        """
        geom = (self.model.geom_friction[None] if geom_friction is None
                else np.asarray(geom_friction))
        pair = (self.model.pair_friction[None] if pair_friction is None
                else np.asarray(pair_friction))
        n = max(geom.shape[0], pair.shape[0])
        if self.model.opt.enableflags & mujoco.mjtEnableBit.mjENBL_OVERRIDE:
            return np.full(n, float(self.model.opt.o_friction[0]))  # every contact's
        return act_info.source_friction(self._grip_sources, geom, pair)

    def _targets(self, p, index: int, model: mujoco.MjModel) -> tuple[int, ...]:
        """The ids parameter ``p`` (resolved to ``index``) writes."""
        if not isinstance(p, FrictionParameter):
            return (index,)
        body = int(model.geom_bodyid[index])
        if body != model.body(self.scenario.object_body).id:
            return (index,)
        colliding = act_info.collision_geoms(model)
        geoms = tuple(int(g) for g in np.flatnonzero(model.geom_bodyid == body) if colliding[g])
        mu = model.geom_friction[list(geoms), 0]
        if not np.all(mu == mu[0]):
            each = ", ".join(f"{model.geom(g).name or f'geom #{g}'}: {m:g}"
                             for g, m in zip(geoms, mu, strict=True))
            warnings.warn(f"[uncertainty.{p.name}]: the object's collision geoms have different "
                          f"frictions ({each}); the parameter sets the friction of all of them "
                          f"(the object's)", CritmomentWarning, stacklevel=3)
        return geoms

    def add_sensors(self, spec: mujoco.MjSpec) -> None:
        """Add the twin's safety sensors to ``spec`` (the scenario's model, as an MjSpec).

        The twin's model is the scenario's MJCF with these sensors. Tools that need more
        readings (e.g. :mod:`critmoment.validation`) call this first and append their own
        sensors after it: the twin's readings then keep their addresses, ``signals`` reads
        the first :attr:`nsensordata` values unchanged, and the physics is the same (sensors
        do not act on the dynamics).
        """
        sc = self.scenario
        found_force = (1 << int(mujoco.mjtConDataField.mjCONDATA_FOUND)) | (
            1 << int(mujoco.mjtConDataField.mjCONDATA_FORCE))
        found = 1 << int(mujoco.mjtConDataField.mjCONDATA_FOUND)

        def contact(name, geom, num, data):
            s = spec.add_sensor()
            s.name = name
            s.type = mujoco.mjtSensor.mjSENS_CONTACT
            # every geom of the object's body: a compound object (a base and a handle, a
            # convex decomposition) is gripped and supported by any of them
            s.objtype = mujoco.mjtObj.mjOBJ_BODY
            s.objname = sc.object_body
            s.reftype = mujoco.mjtObj.mjOBJ_GEOM
            s.refname = geom
            s.intprm = [data, 0, num]

        for g in sc.grippers:
            for geom in g.geoms:
                contact(_sensor_name("grip", g.name, geom), geom, CONTACT_SLOTS, found_force)
        # each gripper's geoms in the frame of its first: its fingers' motion, whatever
        # carries the gripper (grasp_formed)
        for g in sc.grippers:
            for geom in g.geoms[1:]:
                s = spec.add_sensor()
                s.name = _sensor_name("finger", g.name, geom)
                s.type = mujoco.mjtSensor.mjSENS_FRAMEPOS
                s.objtype = mujoco.mjtObj.mjOBJ_GEOM
                s.objname = geom
                s.reftype = mujoco.mjtObj.mjOBJ_GEOM
                s.refname = g.geoms[0]
        for geom in sc.support_geoms:
            contact(_sensor_name("support", geom), geom, 1, found)
        # the acceleration of the object's centre of mass (its load is m (a + g)); its
        # position and velocity those of its body frame, which a goal, a start pose and a
        # lift are given in (BODY would read the centre of mass: a compound object placed
        # exactly at its goal read 31 mm off, and a CoM-offset parameter moved the goal)
        for key, kind, frame in (
                ("object_acc", mujoco.mjtSensor.mjSENS_FRAMELINACC, mujoco.mjtObj.mjOBJ_BODY),
                ("object_pos", mujoco.mjtSensor.mjSENS_FRAMEPOS, mujoco.mjtObj.mjOBJ_XBODY),
                ("object_vel", mujoco.mjtSensor.mjSENS_FRAMELINVEL,
                 mujoco.mjtObj.mjOBJ_XBODY)):
            s = spec.add_sensor()
            s.name = _sensor_name(key)
            s.type = kind
            s.objtype = frame
            s.objname = sc.object_body
        # every other free body's up axis: the robot's free-floating base is among them
        # (a free body that carries actuated joints, known once compiled), whose tilt the
        # task's rule reads (Task.max_base_tilt)
        for index, body in enumerate(spec.bodies):
            if (index and body.name != sc.object_body
                    and any(j.type == mujoco.mjtJoint.mjJNT_FREE for j in body.joints)):
                # an unnamed one is named in critmoment's copy, as its geoms are, so that a
                # sensor can read it (its tilt had gone unjudged)
                body.name = body.name or f"{GENERATED}body:{index}"
                s = spec.add_sensor()
                s.name = _sensor_name("base_up", body.name)
                s.type = mujoco.mjtSensor.mjSENS_FRAMEZAXIS
                s.objtype = mujoco.mjtObj.mjOBJ_XBODY
                s.objname = body.name
        for act in spec.actuators:
            s = spec.add_sensor()
            s.name = _sensor_name("force", act.name)
            s.type = mujoco.mjtSensor.mjSENS_ACTUATORFRC
            s.objtype = mujoco.mjtObj.mjOBJ_ACTUATOR
            s.objname = act.name

    def _index(self, model: mujoco.MjModel) -> None:
        sc = self.scenario

        def adr(name):
            sid = model.sensor(name).id
            return int(model.sensor_adr[sid]), int(model.sensor_dim[sid])

        self._grip_adr = []
        for g in sc.grippers:
            blocks = []
            for geom in g.geoms:
                a, dim = adr(_sensor_name("grip", g.name, geom))
                blocks.append(np.arange(a, a + dim))
            self._grip_adr.append(np.concatenate(blocks))
        #: per gripper, the addresses of its other geoms' positions in its first geom's
        #: frame (P − 1, 3)
        self._finger_adr = [np.array([np.arange(a, a + 3) for a in (
            adr(_sensor_name("finger", g.name, geom))[0] for geom in g.geoms[1:])],
            dtype=np.int64).reshape(-1, 3) for g in sc.grippers]
        # each slot's first value says whether it holds a contact: read only those
        self._grip_found = [block[0::4] for block in self._grip_adr]
        self._support_adr = np.array([adr(_sensor_name("support", geom))[0]
                                      for geom in sc.support_geoms])
        a, _ = adr(_sensor_name("object_acc"))
        self._acc_adr = np.arange(a, a + 3)
        a, _ = adr(_sensor_name("object_pos"))
        self._pos_adr = np.arange(a, a + 3)
        a, _ = adr(_sensor_name("object_vel"))
        self._vel_adr = np.arange(a, a + 3)
        self._force_adr = np.array([adr(_sensor_name("force", model.actuator(i).name))[0]
                                    for i in range(model.nu)])
        # contiguous addresses read as slices: views, where an index array copies (the grip
        # blocks stay index arrays: their sums over contacts round by memory layout, and a
        # contiguous copy keeps the signals what they were to the bit)
        self._force_ids = self._force_adr  # per actuator, to pick some
        for name in ("_support_adr", "_acc_adr", "_pos_adr", "_vel_adr", "_force_adr"):
            setattr(self, name, _as_slice(getattr(self, name)))
        #: the robot's free-floating bases (act_info.robot_bases), and the addresses of their
        #: up axes' readings (B, 3)
        self.robot_bases = tuple(act_info.robot_bases(model))
        self._base_adr = np.array([np.arange(a, a + 3) for a in (
            adr(_sensor_name("base_up", model.body(b).name))[0] for b in self.robot_bases)],
            dtype=np.int64).reshape(-1, 3)
        self.object_body_id = model.body(sc.object_body).id
        #: the object's points whose motion in a grip is measured as slip (:func:`grip_points`)
        self.grip_points = grip_points(model, self.object_body_id)
        self.object_geom_id = model.geom(sc.object_geom).id
        self.object_qposadr = int(model.jnt_qposadr[model.body_jntadr[self.object_body_id]])
        missing = [model.actuator(i).name for i in range(model.nu)
                   if model.actuator(i).name not in sc.limits]
        if missing:
            raise ScenarioError(
                f"Scenario limits: expected a force limit for every actuator (inf for none; "
                f"load_scenario fills them from [limits] and the MJCF), missing "
                f"{missing[:8]}{' ...' if len(missing) > 8 else ''}")
        self.limits = np.array([sc.limits[model.actuator(i).name] for i in range(model.nu)])
        # the arm's joint actuators enter the motor FOS (eq. 13-14): on hinges, and on the
        # arm's slides (a lift, a gantry axis); a gripper's fingers, on either kind of joint,
        # stay out (their force limit is the grip's squeeze, limited on purpose)
        arm = set(_arm_actuators(model, sc))
        on_arm = np.array([model.actuator(i).name in arm for i in range(model.nu)])
        hinge = np.array([
            model.actuator_trntype[i] == mujoco.mjtTrn.mjTRN_JOINT
            and model.jnt_type[model.actuator_trnid[i, 0]] == mujoco.mjtJoint.mjJNT_HINGE
            for i in range(model.nu)])
        #: actuators on the arm's hinge joints (a gripper's hinge fingers are not)
        self.rotational = on_arm & hinge
        if not on_arm.any():
            fingers = [model.actuator(i).name for i in np.flatnonzero(hinge)]
            raise ScenarioError(
                "expected at least one actuator on a hinge or slide joint of the arm (not a "
                "gripper's finger), found none" + (f"; the hinge actuators {fingers} drive a "
                                                   f"gripper's fingers" if fingers else "")
                + _mocap_hint(model))
        #: actuators on slide joints of the arm (a lift, a gantry axis; not a gripper's
        #: fingers): in the motor checks with the rotational ones, their force in N
        self.arm_slides = tuple(model.actuator(i).name for i in np.flatnonzero(on_arm & ~hinge))
        self.slide = on_arm & ~hinge
        #: the actuators the motor checks read (motor FOS, load bounds, the ground truth's
        #: saturation and tracking rules): the arm's hinges and slides
        self.motors = self.rotational | self.slide
        #: joint actuators of a gripper's fingers (a normalised channel's, or on a joint
        #: below a gripper's base): out of the motor checks, their squeeze limited on purpose
        joint_act = np.array([model.actuator_trntype[i] == mujoco.mjtTrn.mjTRN_JOINT
                              for i in range(model.nu)], dtype=bool)
        self.fingers = joint_act & ~on_arm
        #: per actuator, its joint target as ``scale·ctrl + offset`` [rad or m]
        #: (:func:`critmoment.actuators.position_target`: a servo geared 50:1 holds its
        #: joint at ctrl / 50): the tracking rules compare the joint's own position with it,
        #: so a joint's lag is in the tolerance's units whatever the gear or bias
        self.target_scale, self.target_offset = _joint_targets(model)
        self.actuator_names = tuple(model.actuator(i).name for i in range(model.nu))
        #: the motor-checked actuators with no force limit in the scenario or the MJCF:
        #: their motor FOS is not checked (a gripper's, never checked, are not listed)
        self.unlimited_motors = tuple(
            name for name, checked, limit in zip(self.actuator_names, self.motors,
                                                 self.limits, strict=True)
            if checked and not np.isfinite(limit))
        self.task = sc.task
        # action channels -> actuators
        conv = sc.actions
        self._chan_act = [np.array([model.actuator(a).id for a in ch]) for ch in conv.channels]
        lower, upper = np.empty(conv.width), np.empty(conv.width)
        for c, acts in enumerate(self._chan_act):
            if conv.normalised[c]:
                lower[c], upper[c] = 0.0, 1.0
                continue
            lower[c], upper[c] = -np.inf, np.inf
            for a, s, o in zip(acts, conv.scales[c], conv.offsets[c], strict=True):
                lo, hi = _channel_range(model, int(a), s, o)
                lower[c], upper[c] = max(lower[c], lo), min(upper[c], hi)
            if lower[c] > upper[c]:
                raise ScenarioError(_empty_channel(model, conv.labels[c], c, acts))
        self.channel_lower, self.channel_upper = lower, upper
        self.channel_normalised = np.array(conv.normalised)

    # -- parameters ---------------------------------------------------------------
    def copy_model(self) -> mujoco.MjModel:
        """A private copy of the nominal model, to modify."""
        return copy.copy(self.model)

    def parameter_fields(self) -> tuple[str, ...]:
        """MjModel fields the uncertainty box writes."""
        fields: list[str] = []
        for p in self.scenario.box.parameters:
            fields.extend(f for f in p.fields if f not in fields)
        if any(pairs.size for pairs in self._param_pairs):
            fields.append("pair_friction")
        return tuple(fields)

    def write_parameters(self, target, samples: np.ndarray, arrays: Mapping[str, np.ndarray] | None = None) -> None:
        """Write parameter samples into a model (n = 1) or into per-simulation arrays.

        Args:
            target: an ``MjModel`` to modify in place (samples (1, k)), or a
                ``mujoco.batch.Batch`` (samples (nsim, k)); its fields are expanded.
            samples: parameter values, (n, k) in the box's column order.
            arrays: optional per-simulation arrays already expanded from ``target``.
        """
        box = self.scenario.box
        samples = box.check_samples(samples)
        if isinstance(target, mujoco.MjModel):
            if samples.shape[0] != 1:
                raise ParameterError(f"a single model takes samples of shape (1, k), got {samples.shape}")
            arrays = {f: getattr(target, f)[None] for f in self.parameter_fields()}
        elif arrays is None:
            arrays = {f: target.expand(f) for f in self.parameter_fields()}
        for j, p in enumerate(box.parameters):
            for index in self._param_targets[j]:
                p.write(index, self._original, arrays, samples[:, j])
            pairs = self._param_pairs[j]
            if pairs.size:  # both tangential directions: the pair's sliding friction
                arrays["pair_friction"][:, pairs[:, None], np.arange(2)] = samples[:, j, None, None]
        if any(p.needs_set_const for p in box.parameters):
            if isinstance(target, mujoco.MjModel):
                mujoco.mj_setConst(target, mujoco.MjData(target))
            else:
                target.set_const()

    def object_friction(self, model: mujoco.MjModel | None = None) -> float:
        """Sliding friction of the object's grip contacts in ``model`` (default the nominal
        one): :meth:`grip_friction` of its fields."""
        model = model or self.model
        return float(self.grip_friction(model.geom_friction[None], model.pair_friction[None])[0])

    def lifted(self, carried: np.ndarray, states: np.ndarray) -> np.ndarray:
        """:func:`lifted_flags` of ``carried`` (T,), with the object's height read from
        integration states (at least T rows of ``STATE_SPEC``)."""
        carried = np.asarray(carried, dtype=bool)
        return lifted_flags(carried, self.object_height(states)[:carried.size])

    def object_height(self, states: np.ndarray) -> np.ndarray:
        """The object's height [m] (along the task's up, against gravity) in integration
        states (T, nstate) of ``STATE_SPEC``, (T,)."""
        adr = self.object_qposadr
        return self.qpos(states)[:, adr:adr + 3] @ np.asarray(self.task.up, dtype=float)

    def qpos(self, states: np.ndarray) -> np.ndarray:
        """The positions in integration states (T, nstate) of ``STATE_SPEC``, (T, nq) (a
        view)."""
        return np.asarray(states)[:, state_slice(self.model, mujoco.mjtState.mjSTATE_QPOS)]

    # -- actions and state ------------------------------------------------------------
    def sample_limits(self, samples: np.ndarray) -> np.ndarray | None:
        """Each sample's actuator force limits, (n, nu): :attr:`limits` with the box's
        force-limit parameters at the sample's values; None when the box has none (every
        sample has :attr:`limits`)."""
        if not self._limit_columns:
            return None
        samples = np.atleast_2d(np.asarray(samples, dtype=np.float64))
        out = np.repeat(np.asarray(self.limits, dtype=np.float64)[None], samples.shape[0], 0)
        for j, a in self._limit_columns:
            out[:, a] = samples[:, j]
        return out

    @property
    def lowest_limits(self) -> np.ndarray:
        """The force limits at the worst corner of the box, (nu,): :attr:`limits` with each
        force-limit parameter at the low end of its range (the analytic bounds hold over
        the whole box with them). Where ``[limits]`` rates the actuator and the parameter is
        a protective clamp, the clamp's low end where it is tighter than the rating: the
        actuator cannot give more (a bound had said "no motor saturates" where every sample's
        clamped shoulder lost its tracking)."""
        out = np.asarray(self.limits, dtype=np.float64).copy()
        columns = {j for j, _ in self._limit_columns}
        for j, (p, a) in enumerate(zip(self.scenario.box.parameters, self._param_ids,
                                       strict=True)):
            if isinstance(p, ForceLimitParameter):
                out[int(a)] = float(p.low) if j in columns else min(out[int(a)], float(p.low))
        return out

    def controls(self, actions: np.ndarray) -> np.ndarray:
        """Map action vectors (..., na) to actuator controls (..., nu), clamped to ctrlrange."""
        actions = np.asarray(actions, dtype=np.float64)
        conv = self.scenario.actions
        if actions.shape[-1] != conv.width:
            raise TrajectoryError(
                f"expected actions with {conv.width} values per step ({conv.name}: "
                f"{', '.join(conv.labels)}), got {actions.shape[-1]}")
        ctrl = np.zeros(actions.shape[:-1] + (self.model.nu,))
        for c, acts in enumerate(self._chan_act):
            ctrl[..., acts] = (np.asarray(conv.offsets[c])
                               + np.asarray(conv.scales[c]) * actions[..., c, None])
        limited = self.model.actuator_ctrllimited.astype(bool)
        rng = self.model.actuator_ctrlrange
        ctrl[..., limited] = np.clip(ctrl[..., limited], rng[limited, 0], rng[limited, 1])
        return ctrl

    def initial_data(self, *, start: np.ndarray | None = None, qpos0: np.ndarray | None = None,
                     object_pose: np.ndarray | None = None, model: mujoco.MjModel | None = None,
                     settle: bool | None = None,
                     qvel0: np.ndarray | None = None) -> mujoco.MjData:
        """An MjData at the trajectory's initial state, forward-computed.

        Args:
            start: initial joint state in the action convention, (na,); each joint driven
                by a position-like actuator starts where that actuator pulls it at the control
                ``start`` maps to (:func:`critmoment.actuators.position_target`).
            qpos0: full initial qpos, (nq,); overrides ``start``.
            qvel0: full initial qvel, (nv,), with ``qpos0`` (default: at rest).
            object_pose: object position and quaternion (w, x, y, z), (7,).
            model: the model to make data for (default: the nominal model).
            settle: let an object that touches nothing at the start fall onto its support
                first (:meth:`settle_object`); default: the scenario's ``settle``.
        """
        model = model or self.model
        data = mujoco.MjData(model)
        key = self.scenario.keyframe_id(model)
        if key is not None:
            mujoco.mj_resetDataKeyframe(model, data, key)
        if qpos0 is not None:
            qpos0 = np.asarray(qpos0, dtype=np.float64)
            if qpos0.shape != (model.nq,):
                raise TrajectoryError(
                    f"the trajectory's qpos0: expected the model's full joint positions, "
                    f"shape ({model.nq},), got {qpos0.shape}; {_qpos_layout(model)} (a "
                    f"qpos0 recorded on a model with other joints, such as a free body "
                    f"added or removed, does not fit: record it on this model, or give "
                    f"the start in the action convention instead)")
            _check_qpos_quaternions(model, qpos0)
            _check_qpos_ranges(model, qpos0)
            data.qpos[:] = qpos0
        elif start is not None:
            for _, adr, q in self._start_positions(model, start, range(model.nu)):
                data.qpos[adr] = q
        if object_pose is not None or qpos0 is not None:
            self._check_object_start(model, object_pose if object_pose is not None
                                     else qpos0[self.object_qposadr:self.object_qposadr + 3])
        if object_pose is not None:
            pose = np.asarray(object_pose, dtype=np.float64)
            if pose.shape != (7,):
                raise TrajectoryError(f"expected object_pose (7,) xyz + quat wxyz, got {pose.shape}")
            adr = self.object_qposadr
            if qpos0 is not None:
                _warn_pose_disagreement(qpos0[adr:adr + 7], pose)
            data.qpos[adr:adr + 7] = pose
        data.qvel[:] = 0
        if qvel0 is not None:
            qvel0 = np.asarray(qvel0, dtype=np.float64)
            if qpos0 is None or qvel0.shape != (model.nv,):
                raise TrajectoryError(f"expected qvel0 of shape ({model.nv},) with qpos0, got "
                                      f"{qvel0.shape}{'' if qpos0 is not None else ' alone'}")
            data.qvel[:] = qvel0
        if start is not None:
            data.ctrl[:] = self.controls(np.asarray(start)[None])[0]
            # a filtered servo (<position timeconst>) at rest at its target: its activation
            # is the control (from 0 it would pull the arm down first)
            for a in act_info.filtered_actuators(model):
                data.act[model.actuator_actadr[a]] = data.ctrl[a]
        mujoco.mj_forward(model, data)
        if self.scenario.settle if settle is None else settle:
            self.settle_object(model, data)
        return data

    def warn_start_disagreement(self, qpos0: np.ndarray, start,
                                model: mujoco.MjModel | None = None) -> None:
        """A trajectory that gives both qpos0 and a start: qpos0 wins (the run starts
        there, its servos pulling towards start's controls from the first step), said where
        an arm joint's two starts differ by more than :data:`START_AGREEMENT` (rad; a tenth
        of it in m). Not for a start taken from the first action (a target that leads the
        joint by design)."""
        model = model or self.model
        qpos0 = np.asarray(qpos0, dtype=np.float64)
        if qpos0.shape != (model.nq,):
            return  # the length is checked, and named, where qpos0 is used
        worst = None
        for a, adr, q in self._start_positions(model, start, np.flatnonzero(self.motors)):
            tol = START_AGREEMENT * (0.1 if self.slide[a] else 1.0)
            gap = abs(float(qpos0[adr]) - q)
            if gap > tol and (worst is None or gap / tol > worst[0]):
                joint = model.joint(int(model.actuator_trnid[a, 0])).name
                worst = (gap / tol, joint, float(qpos0[adr]), q)
        if worst is not None:
            _, name, there, target = worst
            warnings.warn(
                f"qpos0 and start disagree: joint {name!r} at {there:.4g} in qpos0, {target:.4g} "
                f"by start; the run starts from qpos0 (its servos pull towards start's "
                f"targets from the first step; drop one of the two if that is not meant)",
                CritmomentWarning, stacklevel=3)

    def _start_positions(self, model: mujoco.MjModel, start, actuators):
        """(actuator, qpos address, position) of each of ``actuators`` that pulls its joint
        to a position at ``start``'s control (:func:`critmoment.actuators.position_target`),
        inside the joint's range: where a start puts the joints it drives."""
        ctrl = self.controls(np.asarray(start, dtype=np.float64)[None])[0]
        for a in actuators:
            q = act_info.position_target(model, int(a), ctrl[a])
            if q is None:
                continue
            j = int(model.actuator_trnid[a, 0])
            if model.jnt_limited[j]:
                q = float(np.clip(q, *model.jnt_range[j]))
            yield int(a), int(model.jnt_qposadr[j]), float(q)

    def _check_object_start(self, model: mujoco.MjModel, pose) -> None:
        """An object start no gripper can reach is an error (a pose in mm), not an audit in
        which every sample fails. Checked once per start position."""
        position = tuple(float(v) for v in np.asarray(pose, dtype=float).reshape(-1)[:3])
        checked = self._starts_checked
        if position in checked or len(position) != 3 or not all(map(math.isfinite, position)):
            return
        from critmoment.scenario import start_out_of_reach

        why = start_out_of_reach(model, self.scenario, np.array(position))
        if why:
            raise TrajectoryError(why)
        checked.add(position)

    @staticmethod
    def get_state(model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
        state = np.empty(mujoco.mj_stateSize(model, STATE_SPEC))
        mujoco.mj_getState(model, data, state, STATE_SPEC)
        return state

    @staticmethod
    def set_state(model: mujoco.MjModel, data: mujoco.MjData, state: np.ndarray) -> None:
        mujoco.mj_setState(model, data, np.asarray(state, dtype=np.float64), STATE_SPEC)

    def evidence(self, signals: Signals, sensordata: np.ndarray | None = None) -> TaskEvidence:
        """The task's evidence of signals with leading shape (..., T) (and of the robot's
        free base, read from ``sensordata`` (..., T, nsensordata) where given)."""
        return self.task_evidence(signals.contact_gripper, signals.contact_support,
                                  signals.object_pos, signals.object_vel,
                                  base_axis=None if sensordata is None
                                  else self.base_axis(sensordata))

    def base_axis(self, sensordata: np.ndarray) -> np.ndarray | None:
        """The up axes of the robot's free-floating bases (:attr:`robot_bases`) in the world,
        (..., B, 3), from readings (..., nsensordata); None for a robot with none."""
        if not self.robot_bases:
            return None
        return np.asarray(sensordata)[..., self._base_adr]

    def task_evidence(self, contact_gripper: np.ndarray, contact_support: np.ndarray,
                      object_pos: np.ndarray, object_vel: np.ndarray,
                      base_axis: np.ndarray | None = None) -> TaskEvidence:
        """The task's evidence of contact flags and the object's motion, leading shape
        (..., T), in this twin's time step (``base_axis`` (..., T, B, 3): the robot's free
        bases' up axes, :meth:`base_axis`)."""
        return TaskEvidence(contact_gripper=contact_gripper, contact_support=contact_support,
                            object_pos=object_pos, object_vel=object_vel,
                            dt=float(self.model.opt.timestep), base_axis=base_axis)

    def success(self, signals: Signals, sensordata: np.ndarray | None = None) -> np.ndarray:
        """The task's success rule over signals (..., T) (and ``sensordata`` for the robot's
        free base, :meth:`evidence`): (...) bool."""
        return self.task.success(self.evidence(signals, sensordata))

    def settle_object(self, model: mujoco.MjModel, data: mujoco.MjData, *,
                      seconds: float = 2.0, speed: float = 1e-3) -> int:
        """Let an object that starts touching nothing fall and settle, robot held still.

        Only the object's free joint moves; every other joint keeps its position and a
        zero velocity. Stops once the object touches something and moves slower than
        ``speed`` [m/s] for 50 ms, or after ``seconds`` [s] of simulated time, which is
        not added to the audit's clock. An object that lands on nothing within that time
        keeps its start pose (it is meant to start in the air).

        Returns:
            The physics steps taken (0 when the object already touched something).
        """
        adr = self.object_qposadr
        dof = int(model.jnt_dofadr[model.body_jntadr[self.object_body_id]])
        if self._touching(model, data):
            return 0
        keep_q = np.ones(model.nq, bool)
        keep_q[adr:adr + 7] = False
        keep_v = np.ones(model.nv, bool)
        keep_v[dof:dof + 6] = False
        q, ctrl, t0 = data.qpos.copy(), data.ctrl.copy(), data.time
        still, need = 0, max(1, int(round(0.05 / model.opt.timestep)))
        taken = 0
        for _ in range(int(seconds / model.opt.timestep)):
            mujoco.mj_step(model, data)
            taken += 1
            data.qpos[keep_q] = q[keep_q]
            data.qvel[keep_v] = 0
            data.ctrl[:] = ctrl
            if not np.isfinite(data.qpos[adr:adr + 3]).all():
                raise TrajectoryError("the object diverged while settling at its start pose: "
                                      "expected a start pose above a support")
            moving = np.linalg.norm(data.qvel[dof:dof + 3]) > speed
            still = 0 if moving or not self._touching(model, data) else still + 1
            if still >= need:
                break
        if not self._touching(model, data):
            # nothing below it: the object is meant to start in the air (a throw, a
            # free-fall test); keep the start pose as given
            data.qpos[:] = q
            taken = 0
        data.qvel[:] = 0
        data.time = t0
        mujoco.mj_forward(model, data)
        return taken

    def _touching(self, model: mujoco.MjModel, data: mujoco.MjData) -> bool:
        body = self.object_body_id
        geom_body = model.geom_bodyid
        for c in data.contact[:data.ncon]:
            if geom_body[c.geom1] == body or geom_body[c.geom2] == body:
                return True
        return False

    # -- signals ------------------------------------------------------------------
    @property
    def nsensordata(self) -> int:
        return int(self.model.nsensordata)

    def gripper_opening(self, controls: np.ndarray) -> np.ndarray:
        """Each gripper's commanded opening, (T, G): the mean over the actuators of the
        normalised channels that move its geoms of (ctrl − closed) / (open − closed), 0
        closed and 1 open; NaN for a gripper no normalised channel drives."""
        controls = np.asarray(controls, dtype=np.float64)
        out = np.full(controls.shape[:-1] + (len(self.scenario.grippers),), np.nan)
        conv = self.scenario.actions
        for g, channels in enumerate(self._grip_channels):
            parts = [(controls[..., a] - o) / sc
                     for c in channels
                     for a, sc, o in zip(self._chan_act[c], conv.scales[c], conv.offsets[c],
                                         strict=True) if sc != 0]
            if parts:
                out[..., g] = np.mean(parts, axis=0)
        return out

    @functools.cached_property
    def _grip_channels(self) -> list[list[int]]:
        """Per gripper, the normalised action channels whose actuators move its geoms."""
        grippers = self.scenario.grippers
        found: list[list[int]] = [[] for _ in grippers]
        for c, acts in enumerate(self._chan_act):
            g = (channel_gripper(self.model, [int(a) for a in acts], grippers)
                 if self.scenario.actions.normalised[c] else None)
            if g is not None:
                found[g].append(c)
        return found

    @staticmethod
    def held_alone(contact_gripper: np.ndarray, contact_support: np.ndarray) -> np.ndarray:
        """Where each gripper holds the object alone, (T, G) bool: touching it off its
        support, no other gripper touching it (an object moves in a gripper that lets go
        to another, the hand-over's release)."""
        held = np.asarray(contact_gripper, bool) & ~np.asarray(contact_support, bool)[..., None]
        return held & (held.sum(axis=-1, keepdims=True) == 1)

    def slip_counted(self, contact_gripper: np.ndarray, contact_support: np.ndarray,
                     controls: np.ndarray) -> np.ndarray:
        """Where the ground truth counts a gripper's slip in the nominal run, (T, G) bool:
        it holds the object alone (:meth:`held_alone`) and is not in the release that ends
        its hold (:meth:`letting_go`)."""
        return self.slip_masks(controls, contact_gripper, contact_support).counted

    def slip_masks(self, controls: np.ndarray, contact_gripper: np.ndarray,
                   contact_support: np.ndarray,
                   sensordata: np.ndarray | None = None) -> SlipMasks:
        """The nominal run's :meth:`slip_counted`, :meth:`hold_segments`,
        :meth:`grasp_formed` and :meth:`letting_go` at once (the commands read and the
        holds found once): what the ground truth, the chains and sparse evaluation measure
        slip with. ``sensordata``: the nominal run's readings, (T, nsensordata) or more
        columns (the grasp forms once its fingers stop, :meth:`grasp_formed`)."""
        touching = np.asarray(contact_gripper, bool)
        opening = self.gripper_opening(controls)
        releases = list(self._releases(opening, touching))
        letting = self._letting(releases, touching.shape)
        segments = self._segments(releases, touching.shape)
        return SlipMasks(counted=self.held_alone(touching, contact_support) & ~letting,
                         segments=segments,
                         formed=self._formed(opening, touching, segments,
                                             self._fingers(sensordata, touching.shape[0])),
                         letting=letting)

    def _fingers(self, sensordata: np.ndarray | None, steps: int) -> list | None:
        """Each gripper's other geoms in its first geom's frame, (T, P − 1, 3) [m], from
        the readings ``sensordata`` (T, ≥ nsensordata); None without readings."""
        if sensordata is None:
            return None
        sd = np.asarray(sensordata, dtype=np.float64)
        if sd.ndim != 2 or sd.shape[0] != steps or sd.shape[1] < self.nsensordata:
            raise ParameterError(f"sensordata: expected ({steps}, >= {self.nsensordata}) "
                                 f"readings of the nominal run, got {sd.shape}")
        return [sd[:, adr] for adr in self._finger_adr]

    def letting_go(self, controls: np.ndarray, touching: np.ndarray) -> np.ndarray:
        """Where each gripper lets its object go, (T, G) bool: the release that ends a hold
        (the gripper touching the object, gaps up to ``HOLD_GAP`` bridged), from where the
        command's last rise crosses halfway to its opening at the hold's end, where it ends
        the hold opened by ``RELEASE_OPENING`` of its range or more past its tightest
        (:func:`_release_start`). ACT's scripted hand-over opens the picker 0.95 s before
        the receiver touches the cube: the cube slid 5-6 mm down the opening fingers into
        the receiver and the hand-over succeeded, but that had counted as a slip. A command
        that jitters or opens partly during the carry and closes again, or stays partly open
        until a later release, is no release there: a cube falling out of a jittering grip
        1.7 s before the release had been called a success once its slip stopped counting.

        Args:
            controls: per-step controls, (T, nu).
            touching: the gripper touches the object, (T, G) bool.
        """
        touching = np.asarray(touching, bool)
        return self._letting(self._releases(self.gripper_opening(controls), touching),
                             touching.shape)

    @staticmethod
    def _letting(releases, shape: tuple[int, int]) -> np.ndarray:
        """:meth:`letting_go` from the holds that end in a release (:meth:`_releases`)."""
        out = np.zeros(shape, bool)
        for g, a, b, start in releases:
            out[a + start:b, g] = True
        return out

    def hold_segments(self, controls: np.ndarray, touching: np.ndarray) -> np.ndarray:
        """Which of a gripper's holds each step belongs to, (T, G) int: 0 up to the end of
        the gripper's first hold that ends in a release (:meth:`letting_go`), 1 up to the
        end of the next, and so on. A regrasp (a release, then a new grasp of the object)
        starts a new segment, from which slip is measured afresh: measured from the first
        grasp, a second grasp 10 mm lower on a Panda's cube had hidden 10 mm of the second
        hold's slip. Only the gripper's command ends a segment; a contact that flickers, or
        an object that slides out of a grip still closed, does not."""
        touching = np.asarray(touching, bool)
        return self._segments(self._releases(self.gripper_opening(controls), touching),
                              touching.shape)

    @staticmethod
    def _segments(releases, shape: tuple[int, int]) -> np.ndarray:
        """:meth:`hold_segments` from the holds that end in a release (:meth:`_releases`)."""
        out = np.zeros(shape, np.int64)
        for g, _, b, _ in releases:
            out[b:, g] += 1
        return out

    def grasp_formed(self, controls: np.ndarray, touching: np.ndarray,
                     sensordata: np.ndarray | None = None) -> np.ndarray:
        """Where each gripper's grasp has formed, (T, G) bool: in each of its holds
        (:meth:`hold_segments`), from the first step after its first touch at which the
        command has done all but ``GRASP_CLOSING`` of its closing, from its widest opening
        in the hold before the touch to the tightest it reaches within ``GRASP_FORMING`` of
        the touch, and its tightest value so far no longer drops by ``GRASP_RATE`` within
        ``GRASP_SETTLE`` (a closing ramp's slow tail still closes the fingers). A closed
        command that later dips or creeps a little tighter, or jitters, does not move it
        (measured to a dip of 0.02 at 0.9 s, a Panda's slip of 6.9 mm during the lift had
        gone uncounted); a gripper no normalised channel drives has formed its grasp
        everywhere. A closing that goes on into the lift is measured from its end (a Panda
        closing over 1.2 s, the lift 0.4 s before its end: 9.2 mm from there, 14.3 mm from
        the first touch). Slip is measured from there: a hand that
        wraps its fingers around an object pushes it 1-2 cm into place while it closes, and
        differently for each mass and friction (a Kinova Gen3 with a multi-finger hand:
        17 of 32 samples were "slipped" during the closing, and held the object to the end).

        The window runs ``GRASP_FORMING`` from where the command starts closing, at the
        touch or after it (a palm that touches the object before the fingers close). With
        the run's readings ``sensordata`` (T, nsensordata), the grasp also waits, within that
        window, for the fingers to stop: no geom of the gripper
        moving more than ``FINGERS_STILL`` relative to its first within ``GRASP_SETTLE``.
        A command is done before slow servos are: a Wonik Allegro's fingers (kp 10) go on
        pushing a ball into place for about 100 ms after their command has closed, and 18
        of 32 samples that held the ball to the end were "slipped" by that push.
        """
        touching = np.asarray(touching, bool)
        opening = self.gripper_opening(controls)
        return self._formed(opening, touching, self._segments(
            self._releases(opening, touching), touching.shape),
            self._fingers(sensordata, touching.shape[0]))

    def _formed(self, opening: np.ndarray, touching: np.ndarray,
                segments: np.ndarray, fingers: list | None = None) -> np.ndarray:
        """:meth:`grasp_formed` from the commanded opening, the holds' segments and the
        fingers' positions (:meth:`_fingers`, or None)."""
        out = np.ones(touching.shape, bool)
        if touching.shape[0] == 0:
            return out
        dt = float(self.model.opt.timestep)
        cap = max(1, int(round(GRASP_FORMING / dt)))
        w = max(1, int(round(GRASP_SETTLE / dt)))
        steps = np.arange(touching.shape[0])
        for g in range(touching.shape[1]):
            if np.isnan(opening[:, g]).all():
                continue
            u = np.nan_to_num(opening[:, g], nan=1.0)
            for j in np.unique(segments[:, g]):
                inside = np.flatnonzero(segments[:, g] == j)
                a, b = int(inside[0]), int(inside[-1]) + 1
                touched = np.flatnonzero(touching[a:b, g])
                if not touched.size:
                    continue
                t1 = a + int(touched[0])
                # the window runs GRASP_FORMING from where the command starts closing, at
                # the touch or after it: a Shadow Hand's palm touched the ball 0.3 s before
                # its fingers began to close, and the grasp had "formed" with its command
                # still 22 % open
                tighter = np.flatnonzero(u[t1:b] < u[t1] - GRASP_RATE)
                c0 = t1 + (int(tighter[0]) - 1 if tighter.size else 0)
                low = np.minimum.accumulate(u[t1:min(b, c0 + cap)])
                span = max(float(u[a:t1 + 1].max()) - float(low[-1]), 0.0)
                closed = low <= low[-1] + GRASP_CLOSING * span
                later = np.concatenate([low[w:], np.full(min(w, low.size), low[-1])])
                settled = later >= low - GRASP_RATE
                start = t1 + max(int(np.argmax(closed)),
                                 int(np.argmax(settled)) if settled.any() else low.size)
                if fingers is not None:
                    start = _fingers_still(fingers[g], start, min(b, c0 + cap), w)
                out[a:b, g] = steps[a:b] >= start
        return out

    def _releases(self, opening: np.ndarray, touching: np.ndarray):
        """Each hold that ends in a release: (gripper, the hold's first step, its end
        (exclusive), where its release starts within it), in time order per gripper, from
        the commanded ``opening`` (:meth:`gripper_opening`). A hold is a stretch of
        ``touching`` with gaps up to ``HOLD_GAP`` bridged."""
        gap = int(round(HOLD_GAP / float(self.model.opt.timestep)))
        for g in range(touching.shape[1]):
            if np.isnan(opening[:, g]).all():
                continue
            hold = touching[:, g].copy()
            idle = np.flatnonzero(np.diff(np.concatenate([[1], hold.astype(np.int8), [1]])))
            for a, b in zip(idle[::2], idle[1::2], strict=True):  # gaps [a, b)
                if 0 < a and b < hold.size and b - a <= gap:
                    hold[a:b] = True
            edges = np.flatnonzero(np.diff(np.concatenate([[0], hold.astype(np.int8), [0]])))
            for a, b in zip(edges[::2], edges[1::2], strict=True):
                start = _release_start(opening[a:b, g])
                if start is not None:
                    yield g, int(a), int(b), start

    def contact_flags(self, sensordata: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Which grippers and supports the object touches, from ``sensordata``
        (..., nsensordata): (contact_gripper (..., G) bool, contact_support (...) bool).
        The contact part of :meth:`signals`, without the forces."""
        sd = np.asarray(sensordata, dtype=np.float64)
        lead = sd.shape[:-1]
        touch = [(sd[..., found] > 0).any(axis=-1) for found in self._grip_found]
        gripper = (np.stack(touch, axis=-1) if touch else np.zeros(lead + (0,), bool))
        return gripper, (sd[..., self._support_adr] > 0).any(axis=-1)

    def signals(self, sensordata: np.ndarray, mu: np.ndarray | float | None = None, *,
                limits: np.ndarray | None = None,
                carried: np.ndarray | None = None) -> Signals:
        """Safety signals from ``sensordata`` (..., nsensordata).

        Args:
            sensordata: sensor readings after a step (or a forward).
            mu: friction of the object's contacts, broadcastable to the leading shape
                (...); default: the nominal model's.
            limits: the actuators' force limits, broadcastable to (..., nu) (a sample's
                :meth:`sample_limits` row where the box varies one); default :attr:`limits`.
            carried: where the grip must carry the object, broadcastable to (...) bool;
                default: wherever a gripper holds the object off its support in
                ``sensordata``. Sparse evaluation passes the nominal run's flags, so that an
                object too heavy to lift, which stays on (or sinks back onto) the table, still
                counts as slipping, and one that falls out of the grip counts as falling.
        """
        sd = np.asarray(sensordata, dtype=np.float64)
        lead = sd.shape[:-1]
        if mu is None:
            mu = self.object_friction()
        mu = np.asarray(mu, dtype=np.float64)[..., None]
        # eq. 12 per gripper, and over every object-gripper contact for the grasp: a
        # releasing gripper's slip weighs little next to a gripper that holds
        fos_c, totals, demands = [], [], []
        for adr in self._grip_adr:
            block = sd[..., adr].reshape(lead + (-1, 4))  # (..., slots, [found, fn, ft1, ft2])
            total, demand = safety.contact_load(
                block[..., 1], np.hypot(block[..., 2], block[..., 3]), mu)
            fos_c.append(safety.fos_ratio(total, demand))
            totals.append(total)
            demands.append(demand)
        fos_contact = np.stack(fos_c, axis=-1)
        contact_gripper, contact_support = self.contact_flags(sd)
        # the grip only carries the object off its support
        fos_grasp = safety.fos_ratio(sum(totals, np.zeros(lead)), sum(demands, np.zeros(lead)))
        if carried is None:
            carried = self.task.must_carry(contact_gripper, contact_support)
        # carried but touched by no gripper: the object is falling (FOS 0, a failure)
        held = np.where(contact_gripper.any(axis=-1), fos_grasp, 0.0)
        fos_grasp = np.where(np.broadcast_to(carried, fos_grasp.shape), held, np.inf)
        acc = sd[..., self._acc_adr] + self.model.opt.gravity
        force = sd[..., self._force_adr].copy()  # the signals own their arrays
        # per simulation where the box varies a force limit (:meth:`sample_limits`)
        limits = self.limits if limits is None else np.asarray(limits, dtype=np.float64)
        fos_m, arg = safety.motor_fos(force[..., self.motors], limits[..., self.motors])
        rot_ids = np.flatnonzero(self.motors)
        cost = safety.cost(fos_grasp, fos_m, self.scenario.cost)
        pos = sd[..., self._pos_adr].copy()
        stage = self.task.stage(contact_gripper, contact_support, pos)
        return Signals(object_pos=pos, object_vel=sd[..., self._vel_adr].copy(), object_acc=acc, actuator_force=force, actuator_norm=force / limits,
                       fos_contact=fos_contact, fos_grasp=fos_grasp, fos_motor=fos_m, motor_argmax=rot_ids[arg],
                       cost=cost, contact_support=contact_support,
                       contact_gripper=contact_gripper, stage=stage)



def _as_slice(index: np.ndarray) -> np.ndarray | slice:
    """``index`` as a slice when its entries are consecutive (reading through it gives the
    same values as a view), else unchanged."""
    index = np.asarray(index, dtype=np.int64)
    if index.size and np.array_equal(index, np.arange(index[0], index[0] + index.size)):
        return slice(int(index[0]), int(index[0]) + index.size)
    return index


_QUIET_LOCK = threading.Lock()
_QUIET = {"depth": 0, "before": None}


@contextlib.contextmanager
def quiet_mujoco_log() -> Iterator[None]:
    """MuJoCo's own log (the ``MUJOCO_LOG.TXT`` file in the current folder and the console)
    off inside the block, its previous settings back after; MuJoCo's warning counters, which
    critmoment reads, still count. The settings are the process's: blocks nested or in
    several threads at once switch them off at the first entry and back at the last exit.
    ``analyze``, ``validate``, ``rollout`` and ``brute_force`` run in one (:func:`entry_point`) (a library call
    that met a diverging sample had left ``MUJOCO_LOG.TXT`` in the caller's folder)."""
    if not hasattr(mujoco, "MjLogConfig"):  # a MuJoCo without the log settings
        yield
        return
    with _QUIET_LOCK:
        if _QUIET["depth"] == 0:
            config = mujoco.MjLogConfig.get()
            _QUIET["before"] = (config.logto_file, config.logto_console)
            config.logto_file, config.logto_console = False, False
            config.set()
        _QUIET["depth"] += 1
    try:
        yield
    finally:
        with _QUIET_LOCK:
            _QUIET["depth"] -= 1
            if _QUIET["depth"] == 0:
                config = mujoco.MjLogConfig.get()
                config.logto_file, config.logto_console = _QUIET["before"]
                config.set()


#: the warnings given during the outermost library call in progress (:func:`entry_point`)
_CALL_WARNINGS: contextvars.ContextVar[set | None] = contextvars.ContextVar(
    "critmoment_call_warnings", default=None)


def entry_point(fn):
    """``fn`` as a library entry point (``analyze``, ``validate``, ``rollout``,
    ``brute_force``): inside :func:`quiet_mujoco_log`, and with :func:`warn_once` giving
    each warning once over the call, the entry points it calls included (``analyze``'s own
    rollout warned again of what ``analyze`` had)."""

    @functools.wraps(fn)
    def run(*args, **kwargs):
        token = _CALL_WARNINGS.set(set()) if _CALL_WARNINGS.get() is None else None
        try:
            with quiet_mujoco_log():
                return fn(*args, **kwargs)
        finally:
            if token is not None:
                _CALL_WARNINGS.reset(token)

    return run


def warn_once(message: str, category: type[Warning], *, stacklevel: int = 2) -> None:
    """``warnings.warn``, once per :func:`entry_point` call for the same message."""
    seen = _CALL_WARNINGS.get()
    if seen is not None:
        if message in seen:
            return
        seen.add(message)
    warnings.warn(message, category, stacklevel=stacklevel + 1)


#: how far qpos0's object pose may lie from an object_pose given beside it before the
#: override is warned of [m], [rad]
POSE_AGREEMENT = (1e-3, np.radians(1.0))


#: how far [rad] an arm joint's qpos0 and the position its start control holds may differ
#: before a trajectory that gives both is warned of (a tenth of it in metres on a slide)
START_AGREEMENT = 0.05


def _warn_pose_disagreement(in_qpos0: np.ndarray, pose: np.ndarray) -> None:
    """qpos0 and object_pose both place the object: object_pose wins, which is what a
    caller overriding a recorded pose means, but a file whose two records disagree is more
    often a slip (a pose in another frame, a stale field), so say which pose is used."""
    shift = float(np.linalg.norm(in_qpos0[:3] - pose[:3]))
    dot = abs(float(np.dot(in_qpos0[3:] / np.linalg.norm(in_qpos0[3:]),
                           pose[3:] / np.linalg.norm(pose[3:]))))
    turn = 2.0 * float(np.arccos(min(dot, 1.0)))
    if shift > POSE_AGREEMENT[0] or turn > POSE_AGREEMENT[1]:
        warnings.warn(
            f"object_pose {np.round(pose[:3], 4).tolist()} (m) replaces the object's pose in "
            f"qpos0, {np.round(in_qpos0[:3], 4).tolist()}: they differ by {shift * 1e3:.1f} mm "
            f"and {np.degrees(turn):.1f} deg; the run starts from object_pose (drop one of the "
            f"two if that is not meant)", CritmomentWarning, stacklevel=3)


def _check_qpos_quaternions(model: mujoco.MjModel, qpos: np.ndarray) -> None:
    """Every free and ball joint's quaternion in ``qpos`` must be a unit quaternion (within
    1 %): MuJoCo would silently replace a zero one by the identity and rescale any other.

    Raises:
        TrajectoryError: naming the joint, its qpos addresses and the norm found.
    """
    for j in range(model.njnt):
        kind = int(model.jnt_type[j])
        if kind not in (int(mujoco.mjtJoint.mjJNT_FREE), int(mujoco.mjtJoint.mjJNT_BALL)):
            continue
        adr = int(model.jnt_qposadr[j]) + (3 if kind == int(mujoco.mjtJoint.mjJNT_FREE) else 0)
        norm = float(np.linalg.norm(qpos[adr:adr + 4]))
        if not abs(norm - 1.0) <= 0.01:
            name = model.joint(j).name or f"joint #{j}"
            raise TrajectoryError(
                f"qpos0: expected a unit quaternion (w, x, y, z) for joint {name!r} at "
                f"qpos[{adr}:{adr + 4}], got {qpos[adr:adr + 4].tolist()} with norm {norm:.6g}")


def _check_qpos_ranges(model: mujoco.MjModel, qpos: np.ndarray, *, slack: float = 1.0) -> None:
    """Every limited hinge and slide joint in ``qpos`` within its range widened by ``slack``
    of its width on each side: far outside, the limit's constraint throws the joint back and
    the run diverges at once (50 rad on a ±3 rad joint). A little outside is left to the
    limit (MuJoCo's own qpos0 puts a slide finger at 0 below a range starting at 0.021 m).

    Raises:
        TrajectoryError: naming the joint, its value and its range.
    """
    for j in range(model.njnt):
        kind = int(model.jnt_type[j])
        if kind not in (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE)) \
                or not model.jnt_limited[j]:
            continue
        lo, hi = (float(v) for v in model.jnt_range[j])
        margin = slack * (hi - lo)
        value = float(qpos[model.jnt_qposadr[j]])
        if not lo - margin <= value <= hi + margin:
            name = model.joint(j).name or f"joint #{j}"
            unit = "rad" if kind == int(mujoco.mjtJoint.mjJNT_HINGE) else "m"
            raise TrajectoryError(
                f"qpos0: joint {name!r} at {value:g} {unit}, outside its range [{lo:g}, {hi:g}] "
                f"{unit}; expected a start pose the model allows (qpos0 is in MuJoCo's qpos "
                f"order, radians and metres)")


def _scenario_label(scenario) -> str:
    name = getattr(scenario, "name", None)
    if isinstance(scenario, Twin):
        name = scenario.scenario.name
    return repr(name if isinstance(name, str) else str(scenario))


def _same_scenario(scenario, twin: Twin) -> bool:
    """Whether ``scenario`` (as :func:`resolve_twin` takes it) names ``twin``'s scenario."""
    own = twin.scenario
    if scenario is twin or scenario is own:
        return True
    if isinstance(scenario, type(own)):
        try:
            return bool(scenario == own)
        except (ValueError, TypeError):  # fields holding arrays compare element-wise
            return scenario.name == own.name and scenario.path == own.path
    if isinstance(scenario, (str, os.PathLike)):
        text = os.fspath(scenario)
        if text == own.name:
            return True
        if own.path is not None:
            given = os.path.abspath(text)
            return given in (os.path.abspath(own.path), os.path.abspath(own.path.parent))
    return False


def resolve_twin(scenario=None, twin: Twin | None = None) -> Twin:
    """The twin a library call runs on: ``twin`` if given, else one built from ``scenario``
    (a :class:`~critmoment.scenario.Scenario`, a :class:`Twin`, a path to a scenario.toml or
    its folder, a bundled scenario's name, or None for the bundled default).

    Raises:
        ScenarioError: ``scenario`` or ``twin`` of another type.
    """
    from os import PathLike

    from critmoment.scenario import Scenario, load_scenario

    if twin is not None:
        if not isinstance(twin, Twin):
            raise ScenarioError(f"twin: expected a critmoment Twin, got "
                                f"{type(twin).__name__}")
        if scenario is not None and not _same_scenario(scenario, twin):
            warnings.warn(
                f"both a scenario ({_scenario_label(scenario)}) and a twin (of "
                f"{twin.scenario.name!r}) were given; the twin's scenario is used (pass one "
                f"of them)", CritmomentWarning, stacklevel=3)
        return twin
    if isinstance(scenario, Twin):
        return scenario
    if isinstance(scenario, Scenario):
        return Twin(scenario)
    if scenario is None or isinstance(scenario, (str, PathLike)):
        return Twin(load_scenario(scenario))
    raise ScenarioError(
        f"scenario: expected a Scenario, a Twin, a path to a scenario.toml, a bundled "
        f"scenario's name or None, got {type(scenario).__name__}")


def _mocap_hint(model: mujoco.MjModel) -> str:
    """Why a model's arm may have no actuators: a mocap body welded to it moves it (as in
    teleoperation and end-effector-control scenes); empty if none is."""
    welds = []
    for e in range(model.neq):
        if (model.eq_type[e] != mujoco.mjtEq.mjEQ_WELD
                or model.eq_objtype[e] != mujoco.mjtObj.mjOBJ_BODY):
            continue
        a, b = int(model.eq_obj1id[e]), int(model.eq_obj2id[e])
        for mocap, other in ((a, b), (b, a)):
            if model.body_mocapid[mocap] >= 0:
                welds.append(f"mocap body {model.body(mocap).name!r} welded to "
                             f"{model.body(other).name!r}")
    if not welds:
        return ""
    return (f"; the model moves its arm with a {', '.join(welds)} (end-effector control): "
            "critmoment replays joint-space actions through the model's actuators, so give "
            "the arm's joints position actuators and remove the weld")


def _qpos_layout(model: mujoco.MjModel) -> str:
    """The model's joint coordinates in a few words: how many, and where its free and ball
    joints (several coordinates each) sit."""
    multi = []
    for j in range(model.njnt):
        kind = int(model.jnt_type[j])
        if kind in (int(mujoco.mjtJoint.mjJNT_FREE), int(mujoco.mjtJoint.mjJNT_BALL)):
            name = (repr(model.joint(j).name) if model.joint(j).name
                    else f"of body {model.body(model.jnt_bodyid[j]).name!r}")
            size = 7 if kind == int(mujoco.mjtJoint.mjJNT_FREE) else 4
            adr = int(model.jnt_qposadr[j])
            multi.append(f"{'free' if size == 7 else 'ball'} joint {name} at "
                         f"qpos[{adr}:{adr + size}]")
    return (f"the model has {model.njnt} joints, {model.nq} coordinates"
            + (f", with {', '.join(multi)}" if multi else ""))


def _joint_targets(model: mujoco.MjModel) -> tuple[np.ndarray, np.ndarray]:
    """Per actuator, the joint position it holds at rest as ``scale·ctrl + offset``
    (:func:`critmoment.actuators.position_target`, linear in ctrl); for an actuator that
    tracks no position or drives no joint, ctrl / gear."""
    scale = np.empty(model.nu)
    offset = np.zeros(model.nu)
    for a in range(model.nu):
        zero = act_info.position_target(model, a, 0.0)
        one = act_info.position_target(model, a, 1.0)
        if zero is None or one is None:
            scale[a] = 1.0 / (float(model.actuator_gear[a, 0]) or 1.0)
        else:
            scale[a], offset[a] = one - zero, zero
    return scale, offset


def _arm_actuators(model: mujoco.MjModel, scenario: Scenario) -> tuple[str, ...]:
    """Joint actuators (hinge or slide) that move the arm rather than a gripper's fingers
    (their force, a grip's squeeze, is limited on purpose and stays out of the motor
    checks): driven by a channel that is not a normalised gripper channel, on a joint whose
    body is not below a gripper's base (the deepest body above all its geoms; a base that is
    the world, a "gripper" whose geoms hang on different arms, names no fingers)."""
    conv = scenario.actions
    fingers = {a for c, acts in enumerate(conv.channels) if conv.normalised[c] for a in acts}
    bases = {act_info.common_ancestor(model, [int(model.geom_bodyid[model.geom(g).id])
                                              for g in grip.geoms])
             for grip in scenario.grippers} - {0}

    def below_a_base(body: int) -> bool:
        while body > 0:
            body = int(model.body_parentid[body])
            if body in bases:
                return True
        return False

    out = []
    for i in range(model.nu):
        name = model.actuator(i).name
        j = int(model.actuator_trnid[i, 0])
        if (model.actuator_trntype[i] == mujoco.mjtTrn.mjTRN_JOINT
                and int(model.jnt_type[j]) in (int(mujoco.mjtJoint.mjJNT_HINGE),
                                               int(mujoco.mjtJoint.mjJNT_SLIDE))
                and name not in fingers and not below_a_base(int(model.jnt_bodyid[j]))):
            out.append(name)
    return tuple(out)
