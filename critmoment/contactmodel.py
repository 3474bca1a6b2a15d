"""Is the twin's contact model hard enough for a one-step force ratio to mean what it says?

The contact FOS of sparse evaluation (thesis eq. 12) reads the friction a grip uses
against the friction it could use. That ratio predicts slip only when MuJoCo's friction
behaves like Coulomb friction. With soft contacts (a pyramidal cone with ``impratio`` 1,
a soft ``solref``) MuJoCo's constraints let a held object creep through the grip at forces
well inside the cone: a heavy cube slides down the pads and drops while FOS_contact stays
above 2. No one-step measurement sees that.

:func:`check_contact_model` inspects the model (``opt.cone``, ``opt.impratio``,
``opt.noslip_iterations``, the ``solref``/``solimp`` of every object/pad contact), then
measures the consequence: it holds the object in the nominal run's grip, at the mass the
force ratio calls safe with FOS 2 (at most the box's largest mass), with the grip's
controls frozen, and reports the creep rate of the object in the gripper [m/s]. When that
creep over the recorded carry would exceed the ground truth's slip tolerance, the model is
*soft*: a :class:`ContactModelWarning` says so with the measured numbers, and the report
gives the creep horizon [steps] over which sparse evaluation should measure each sample's
slip (``SparseEvaluator(creep_horizon=...)``) rather than trust a one-step force ratio.

:func:`probe_contact_model` is the same check on any model and held state (no twin).
"""

from __future__ import annotations

import dataclasses
import enum
import math
import warnings
from collections.abc import Sequence

import mujoco
import numpy as np

from critmoment import actuators as act_info
from critmoment.exceptions import CritmomentWarning, ParameterError

__all__ = [
    "ContactModelWarning",
    "Severity",
    "ContactFinding",
    "ContactModelReport",
    "inspect_contact_model",
    "measure_creep",
    "probe_contact_model",
    "check_contact_model",
    "DROP_TOLERANCE",
    "MAX_CREEP_HORIZON",
]

#: displacement in the grip over a whole carry that counts as a slip [m] (the ground
#: truth's ``OutcomeCriteria.slip_tolerance``)
DROP_TOLERANCE = 0.01
#: longest creep horizon recommended [steps]
MAX_CREEP_HORIZON = 250
#: force-ratio FOS of the probe's mass: a grip the one-step ratio calls safe
PROBE_FOS = 2.0
#: MuJoCo's default contact time constant [s]; softer contacts are reported
_DEFAULT_TIMECONST = 0.02


class ContactModelWarning(CritmomentWarning):
    """The contact model lets a held object creep: the one-step force ratio is optimistic."""


class Severity(enum.Enum):
    """How much a finding matters."""

    INFO = "info"
    """Worth knowing; the measured creep decides."""
    WARNING = "warning"
    """The measured consequence makes the one-step criterion unreliable."""


@dataclasses.dataclass(frozen=True)
class ContactFinding:
    """One observation about the contact model.

    Attributes:
        code: short name (``pyramidal-cone``, ``low-impratio``, ``noslip``, ``soft-solref``,
            ``soft-solimp``, ``creep``, ``nominal-creep``, ``solver-cap``: the probe's solver stopped
            at its iteration cap, so the creep measured is not the contact model's).
        severity: INFO or WARNING.
        message: what was found, in words.
    """

    code: str
    severity: Severity
    message: str


@dataclasses.dataclass(frozen=True)
class ContactModelReport:
    """The contact model and its measured consequence.

    Attributes:
        cone: ``"elliptic"`` or ``"pyramidal"``.
        impratio: ``opt.impratio``.
        noslip_iterations: ``opt.noslip_iterations``.
        timestep: ``opt.timestep`` [s].
        solref: effective (timeconst [s], dampratio) of each object/pad geom pair, (P, 2)
            (a direct (−stiffness, −damping) one converted; the option's under the contact
            override).
        solimp: effective (dmin, dmax, width [m], midpoint, power) of each pair, (P, 5).
        findings: what the inspection and the probe found.
        probe_mass: mass of the probe [kg], or NaN without a probe.
        creep_rate: creep of the object in the grip at ``probe_mass`` [m/s], NaN without
            a probe.
        carry_time: how long the object is carried [s] (the longest hold of the recording).
        soft: the measured creep over ``carry_time`` exceeds :data:`DROP_TOLERANCE`.
        creep_horizon: steps over which sparse evaluation should measure slip (0 when not
            soft): a sample creeping fast enough to move the object ``DROP_TOLERANCE`` over
            the carry moves it ``slip_tolerance`` over the horizon.
        slip_tolerance: the sparse slip tolerance the horizon was sized for [m].
        nominal_creep: how far the nominal run's own object moves in its grip over the
            probed hold [m] (the fingers' closing axes projected out), NaN without a probe.
            Slip is counted beyond it: a nominal grip that creeps this much passes.
    """

    cone: str
    impratio: float
    noslip_iterations: int
    timestep: float
    solref: np.ndarray
    solimp: np.ndarray
    findings: tuple[ContactFinding, ...]
    probe_mass: float = math.nan
    creep_rate: float = math.nan
    carry_time: float = math.nan
    soft: bool = False
    creep_horizon: int = 0
    slip_tolerance: float = math.nan
    nominal_creep: float = math.nan

    @property
    def creep_over_carry(self) -> float:
        """The probe's creep over the carry [m] (NaN without a probe)."""
        return self.creep_rate * self.carry_time

    def summary(self) -> str:
        """One line: the model, and the measured consequence when there is a probe."""
        text = f"{self.cone} cone, impratio {self.impratio:g}, noslip {self.noslip_iterations}"
        unconverged = [f.message for f in self.findings if f.code == "solver-cap"]
        if unconverged:
            text += f": {unconverged[0]}"
        elif math.isfinite(self.creep_rate):
            text += (f": holding {self.probe_mass:.3g} kg (force-ratio FOS {PROBE_FOS:g}) the "
                     f"object creeps {self.creep_rate * 1e3:.3g} mm/s in the grip, "
                     f"{self.creep_over_carry * 1e3:.3g} mm over the {self.carry_time:.2g} s "
                     f"carry")
        if math.isfinite(self.nominal_creep) and self.nominal_creep > NOMINAL_CREEP:
            text += (f"; the nominal run's own object moves {self.nominal_creep * 1e3:.3g} mm "
                     f"in the grip (slip is counted beyond that)")
        if self.soft:
            text += ("; soft: the one-step force ratio is not trusted, each sample's slip is "
                     "measured on its own run over the whole hold (chained segments; without "
                     f"them over a {self.creep_horizon * self.timestep:.3g} s creep horizon, "
                     f"creep_horizon = {self.creep_horizon})")
        return text


def _pair_parameters(model: mujoco.MjModel, g1: int, g2: int) -> tuple[np.ndarray, np.ndarray]:
    """Effective solref (2,) and solimp (5,) of a contact between geoms g1 and g2: an
    explicit ``<pair>`` wins, else MuJoCo's rule
    (:func:`critmoment.actuators.contact_parameters`)."""
    for p in range(model.npair):
        if {int(model.pair_geom1[p]), int(model.pair_geom2[p])} == {g1, g2}:
            return model.pair_solref[p].copy(), model.pair_solimp[p].copy()
    mixed = act_info.contact_parameters(model, g1, g2)
    return np.array(mixed.solref), np.array(mixed.solimp)


def _standard_solref(solref: np.ndarray, solimp: np.ndarray) -> np.ndarray:
    """A solref as (time constant [s], damping ratio): a direct one, (−stiffness,
    −damping), converted by MuJoCo's own relations b = 2 / (dmax·timeconst) and
    k = d / (dmax² · timeconst² · dampratio²) at d = dmax (``-500 -45`` is about 0.047 s)."""
    solref = np.asarray(solref, dtype=float)
    if solref[0] >= 0 or solref[1] >= 0:
        return solref.copy()
    k, b = -solref[0], -solref[1]
    dmax = float(np.clip(solimp[1], 1e-4, 1.0))
    timeconst = 2.0 / (dmax * b)
    return np.array([timeconst, 1.0 / (timeconst * np.sqrt(k * dmax))])


def inspect_contact_model(model: mujoco.MjModel, *, object_geom: str | int,
                          pad_geoms: Sequence[str | int]) -> ContactModelReport:
    """What the model's options and the object/pad contact parameters say (no simulation).

    Args:
        model: the compiled model.
        object_geom: the object's geom (name or id).
        pad_geoms: the grippers' pad geoms (names or ids).

    Returns:
        A :class:`ContactModelReport` without a probe (INFO findings only).
    """
    obj = model.geom(object_geom).id
    pads = [model.geom(g).id for g in pad_geoms]
    if not pads:
        raise ParameterError("pad_geoms: expected at least one pad geom, got none")
    opt = model.opt
    if opt.enableflags & mujoco.mjtEnableBit.mjENBL_OVERRIDE:
        # the contact override gives every contact the option's solref and solimp
        params = [(np.array(opt.o_solref, float), np.array(opt.o_solimp, float))] * len(pads)
    else:
        params = [_pair_parameters(model, obj, p) for p in pads]
    solref = np.array([_standard_solref(r, i) for r, i in params])
    solimp = np.array([i for _, i in params])
    cone = "elliptic" if opt.cone == mujoco.mjtCone.mjCONE_ELLIPTIC else "pyramidal"
    findings = []
    if cone == "pyramidal":
        findings.append(ContactFinding(
            "pyramidal-cone", Severity.INFO,
            "pyramidal friction cone: friction is a set of soft pyramid edges, a held object "
            "can creep at forces inside the cone"))
    if opt.impratio < 2:
        findings.append(ContactFinding(
            "low-impratio", Severity.INFO,
            f"impratio {opt.impratio:g}: friction is as soft as the normal contact (10 makes it "
            "close to hard Coulomb friction on elliptic cones)"))
    if opt.noslip_iterations > 0:
        findings.append(ContactFinding(
            "noslip", Severity.INFO,
            f"noslip_iterations {opt.noslip_iterations}: a post-solve removes friction slip; "
            "sparse evaluation steps with it like the full rollout"))
    timeconst = solref[:, 0]
    soft_ref = (timeconst > _DEFAULT_TIMECONST + 1e-12)
    if soft_ref.any():
        findings.append(ContactFinding(
            "soft-solref", Severity.INFO,
            f"object/pad solref time constant up to {timeconst.max():g} s (MuJoCo's default "
            f"{_DEFAULT_TIMECONST:g} s): soft contacts"))
    if (solimp[:, 0] < 0.5).any():
        findings.append(ContactFinding(
            "soft-solimp", Severity.INFO,
            f"object/pad solimp dmin down to {solimp[:, 0].min():g}: soft impedance"))
    return ContactModelReport(cone=cone, impratio=float(opt.impratio),
                              noslip_iterations=int(opt.noslip_iterations),
                              timestep=float(opt.timestep), solref=solref, solimp=solimp,
                              findings=tuple(findings))


def _scale_mass(model: mujoco.MjModel, body: int, mass: float) -> None:
    """Set a body's mass, its inertia scaled with it, and recompute the derived constants."""
    scale = mass / model.body_mass[body]
    model.body_mass[body] = mass
    model.body_inertia[body] *= scale
    mujoco.mj_setConst(model, mujoco.MjData(model))


#: a soft-looking creep rate is measured over at most this many windows of the probe's steps
MAX_PROBE_WINDOWS = 8
#: a window's rate under this share of the one before: the grip is still settling
SETTLING = 0.5


def measure_creep(model: mujoco.MjModel, data: mujoco.MjData, *, object_body: str | int,
                  anchor_body: str | int, steps: int = 250, settle: float = 0.5,
                  projector: np.ndarray | None = None) -> float:
    """Creep rate of a held object in its gripper with the controls frozen [m/s].

    Steps ``data`` (modified in place) ``steps`` times with its current controls, tracking
    the object's position in the anchor body's frame; the rate is the displacement over the
    steps after the first ``settle`` fraction (the grip's transient) divided by their time.

    Args:
        model: the model (with the mass to probe written in).
        data: the held state, controls set.
        object_body: the object's body.
        anchor_body: the gripper's base body.
        steps: physics steps to hold.
        settle: fraction of the steps left out as the transient, in [0, 1).
        projector: (3, 3) projector applied to the displacement (drop the closing axes).

    Returns:
        Creep rate [m/s]; ``inf`` when the simulation diverges.
    """
    if isinstance(steps, bool) or not isinstance(steps, int) or steps < 2:
        raise ParameterError(f"steps: expected an integer >= 2, got {steps!r}")
    if not 0 <= settle < 1:
        raise ParameterError(f"settle: expected a fraction in [0, 1), got {settle!r}")
    ob, an = model.body(object_body).id, model.body(anchor_body).id
    proj = np.eye(3) if projector is None else np.asarray(projector, dtype=float)
    start = int(settle * steps)
    rel = np.empty((steps + 1, 3))
    mujoco.mj_kinematics(model, data)
    for i in range(steps + 1):
        rel[i] = _in_frame(data, ob, an)
        if i < steps:
            mujoco.mj_step(model, data)
            if data.warning[mujoco.mjtWarning.mjWARN_BADQACC].number > 0:
                return math.inf
    shift = proj @ (rel[-1] - rel[start])
    return float(np.linalg.norm(shift) / ((steps - start) * model.opt.timestep))


def probe_contact_model(model: mujoco.MjModel, data: mujoco.MjData, *, object_body: str | int,
                        object_geom: str | int, pad_geoms: Sequence[str | int],
                        anchor_body: str | int, carry_time: float, mass: float | None = None,
                        max_mass: float = math.inf, friction: float | None = None,
                        steps: int = 250, horizon: int = 1,
                        slip_tolerance: float = 0.005, projector: np.ndarray | None = None,
                        warn: bool = True) -> ContactModelReport:
    """Inspect the contact model and measure a held object's creep (any model, no twin).

    Args:
        model: the model (not modified: the probe runs on a copy).
        data: the held state with the grip's controls set (not modified).
        object_body: the object's body.
        object_geom: the object's geom.
        pad_geoms: the gripper's pad geoms.
        anchor_body: the gripper's base body.
        carry_time: how long the object is carried [s].
        mass: the probe's mass [kg]; default the mass the force ratio holds with FOS
            :data:`PROBE_FOS` (from the normal forces on the pads in ``data``), at most
            ``max_mass``.
        max_mass: the largest mass of interest [kg] (the box's).
        friction: friction coefficient of the object's contacts for that estimate
            (default: the object geom's).
        steps: physics steps of the hold.
        horizon: the sparse horizon [steps] (the creep horizon is at least this).
        slip_tolerance: the sparse slip tolerance the creep horizon is sized for [m].
        projector: (3, 3) projector of the displacement (drop the closing axes).
        warn: issue a :class:`ContactModelWarning` when the model is soft.

    Returns:
        The :class:`ContactModelReport` with the probe.
    """
    if not (math.isfinite(carry_time) and carry_time > 0):
        raise ParameterError(f"carry_time: expected a time > 0 s, got {carry_time!r}")
    report = inspect_contact_model(model, object_geom=object_geom, pad_geoms=pad_geoms)
    ob = model.body(object_body).id
    work = _copy_model(model)
    held = mujoco.MjData(work)
    mujoco.mj_setState(work, held, _state(model, data), mujoco.mjtState.mjSTATE_INTEGRATION)
    if mass is None:
        mujoco.mj_forward(work, held)
        mu = float(model.geom_friction[model.geom(object_geom).id, 0]) if friction is None \
            else float(friction)
        normal = _normal_force(work, held, model.geom(object_geom).id,
                               {model.geom(g).id for g in pad_geoms})
        g = float(np.linalg.norm(model.opt.gravity)) or 9.81
        mass = min(max_mass, mu * normal / (PROBE_FOS * g)) if normal > 0 else max_mass
        if not (math.isfinite(mass) and mass > 0):
            mass = float(model.body_mass[ob])
    if not (math.isfinite(mass) and mass > 0):
        raise ParameterError(f"mass: expected a probe mass > 0 kg, got {mass!r}")
    _scale_mass(work, ob, float(mass))
    held = mujoco.MjData(work)
    mujoco.mj_setState(work, held, _state(model, data), mujoco.mjtState.mjSTATE_INTEGRATION)
    rate = measure_creep(work, held, object_body=ob, anchor_body=anchor_body, steps=steps,
                         projector=projector)
    # a rate that would call the model soft is measured on while it keeps falling: a grip
    # that settles for longer than the probe's first half (a linkage gripper closing further
    # under the new load) had its transient extrapolated over the carry ("20.3 mm/s, 123 mm
    # over the 6.1 s carry" for a 2F-85 whose runs then moved 0.2 mm/s)
    # -- while the pads still hold it: an object that has slid out of the grip and lies on
    # the table creeps no more, and its rate then read as a rigid grip's (a Panda's mesh
    # object: 90.7 mm/s in the first window, 0 once it lay on the table)
    pads = {work.geom(g).id for g in pad_geoms}
    start = mujoco.MjData(work)
    mujoco.mj_setState(work, start, _state(model, data), mujoco.mjtState.mjSTATE_INTEGRATION)
    mujoco.mj_forward(work, start)
    pinched = _touches(work, start, ob, pads)

    def out_of_grip() -> bool:
        return pinched and not _touches(work, held, ob, pads)

    for _ in range(MAX_PROBE_WINDOWS - 1):
        if not (math.isfinite(rate) and rate * carry_time > DROP_TOLERANCE) or out_of_grip():
            break  # not soft-looking, or out of the grip: the rate measured stands
        later = measure_creep(work, held, object_body=ob, anchor_body=anchor_body,
                              steps=steps, settle=0.0, projector=projector)
        if later >= SETTLING * rate or out_of_grip():
            rate = max(rate, later)  # sustained, faster, or out of the grip
            break
        rate = later  # still settling in the grip: measure on
    soft = rate * carry_time > DROP_TOLERANCE
    findings = list(report.findings)
    capped = _capped_share(work, _state(model, data), steps) if soft else 0.0
    if capped >= CAPPED_SHARE:
        # the creep is the unconverged solver's, not the contact model's: a Panda with
        # iterations="3" read 423 mm/s ("1.67e+03 mm over the carry") where its full run at
        # that mass slips 9 mm; its solver stopped at the cap on 141 of the 250 steps
        findings.append(ContactFinding(
            "solver-cap", Severity.WARNING,
            f"the solver stops at its {work.opt.iterations}-iteration cap on {capped:.0%} of "
            f"the probe's steps holding {mass:.3g} kg: the object's motion in the grip "
            f"({rate * 1e3:.3g} mm/s) is the unconverged solver's, not a measure of the "
            f"contact model (raise <option iterations> or lower its tolerance)"))
        soft = False
    horizon_steps = 0
    if soft:
        creep_time = carry_time * slip_tolerance / DROP_TOLERANCE
        horizon_steps = int(min(MAX_CREEP_HORIZON, max(horizon + 1,
                                                        math.ceil(creep_time / report.timestep))))
        findings.append(ContactFinding(
            "creep", Severity.WARNING,
            f"held at {mass:.3g} kg, which the one-step force ratio calls safe (FOS "
            f"{PROBE_FOS:g}), the object creeps {rate * 1e3:.3g} mm/s in the grip: "
            f"{rate * carry_time * 1e3:.3g} mm over the {carry_time:.2g} s carry"))
    out = dataclasses.replace(report, findings=tuple(findings), probe_mass=float(mass),
                              creep_rate=float(rate), carry_time=float(carry_time), soft=soft,
                              creep_horizon=horizon_steps, slip_tolerance=float(slip_tolerance))
    if (soft or capped >= CAPPED_SHARE) and warn:
        warnings.warn(f"contact model: {out.summary()}", ContactModelWarning, stacklevel=2)
    return out


#: share of a probe's steps at the solver's iteration cap from which its creep is not the
#: contact model's (the bundled Panda: 0 of 250 steps)
CAPPED_SHARE = 0.1


def _capped_share(model: mujoco.MjModel, state: np.ndarray, steps: int) -> float:
    """The share of ``steps`` held steps from ``state`` (controls as in it: none) at which
    the constraint solver stops at ``opt.iterations``."""
    data = mujoco.MjData(model)
    mujoco.mj_setState(model, data, state, mujoco.mjtState.mjSTATE_INTEGRATION)
    capped = 0
    for _ in range(steps):
        mujoco.mj_step(model, data)
        capped += int(data.solver_niter[0] >= model.opt.iterations)
    return capped / steps


def _in_frame(data: mujoco.MjData, body: int, anchor: int) -> np.ndarray:
    """The position of ``body`` in ``anchor``'s frame (3,) [m] (kinematics computed)."""
    return data.xmat[anchor].reshape(3, 3).T @ (data.xpos[body] - data.xpos[anchor])


def _touches(model: mujoco.MjModel, data: mujoco.MjData, body: int, geoms: set[int]) -> bool:
    """Whether a geom of ``body`` touches one of ``geoms`` in ``data`` (its contacts as
    last computed)."""
    for g1, g2 in np.asarray(data.contact.geom).reshape(-1, 2)[:data.ncon]:
        b1, b2 = int(model.geom_bodyid[g1]), int(model.geom_bodyid[g2])
        if (b1 == body and int(g2) in geoms) or (b2 == body and int(g1) in geoms):
            return True
    return False


def _copy_model(model: mujoco.MjModel) -> mujoco.MjModel:
    """A private copy of a model, to modify."""
    import copy

    return copy.copy(model)


def _state(model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
    spec = mujoco.mjtState.mjSTATE_INTEGRATION
    state = np.empty(mujoco.mj_stateSize(model, spec))
    mujoco.mj_getState(model, data, state, spec)
    return state


def _normal_force(model: mujoco.MjModel, data: mujoco.MjData, obj: int, pads: set[int]) -> float:
    """Sum of the normal forces between the object geom and the pad geoms [N]."""
    total = 0.0
    force = np.zeros(6)
    for i in range(data.ncon):
        c = data.contact[i]
        if {int(c.geom1), int(c.geom2)} & {obj} and ({int(c.geom1), int(c.geom2)} & pads):
            mujoco.mj_contactForce(model, data, i, force)
            total += float(force[0])
    return total


def check_contact_model(twin, recording=None, *, steps: int = 250, warn: bool = True,
                        slip_tolerance: float | None = None) -> ContactModelReport:
    """Check the twin's contact model, with a probe in the recording's grip when given.

    Without a recording (or when its nominal run never holds the object off its support
    with one gripper) only the inspection runs. With one, the probe holds the object where
    the nominal run holds it with one gripper alone (a quarter into the longest such hold,
    the grip's controls frozen) at the mass the force ratio holds with FOS 2, at most the
    box's largest mass; the carry time is that hold's length.

    Args:
        twin: the twin.
        recording: its frequent rollout, or None.
        steps: physics steps of the probe's hold.
        warn: issue a :class:`ContactModelWarning` when the model is soft.
        slip_tolerance: the sparse slip tolerance [m] (default: the scenario's).

    Returns:
        The :class:`ContactModelReport`.
    """
    from critmoment.groundtruth import hold_starts
    from critmoment.sparse import grip_frames, sparse_settings
    from critmoment.twin import STATE_SPEC

    sc, model = twin.scenario, twin.model
    pads = [geom for g in sc.grippers for geom in g.geoms]
    report = inspect_contact_model(model, object_geom=sc.object_geom, pad_geoms=pads)
    if recording is None:
        return report
    settings = sparse_settings(sc, slip_tolerance=slip_tolerance)
    sig = recording.signals
    masks = twin.slip_masks(recording.controls, sig.contact_gripper, sig.contact_support,
                            getattr(recording, "sensordata", None))
    alone = masks.counted
    best = None  # (length, start, gripper)
    for g in range(alone.shape[1]):
        edges = np.flatnonzero(np.diff(np.concatenate([[0], alone[:, g].astype(np.int8), [0]])))
        for a, b in zip(edges[::2], edges[1::2], strict=True):
            if best is None or b - a > best[0]:
                best = (int(b - a), int(a), g)
    if best is None or best[0] < 10:
        return report
    length, start, g = best
    k = start + length // 4
    anchors, projectors = grip_frames(model, sc)
    data = mujoco.MjData(model)
    mujoco.mj_setState(model, data, np.asarray(recording.states[k], dtype=float), STATE_SPEC)
    data.ctrl[:] = recording.controls[k]
    box = sc.box
    max_mass = box.high[box.names.index("mass")] if "mass" in box.names else math.inf
    friction = twin.object_friction()
    probed = probe_contact_model(
        model, data, object_body=sc.object_body, object_geom=sc.object_geom,
        pad_geoms=sc.grippers[g].geoms, anchor_body=int(anchors[g]),
        carry_time=length * float(recording.dt), max_mass=max_mass, friction=friction,
        steps=steps, horizon=twin.scenario.horizon, slip_tolerance=settings.slip_tolerance,
        projector=projectors[g], warn=warn)
    # from where the ground truth starts counting (the gripper's first hold, or after a
    # regrasp the hold's own grasp), over the steps it counts: the lift-off's sag included
    # (measured from the longest hold's start it read 12 mm where the ground truth forgave 24)
    first = int(hold_starts(np.asarray(sig.contact_gripper, bool), masks.segments,
                            masks.formed)[start, g])
    first = first if first >= 0 else start
    inside = masks.segments[:, g] == masks.segments[start, g]
    counted = np.flatnonzero(alone[:, g] & inside)
    counted = counted[counted >= first]
    creep, touched, origin = _nominal_creep(model, recording.states, first, counted,
                                            model.body(sc.object_body).id, int(anchors[g]),
                                            projectors[g], twin.grip_points,
                                            known=set(pads) | set(sc.support_geoms))
    out = dataclasses.replace(probed, nominal_creep=creep)
    if creep > NOMINAL_CREEP:
        # what else the object touched on the way: a collision moves it in the grip as a
        # soft contact does, and widens every sample's allowance the same way
        hit = (f", where it touches {', '.join(touched)} (neither a gripper "
               f"nor a support: a collision in the nominal run)" if touched else "")
        # a turn in the grip (the object pivots about the fingers) moves its ends, not its
        # middle: said so (an OpenMANIPULATOR-X's cube turned about 60° before its set-down)
        turn = (f" (it turns in the grip: its origin moves {origin * 1e3:.3g} mm)"
                if origin < 0.5 * creep else "")
        finding = ContactFinding(
            "nominal-creep", Severity.WARNING,
            f"the nominal run's own object moves {creep * 1e3:.3g} mm{turn} in the grip over its "
            f"{(counted[-1] + 1 - first) * float(recording.dt):.2g} s hold{hit}: slip is counted beyond the "
            f"nominal run's own motion, so every sample may move this much and pass; if that "
            f"is too much for the task, the nominal grasp itself is not good enough (grip "
            f"harder, or check the object's contact settings{' and its path' if hit else ''})")
        out = dataclasses.replace(out, findings=out.findings + (finding,))
        if warn:
            warnings.warn(f"contact model: {finding.message}", ContactModelWarning,
                          stacklevel=2)
    return out


#: the nominal run's own motion in its grip [m] that is warned of: the ground truth's slip
#: tolerance (OutcomeCriteria.slip_tolerance); a soft object contact (solref 0.05) let the
#: nominal cube move 13.6 mm, which passes since slip is counted beyond it
NOMINAL_CREEP = 0.01


def _nominal_creep(model: mujoco.MjModel, states: np.ndarray, first: int, steps: np.ndarray,
                   body: int, anchor: int, projector: np.ndarray, points: np.ndarray,
                   known: set[str] = frozenset(), probes: int = 200
                   ) -> tuple[float, tuple[str, ...], float]:
    """The largest displacement [m] of ``body``'s ``points`` (``Twin.grip_points``, its
    origin first) in ``anchor``'s frame, projected, at the physics ``steps`` (at most
    ``probes`` of them, evenly) from physics step ``first`` (``states[k + 1]`` is the state
    after step k); the names of the geoms (bodies for unnamed ones) other than ``known``
    that the body touches at those steps up to the largest displacement; and its origin's
    displacement there [m] (far less than its farthest point's: it turns in the grip)."""
    from critmoment.sparse import _object_in_grippers
    from critmoment.twin import STATE_SPEC

    if steps.size == 0:
        return 0.0, (), 0.0
    picks = np.concatenate([[first], steps[np.unique(
        np.linspace(0, steps.size - 1, min(steps.size, probes)).astype(int))]]) + 1
    picks = np.minimum(picks, len(states) - 1)
    data = mujoco.MjData(model)
    points = np.asarray(points, dtype=float)
    rel = np.empty((picks.size, len(points), 3))
    touched: list[set[str]] = []
    for i, k in enumerate(picks):
        mujoco.mj_setState(model, data, np.asarray(states[k], dtype=float), STATE_SPEC)
        mujoco.mj_fwdPosition(model, data)
        rel[i] = _object_in_grippers(data.xpos[None, None], data.xmat[None, None], body,
                                     np.array([anchor]), points)[0, 0, 0]
        touched.append(_other_contacts(model, data, body, known))
    moved = np.linalg.norm((rel - rel[0]) @ np.asarray(projector, dtype=float).T, axis=-1)
    worst = int(np.argmax(moved.max(axis=1)))
    names = sorted(set().union(*touched[:worst + 1]))
    return float(moved.max()), tuple(names), float(moved[worst, 0])


def _other_contacts(model: mujoco.MjModel, data: mujoco.MjData, body: int,
                    known: set[str]) -> set[str]:
    """The geoms touching ``body`` in ``data``'s contacts, named for a message (``'post'``,
    or ``a geom of body 'bottle'`` for an unnamed one), but for the geoms named in
    ``known``."""
    out = set()
    for c in data.contact[:data.ncon]:
        g1, g2 = int(c.geom1), int(c.geom2)
        b1, b2 = int(model.geom_bodyid[g1]), int(model.geom_bodyid[g2])
        if (b1 == body) == (b2 == body):
            continue
        other = g2 if b1 == body else g1
        name = model.geom(other).name
        if name in known:
            continue
        body_name = model.body(int(model.geom_bodyid[other])).name
        out.add(repr(name) if name else f"a geom of body {body_name!r}")
    return out
