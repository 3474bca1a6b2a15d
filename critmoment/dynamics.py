"""Rigid-body dynamics of a MuJoCo model, computed with Pinocchio.

Pinocchio's own MJCF parser reads only the first top-level body and does not
expand ``<include>``/``<attach>``, so :func:`from_mujoco` builds the
``pinocchio.Model`` directly from a *compiled* :class:`mujoco.MjModel`. Every
public function takes and returns vectors in MuJoCo's conventions; the
conversions to Pinocchio's are done here and nowhere else.

Conventions handled:

* Quaternions: MuJoCo stores (w, x, y, z), Pinocchio (x, y, z, w). Quaternions
  in ``qpos`` are normalised on the way in, as MuJoCo's kinematics does.
* Hinge and slide joints: MuJoCo's joint displacement is ``qpos - qpos0``
  (``qpos0`` is the joint's ``ref``); Pinocchio's ``q`` is that displacement.
* Free joints: MuJoCo ``qpos`` = (position [m] in the world, quaternion wxyz),
  ``qvel`` = (linear velocity [m/s] of the body origin in the WORLD frame,
  angular velocity [rad/s] in the LOCAL body frame). Pinocchio's free flyer has
  ``v`` = (linear, angular) velocity both in the LOCAL frame. With ``R`` the
  body's rotation, ``v_lin = R^T qvel_lin``; the acceleration picks up a
  transport term, ``a_lin = R^T qacc_lin - omega x (R^T qvel_lin)``; and
  generalised forces map by the transpose of the velocity map,
  ``qfrc_lin = R tau_lin`` (a world-frame force [N]).
* Ball joints: both libraries use the local angular velocity, so only the
  quaternion order differs.
* Armature (``dof_armature``) is *not* put into ``pinocchio.Model.armature``.
  It is kept in MuJoCo's dof order in :attr:`PinocchioModel.armature` and
  added in MuJoCo coordinates (``armature * qacc``) when a caller asks for it
  with ``include_armature=True``. This reproduces MuJoCo exactly, also for free
  joints, where Pinocchio's local-frame armature would differ by a
  velocity-dependent term.
* Not modelled: joint damping, springs, friction loss, gravity compensation
  (``body_gravcomp``), fluid forces, tendon armature, contacts and equality
  constraints. Compare with ``mujoco.mj_inverse`` with constraints, springs
  and dampers disabled. The load bounds subtract MuJoCo's own passive forces
  (:func:`passive_forces`: damping, springs, gravity compensation, fluid).

The built model holds one ``pinocchio.Data`` that every call reuses, so a
:class:`PinocchioModel` must not be shared between threads.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import mujoco
import numpy as np
import pinocchio as pin

from critmoment.exceptions import (
    CritmomentError,
    ParameterError,
    ScenarioError,
    TrajectoryError,
)

__all__ = [
    "JointMap",
    "PinocchioModel",
    "from_mujoco",
    "q_mj_to_pin",
    "q_pin_to_mj",
    "v_mj_to_pin",
    "v_pin_to_mj",
    "a_mj_to_pin",
    "tau_pin_to_mj",
    "tau_mj_to_pin",
    "payload_regressor",
    "critical_mass",
    "motor_fos",
    "analytic_contact_fos",
    "LoadBound",
    "trajectory_load_bound",
]

_KIND = {
    int(mujoco.mjtJoint.mjJNT_FREE): "free",
    int(mujoco.mjtJoint.mjJNT_BALL): "ball",
    int(mujoco.mjtJoint.mjJNT_SLIDE): "slide",
    int(mujoco.mjtJoint.mjJNT_HINGE): "hinge",
}
_NQ = {"free": 7, "ball": 4, "slide": 1, "hinge": 1}
_NV = {"free": 6, "ball": 3, "slide": 1, "hinge": 1}


# --------------------------------------------------------------------------
# small geometry helpers
# --------------------------------------------------------------------------


def _normalize_quat(quat: np.ndarray) -> np.ndarray:
    """Unit quaternions (..., 4); a zero quaternion becomes the identity."""
    norm = np.linalg.norm(quat, axis=-1, keepdims=True)
    ident = np.zeros_like(quat)
    ident[..., 0] = 1.0
    safe = np.where(norm > 1e-15, norm, 1.0)
    return np.where(norm > 1e-15, quat / safe, ident)


def _quat_to_mat(quat_wxyz: np.ndarray) -> np.ndarray:
    """Rotation matrices (..., 3, 3) of quaternions (..., 4) in w, x, y, z order."""
    q = _normalize_quat(np.asarray(quat_wxyz, dtype=float))
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    rot = np.empty(q.shape[:-1] + (3, 3))
    rot[..., 0, 0] = 1 - 2 * (y * y + z * z)
    rot[..., 0, 1] = 2 * (x * y - w * z)
    rot[..., 0, 2] = 2 * (x * z + w * y)
    rot[..., 1, 0] = 2 * (x * y + w * z)
    rot[..., 1, 1] = 1 - 2 * (x * x + z * z)
    rot[..., 1, 2] = 2 * (y * z - w * x)
    rot[..., 2, 0] = 2 * (x * z - w * y)
    rot[..., 2, 1] = 2 * (y * z + w * x)
    rot[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return rot


def _se3(pos: np.ndarray, quat_wxyz: np.ndarray) -> pin.SE3:
    return pin.SE3(_quat_to_mat(quat_wxyz), np.asarray(pos, dtype=float).copy())


def _translation(vec: np.ndarray) -> pin.SE3:
    return pin.SE3(np.eye(3), np.asarray(vec, dtype=float).copy())


def _readonly(arr: np.ndarray) -> np.ndarray:
    arr = np.array(arr)
    arr.setflags(write=False)
    return arr


# --------------------------------------------------------------------------
# model
# --------------------------------------------------------------------------


@dataclass(frozen=True)
class JointMap:
    """Where one MuJoCo joint lives in MuJoCo's and Pinocchio's vectors.

    Attributes:
        mj_id: MuJoCo joint id.
        name: MuJoCo joint name (``"joint<id>"`` when unnamed).
        kind: ``"free"``, ``"ball"``, ``"slide"`` or ``"hinge"``.
        body_id: MuJoCo id of the body the joint moves.
        pin_id: Pinocchio joint id.
        qposadr: start of the joint in MuJoCo's ``qpos``.
        dofadr: start of the joint in MuJoCo's ``qvel`` / ``qacc`` / forces.
        nq: number of position coordinates (7, 4, 1 or 1).
        nv: number of degrees of freedom (6, 3, 1 or 1).
        idx_q: start of the joint in Pinocchio's ``q``.
        idx_v: start of the joint in Pinocchio's ``v``.
        qpos0: MuJoCo reference position of a hinge [rad] or slide [m]
            (``ref``); 0 for free and ball joints.
    """

    mj_id: int
    name: str
    kind: str
    body_id: int
    pin_id: int
    qposadr: int
    dofadr: int
    nq: int
    nv: int
    idx_q: int
    idx_v: int
    qpos0: float


@dataclass(frozen=True, eq=False)
class PinocchioModel:
    """A Pinocchio model of a compiled MuJoCo model, with MuJoCo-convention I/O.

    Build it with :func:`from_mujoco` (or :meth:`from_mujoco`). All methods
    take MuJoCo-convention vectors: ``qpos`` (nq,), ``qvel``/``qacc`` (nv,),
    or stacks of them with a leading time axis (T, nq) / (T, nv).

    Attributes:
        model: the ``pinocchio.Model``. One Pinocchio joint per MuJoCo joint;
            bodies without joints are merged into the nearest moving ancestor
            (or the universe). Pinocchio frames carry the MuJoCo body names
            (type BODY), joint names (type JOINT) and site names (type
            OP_FRAME).
        data: the ``pinocchio.Data`` reused by every call.
        joints: one :class:`JointMap` per MuJoCo joint, in MuJoCo order.
        body_names: MuJoCo body names by body id (``"body<id>"`` if unnamed).
        body_joint: (nbody,) Pinocchio joint id that carries each MuJoCo body
            (0: fixed to the world).
        body_in_joint: per body, the placement of the MuJoCo body frame in the
            frame of its Pinocchio joint.
        body_inertial: per body, the placement of the inertial frame in the
            body frame (``body_ipos``, ``body_iquat``).
        site_names: MuJoCo site names by site id.
        site_body: (nsite,) MuJoCo body id of each site.
        site_in_body: per site, its placement in its body frame.
        gravity: (3,) gravity [m/s^2] in the world frame (zero when the
            MuJoCo model disables gravity).
        armature: (nv,) ``dof_armature`` in MuJoCo dof order [kg m^2 or kg].
    """

    model: pin.Model
    data: pin.Data
    joints: tuple[JointMap, ...]
    body_names: tuple[str, ...]
    body_joint: np.ndarray
    body_in_joint: tuple[pin.SE3, ...]
    body_inertial: tuple[pin.SE3, ...]
    site_names: tuple[str, ...]
    site_body: np.ndarray
    site_in_body: tuple[pin.SE3, ...]
    gravity: np.ndarray
    armature: np.ndarray
    _q_mj: np.ndarray = field(repr=False)
    _q_pin: np.ndarray = field(repr=False)
    _q_ref: np.ndarray = field(repr=False)
    _v_mj: np.ndarray = field(repr=False)
    _v_pin: np.ndarray = field(repr=False)
    _free: tuple[JointMap, ...] = field(repr=False)
    _ball: tuple[JointMap, ...] = field(repr=False)

    # ---------------------------------------------------------------- build

    @classmethod
    def from_mujoco(cls, mjmodel: mujoco.MjModel) -> PinocchioModel:
        """Same as the module-level :func:`from_mujoco`."""
        return from_mujoco(mjmodel)

    # ---------------------------------------------------------------- sizes

    @property
    def nq(self) -> int:
        """Number of position coordinates (same in MuJoCo and Pinocchio)."""
        return int(self.model.nq)

    @property
    def nv(self) -> int:
        """Number of degrees of freedom (same in MuJoCo and Pinocchio)."""
        return int(self.model.nv)

    @property
    def nbody(self) -> int:
        """Number of MuJoCo bodies, the world included."""
        return len(self.body_names)

    # ---------------------------------------------------------------- names

    def body_id(self, body: str | int) -> int:
        """MuJoCo body id of a body given by name or id.

        Raises:
            ScenarioError: no such body.
        """
        return _lookup(body, self.body_names, "body")

    def site_id(self, site: str | int) -> int:
        """MuJoCo site id of a site given by name or id.

        Raises:
            ScenarioError: no such site.
        """
        return _lookup(site, self.site_names, "site")

    def joint(self, joint: str | int) -> JointMap:
        """The :class:`JointMap` of a MuJoCo joint given by name or id.

        Raises:
            ScenarioError: no such joint.
        """
        return self.joints[_lookup(joint, tuple(j.name for j in self.joints), "joint")]

    def dofs_supporting(self, body: str | int) -> np.ndarray:
        """MuJoCo dof indices whose motion moves ``body``.

        Args:
            body: MuJoCo body name or id.

        Returns:
            Sorted int array of MuJoCo dof indices (empty for a body fixed to
            the world).
        """
        jid = int(self.body_joint[self.body_id(body)])
        support = set(int(i) for i in self.model.supports[jid])
        dofs = [
            d
            for jm in self.joints
            if jm.pin_id in support
            for d in range(jm.dofadr, jm.dofadr + jm.nv)
        ]
        return np.array(sorted(dofs), dtype=int)

    # ----------------------------------------------------------- conversions

    def q_mj_to_pin(self, qpos: np.ndarray) -> np.ndarray:
        """See :func:`q_mj_to_pin`."""
        return q_mj_to_pin(self, qpos)

    def q_pin_to_mj(self, q: np.ndarray) -> np.ndarray:
        """See :func:`q_pin_to_mj`."""
        return q_pin_to_mj(self, q)

    def v_mj_to_pin(self, qpos: np.ndarray, qvel: np.ndarray) -> np.ndarray:
        """See :func:`v_mj_to_pin`."""
        return v_mj_to_pin(self, qpos, qvel)

    def v_pin_to_mj(self, qpos: np.ndarray, v: np.ndarray) -> np.ndarray:
        """See :func:`v_pin_to_mj`."""
        return v_pin_to_mj(self, qpos, v)

    def a_mj_to_pin(self, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
        """See :func:`a_mj_to_pin`."""
        return a_mj_to_pin(self, qpos, qvel, qacc)

    def tau_pin_to_mj(self, qpos: np.ndarray, tau: np.ndarray) -> np.ndarray:
        """See :func:`tau_pin_to_mj`."""
        return tau_pin_to_mj(self, qpos, tau)

    def tau_mj_to_pin(self, qpos: np.ndarray, qfrc: np.ndarray) -> np.ndarray:
        """See :func:`tau_mj_to_pin`."""
        return tau_mj_to_pin(self, qpos, qfrc)

    def velocity_map(self, qpos: np.ndarray) -> np.ndarray:
        """Matrix ``J`` with ``v_pin = J @ qvel`` at one configuration.

        Generalised forces map by its transpose, ``qfrc = J.T @ tau_pin``, and
        the mass matrices by ``M_mj = J.T @ M_pin @ J``.

        Args:
            qpos: (nq,) MuJoCo positions.

        Returns:
            (nv, nv) array.
        """
        qpos = _check_vec(qpos, self.nq, "qpos", batch=False)
        return v_mj_to_pin(self, np.broadcast_to(qpos, (self.nv, self.nq)), np.eye(self.nv)).T

    # -------------------------------------------------------------- dynamics

    def rnea(
        self,
        qpos: np.ndarray,
        qvel: np.ndarray,
        qacc: np.ndarray,
        *,
        include_armature: bool = False,
    ) -> np.ndarray:
        """Inverse dynamics: generalised forces that produce ``qacc``.

        Equals MuJoCo's ``qfrc_inverse`` with constraints, springs and
        dampers disabled (``M qacc + qfrc_bias``), where MuJoCo's ``M`` holds
        the armature; pass ``include_armature=True`` to add it.

        Args:
            qpos: (nq,) or (T, nq) MuJoCo positions.
            qvel: (nv,) or (T, nv) MuJoCo velocities.
            qacc: (nv,) or (T, nv) MuJoCo accelerations.
            include_armature: add ``armature * qacc``.

        Returns:
            (nv,) or (T, nv) generalised forces in MuJoCo's convention
            [N m for hinges, N for slides, world-frame N and local N m for free
            joints].

        Raises:
            TrajectoryError: shapes disagree or values are not finite.
        """
        qpos, qvel, qacc, single = self._states(qpos, qvel, qacc)
        q = q_mj_to_pin(self, qpos)
        v = v_mj_to_pin(self, qpos, qvel)
        a = a_mj_to_pin(self, qpos, qvel, qacc)
        tau = np.empty_like(v)
        for k in range(q.shape[0]):
            tau[k] = pin.rnea(self.model, self.data, q[k], v[k], a[k])
        out = tau_pin_to_mj(self, qpos, tau)
        if include_armature:
            out = out + self.armature * qacc
        return out[0] if single else out

    def mass_matrix(self, qpos: np.ndarray, *, include_armature: bool = False) -> np.ndarray:
        """Joint-space mass matrix in MuJoCo's coordinates.

        Matches ``mujoco.mj_fullM`` when ``include_armature=True`` (MuJoCo's
        ``qM`` holds the armature on its diagonal).

        Args:
            qpos: (nq,) or (T, nq) MuJoCo positions.
            include_armature: add ``diag(armature)``.

        Returns:
            (nv, nv) or (T, nv, nv) symmetric matrix [kg, kg m, kg m^2].
        """
        qpos = np.asarray(qpos, dtype=float)
        single = qpos.ndim == 1
        qpos = _check_vec(qpos, self.nq, "qpos", batch=True)
        q = q_mj_to_pin(self, qpos)
        out = np.empty((qpos.shape[0], self.nv, self.nv))
        for k in range(qpos.shape[0]):
            m_pin = pin.crba(self.model, self.data, q[k])
            m_pin = np.triu(m_pin) + np.triu(m_pin, 1).T
            jac = self.velocity_map(qpos[k])
            out[k] = jac.T @ m_pin @ jac
            if include_armature:
                out[k] += np.diag(self.armature)
        return out[0] if single else out

    # ------------------------------------------------------------ placements

    def body_placement(self, qpos: np.ndarray, body: str | int, *, inertial: bool = False) -> pin.SE3:
        """World placement of a MuJoCo body frame (``xpos``, ``xmat``).

        Args:
            qpos: (nq,) MuJoCo positions.
            body: body name or id.
            inertial: return the body's inertial frame instead (``xipos``,
                ``ximat``).

        Returns:
            ``pinocchio.SE3``; ``.translation`` [m] (3,), ``.rotation`` (3, 3)
            maps body-frame vectors to the world.
        """
        b = self.body_id(body)
        self._forward_kinematics(qpos)
        pose = self.data.oMi[int(self.body_joint[b])] * self.body_in_joint[b]
        return pose * self.body_inertial[b] if inertial else pose

    def site_placement(self, qpos: np.ndarray, site: str | int) -> pin.SE3:
        """World placement of a MuJoCo site (``site_xpos``, ``site_xmat``).

        Args:
            qpos: (nq,) MuJoCo positions.
            site: site name or id.

        Returns:
            ``pinocchio.SE3`` of the site frame in the world.
        """
        s = self.site_id(site)
        return self.body_placement(qpos, int(self.site_body[s])) * self.site_in_body[s]

    # --------------------------------------------------------------- private

    def _forward_kinematics(self, qpos: np.ndarray) -> None:
        qpos = _check_vec(qpos, self.nq, "qpos", batch=False)
        pin.forwardKinematics(self.model, self.data, q_mj_to_pin(self, qpos))

    def _states(
        self, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool]:
        single = np.asarray(qpos).ndim == 1
        qpos = _check_vec(qpos, self.nq, "qpos", batch=True)
        qvel = _check_vec(qvel, self.nv, "qvel", batch=True)
        qacc = _check_vec(qacc, self.nv, "qacc", batch=True)
        if not (qpos.shape[0] == qvel.shape[0] == qacc.shape[0]):
            raise TrajectoryError(
                "qpos, qvel and qacc must have the same number of rows; got "
                f"{qpos.shape[0]}, {qvel.shape[0]} and {qacc.shape[0]}"
            )
        return qpos, qvel, qacc, single


def _lookup(item: str | int, names: Sequence[str], what: str) -> int:
    if isinstance(item, (int, np.integer)) and not isinstance(item, bool):
        if 0 <= int(item) < len(names):
            return int(item)
        raise ScenarioError(f"{what} id must be in [0, {len(names) - 1}]; got {item}")
    if isinstance(item, str):
        try:
            return list(names).index(item)
        except ValueError:
            shown = ", ".join(repr(n) for n in names[:40])
            more = "" if len(names) <= 40 else f", ... ({len(names)} in all)"
            raise ScenarioError(f"no {what} named {item!r}; valid names: {shown}{more}") from None
    raise ScenarioError(f"{what} must be a name (str) or an id (int); got {type(item).__name__}")


def _check_vec(x: np.ndarray, n: int, name: str, *, batch: bool) -> np.ndarray:
    """Float array of shape (n,) or, with ``batch``, (T, n) (1-D input gains T=1)."""
    try:
        arr = np.asarray(x, dtype=float)
    except (TypeError, ValueError) as exc:
        raise TrajectoryError(f"{name} must be numeric; got {type(x).__name__}") from exc
    ok_shape = arr.ndim == 1 or (batch and arr.ndim == 2)
    if not ok_shape or arr.shape[-1] != n:
        want = f"({n},) or (T, {n})" if batch else f"({n},)"
        raise TrajectoryError(f"{name} must have shape {want}; got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise TrajectoryError(f"{name} holds non-finite values (NaN or inf)")
    if batch and arr.ndim == 1:
        arr = arr[None, :]
    return arr


def from_mujoco(mjmodel: mujoco.MjModel) -> PinocchioModel:
    """Build a :class:`PinocchioModel` from a compiled MuJoCo model.

    Supported: hinge, slide, ball and free joints; any number of joints per
    body except that a free joint must be the only joint of its body and the
    body must not move with any other joint; bodies without joints (merged
    into their parent); arbitrary ``body_pos``/``body_quat``, joint anchors
    ``jnt_pos`` and axes ``jnt_axis``; inertial frames ``body_ipos``,
    ``body_iquat`` with principal inertia ``body_inertia``. Mocap bodies are
    treated as fixed at their ``body_pos``/``body_quat``.

    Args:
        mjmodel: compiled MuJoCo model.

    Returns:
        The model. Its configuration and velocity sizes equal MuJoCo's.

    Raises:
        ScenarioError: unsupported structure (a free joint combined with other
            joints or below a moving body, a moving body below a mocap body).
        CritmomentError: ``mjmodel`` is not a ``mujoco.MjModel``.
    """
    if not isinstance(mjmodel, mujoco.MjModel):
        raise CritmomentError(f"from_mujoco expects a mujoco.MjModel; got {type(mjmodel).__name__}")
    m = mjmodel
    model = pin.Model()
    model.name = "critmoment"

    def _name(obj: mujoco.mjtObj, idx: int, prefix: str) -> str:
        name = mujoco.mj_id2name(m, obj, idx)
        return name if name else f"{prefix}{idx}"

    body_names = tuple(_name(mujoco.mjtObj.mjOBJ_BODY, b, "body") for b in range(m.nbody))
    body_joint = np.zeros(m.nbody, dtype=int)
    body_in_joint: list[pin.SE3] = [pin.SE3.Identity()]
    body_inertial: list[pin.SE3] = [_se3(m.body_ipos[0], m.body_iquat[0])]
    body_frame = np.zeros(m.nbody, dtype=int)  # universe frame is 0
    fixed_by_mocap = np.zeros(m.nbody, dtype=bool)
    joint_pin = np.zeros(m.njnt, dtype=int)

    for b in range(1, m.nbody):
        parent = int(m.body_parentid[b])
        fixed_by_mocap[b] = fixed_by_mocap[parent] or int(m.body_mocapid[b]) >= 0
        parent_jid = int(body_joint[parent])
        # body frame at qpos0, in the frame of the parent's Pinocchio joint
        placement = body_in_joint[parent] * _se3(m.body_pos[b], m.body_quat[b])
        inertial = _se3(m.body_ipos[b], m.body_iquat[b])
        inertia = pin.Inertia(
            float(m.body_mass[b]),
            np.array(m.body_ipos[b], dtype=float),
            inertial.rotation @ np.diag(m.body_inertia[b]) @ inertial.rotation.T,
        )
        jnt_ids = range(int(m.body_jntadr[b]), int(m.body_jntadr[b]) + int(m.body_jntnum[b]))
        kinds = [_KIND[int(m.jnt_type[j])] for j in jnt_ids]
        if kinds and fixed_by_mocap[b]:
            raise ScenarioError(
                f"body {body_names[b]!r} has joints below a mocap body; mocap bodies are treated as "
                "fixed, so this structure is not supported"
            )
        if "free" in kinds:
            if len(kinds) != 1:
                raise ScenarioError(
                    f"body {body_names[b]!r} combines a free joint with other joints {kinds}; "
                    "a free joint must be the only joint of its body"
                )
            if parent_jid != 0:
                raise ScenarioError(
                    f"body {body_names[b]!r} has a free joint but its parent "
                    f"{body_names[parent]!r} moves; free joints are supported only on bodies "
                    "fixed-attached to the world"
                )
            # MuJoCo's free-joint qpos is the absolute world pose of the body frame.
            placement = pin.SE3.Identity()
        jid = parent_jid
        for j in jnt_ids:
            kind = _KIND[int(m.jnt_type[j])]
            anchor = np.array(m.jnt_pos[j], dtype=float)
            axis = np.array(m.jnt_axis[j], dtype=float)
            if kind == "free":
                jmodel, anchor = pin.JointModelFreeFlyer(), np.zeros(3)
            elif kind == "ball":
                jmodel = pin.JointModelSpherical()
            elif kind == "slide":
                jmodel = pin.JointModelPrismaticUnaligned(axis / np.linalg.norm(axis))
            else:
                jmodel = pin.JointModelRevoluteUnaligned(axis / np.linalg.norm(axis))
            # each joint acts as T(anchor) * motion(q) * T(-anchor) in the body frame
            jid = model.addJoint(
                jid, jmodel, placement * _translation(anchor), _name(mujoco.mjtObj.mjOBJ_JOINT, j, "joint")
            )
            joint_pin[j] = jid
            model.addJointFrame(jid, int(body_frame[parent]))
            placement = _translation(-anchor)
        body_joint[b] = jid
        body_in_joint.append(placement)
        body_inertial.append(inertial)
        if jid != 0:
            model.appendBodyToJoint(jid, inertia, placement)
        body_frame[b] = model.addBodyFrame(body_names[b], jid, placement, int(body_frame[parent]))

    site_names = tuple(_name(mujoco.mjtObj.mjOBJ_SITE, s, "site") for s in range(m.nsite))
    site_in_body = tuple(_se3(m.site_pos[s], m.site_quat[s]) for s in range(m.nsite))
    for s in range(m.nsite):
        b = int(m.site_bodyid[s])
        model.addFrame(
            pin.Frame(
                site_names[s],
                int(body_joint[b]),
                int(body_frame[b]),
                body_in_joint[b] * site_in_body[s],
                pin.FrameType.OP_FRAME,
            )
        )

    gravity = np.array(m.opt.gravity, dtype=float)
    if m.opt.disableflags & int(mujoco.mjtDisableBit.mjDSBL_GRAVITY):
        gravity = np.zeros(3)
    model.gravity = pin.Motion(gravity, np.zeros(3))

    joints = []
    for j in range(m.njnt):
        kind = _KIND[int(m.jnt_type[j])]
        jm = model.joints[int(joint_pin[j])]
        joints.append(
            JointMap(
                mj_id=j,
                name=_name(mujoco.mjtObj.mjOBJ_JOINT, j, "joint"),
                kind=kind,
                body_id=int(m.jnt_bodyid[j]),
                pin_id=int(joint_pin[j]),
                qposadr=int(m.jnt_qposadr[j]),
                dofadr=int(m.jnt_dofadr[j]),
                nq=_NQ[kind],
                nv=_NV[kind],
                idx_q=int(jm.idx_q),
                idx_v=int(jm.idx_v),
                qpos0=float(m.qpos0[m.jnt_qposadr[j]]) if kind in ("slide", "hinge") else 0.0,
            )
        )
    if model.nq != m.nq or model.nv != m.nv:  # pragma: no cover - guards the builder itself
        raise CritmomentError(f"built nq/nv {model.nq}/{model.nv} differ from MuJoCo's {m.nq}/{m.nv}")

    scalar = [jm for jm in joints if jm.kind in ("slide", "hinge")]
    v_mj = [jm.dofadr + k for jm in joints for k in range(jm.nv)]
    v_pin = [jm.idx_v + k for jm in joints for k in range(jm.nv)]
    return PinocchioModel(
        model=model,
        data=model.createData(),
        joints=tuple(joints),
        body_names=body_names,
        body_joint=_readonly(body_joint),
        body_in_joint=tuple(body_in_joint),
        body_inertial=tuple(body_inertial),
        site_names=site_names,
        site_body=_readonly(np.array(m.site_bodyid, dtype=int)),
        site_in_body=site_in_body,
        gravity=_readonly(gravity),
        armature=_readonly(np.array(m.dof_armature, dtype=float)),
        _q_mj=_readonly(np.array([jm.qposadr for jm in scalar], dtype=int)),
        _q_pin=_readonly(np.array([jm.idx_q for jm in scalar], dtype=int)),
        _q_ref=_readonly(np.array([jm.qpos0 for jm in scalar], dtype=float)),
        _v_mj=_readonly(np.array(v_mj, dtype=int)),
        _v_pin=_readonly(np.array(v_pin, dtype=int)),
        _free=tuple(jm for jm in joints if jm.kind == "free"),
        _ball=tuple(jm for jm in joints if jm.kind == "ball"),
    )


# --------------------------------------------------------------------------
# convention conversions (all accept a leading batch axis)
# --------------------------------------------------------------------------


def _free_rot(qpos: np.ndarray, jm: JointMap) -> np.ndarray:
    return _quat_to_mat(qpos[..., jm.qposadr + 3 : jm.qposadr + 7])


def _rot_t(rot: np.ndarray, vec: np.ndarray) -> np.ndarray:
    """R^T vec for stacks (..., 3, 3), (..., 3)."""
    return np.einsum("...ji,...j->...i", rot, vec)


def _rot(rot: np.ndarray, vec: np.ndarray) -> np.ndarray:
    """R vec for stacks (..., 3, 3), (..., 3)."""
    return np.einsum("...ij,...j->...i", rot, vec)


def q_mj_to_pin(pm: PinocchioModel, qpos: np.ndarray) -> np.ndarray:
    """MuJoCo ``qpos`` to Pinocchio ``q``.

    Hinges and slides become ``qpos - qpos0``; quaternions are normalised and
    reordered from wxyz to xyzw.

    Args:
        pm: the model.
        qpos: (..., nq) MuJoCo positions.

    Returns:
        (..., nq) Pinocchio configuration.
    """
    qpos = np.asarray(qpos, dtype=float)
    q = np.empty_like(qpos)
    q[..., pm._q_pin] = qpos[..., pm._q_mj] - pm._q_ref
    for jm in pm._free + pm._ball:
        quat_at = jm.qposadr + (3 if jm.kind == "free" else 0)
        pin_at = jm.idx_q + (3 if jm.kind == "free" else 0)
        if jm.kind == "free":
            q[..., jm.idx_q : jm.idx_q + 3] = qpos[..., jm.qposadr : jm.qposadr + 3]
        quat = _normalize_quat(qpos[..., quat_at : quat_at + 4])
        q[..., pin_at : pin_at + 3] = quat[..., 1:4]
        q[..., pin_at + 3] = quat[..., 0]
    return q


def q_pin_to_mj(pm: PinocchioModel, q: np.ndarray) -> np.ndarray:
    """Pinocchio ``q`` to MuJoCo ``qpos`` (inverse of :func:`q_mj_to_pin`).

    Args:
        pm: the model.
        q: (..., nq) Pinocchio configuration.

    Returns:
        (..., nq) MuJoCo positions.
    """
    q = np.asarray(q, dtype=float)
    qpos = np.empty_like(q)
    qpos[..., pm._q_mj] = q[..., pm._q_pin] + pm._q_ref
    for jm in pm._free + pm._ball:
        quat_at = jm.qposadr + (3 if jm.kind == "free" else 0)
        pin_at = jm.idx_q + (3 if jm.kind == "free" else 0)
        if jm.kind == "free":
            qpos[..., jm.qposadr : jm.qposadr + 3] = q[..., jm.idx_q : jm.idx_q + 3]
        qpos[..., quat_at] = q[..., pin_at + 3]
        qpos[..., quat_at + 1 : quat_at + 4] = q[..., pin_at : pin_at + 3]
    return qpos


def v_mj_to_pin(pm: PinocchioModel, qpos: np.ndarray, qvel: np.ndarray) -> np.ndarray:
    """MuJoCo ``qvel`` to Pinocchio ``v``.

    Free joints: the world-frame linear velocity is rotated into the body
    frame, ``v_lin = R^T qvel_lin``; the angular part is already local.

    Args:
        pm: the model.
        qpos: (..., nq) MuJoCo positions (for the free-joint rotations).
        qvel: (..., nv) MuJoCo velocities.

    Returns:
        (..., nv) Pinocchio velocity.
    """
    return _mj_to_pin(pm, qpos, qvel)


def _mj_to_pin(pm: PinocchioModel, qpos: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Reorder MuJoCo dof vectors to Pinocchio's, free joints' linear part world → local."""
    qpos, x = np.asarray(qpos, dtype=float), np.asarray(x, dtype=float)
    out = np.empty_like(x)
    out[..., pm._v_pin] = x[..., pm._v_mj]
    for jm in pm._free:
        rot = _free_rot(qpos, jm)
        out[..., jm.idx_v : jm.idx_v + 3] = _rot_t(rot, x[..., jm.dofadr : jm.dofadr + 3])
    return out


def _pin_to_mj(pm: PinocchioModel, qpos: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Reorder Pinocchio dof vectors to MuJoCo's, free joints' linear part local → world."""
    qpos, x = np.asarray(qpos, dtype=float), np.asarray(x, dtype=float)
    out = np.empty_like(x)
    out[..., pm._v_mj] = x[..., pm._v_pin]
    for jm in pm._free:
        rot = _free_rot(qpos, jm)
        out[..., jm.dofadr : jm.dofadr + 3] = _rot(rot, x[..., jm.idx_v : jm.idx_v + 3])
    return out


def v_pin_to_mj(pm: PinocchioModel, qpos: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Pinocchio ``v`` to MuJoCo ``qvel`` (inverse of :func:`v_mj_to_pin`).

    Args:
        pm: the model.
        qpos: (..., nq) MuJoCo positions.
        v: (..., nv) Pinocchio velocity.

    Returns:
        (..., nv) MuJoCo velocities.
    """
    return _pin_to_mj(pm, qpos, v)


def a_mj_to_pin(pm: PinocchioModel, qpos: np.ndarray, qvel: np.ndarray, qacc: np.ndarray) -> np.ndarray:
    """MuJoCo ``qacc`` to Pinocchio ``a`` (the time derivative of ``v``).

    Free joints: ``a_lin = R^T qacc_lin - omega x (R^T qvel_lin)`` with
    ``omega`` the local angular velocity; the angular part is unchanged.

    Args:
        pm: the model.
        qpos: (..., nq) MuJoCo positions.
        qvel: (..., nv) MuJoCo velocities.
        qacc: (..., nv) MuJoCo accelerations.

    Returns:
        (..., nv) Pinocchio acceleration.
    """
    qpos, qvel, qacc = (np.asarray(x, dtype=float) for x in (qpos, qvel, qacc))
    a = np.empty_like(qacc)
    a[..., pm._v_pin] = qacc[..., pm._v_mj]
    for jm in pm._free:
        rot = _free_rot(qpos, jm)
        d = jm.dofadr
        v_loc = _rot_t(rot, qvel[..., d : d + 3])
        omega = qvel[..., d + 3 : d + 6]
        a[..., jm.idx_v : jm.idx_v + 3] = _rot_t(rot, qacc[..., d : d + 3]) - np.cross(omega, v_loc)
    return a


def tau_pin_to_mj(pm: PinocchioModel, qpos: np.ndarray, tau: np.ndarray) -> np.ndarray:
    """Pinocchio generalised forces to MuJoCo's (``qfrc = J^T tau``).

    ``J`` is the velocity map of :meth:`PinocchioModel.velocity_map`; for a
    free joint the local force becomes a world-frame force, ``R tau_lin``.

    Args:
        pm: the model.
        qpos: (..., nq) MuJoCo positions.
        tau: (..., nv) Pinocchio generalised forces.

    Returns:
        (..., nv) MuJoCo generalised forces.
    """
    return _pin_to_mj(pm, qpos, tau)


def tau_mj_to_pin(pm: PinocchioModel, qpos: np.ndarray, qfrc: np.ndarray) -> np.ndarray:
    """MuJoCo generalised forces to Pinocchio's (inverse of :func:`tau_pin_to_mj`).

    Args:
        pm: the model.
        qpos: (..., nq) MuJoCo positions.
        qfrc: (..., nv) MuJoCo generalised forces.

    Returns:
        (..., nv) Pinocchio generalised forces.
    """
    return _mj_to_pin(pm, qpos, qfrc)


# --------------------------------------------------------------------------
# payload-affine inverse dynamics
# --------------------------------------------------------------------------


def payload_regressor(
    pm: PinocchioModel,
    qpos: np.ndarray,
    qvel: np.ndarray,
    qacc: np.ndarray,
    *,
    attach_body: str | int,
    payload_pose_world: np.ndarray,
    unit_inertia: np.ndarray,
    exclude_joints: Sequence[str | int] | None = None,
    include_armature: bool = False,
) -> tuple[np.ndarray, np.ndarray]:
    """Inverse dynamics that is affine in the mass of a rigidly held payload.

    A payload of mass ``m`` [kg] whose inertial frame sits at
    ``payload_pose_world`` and whose inertia about its centre of mass is
    ``m * unit_inertia`` moves rigidly with ``attach_body``. The generalised
    forces needed are exactly ``tau0 + m * y``: ``tau0`` is :meth:`rnea`
    without payload, and ``y`` is ``J^T f`` with ``f`` the Newton-Euler wrench
    of the unit-mass payload (gravity included) at the frame of the holding
    joint and ``J`` that joint's local Jacobian.

    The payload's placement relative to ``attach_body`` is computed from the
    world pose at each state, so a recorded object pose can be used directly.

    Args:
        pm: the model *without* the payload attached.
        qpos: (nq,) or (T, nq) MuJoCo positions.
        qvel: (nv,) or (T, nv) MuJoCo velocities.
        qacc: (nv,) or (T, nv) MuJoCo accelerations.
        attach_body: MuJoCo body (name or id) that holds the payload, e.g. the
            gripper link.
        payload_pose_world: (7,) or (T, 7) position [m] and quaternion (w, x,
            y, z) of the payload's inertial frame in the world.
        unit_inertia: (3, 3) inertia per unit mass [m^2] about the centre of
            mass, in the payload's frame (e.g. ``diag(a^2/6)`` for a cube of
            side ``a``).
        exclude_joints: MuJoCo joints (names or ids) whose dofs are set to 0
            in both outputs. ``None`` excludes every free joint that does not
            carry ``attach_body`` -- the free-floating objects, including the
            payload's own free joint, whose forces no motor supplies.
        include_armature: add ``armature * qacc`` to ``tau0``.

    Returns:
        ``(tau0, y)``, each (nv,) or (T, nv) in MuJoCo's dof order and
        convention; ``y`` [N m/kg or N/kg] is nonzero only on dofs that move
        ``attach_body``.

    Raises:
        TrajectoryError: bad shapes or non-finite values.
        ParameterError: ``unit_inertia`` not symmetric positive semidefinite.
        ScenarioError: unknown body or joint.
    """
    qpos, qvel, qacc, single = pm._states(qpos, qvel, qacc)
    n = qpos.shape[0]
    poses = _check_vec(payload_pose_world, 7, "payload_pose_world", batch=True)
    if poses.shape[0] not in (1, n):
        raise TrajectoryError(f"payload_pose_world must have 1 or {n} rows; got {poses.shape[0]}")
    poses = np.broadcast_to(poses, (n, 7))
    unit = np.asarray(unit_inertia, dtype=float)
    if unit.shape != (3, 3) or not np.all(np.isfinite(unit)):
        raise ParameterError(f"unit_inertia must be a finite (3, 3) array; got shape {unit.shape}")
    scale = max(float(np.abs(unit).max()), 1e-300)
    if not np.allclose(unit, unit.T, rtol=0.0, atol=1e-12 * scale):
        raise ParameterError("unit_inertia must be symmetric")
    if np.linalg.eigvalsh(unit).min() < -1e-12 * scale:
        raise ParameterError(f"unit_inertia must be positive semidefinite; eigenvalues {np.linalg.eigvalsh(unit)}")
    unit = 0.5 * (unit + unit.T)

    b = pm.body_id(attach_body)
    jid = int(pm.body_joint[b])
    if exclude_joints is None:
        support = set(int(i) for i in pm.model.supports[jid])
        excluded = [jm for jm in pm.joints if jm.kind == "free" and jm.pin_id not in support]
    else:
        excluded = [pm.joint(j) for j in exclude_joints]
    mask = np.ones(pm.nv, dtype=bool)
    for jm in excluded:
        mask[jm.dofadr : jm.dofadr + jm.nv] = False

    q = q_mj_to_pin(pm, qpos)
    v = v_mj_to_pin(pm, qpos, qvel)
    a = a_mj_to_pin(pm, qpos, qvel, qacc)
    tau0 = np.empty((n, pm.nv))
    y_pin = np.zeros((n, pm.nv))
    model, data = pm.model, pm.data
    rotations = _quat_to_mat(poses[:, 3:])  # once for every row
    for k in range(n):
        tau0[k] = pin.rnea(model, data, q[k], v[k], a[k])
        if jid == 0:
            continue  # held by a body fixed to the world: no dof feels the payload
        # joint-frame velocity and acceleration (a_gf includes -gravity), copied
        vel, acc = pin.Motion(data.v[jid]), pin.Motion(data.a_gf[jid])
        # rnea does not update data.oMi; computeJointJacobians does (and fills data.J)
        pin.computeJointJacobians(model, data, q[k])
        joint_payload = data.oMi[jid].actInv(pin.SE3(rotations[k], poses[k, :3].copy()))
        rot = joint_payload.rotation
        inertia = pin.Inertia(1.0, joint_payload.translation.copy(), rot @ unit @ rot.T)
        wrench = inertia * acc + vel.cross(inertia * vel)
        jac = pin.getJointJacobian(model, data, jid, pin.ReferenceFrame.LOCAL)
        y_pin[k] = jac.T @ wrench.vector
    tau0 = tau_pin_to_mj(pm, qpos, tau0)
    if include_armature:
        tau0 = tau0 + pm.armature * qacc
    y = tau_pin_to_mj(pm, qpos, y_pin)
    tau0[:, ~mask] = 0.0
    y[:, ~mask] = 0.0
    return (tau0[0], y[0]) if single else (tau0, y)


def _check_tau_max(tau_max: np.ndarray) -> np.ndarray:
    tau_max = np.asarray(tau_max, dtype=float)
    if np.any(np.isnan(tau_max)) or np.any(tau_max < 0):
        raise ParameterError("tau_max must be >= 0 (inf allowed, NaN not)")
    return tau_max


def critical_mass(tau0: np.ndarray, y: np.ndarray, tau_max: np.ndarray) -> np.ndarray:
    """Smallest payload mass at which each joint reaches its effort limit.

    Per joint, the smallest ``m >= 0`` with ``|tau0 + m y| >= tau_max``. When
    ``|tau0| < tau_max`` this is the root of ``|tau0 + m y| = tau_max``,
    ``m = (sign(y) tau_max - tau0) / y``; it is 0 when the joint is already at
    or over its limit without payload, and inf when ``y = 0`` (the payload
    never loads the joint) and the joint is within its limit.

    Args:
        tau0: (..., nv) generalised forces without payload.
        y: (..., nv) generalised forces per kg of payload.
        tau_max: scalar or broadcastable (nv,) effort limits [N m or N]; inf
            for joints without a limit.

    Returns:
        Array of the broadcast shape of ``tau0``, ``y``, ``tau_max`` [kg].

    Raises:
        ParameterError: ``tau_max`` negative or NaN.
    """
    tau0, y = np.asarray(tau0, dtype=float), np.asarray(y, dtype=float)
    tau_max = _check_tau_max(tau_max)
    tau0, y, tau_max = np.broadcast_arrays(tau0, y, tau_max)
    out = np.full(tau0.shape, np.inf)
    over = np.abs(tau0) >= tau_max
    out[over] = 0.0
    root = ~over & (y != 0) & np.isfinite(tau_max)
    out[root] = (np.sign(y[root]) * tau_max[root] - tau0[root]) / y[root]
    return out


def motor_fos(tau0: np.ndarray, y: np.ndarray, tau_max: np.ndarray, m: float | np.ndarray) -> np.ndarray:
    """Motor factor of safety ``min_j tau_max_j / |tau0_j + m y_j|``.

    Args:
        tau0: (nv,) or (T, nv) generalised forces without payload; with a time
            axis the minimum runs over time too.
        y: same shape as ``tau0``, generalised forces per kg of payload.
        tau_max: scalar or (nv,) effort limits [N m or N]; inf for joints
            without a limit (they never bind).
        m: payload mass [kg], scalar or array of any shape.

    Returns:
        FOS with the shape of ``m`` (a float for a scalar ``m``); inf where no
        joint is loaded. FOS < 1 means some joint exceeds its limit.

    Raises:
        ParameterError: ``tau_max`` negative or NaN, or ``m`` negative or NaN.
    """
    tau0, y = np.asarray(tau0, dtype=float), np.asarray(y, dtype=float)
    tau_max = _check_tau_max(tau_max)
    m = np.asarray(m, dtype=float)
    if np.any(np.isnan(m)) or np.any(m < 0):
        raise ParameterError("payload mass m must be >= 0")
    tau0, y = np.broadcast_arrays(tau0, y)
    flat0 = tau0.reshape(-1, tau0.shape[-1]) if tau0.ndim else tau0.reshape(1, 1)
    flaty = y.reshape(flat0.shape)
    lim = np.broadcast_to(tau_max, flat0.shape[-1:])
    tau = flat0[None] + m.reshape(-1, 1, 1) * flaty[None]
    mag = np.abs(tau)
    ratio = np.full(tau.shape, np.inf)
    np.divide(np.broadcast_to(lim, tau.shape), mag, out=ratio, where=mag > 0)
    fos = ratio.min(axis=(1, 2)).reshape(m.shape)
    return float(fos) if fos.ndim == 0 else fos


def analytic_contact_fos(
    mass: float | np.ndarray,
    mu: float | np.ndarray,
    *,
    acc_world: np.ndarray,
    gravity: np.ndarray,
    normal_force_total: float | np.ndarray,
) -> np.ndarray:
    """Closed-form friction factor of safety of a grasped object.

    ``fos = mu * sum(F_n) / |m (a - g)|``: the friction the grasp can supply
    over the force needed to give the object its acceleration against
    gravity. Assumptions: rigid grasp (the object moves with the gripper);
    the object is supported by friction alone (no table, no form closure);
    the whole normal force ``normal_force_total`` (e.g. the gripper's force
    limit summed over the pads) is available and pressed on the object;
    Coulomb friction with one coefficient ``mu`` at every contact; no
    torsional or rolling demand (the centre of mass lies between the pads, so
    no moment has to be resisted).

    Args:
        mass: object mass [kg], scalar or array.
        mu: friction coefficient [-], scalar or array (broadcast with
            ``mass``).
        acc_world: (3,) or (..., 3) object acceleration [m/s^2] in the world.
        gravity: (3,) gravity [m/s^2] in the world, e.g. (0, 0, -9.81).
        normal_force_total: sum of the normal forces [N], scalar or array.

    Returns:
        FOS with the broadcast shape of ``mass``, ``mu``,
        ``normal_force_total`` and ``acc_world[..., 0]``; inf where the
        demand ``|m (a - g)|`` is 0. FOS < 1 means the object slips.

    Raises:
        ParameterError: negative mass, friction or normal force, or vectors
            not of length 3.
    """
    mass, mu, fn = (np.asarray(x, dtype=float) for x in (mass, mu, normal_force_total))
    acc, grav = np.asarray(acc_world, dtype=float), np.asarray(gravity, dtype=float)
    if acc.shape[-1:] != (3,) or grav.shape != (3,):
        raise ParameterError(f"acc_world must be (..., 3) and gravity (3,); got {acc.shape} and {grav.shape}")
    for name, val in (("mass", mass), ("mu", mu), ("normal_force_total", fn)):
        if np.any(np.isnan(val)) or np.any(val < 0):
            raise ParameterError(f"{name} must be >= 0 and not NaN")
    demand = mass * np.linalg.norm(acc - grav, axis=-1)
    supply = mu * fn
    supply, demand = np.broadcast_arrays(supply, demand)
    fos = np.full(demand.shape, np.inf)
    np.divide(supply, demand, out=fos, where=demand > 0)
    return float(fos) if fos.ndim == 0 else fos


# --------------------------------------------------------------------------
# loads over the whole motion
# --------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class LoadBound:
    """Analytic motor loads over a whole recorded motion, for several payload masses.

    ``τ(m, t) = τ0(t) + m·y(t)`` on each rotational actuator, where ``y`` is non-zero only
    at the steps where a gripper carries the object (:func:`trajectory_load_bound`).

    Attributes:
        masses: payload masses [kg], (k,).
        fos: motor FOS ``min_a limit_a / |τ_a(m, t)|`` per mass and step, (k, T); inf
            where nothing is loaded.
        limiting: index (into ``actuator_names``) of the limiting actuator, (k, T) int64.
        carried: a gripper carries the object at the step, (T,) bool.
        critical_mass: smallest payload that brings a joint to ``saturation`` × its limit
            at each step [kg], (T,); 0 where the arm alone does, inf where no mass does.
        actuator_names: names of all actuators (``limiting`` indexes them).
        dt: physics step [s].
        saturation: fraction of a limit at which an actuator counts as saturated.
        min_duration: how long a saturation must last to count [s].
        unbounded: the actuators that stand a free-floating robot on its contacts at some
            step (:func:`standing_actuators`): their bound leaves the robot's weight out.
    """

    masses: np.ndarray
    fos: np.ndarray
    limiting: np.ndarray
    carried: np.ndarray
    critical_mass: np.ndarray
    actuator_names: tuple[str, ...]
    dt: float
    saturation: float
    min_duration: float
    unbounded: tuple[str, ...] = ()

    @property
    def overloaded(self) -> np.ndarray:
        """(k, T) bool: an actuator needs at least ``saturation`` × its limit."""
        return self.fos * self.saturation <= 1.0

    @property
    def first_failing_step(self) -> np.ndarray:
        """(k,) int64: first step of the first overload lasting longer than
        ``min_duration`` (as the ground truth's ``motor_step`` counts a saturation), −1
        where none."""
        need = int(round(self.min_duration / self.dt)) + 1 if self.min_duration > 0 else 1
        out = np.full(self.masses.shape[0], -1, dtype=np.int64)
        for i, row in enumerate(self.overloaded):
            edges = np.flatnonzero(np.diff(np.concatenate([[0], row.astype(np.int8), [0]])))
            for start, stop in zip(edges[::2], edges[1::2], strict=True):
                if stop - start >= need:
                    out[i] = start
                    break
        return out

    @property
    def first_failing_time(self) -> np.ndarray:
        """(k,) [s]: time of ``first_failing_step``, NaN where none."""
        step = self.first_failing_step
        return np.where(step >= 0, step * self.dt, np.nan)

    def limiting_at(self, row: int, step: int) -> str:
        """Name of the limiting actuator for mass row ``row`` at ``step``."""
        return self.actuator_names[int(self.limiting[row, step])]


def unactuated_force(model: mujoco.MjModel, data: mujoco.MjData) -> np.ndarray:
    """The generalised forces at ``data`` (after :func:`mujoco.mj_fwdVelocity`) that no
    actuator of the model supplies, (nv,): ``qfrc_passive`` (joint damping, springs, fluid,
    gravity compensation) plus the gravity compensation a joint with ``actuatorgravcomp``
    takes through ``qfrc_actuator`` instead (trossen-arm-sim's WidowX AI: 6.95 N·m of its
    shoulder's weight that its servo never carries)."""
    out = data.qfrc_passive.copy()
    if model.jnt_actgravcomp.any():
        out += data.qfrc_gravcomp * model.jnt_actgravcomp[model.dof_jntid]
    return out


def passive_forces(model: mujoco.MjModel, states: np.ndarray) -> np.ndarray:
    """The forces the actuators need not supply at recorded states (T, nv),
    :func:`unactuated_force` per state (joint damping, and springs, gravity compensation
    and fluid forces where the model has them). Inverse dynamics minus these is what the
    actuators carry.

    Args:
        model: the compiled model.
        states: ``mjSTATE_INTEGRATION`` rows (T, nstate).
    """
    from critmoment.twin import STATE_SPEC, state_slice

    states = np.asarray(states, dtype=float)
    qvel = states[:, state_slice(model, mujoco.mjtState.mjSTATE_QVEL)]
    others = (model.body_gravcomp.any() or model.jnt_stiffness.any()
              or model.tendon_stiffness.any() or model.tendon_damping.any()
              or model.opt.density > 0 or model.opt.viscosity > 0)
    if not others:  # damping alone: -b·q̇, as MuJoCo computes it
        return -model.dof_damping * qvel
    data = mujoco.MjData(model)
    out = np.empty((states.shape[0], model.nv))
    for t, row in enumerate(states):
        mujoco.mj_setState(model, data, row, STATE_SPEC)
        mujoco.mj_fwdPosition(model, data)
        mujoco.mj_fwdVelocity(model, data)
        out[t] = unactuated_force(model, data)
    return out


def standing_actuators(model: mujoco.MjModel, data: mujoco.MjData, twin,
                       bases: Sequence[int] | None = None) -> set[int]:
    """The actuators on joints that stand a free-floating robot base on its contacts in
    ``data`` (collision done; :func:`critmoment.actuators.supporting_joints`, the object's
    contacts left out): their load includes the robot's weight, which inverse dynamics of
    the floating chain does not give them. ``bases``: the model's
    :func:`critmoment.actuators.robot_bases`, where the caller has them."""
    from critmoment import actuators as act_info

    bases = act_info.robot_bases(model) if bases is None else bases
    if not bases:
        return set()
    joints = act_info.supporting_joints(model, data, bases, exclude=[twin.object_body_id])
    trn = mujoco.mjtTrn
    return {a for a in range(model.nu)
            if int(model.actuator_trntype[a]) in (trn.mjTRN_JOINT, trn.mjTRN_JOINTINPARENT)
            and int(model.actuator_trnid[a, 0]) in joints}


def trajectory_load_bound(recording, twin, *, masses: Sequence[float] | np.ndarray | None = None,
                          pin_model: PinocchioModel | None = None, saturation: float = 0.999,
                          min_duration: float = 0.05) -> LoadBound:
    """The analytic motor bound over every step of a recorded motion.

    For each step the recorded motion (positions and velocities of the recorded states,
    accelerations by finite differences of the velocities, so the accelerations the
    integrator realised) gives ``τ0`` by inverse dynamics with the arm's armature and joint
    damping; where a gripper carries the object in the recording (it touches it off its
    support) the object's inertia, at its recorded pose and scaled per kg, rides on the
    gripper's base body and gives ``y``. A hand-over lets either gripper carry the whole
    payload (the worse one counts). Contact forces other than the carried payload's are not
    modelled (a squeeze against the table, a collision).

    Args:
        recording: the frequent rollout (``states`` (T + 1, nstate), ``signals``, ``dt``).
        twin: its twin.
        masses: payload masses [kg] (k,); default the box's nominal and largest mass (or
            the model's object mass without a mass parameter).
        pin_model: Pinocchio model of ``twin.model`` (built when None).
        saturation: fraction of a limit that counts as saturated (the ground truth's 0.999).
        min_duration: how long an overload must last to count for ``first_failing_step``
            [s] (the ground truth's ``motor_time``, 0.05 s).

    Returns:
        The :class:`LoadBound`.

    Raises:
        ParameterError: negative masses, or a saturation outside (0, 1].
    """
    from critmoment.sparse import grip_frames
    from critmoment.twin import STATE_SPEC, state_slice

    model = twin.model
    sc = twin.scenario
    if masses is None:
        names = sc.box.names
        if "mass" in names:
            j = names.index("mass")
            masses = [sc.box.nominal[j], sc.box.high[j]]
        else:
            masses = [float(model.body_mass[twin.object_body_id])]
    masses = np.atleast_1d(np.asarray(masses, dtype=float))
    if masses.ndim != 1 or np.isnan(masses).any() or (masses < 0).any():
        raise ParameterError(f"masses: expected payload masses >= 0 [kg], got {masses}")
    if not 0 < saturation <= 1:
        raise ParameterError(f"saturation: expected a fraction in (0, 1], got {saturation!r}")
    if not (np.isfinite(min_duration) and min_duration >= 0):
        raise ParameterError(f"min_duration: expected a time >= 0 s, got {min_duration!r}")
    pm = pin_model if pin_model is not None else from_mujoco(model)
    dt = float(recording.dt)
    states = np.asarray(recording.states, dtype=float)
    n_steps = states.shape[0] - 1
    qpos = states[:n_steps, state_slice(model, mujoco.mjtState.mjSTATE_QPOS)]
    qvel_all = states[:, state_slice(model, mujoco.mjtState.mjSTATE_QVEL)]
    qvel = qvel_all[:n_steps]
    qacc = (qvel_all[1:] - qvel_all[:-1]) / dt
    rot = np.flatnonzero(twin.motors)
    dofs = model.jnt_dofadr[model.actuator_trnid[rot, 0]]
    gear = model.actuator_gear[rot, 0]
    limits = twin.lowest_limits[rot]  # a force-limit parameter at its range's low end
    tau0 = pm.rnea(qpos, qvel, qacc, include_armature=True)
    tau0 = (tau0[:, dofs] - passive_forces(model, states[:n_steps])[:, dofs]) / gear  # (T, J)

    sig = recording.signals
    held = np.asarray(sig.contact_gripper, bool) & ~np.asarray(sig.contact_support, bool)[:, None]
    carried = held.any(axis=1)
    anchors, _ = grip_frames(model, sc)
    ob = twin.object_body_id
    unit_inertia = np.diag(model.body_inertia[ob] / model.body_mass[ob])
    y = np.zeros((len(anchors),) + tau0.shape)  # (G, T, J)
    data = mujoco.MjData(model)
    for g, body in enumerate(anchors):
        rows = np.flatnonzero(held[:, g])
        if not rows.size:
            continue
        poses = np.empty((rows.size, 7))
        for r, t in enumerate(rows):
            mujoco.mj_setState(model, data, states[t], STATE_SPEC)
            mujoco.mj_kinematics(model, data)
            poses[r, :3] = data.xipos[ob]
            mujoco.mju_mat2Quat(poses[r, 3:], data.ximat[ob])
        _, y_g = payload_regressor(pm, qpos[rows], qvel[rows], qacc[rows],
                                   attach_body=int(body), payload_pose_world=poses,
                                   unit_inertia=unit_inertia)
        y[g, rows] = y_g[:, dofs] / gear
    # (k, G, T, J): every holder carries the whole payload; the worse one counts
    tau = np.abs(tau0[None, None] + masses[:, None, None, None] * y[None])
    with np.errstate(divide="ignore"):
        ratio = np.where(tau > 0, limits / tau, np.inf)
    per_holder = ratio.min(axis=-1)  # (k, G, T)
    worst_g = np.argmin(per_holder, axis=1)  # (k, T)
    k_idx, t_idx = np.indices(worst_g.shape)
    fos = per_holder[k_idx, worst_g, t_idx]
    limiting = rot[np.argmin(ratio[k_idx, worst_g, t_idx], axis=-1)]
    crit = critical_mass(tau0[None], y, saturation * limits[None, None]).min(axis=(0, 2))
    standing: set[int] = set()
    from critmoment import actuators as act_info

    bases = act_info.robot_bases(model)
    if bases:
        for k in range(0, n_steps, max(1, int(round(0.05 / dt)))):  # every 50 ms
            mujoco.mj_setState(model, data, states[k], STATE_SPEC)
            mujoco.mj_fwdPosition(model, data)
            standing |= standing_actuators(model, data, twin, bases)
    return LoadBound(masses=masses, fos=fos, limiting=limiting.astype(np.int64),
                     carried=carried, critical_mass=crit,
                     actuator_names=tuple(twin.actuator_names), dt=dt,
                     saturation=float(saturation), min_duration=float(min_duration),
                     unbounded=tuple(twin.actuator_names[a] for a in rot if a in standing))
