"""What a model's actuators are: type, target, control and force ranges.

MuJoCo's actuators are all ``general`` underneath: force = gain·ctrl + bias with
gain and bias affine in the actuator length and velocity. critmoment needs to know
which of the common shapes each one is, because a joint-position action channel only
makes sense on a position-like actuator (a position servo, or a ``general`` one with an
affine bias that pulls towards ctrl), never on a torque motor.

:func:`describe` reads that off the compiled model; :func:`force_limit` gives the
default force limit from the MJCF (``forcerange`` of the actuator, else
``actuatorfrcrange`` of its joint), or None when the model states none;
:func:`gripper_gap` measures how far apart a gripper's geoms are at a control value, so
that a normalised gripper channel knows which end of the control range closes it.
"""

from __future__ import annotations

import copy
import dataclasses
import enum
from collections.abc import Sequence

import mujoco
import numpy as np

__all__ = ["ActuatorKind", "ActuatorInfo", "describe", "describe_all", "force_limit",
           "gripper_gap", "into_ranges", "control_span", "closing_ends", "closing_end", "moves_geoms",
           "position_target", "joint_force_limit", "body_chain", "common_ancestor",
           "robot_bases", "supporting_joints", "closing_projector", "AXIS_TOLERANCE",
           "collision_geoms", "geom_pairs",
           "filtered_actuators", "ContactParameters", "contact_parameters",
           "dynamic_partners", "grip_friction_sources", "grip_condims", "source_friction"]


def collision_geoms(model: mujoco.MjModel) -> np.ndarray:
    """Which geoms can touch anything, (ngeom,) bool: bits (contype, conaffinity) that match
    another geom's (MuJoCo collides two geoms when either's contype shares a bit with the
    other's conaffinity), or a place in an explicit ``<pair>`` (which MuJoCo collides
    whatever the two geoms' bits say; some models give their objects contacts only that
    way). Fingertip pads whose bits match no other geom (lerobot's SO-101 as shipped) touch
    nothing and are not counted."""
    ct = model.geom_contype.astype(np.int64)
    ca = model.geom_conaffinity.astype(np.int64)
    patterns, inverse, counts = np.unique(np.stack([ct, ca], axis=1), axis=0,
                                          return_inverse=True, return_counts=True)
    inverse = np.asarray(inverse).reshape(-1)
    pc, pa = patterns[:, 0], patterns[:, 1]
    meets = ((pc[:, None] & pa[None, :]) | (pc[None, :] & pa[:, None])) != 0
    # a pattern meets itself only through another geom of that pattern
    np.fill_diagonal(meets, np.diag(meets) & (counts > 1))
    mask = meets.any(axis=1)[inverse] if model.ngeom else np.zeros(0, bool)
    mask[model.pair_geom1] = True
    mask[model.pair_geom2] = True
    return mask


def geom_pairs(model: mujoco.MjModel, geoms: Sequence[int]) -> np.ndarray:
    """The ids of the explicit ``<pair>`` elements in which any of ``geoms`` takes part. Their
    own friction, condim and solver parameters replace the geoms' (and MuJoCo skips dynamic
    contacts between the two bodies)."""
    geoms = np.asarray(list(geoms), dtype=int)
    return np.flatnonzero(np.isin(model.pair_geom1, geoms) | np.isin(model.pair_geom2, geoms))


@dataclasses.dataclass(frozen=True)
class ContactParameters:
    """The parameters of a contact between two geoms, as MuJoCo sets them.

    Attributes:
        condim: contact dimensionality.
        friction: (5,) sliding, sliding, torsional, rolling, rolling.
        solref: (2,) and solimp: (5,) the solver's reference and impedance.
        margin, gap: distances [m].
    """

    condim: int
    friction: tuple[float, ...]
    solref: tuple[float, ...]
    solimp: tuple[float, ...]
    margin: float
    gap: float


def contact_parameters(model: mujoco.MjModel, g1: int, g2: int) -> ContactParameters:
    """MuJoCo's parameters for a dynamic (not ``<pair>``) contact between geoms ``g1`` and
    ``g2``: every one of the geom of higher priority, or at equal priority the larger condim,
    the element-wise larger friction, solref and solimp weighted by ``solmix`` (the smaller
    solref where either is a direct, negative one); margin and gap the sums of the two
    geoms' (MuJoCo 4; its contacts' ``includemargin`` is that margin)."""
    p1, p2 = int(model.geom_priority[g1]), int(model.geom_priority[g2])
    if p1 != p2:
        g = g1 if p1 > p2 else g2
        condim = int(model.geom_condim[g])
        fr = model.geom_friction[g]
        solref, solimp = model.geom_solref[g], model.geom_solimp[g]
    else:
        condim = int(max(model.geom_condim[g1], model.geom_condim[g2]))
        fr = np.maximum(model.geom_friction[g1], model.geom_friction[g2])
        m1, m2 = float(model.geom_solmix[g1]), float(model.geom_solmix[g2])
        tiny = mujoco.mjMINVAL
        if m1 >= tiny and m2 >= tiny:
            mix = m1 / (m1 + m2)
        elif m1 < tiny and m2 < tiny:
            mix = 0.5
        else:
            mix = 0.0 if m1 < tiny else 1.0
        r1, r2 = model.geom_solref[g1], model.geom_solref[g2]
        solref = (mix * r1 + (1 - mix) * r2 if r1[0] > 0 and r2[0] > 0
                  else np.minimum(r1, r2))
        solimp = mix * model.geom_solimp[g1] + (1 - mix) * model.geom_solimp[g2]
    return ContactParameters(
        condim=condim,
        friction=(float(fr[0]), float(fr[0]), float(fr[1]), float(fr[2]), float(fr[2])),
        solref=tuple(float(v) for v in solref), solimp=tuple(float(v) for v in solimp),
        margin=float(model.geom_margin[g1] + model.geom_margin[g2]),
        gap=float(model.geom_gap[g1] + model.geom_gap[g2]))


def dynamic_partners(model: mujoco.MjModel, geom: int) -> list[int]:
    """The geoms MuJoCo's dynamic collision may pair with ``geom``: their contype and
    conaffinity bits match, they sit on another body that is neither welded to it nor its
    parent (unless the parent is the world), and no ``<exclude>`` or explicit ``<pair>``
    joins the two bodies."""
    b = int(model.geom_bodyid[geom])
    weld = int(model.body_weldid[b])
    parent_weld = int(model.body_weldid[model.body_parentid[weld]])
    filter_parent = not (model.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_FILTERPARENT)
    skip = set(model.exclude_signature.tolist()) | set(model.pair_signature.tolist())
    out = []
    for x in range(model.ngeom):
        bx = int(model.geom_bodyid[x])
        if bx == b or not (model.geom_contype[geom] & model.geom_conaffinity[x]
                           or model.geom_contype[x] & model.geom_conaffinity[geom]):
            continue
        wx = int(model.body_weldid[bx])
        if wx == weld:
            continue
        if filter_parent and weld != 0 and wx != 0 and (
                wx == parent_weld or weld == int(model.body_weldid[model.body_parentid[wx]])):
            continue
        lo, hi = sorted((b, bx))
        if (lo << 16) + hi in skip:
            continue
        out.append(x)
    return out


def grip_contacts(model: mujoco.MjModel, object_body: int, pad_geoms: Sequence[int]
                   ) -> list[tuple[int, int, int | None]]:
    """The contacts the object's collision geoms can make with ``pad_geoms``: (object geom,
    pad geom, its explicit pair or None). Bodies joined by an explicit pair have no other
    contacts (MuJoCo skips their dynamic ones)."""
    colliding = collision_geoms(model)
    obj = [int(g) for g in np.flatnonzero(model.geom_bodyid == object_body) if colliding[g]]
    pads = sorted({int(g) for g in pad_geoms})
    out = []
    for o in obj:
        partners = set(dynamic_partners(model, o))
        for g in pads:
            pair = [p for p in geom_pairs(model, [o])
                    if {int(model.pair_geom1[p]), int(model.pair_geom2[p])} == {o, g}]
            if pair:
                out.append((o, g, int(pair[0])))
            elif g in partners:
                out.append((o, g, None))
    return out


def grip_friction_sources(model: mujoco.MjModel, object_body: int, pad_geoms: Sequence[int]
                          ) -> list[tuple[str, tuple[int, ...]]]:
    """Where the sliding friction of each contact the object's geoms can make with
    ``pad_geoms`` comes from: an explicit pair (``("pair", (p,))``), the geom of higher
    priority (``("geom", (g,))``) or, at equal priority, the larger of the two (``("max",
    (g1, g2))``). None found: the object geom's own."""
    sources = []
    for o, g, pair in grip_contacts(model, object_body, pad_geoms):
        if pair is not None:
            sources.append(("pair", (pair,)))
        elif model.geom_priority[o] != model.geom_priority[g]:
            top = o if model.geom_priority[o] > model.geom_priority[g] else g
            sources.append(("geom", (top,)))
        else:
            sources.append(("max", (o, g)))
    if sources:
        return sorted(set(sources))
    colliding = collision_geoms(model)
    obj = [int(g) for g in np.flatnonzero(model.geom_bodyid == object_body) if colliding[g]]
    return [("geom", (obj[0] if obj else 0,))]


def grip_condims(model: mujoco.MjModel, object_body: int, pad_geoms: Sequence[int]) -> list[int]:
    """The condim of each contact the object's geoms can make with ``pad_geoms`` (an
    explicit pair's own, else MuJoCo's rule for a dynamic contact); empty where none can."""
    return [int(model.pair_dim[pair]) if pair is not None
            else contact_parameters(model, o, g).condim
            for o, g, pair in grip_contacts(model, object_body, pad_geoms)]


def source_friction(sources: Sequence[tuple[str, tuple[int, ...]]], geom_friction: np.ndarray,
                    pair_friction: np.ndarray) -> np.ndarray:
    """The lowest sliding friction over ``sources`` (:func:`grip_friction_sources`), per
    simulation, from ``geom_friction`` (n, ngeom, 3) and ``pair_friction`` (n, npair, 5)
    (n may be 1 for either)."""
    geom, pair = np.asarray(geom_friction), np.asarray(pair_friction)
    n = max(geom.shape[0], pair.shape[0])
    values = []
    for kind, ids in sources:
        if kind == "pair":
            values.append(np.broadcast_to(pair[:, ids[0], 0], (n,)))
        elif kind == "geom":
            values.append(np.broadcast_to(geom[:, ids[0], 0], (n,)))
        else:
            values.append(np.broadcast_to(np.maximum(geom[:, ids[0], 0], geom[:, ids[1], 0]),
                                          (n,)))
    return np.min(values, axis=0)


#: what to do with a plugin actuator (:attr:`ActuatorKind.PLUGIN`) on a joint the trajectory
#: drives: critmoment cannot tell what its control means
PLUGIN_ADVICE = ("its force is the plugin's own law, whose control critmoment cannot read; "
                 "drive the joint with a <position> servo of the same gains to audit it")


class ActuatorKind(enum.Enum):
    """The shape of an actuator's force law."""

    POSITION = "position"      # gain kp·ctrl, bias −kp·length (−kv·velocity): a servo on ctrl
    AFFINE = "general-affine"  # general with an affine bias: a servo on −bias0/bias1 ... of ctrl
    VELOCITY = "velocity"      # gain kv·ctrl, bias −kv·velocity
    INTVELOCITY = "intvelocity"  # a servo on the integral of ctrl: ctrl is a velocity
    MOTOR = "motor"            # force = gear·ctrl: a torque (or force) command
    ADHESION = "adhesion"      # <adhesion>: a suction/magnet pull on a body's contacts, gain·ctrl
    PLUGIN = "plugin"          # an engine plugin computes its force (mujoco.pid, ...)
    OTHER = "other"            # muscles, dampers, user dynamics

    @property
    def tracks_position(self) -> bool:
        """Whether ctrl is a position target (the action convention's joint channels)."""
        return self in (ActuatorKind.POSITION, ActuatorKind.AFFINE)


_TRN = {
    mujoco.mjtTrn.mjTRN_JOINT: "joint", mujoco.mjtTrn.mjTRN_JOINTINPARENT: "joint",
    mujoco.mjtTrn.mjTRN_TENDON: "tendon", mujoco.mjtTrn.mjTRN_SITE: "site",
    mujoco.mjtTrn.mjTRN_SLIDERCRANK: "slider-crank", mujoco.mjtTrn.mjTRN_BODY: "body",
}


@dataclasses.dataclass(frozen=True)
class ActuatorInfo:
    """One actuator, as :func:`describe` reads it.

    Attributes:
        index: actuator id.
        name: its name ("" when unnamed).
        kind: the force law's shape.
        transmission: "joint", "tendon", "site", ...
        target: name of the joint or tendon it drives ("" when unnamed).
        joint_type: "hinge", "slide", ... for a joint transmission, else "".
        ctrlrange: (low, high), or None when the control is unlimited.
        forcerange: the model's force limit (low, high) [N·m or N], or None.
        gain: kp (position) / kv (velocity) / gear (motor), for reports.
    """

    index: int
    name: str
    kind: ActuatorKind
    transmission: str
    target: str
    joint_type: str
    ctrlrange: tuple[float, float] | None
    forcerange: tuple[float, float] | None
    gain: float

    @property
    def label(self) -> str:
        """Its name, or ``<transmission> <target>`` when unnamed."""
        return self.name or f"{self.transmission} {self.target or '#' + str(self.index)}"

    def to_json(self) -> dict:
        return {"index": self.index, "name": self.name, "kind": self.kind.value,
                "transmission": self.transmission, "target": self.target,
                "joint_type": self.joint_type,
                "ctrlrange": list(self.ctrlrange) if self.ctrlrange else None,
                "forcerange": list(self.forcerange) if self.forcerange else None,
                "gain": self.gain}


def filtered_actuators(model: mujoco.MjModel) -> np.ndarray:
    """Actuators whose activation low-pass filters their control (``dyntype`` filter or
    filterexact, e.g. ``<position timeconst>``): at rest their activation equals the
    control."""
    dyn = model.actuator_dyntype
    return np.flatnonzero(((dyn == int(mujoco.mjtDyn.mjDYN_FILTER))
                           | (dyn == int(mujoco.mjtDyn.mjDYN_FILTEREXACT)))
                          & (model.actuator_actadr >= 0))


def _kind(model: mujoco.MjModel, i: int) -> ActuatorKind:
    gain_t, bias_t = model.actuator_gaintype[i], model.actuator_biastype[i]
    g, b = model.actuator_gainprm[i], model.actuator_biasprm[i]
    fixed, affine = mujoco.mjtGain.mjGAIN_FIXED, mujoco.mjtBias.mjBIAS_AFFINE
    dyn = int(model.actuator_dyntype[i])
    if int(model.actuator_plugin[i]) >= 0:
        # its force is the plugin's (mujoco.pid's: a servo on ctrl), not gain·ctrl + bias:
        # read as a torque motor, init had written a PD servo whose force limit was the set
        # point's range
        return ActuatorKind.PLUGIN
    if dyn == int(mujoco.mjtDyn.mjDYN_INTEGRATOR):
        # the activation integrates ctrl: <intvelocity> (a servo on ∫ctrl, ctrl a velocity)
        return (ActuatorKind.INTVELOCITY if gain_t == fixed and bias_t == affine
                else ActuatorKind.OTHER)
    if dyn not in (int(mujoco.mjtDyn.mjDYN_NONE), int(mujoco.mjtDyn.mjDYN_FILTER),
                   int(mujoco.mjtDyn.mjDYN_FILTEREXACT)):
        return ActuatorKind.OTHER  # muscles, user dynamics
    if gain_t == fixed and bias_t == mujoco.mjtBias.mjBIAS_NONE:
        if int(model.actuator_trntype[i]) == int(mujoco.mjtTrn.mjTRN_BODY):
            return ActuatorKind.ADHESION  # MuJoCo's only body transmission
        return ActuatorKind.MOTOR
    if gain_t == fixed and bias_t == affine:
        if b[1] != 0 and np.isclose(b[1], -g[0]) and b[0] == 0:
            return ActuatorKind.POSITION
        if b[1] < 0:
            return ActuatorKind.AFFINE
        if b[1] == 0 and b[2] != 0 and np.isclose(b[2], -g[0]):
            return ActuatorKind.VELOCITY
    return ActuatorKind.OTHER


def force_limit(model: mujoco.MjModel, i: int) -> float | None:
    """Default force limit of actuator ``i`` from the MJCF [N·m or N, in the actuator's own
    units: before its gear], or None.

    The smaller of its own ``forcerange`` (when ``forcelimited``) and the
    ``actuatorfrcrange`` of the joint it drives (divided by the gear): MuJoCo clamps the
    force by both, so the tighter one is the limit. Each range's limit is the smaller
    magnitude of its two ends (a one-sided range gives its one side).
    """
    own = range_limit(model.actuator_forcerange[i]) if model.actuator_forcelimited[i] else None
    return _tighter(own, joint_force_limit(model, i))


def joint_force_limit(model: mujoco.MjModel, i: int) -> float | None:
    """The limit the ``actuatorfrcrange`` of the joint actuator ``i`` drives sets on its
    force, in the actuator's units (the joint's range over the gear), or None."""
    if int(model.actuator_trntype[i]) not in (int(mujoco.mjtTrn.mjTRN_JOINT),
                                              int(mujoco.mjtTrn.mjTRN_JOINTINPARENT)):
        return None
    j = model.actuator_trnid[i, 0]
    if not model.jnt_actfrclimited[j]:
        return None
    limit = range_limit(model.jnt_actfrcrange[j])
    return None if limit is None else limit / (abs(float(model.actuator_gear[i, 0])) or 1.0)


def _tighter(*limits: float | None) -> float | None:
    given = [v for v in limits if v is not None]
    return min(given) if given else None


def range_limit(bounds: Sequence[float]) -> float | None:
    """The limit a force range ``(low, high)`` sets: the smaller magnitude of its non-zero
    ends (a one-sided range gives its one side), or None when both ends are 0."""
    ends = [abs(float(v)) for v in bounds if v != 0]
    return min(ends) if ends else None


def motor_force_range(ctrlrange: Sequence[float], gain: float, forcerange: Sequence[float], *,
                      ctrl_limited: bool, force_limited: bool) -> np.ndarray | None:
    """The force ``(low, high)`` a torque motor can give (before its gear): its control
    range times its gain, within its own force range; None when neither bounds it."""
    bounds = []
    if ctrl_limited:
        bounds.append(np.sort(float(gain) * np.asarray(ctrlrange, float)))
    if force_limited:
        bounds.append(np.asarray(forcerange, float))
    if not bounds:
        return None
    return np.array([max(b[0] for b in bounds), min(b[1] for b in bounds)])


def motor_limit(model: mujoco.MjModel, i: int) -> float | None:
    """The force limit [N·m or N, before the gear] of torque motor ``i`` when ``[servos]``
    drives it as a joint servo: its control range times its gain, within its force range
    (:func:`motor_force_range`, what :func:`critmoment.scenario.prepare_spec` gives the
    servo), else :func:`force_limit`."""
    bounds = motor_force_range(
        model.actuator_ctrlrange[i], float(model.actuator_gainprm[i, 0]),
        model.actuator_forcerange[i], ctrl_limited=bool(model.actuator_ctrllimited[i]),
        force_limited=bool(model.actuator_forcelimited[i]))
    limit = range_limit(bounds) if bounds is not None else None
    return _tighter(limit, joint_force_limit(model, i))


def describe(model: mujoco.MjModel, i: int) -> ActuatorInfo:
    """Read actuator ``i`` of ``model``."""
    transmission = _TRN.get(mujoco.mjtTrn(int(model.actuator_trntype[i])), "other")
    target, joint_type = "", ""
    tid = model.actuator_trnid[i, 0]
    if transmission == "joint":
        target = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, tid) or ""
        joint_type = mujoco.mjtJoint(model.jnt_type[tid]).name.removeprefix("mjJNT_").lower()
    elif transmission == "tendon":
        target = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_TENDON, tid) or ""
    elif transmission == "site":
        target = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_SITE, tid) or ""
    elif transmission == "body":
        target = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, tid) or f"#{tid}"
    kind = _kind(model, i)
    gain = float(model.actuator_gainprm[i, 0])
    if kind is ActuatorKind.MOTOR:
        gain = float(model.actuator_gear[i, 0])
    ctrl = (tuple(float(v) for v in model.actuator_ctrlrange[i])
            if model.actuator_ctrllimited[i] else None)
    frc = (tuple(float(v) for v in model.actuator_forcerange[i])
           if model.actuator_forcelimited[i] else None)
    return ActuatorInfo(index=i, name=model.actuator(i).name, kind=kind,
                        transmission=transmission, target=target, joint_type=joint_type,
                        ctrlrange=ctrl, forcerange=frc, gain=gain)


def describe_all(model: mujoco.MjModel) -> tuple[ActuatorInfo, ...]:
    """:func:`describe` of every actuator."""
    return tuple(describe(model, i) for i in range(model.nu))


def moved_bodies(model: mujoco.MjModel, i: int, *, sites: bool = False) -> list[int]:
    """Bodies actuator ``i`` moves: the body of the joint it drives, or of the joints its
    tendon wraps; with ``sites``, also the body of its site (a site transmission), of the
    sites its tendon wraps, and its body (a body transmission)."""
    trn = mujoco.mjtTrn
    kind, tid = int(model.actuator_trntype[i]), int(model.actuator_trnid[i, 0])
    if kind in (trn.mjTRN_JOINT, trn.mjTRN_JOINTINPARENT):
        return [int(model.jnt_bodyid[tid])]
    if kind == trn.mjTRN_TENDON:
        adr, num = model.tendon_adr[tid], model.tendon_num[tid]
        bodies = []
        for w in range(adr, adr + num):
            if model.wrap_type[w] == mujoco.mjtWrap.mjWRAP_JOINT:
                bodies.append(int(model.jnt_bodyid[model.wrap_objid[w]]))
            elif sites and model.wrap_type[w] == mujoco.mjtWrap.mjWRAP_SITE:
                bodies.append(int(model.site_bodyid[model.wrap_objid[w]]))
        return bodies
    if sites and kind == trn.mjTRN_SITE:
        return [int(model.site_bodyid[tid])]
    if sites and kind == trn.mjTRN_BODY:
        return [tid]
    return []


#: finger slide axes closer than this [rad] to the span of the others are the same closing
#: direction: a model's quaternions rounded to six digits (Menagerie's PiPER) leave its two
#: fingers' axes 4e-6 rad apart, which had counted as a second closing axis and projected
#: out the slip along the fingers
AXIS_TOLERANCE = 1e-3


def closing_projector(axes: Sequence[np.ndarray]) -> np.ndarray:
    """The projector (3, 3) onto the plane normal to the span of a gripper's finger slide
    ``axes`` (each (3,), in its base's frame; the identity for none): squeezing along them is
    not slip. Directions the axes span by less than :data:`AXIS_TOLERANCE` (relative
    singular value) do not count."""
    if not len(axes):
        return np.eye(3)
    u, sv, _ = np.linalg.svd(np.asarray(axes, dtype=np.float64).T, full_matrices=False)
    basis = u[:, sv > AXIS_TOLERANCE * sv.max()]
    return np.eye(3) - basis @ basis.T


def robot_bases(model: mujoco.MjModel) -> list[int]:
    """The free bodies that carry the robot: a body with a free joint below which an
    actuator moves something (a mobile or legged robot's base, a humanoid's pelvis), in body
    order. Such a body is not an object, and what it does (tip, slide) is the robot's own
    balance."""
    free = [int(model.jnt_bodyid[j]) for j in range(model.njnt)
            if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
    if not free:
        return []
    moved = {b for i in range(model.nu) for b in moved_bodies(model, i, sites=True)}
    out = []
    for base in free:
        if any(base in body_chain(model, b) for b in moved):
            out.append(base)
    return out


def supporting_joints(model: mujoco.MjModel, data: mujoco.MjData, bases: Sequence[int],
                      exclude: Sequence[int] = ()) -> set[int]:
    """The joints that carry a free robot base on its contacts in ``data`` (collision done):
    for each contact between a body below a base in ``bases`` and a body that is not (the
    floor, a table; bodies in ``exclude``, the object, left out), the joints on the chain
    from that body up to the base (a leg's hip and knee: their load includes the robot's
    weight, which inverse dynamics of a floating chain leaves out)."""
    if not bases:
        return set()
    owner = {}
    for b in range(model.nbody):
        chain = body_chain(model, b)
        owner[b] = next((base for base in bases if base in chain), -1)
    skip = set(int(b) for b in exclude)
    out: set[int] = set()
    for c in data.contact[:data.ncon]:
        b1, b2 = (int(model.geom_bodyid[c.geom1]), int(model.geom_bodyid[c.geom2]))
        for mine, other in ((b1, b2), (b2, b1)):
            base = owner[mine]
            if base < 0 or owner[other] == base or other in skip or mine in skip:
                continue
            b = mine
            while b != base:
                first, num = int(model.body_jntadr[b]), int(model.body_jntnum[b])
                out.update(j for j in range(first, first + num)
                           if model.jnt_type[j] != mujoco.mjtJoint.mjJNT_FREE)
                b = int(model.body_parentid[b])
    return out


def body_chain(model: mujoco.MjModel, body: int) -> list[int]:
    """``body`` and its ancestors up to the world (0), in that order."""
    chain = [int(body)]
    while chain[-1] != 0:
        chain.append(int(model.body_parentid[chain[-1]]))
    return chain


def parts_below(model: mujoco.MjModel, body: int) -> dict[str, list[str]]:
    """The bodies below ``body`` that carry collision geoms, each with those geoms' names
    (an object whose geoms hang on a child body: critmoment audits one body's own geoms)."""
    out: dict[str, list[str]] = {}
    colliding = collision_geoms(model)
    for g in range(model.ngeom):
        b = int(model.geom_bodyid[g])
        if b == body or not colliding[g]:
            continue
        if body in body_chain(model, b):
            out.setdefault(model.body(b).name, []).append(model.geom(g).name)
    return out


def object_parts_message(model: mujoco.MjModel, body: int,
                         parts: dict[str, list[str]]) -> str:
    """The error for an object body with collision geoms on bodies below it: parts fixed
    to it (no joint between) MuJoCo can merge into it; an articulated object is not
    audited."""
    name = model.body(body).name
    listed = "; ".join(f"{b}: {', '.join(gs)}" for b, gs in parts.items())
    rigid = all(int(model.body_weldid[model.body(b).id]) == int(model.body_weldid[body])
                for b in parts)
    fix = (f"they are fixed to it (no joint between), so let MuJoCo merge them into it: add "
           f"<compiler fusestatic=\"true\"/> to the MJCF, or move them onto {name!r}"
           if rigid else
           "some are joined to it by joints (an articulated object), which critmoment does "
           "not audit: make the object one rigid body")
    return (f"[object] body {name!r}: expected its collision geoms on the body itself, got "
            f"collision geoms on bodies below it ({listed}); critmoment reads the contacts, "
            f"mass and friction of the object body's own geoms and would not see these: {fix}")


def common_ancestor(model: mujoco.MjModel, bodies: Sequence[int]) -> int:
    """The deepest body that is ``bodies``' common ancestor (or one of them)."""
    chains = [body_chain(model, b) for b in bodies]
    return next(b for b in chains[0] if all(b in c for c in chains[1:]))


def into_ranges(model: mujoco.MjModel, qpos: np.ndarray,
                joints: Sequence[int] | None = None) -> list[str]:
    """Move each limited hinge or slide joint (of ``joints``, default all) whose position
    in ``qpos`` lies outside its range to mid-range, in place; the names of those moved.
    A model without a keyframe may start outside a range (the Menagerie and franka_sim
    Pandas' joint4 at qpos0 = 0, range −3.07..−0.07), where the limit's constraint jolts
    the joint at every step."""
    moved = []
    for j in range(model.njnt) if joints is None else joints:
        if model.jnt_limited[j] and int(model.jnt_type[j]) in (
                int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE)):
            adr = model.jnt_qposadr[j]
            low, high = model.jnt_range[j]
            if not low <= qpos[adr] <= high:
                qpos[adr] = 0.5 * (low + high)
                moved.append(model.joint(j).name)
    return moved


def gripper_gap(model: mujoco.MjModel, actuators: Sequence[int], ctrl: Sequence[float],
                geom_ids: Sequence[int], *, keyframe: int | None = None,
                seconds: float = 0.6) -> float:
    """Mean distance between a gripper's geoms after driving it to ``ctrl`` [m].

    The gripper's own joints move under their actuators for ``seconds`` of simulated
    time; every other joint is held where the keyframe (or qpos0) puts it, gravity and
    contacts are off, so only the gripper's mechanism (slides, hinges, tendons,
    linkages) decides the result.

    Args:
        model: the compiled model (not modified).
        actuators: ids of the gripper channel's actuators.
        ctrl: control of each of them.
        geom_ids: the gripper's geoms (two or more).
        keyframe: keyframe id for the rest of the robot, or None.
        seconds: simulated settling time [s].
    """
    m = copy.copy(model)
    m.opt.gravity[:] = 0
    m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONTACT)
    d = mujoco.MjData(m)
    if keyframe is not None:
        mujoco.mj_resetDataKeyframe(m, d, keyframe)
    root = common_ancestor(m, [int(m.geom_bodyid[g]) for g in geom_ids])
    inside = np.zeros(m.nbody, bool)
    for b in range(m.nbody):
        a = b
        while a != 0 and a != root:
            a = int(m.body_parentid[a])
        inside[b] = a == root and root != 0
    hold_q, hold_v = [], []
    # held outside its range, a joint's limit would jolt the robot at every step (and with
    # it a slow gripper's fingers: franka_sim's bimanual Panda measured 0.00 mm of travel)
    into_ranges(m, d.qpos, [j for j in range(m.njnt) if not inside[m.jnt_bodyid[j]]])
    for j in range(m.njnt):
        if not inside[m.jnt_bodyid[j]]:
            n = {0: 7, 1: 4}.get(int(m.jnt_type[j]), 1)
            hold_q.extend(range(m.jnt_qposadr[j], m.jnt_qposadr[j] + n))
            nv = {0: 6, 1: 3}.get(int(m.jnt_type[j]), 1)
            hold_v.extend(range(m.jnt_dofadr[j], m.jnt_dofadr[j] + nv))
    # the held joints' own actuators and springs off: reset to their pose every step, they
    # would still accelerate the hand within each step, and the fingers feel that as a
    # force (franka_sim's bimanual Panda: its arm servos pulling towards ctrl 0 pressed one
    # finger against its limit harder than that finger's 20 N/m servo could pull)
    others = np.setdiff1d(np.arange(m.nu), np.asarray(list(actuators), int))
    held_joint = ~inside[m.jnt_bodyid]
    m.actuator_gainprm[others] = 0
    m.actuator_biasprm[others] = 0
    m.jnt_stiffness[held_joint] = 0
    q0 = d.qpos[hold_q].copy()
    d.ctrl[:] = 0
    d.ctrl[list(actuators)] = ctrl
    for _ in range(max(1, int(seconds / m.opt.timestep))):
        mujoco.mj_step(m, d)
        d.qpos[hold_q] = q0
        d.qvel[hold_v] = 0
    mujoco.mj_kinematics(m, d)
    pts = d.geom_xpos[list(geom_ids)]
    diff = pts[:, None, :] - pts[None, :, :]
    # the mean over pairs: a palm far from the fingertips would dominate the largest one
    n = len(geom_ids)
    return float(np.sqrt((diff ** 2).sum(-1)).sum() / (n * (n - 1)))


def control_span(model: mujoco.MjModel, i: int) -> tuple[float, float] | None:
    """The controls that drive actuator ``i`` over its range: its ``ctrlrange``; without
    one (mjlab's servos leave ctrl unlimited), for a position-like actuator on a limited
    joint or tendon, the controls whose targets are that range's ends (ctrl = (−b1·length
    − b0)/gain, length = gear·range); else None."""
    if model.actuator_ctrllimited[i]:
        lo, hi = (float(v) for v in model.actuator_ctrlrange[i])
        return lo, hi
    if not describe(model, i).kind.tracks_position:
        return None
    trn, tid = int(model.actuator_trntype[i]), int(model.actuator_trnid[i, 0])
    if trn in (int(mujoco.mjtTrn.mjTRN_JOINT), int(mujoco.mjtTrn.mjTRN_JOINTINPARENT)):
        if not model.jnt_limited[tid] or int(model.jnt_type[tid]) not in (
                int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE)):
            return None
        ends = model.jnt_range[tid]
    elif trn == int(mujoco.mjtTrn.mjTRN_TENDON) and model.tendon_limited[tid]:
        ends = model.tendon_range[tid]
    else:
        return None
    gain = float(model.actuator_gainprm[i, 0])
    b0, b1 = (float(v) for v in model.actuator_biasprm[i, :2])
    gear = float(model.actuator_gear[i, 0]) or 1.0
    if gain == 0.0 or b1 == 0.0:
        return None
    ctrl = sorted((-b1 * gear * float(e) - b0) / gain for e in ends)
    return ctrl[0], ctrl[1]


def _mid(model: mujoco.MjModel, i: int) -> float:
    span = control_span(model, i)
    return 0.0 if span is None else 0.5 * (span[0] + span[1])


def closing_ends(model: mujoco.MjModel, actuators: Sequence[int], geom_ids: Sequence[int], *,
                 keyframe: int | None = None, tolerance: float = 1e-4
                 ) -> tuple[list[float], list[float]]:
    """The control that closes and the one that opens each of a gripper's actuators.

    Each actuator is driven alone to either end of its ``ctrlrange`` (or, without one, of
    :func:`control_span`; the others at mid range); the end at which the gripper's geoms
    are closer together closes it. Two
    fingers on mirrored slides (ALOHA: one closes at its low end, the other at its high
    end) are each told apart this way.

    Returns:
        (closed, open) control values, one per actuator.

    Raises:
        ValueError: an actuator without a ctrlrange or a limited joint or tendon to take
            one from, or one that moves the geoms less than ``tolerance`` [m] over its range.
    """
    closed, open_ = [], []
    for k in range(len(actuators)):
        c, o = closing_end(model, actuators, k, geom_ids, keyframe=keyframe,
                           tolerance=tolerance)
        closed.append(c)
        open_.append(o)
    return closed, open_


def closing_end(model: mujoco.MjModel, actuators: Sequence[int], k: int,
                geom_ids: Sequence[int], *, keyframe: int | None = None,
                tolerance: float = 1e-4) -> tuple[float, float]:
    """The control that closes and the one that opens actuator ``actuators[k]``, driven to
    either end of its range with the other ``actuators`` at mid range (a hand's knuckle
    measured with its finger's other joints half curled, as they are when it grasps: with
    them left straight, the Allegro's knuckles read closed when extended).

    Raises:
        ValueError: as :func:`closing_ends`.
    """
    i = actuators[k]
    base = [_mid(model, a) for a in actuators]
    span = control_span(model, i)
    if span is None:
        raise ValueError(f"actuator {model.actuator(i).name!r} has no ctrlrange (and no "
                         f"limited joint or tendon of a position servo to take one from)")
    lo, hi = span
    gaps = []
    for end in (lo, hi):
        ctrl = list(base)
        ctrl[k] = end
        gaps.append(gripper_gap(model, actuators, ctrl, geom_ids, keyframe=keyframe))
    if abs(gaps[1] - gaps[0]) < tolerance:
        raise ValueError(
            f"actuator {model.actuator(i).name!r} opens or closes the gap between the "
            f"gripper's geoms by {abs(gaps[1] - gaps[0]) * 1e3:.2f} mm over its control "
            f"range {lo:g}..{hi:g} (it may move them all together, as an arm axis does)")
    return (lo, hi) if gaps[0] < gaps[1] else (hi, lo)


def moves_geoms(model: mujoco.MjModel, actuators: Sequence[int], geom_ids: Sequence[int], *,
                tolerance: float = 1e-4) -> bool:
    """Whether driving ``actuators`` over their control ranges moves the geoms apart."""
    spans = [control_span(model, i) for i in actuators]
    if any(span is None for span in spans):
        return False
    lo = [span[0] for span in spans]
    hi = [span[1] for span in spans]
    spread = [gripper_gap(model, actuators, c, geom_ids) for c in (lo, hi)]
    per = []
    for k, _i in enumerate(actuators):
        ctrl_lo, ctrl_hi = list(hi), list(hi)
        ctrl_lo[k] = lo[k]
        per.append(abs(gripper_gap(model, actuators, ctrl_lo, geom_ids)
                       - gripper_gap(model, actuators, ctrl_hi, geom_ids)))
    return abs(spread[1] - spread[0]) > tolerance or max(per) > tolerance


def position_target(model: mujoco.MjModel, i: int, ctrl: float) -> float | None:
    """The joint position a position-like actuator ``i`` pulls towards at ``ctrl``.

    Force = gain·ctrl + b0 + b1·length (+ b2·velocity) vanishes at rest at length
    (gain·ctrl + b0)/(−b1); the joint position is length / gear. For a plain position
    servo that is ctrl (gear 1); for a geared or offset ``general`` servo it is not.

    Returns:
        The target [rad or m], or None for an actuator that does not track a position or
        does not drive a joint.
    """
    if not describe(model, i).kind.tracks_position:
        return None
    if int(model.actuator_trntype[i]) not in (int(mujoco.mjtTrn.mjTRN_JOINT),
                                              int(mujoco.mjtTrn.mjTRN_JOINTINPARENT)):
        return None
    gain = float(model.actuator_gainprm[i, 0])
    b0, b1 = (float(v) for v in model.actuator_biasprm[i, :2])
    gear = float(model.actuator_gear[i, 0]) or 1.0
    return (gain * ctrl + b0) / (-b1) / gear
