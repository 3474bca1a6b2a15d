"""Scripted pick-and-place demonstrations for the bundled Franka Panda scenario.

One Panda picks a 4 cm cube from a seeded spot on the table and places it on the goal
spot 30 cm away. The waypoints are tool-centre-point (TCP) positions with the hand pointing
down and the fingers closing along world y; damped-least-squares inverse kinematics on
MuJoCo's site Jacobians (with a null-space pull toward libfranka's "ready" pose, since the
arm has one redundant joint) turns them into joint paths. Each segment is a minimum-jerk
move, so the joint velocities and accelerations are smooth.

The position servos of the twin produce ``kp (u - q) - kv q̇``: their damping acts on the
joint's absolute velocity, so a plain position target would lag by ``kv/kp · q̇``
(0.1 s × q̇) and saturate the 12 N·m wrist motors at 0.06 rad/s. Each target therefore
carries a feed-forward ``u = q + (kv q̇ + τ_id(q, q̇, q̈)) / kp``, where ``τ_id`` is MuJoCo's
inverse dynamics of the unloaded arm (gravity, inertia with armature, joint damping); the
servo then acts as a PD controller on the tracking error around that feed-forward torque,
as the real robot's controller does with its internal gravity model.

Timeline (control steps at 50 Hz before time scaling, 10 s):

====  ===================================================================
step  arm and hand
====  ===================================================================
0     "ready" pose, hand open
75    above the cube (joint-space move)
125   down to the grasp height
140   settled; the hand closes
165   closed on the cube
180   squeeze settled; lift
230   lifted to the transport height
305   above the goal
355   lowered to the place height
370   settled; the hand opens
395   open (the cube is released on the table)
445   retreated up
500   end (hold)
====  ===================================================================
"""

from __future__ import annotations

import dataclasses
from importlib import resources
from pathlib import Path

import mujoco
import numpy as np

from critmoment.exceptions import ParameterError
from critmoment.trajectory import Trajectory

__all__ = [
    "ARM_JOINTS",
    "CUBE_HALF",
    "CUBE_X",
    "CUBE_Y",
    "FAMILIES",
    "FINGER_OPEN",
    "GOAL",
    "READY_POSE",
    "PickPlaceOptions",
    "ik_tcp",
    "make",
    "make_pick_place",
    "pick_place_plan",
    "sample_cube_pose",
    "scene_path",
]

#: libfranka's "ready" pose [rad]: hand down, fingers closing along world y (panda_facts §1)
READY_POSE = np.array([0.0, -np.pi / 4, 0.0, -3 * np.pi / 4, 0.0, np.pi / 2, np.pi / 4])
#: the arm's joint and actuator names, in action order
ARM_JOINTS = tuple(f"joint{i}" for i in range(1, 8))
FINGER_ACTUATORS = ("finger_left", "finger_right")
#: cube spawn range: x ~ U[0.45, 0.55], y ~ U[-0.20, -0.10] [m], resting on the table (z = 0)
CUBE_X = (0.45, 0.55)
CUBE_Y = (-0.20, -0.10)
#: half the cube's edge [m]
CUBE_HALF = 0.02
#: where the cube centre must end up [m]
GOAL = (0.5, 0.15, CUBE_HALF)
#: finger travel [m]: normalised gripper 1 = 0.04 m per finger (8 cm open), 0 = closed
FINGER_OPEN = 0.04

_SEGMENTS = (75, 125, 140, 165, 180, 230, 305, 355, 370, 395, 445, 500)


@dataclasses.dataclass(frozen=True)
class PickPlaceOptions:
    """Shape of the scripted pick-and-place.

    Attributes:
        goal: where the cube centre is placed, world [m], (3,).
        grasp_offset: TCP height above the cube centre at the grasp [m]; the rubber tips
            (18.5 mm tall) are centred on the TCP, so 0.01 grips the cube's upper half.
        transport_height: TCP height above the table while moving [m].
        place_clearance: how far above resting height the cube is released [m].
        time_scale: multiplies every waypoint time (< 1 is faster).
        fps: action rate [Hz].
    """

    goal: tuple[float, float, float] = GOAL
    grasp_offset: float = 0.01
    transport_height: float = 0.15
    place_clearance: float = 0.002
    time_scale: float = 1.0
    fps: float = 50.0

    def __post_init__(self):
        if len(self.goal) != 3 or not np.all(np.isfinite(self.goal)):
            raise ParameterError(f"goal: expected 3 finite coordinates [m], got {self.goal!r}")
        if not 0.0 <= self.grasp_offset <= 0.015:
            raise ParameterError(
                f"grasp_offset: expected 0..0.015 m (the tips must reach the cube), "
                f"got {self.grasp_offset}")
        if not 0.08 <= self.transport_height <= 0.4:
            raise ParameterError(
                f"transport_height: expected 0.08..0.4 m, got {self.transport_height}")
        if not 0.0 <= self.place_clearance <= 0.02:
            raise ParameterError(
                f"place_clearance: expected 0..0.02 m, got {self.place_clearance}")
        if not 0.3 <= self.time_scale <= 5.0:
            raise ParameterError(f"time_scale: expected 0.3..5, got {self.time_scale}")
        if not 10.0 <= self.fps <= 1000.0:
            raise ParameterError(f"fps: expected 10..1000 Hz, got {self.fps}")


def scene_path() -> Path:
    """The bundled Panda scene, installed (``critmoment.models``) or in a checkout."""
    try:
        path = Path(str(resources.files("critmoment.models"))) / "panda_pick_place"
        if (path / "scene.xml").is_file():
            return path / "scene.xml"
    except (ModuleNotFoundError, TypeError):
        pass
    return Path(__file__).resolve().parent.parent / "models" / "panda_pick_place" / "scene.xml"


def sample_cube_pose(seed: int | np.random.Generator) -> np.ndarray:
    """The cube's spawn, sampled with ``seed``: (7,) xyz [m] + quat (w, x, y, z) at rest."""
    rng = seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)
    x = rng.uniform(*CUBE_X)
    y = rng.uniform(*CUBE_Y)
    return np.array([x, y, CUBE_HALF, 1.0, 0.0, 0.0, 0.0])


def ik_tcp(model: mujoco.MjModel, data: mujoco.MjData, site: int, qadr: np.ndarray,
           dofs: np.ndarray, pos: np.ndarray, rot: np.ndarray, *, rest: np.ndarray,
           iters: int = 200, damping: float = 1e-4, nullspace_gain: float = 0.1,
           tol: float = 1e-8, posture_tol: float = 1e-6) -> float:
    """Damped-least-squares IK of a 7-DoF arm's site to a pose; updates ``data.qpos``.

    The step is ``Jᵀ (J Jᵀ + λ² I)⁻¹ e`` plus a null-space pull ``(I − J⁺J) k (rest − q)``
    that resolves the redundant joint toward ``rest``.

    Args:
        model: the model.
        data: data whose qpos is the start guess; the arm's joints are changed.
        site: the TCP site id.
        qadr: the arm's qpos addresses, (7,).
        dofs: the arm's dof indices, (7,).
        pos: target position, world [m], (3,).
        rot: target orientation, world rotation matrix, (3, 3).
        rest: the posture the null space is pulled toward [rad], (7,).
        iters: maximum iterations.
        damping: λ² [m², rad²].
        nullspace_gain: k, fraction of the posture error removed per iteration.
        tol: stop when the pose error is below this [m or rad] ...
        posture_tol: ... and the null-space step below this [rad].

    Returns:
        The final pose error norm [m or rad].
    """
    n = len(dofs)
    jacp = np.zeros((3, model.nv))
    jacr = np.zeros((3, model.nv))
    lo = model.jnt_range[model.dof_jntid[dofs], 0]
    hi = model.jnt_range[model.dof_jntid[dofs], 1]
    target = np.empty(4)
    mujoco.mju_mat2Quat(target, np.ascontiguousarray(rot).ravel())
    cur, local, err = np.empty(4), np.empty(3), np.empty(6)
    err_norm = np.inf
    for _ in range(iters):
        mujoco.mj_kinematics(model, data)
        mujoco.mj_comPos(model, data)
        xmat = data.site_xmat[site]
        mujoco.mju_mat2Quat(cur, xmat)
        mujoco.mju_subQuat(local, target, cur)
        err[:3] = pos - data.site_xpos[site]
        err[3:] = xmat.reshape(3, 3) @ local
        err_norm = float(np.linalg.norm(err))
        mujoco.mj_jacSite(model, data, jacp, jacr, site)
        jac = np.vstack([jacp[:, dofs], jacr[:, dofs]])
        jjt = jac @ jac.T
        pinv = jac.T @ np.linalg.inv(jjt + damping * np.eye(6))
        # the (nearly) exact projector, so that the posture pull does not disturb the pose
        null = np.eye(n) - jac.T @ np.linalg.solve(jjt + 1e-12 * np.eye(6), jac)
        posture = null @ (nullspace_gain * (rest - data.qpos[qadr]))
        if err_norm < tol and np.linalg.norm(posture) < posture_tol:
            break
        data.qpos[qadr] = np.clip(data.qpos[qadr] + pinv @ err + posture, lo, hi)
    return err_norm


def _min_jerk(s: np.ndarray) -> np.ndarray:
    return s ** 3 * (10.0 - 15.0 * s + 6.0 * s ** 2)


def _waypoints(cube: np.ndarray, opt: PickPlaceOptions) -> list[tuple[int, np.ndarray, float]]:
    """(step, TCP position [m], normalised gripper) per waypoint, after the start."""
    goal = np.asarray(opt.goal, float)
    grasp = cube[:3] + [0.0, 0.0, opt.grasp_offset]
    above = np.array([cube[0], cube[1], opt.transport_height])
    place = goal + [0.0, 0.0, opt.grasp_offset + opt.place_clearance]
    over_goal = np.array([goal[0], goal[1], opt.transport_height])
    targets = (
        (above, 1.0), (grasp, 1.0), (grasp, 1.0), (grasp, 0.0), (grasp, 0.0), (above, 0.0),
        (over_goal, 0.0), (place, 0.0), (place, 0.0), (place, 1.0), (over_goal, 1.0),
        (over_goal, 1.0),
    )
    return [(step, pos, grip) for step, (pos, grip) in zip(_SEGMENTS, targets, strict=True)]


def pick_place_plan(model: mujoco.MjModel, cube: np.ndarray,
                    options: PickPlaceOptions | None = None
                    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The planned motion: joint path, TCP path and gripper command at each action step.

    Args:
        model: the Panda scene (names ``joint1``..``joint7`` and site ``tcp``).
        cube: the cube's pose, (7,) xyz [m] + quat.
        options: the demonstration's shape.

    Returns:
        ``q`` (T, 7) joint path [rad], ``tcp`` (T, 3) planned TCP positions [m] and
        ``grip`` (T,) normalised gripper command (1 open, 0 closed).

    Raises:
        ParameterError: a waypoint is out of the arm's reach.
    """
    opt = options or PickPlaceOptions()
    joints = [model.joint(j).id for j in ARM_JOINTS]
    qadr, dofs = model.jnt_qposadr[joints], model.jnt_dofadr[joints]
    site = model.site("tcp").id
    data = mujoco.MjData(model)
    data.qpos[qadr] = READY_POSE
    mujoco.mj_kinematics(model, data)
    start_pos = data.site_xpos[site].copy()
    rot = data.site_xmat[site].reshape(3, 3).copy()  # hand down, fingers along world y
    points = [(0, start_pos, 1.0), *_waypoints(np.asarray(cube, float), opt)]
    steps = [int(round(p[0] * opt.time_scale)) for p in points]
    n = steps[-1]
    tcp = np.empty((n, 3))
    grip = np.empty(n)
    seg = np.empty(n, int)
    for k in range(len(points) - 1):
        t0, t1 = steps[k], steps[k + 1]
        s = _min_jerk((np.arange(t0, t1) - t0) / (t1 - t0))
        tcp[t0:t1] = points[k][1] + s[:, None] * (points[k + 1][1] - points[k][1])
        grip[t0:t1] = points[k][2] + s * (points[k + 1][2] - points[k][2])
        seg[t0:t1] = k
    q = np.empty((n, 7))
    # the first move (ready -> above the cube) is in joint space
    data.qpos[qadr] = READY_POSE
    err = ik_tcp(model, data, site, qadr, dofs, points[1][1], rot, rest=READY_POSE, iters=2000)
    if err > 1e-5:
        raise ParameterError(
            f"IK found no pose above the cube at {np.round(points[1][1], 3).tolist()} "
            f"(pose error {err:.3g}): expected a cube within x {CUBE_X}, y {CUBE_Y} [m]")
    q_above = data.qpos[qadr].copy()
    first = seg == 0
    s = _min_jerk(np.arange(steps[1]) / steps[1])
    q[first] = READY_POSE + s[:, None] * (q_above - READY_POSE)
    for i in np.flatnonzero(~first):
        err = ik_tcp(model, data, site, qadr, dofs, tcp[i], rot, rest=READY_POSE)
        if err > 1e-5:
            raise ParameterError(
                f"IK found no pose for the TCP at {np.round(tcp[i], 3).tolist()} at step {i} "
                f"(pose error {err:.3g}): is the goal {opt.goal} within reach?")
        q[i] = data.qpos[qadr]
    return q, tcp, grip


def _feed_forward(model: mujoco.MjModel, q: np.ndarray, grip: np.ndarray, dt: float
                  ) -> np.ndarray:
    """Servo targets u (T, 7) that make ``kp (u − q) − kv q̇`` equal the inverse dynamics."""
    joints = [model.joint(j).id for j in ARM_JOINTS]
    qadr, dofs = model.jnt_qposadr[joints], model.jnt_dofadr[joints]
    acts = [model.actuator(j).id for j in ARM_JOINTS]
    kp = model.actuator_gainprm[acts, 0]
    kv = -model.actuator_biasprm[acts, 2]
    qd = np.gradient(q, dt, axis=0)
    qdd = np.gradient(qd, dt, axis=0)
    free = model.__copy__()
    free.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONTACT)  # the arm alone
    data = mujoco.MjData(free)
    fingers = [model.joint(f"finger_joint{i}").id for i in (1, 2)]
    tau = np.empty_like(q)
    for i in range(len(q)):
        data.qpos[qadr] = q[i]
        data.qpos[free.jnt_qposadr[fingers]] = FINGER_OPEN * grip[i]
        data.qvel[:] = 0.0
        data.qacc[:] = 0.0
        data.qvel[dofs] = qd[i]
        data.qacc[dofs] = qdd[i]
        mujoco.mj_inverse(free, data)
        tau[i] = data.qfrc_inverse[dofs]
    return q + (kv * qd + tau) / kp


def make_pick_place(seed: int = 0, *, options: PickPlaceOptions | None = None,
                    model: mujoco.MjModel | None = None) -> Trajectory:
    """A scripted pick-and-place trajectory for the bundled Panda scenario.

    The action vector has 8 channels: the 7 arm joint targets [rad] and the gripper,
    normalised 0 (closed) .. 1 (open, 0.04 m per finger).

    Args:
        seed: seeds the cube's spawn position (x ∈ [0.45, 0.55], y ∈ [−0.2, −0.1] m).
        options: the demonstration's shape (default :class:`PickPlaceOptions`).
        model: the compiled scene to plan on (default: the bundled ``scene.xml``).

    Returns:
        A trajectory at ``options.fps`` with ``start``, ``qpos0`` and ``object_pose`` set.

    Raises:
        ParameterError: bad options or a waypoint out of reach.
    """
    opt = options or PickPlaceOptions()
    model = model or mujoco.MjModel.from_xml_path(str(scene_path()))
    cube = sample_cube_pose(seed)
    q, _, grip = pick_place_plan(model, cube, opt)
    # the waypoint steps are at 50 Hz; a different fps resamples the same motion in time
    if opt.fps != 50.0:
        t_src = np.arange(len(q)) / 50.0
        t_dst = np.arange(int(round(len(q) * opt.fps / 50.0))) / opt.fps
        q = np.stack([np.interp(t_dst, t_src, q[:, j]) for j in range(7)], axis=1)
        grip = np.interp(t_dst, t_src, grip)
    targets = _feed_forward(model, q, grip, 1.0 / opt.fps)
    joints = [model.joint(j).id for j in ARM_JOINTS]
    rng = model.jnt_range[joints]
    if np.any(targets < rng[:, 0]) or np.any(targets > rng[:, 1]):
        bad = np.argwhere((targets < rng[:, 0]) | (targets > rng[:, 1]))[0]
        raise ParameterError(
            f"servo target of {ARM_JOINTS[bad[1]]} at step {bad[0]} is "
            f"{targets[bad[0], bad[1]]:.4f} rad, outside its range {rng[bad[1]].tolist()}")
    actions = np.concatenate([targets, grip[:, None]], axis=1)
    start = np.concatenate([READY_POSE, [1.0]])
    qpos0 = model.key("home").qpos.copy()
    qpos0[model.jnt_qposadr[joints]] = READY_POSE
    for i in (1, 2):
        qpos0[model.jnt_qposadr[model.joint(f"finger_joint{i}").id]] = FINGER_OPEN
    cube_adr = model.jnt_qposadr[model.joint("cube_joint").id]
    qpos0[cube_adr:cube_adr + 7] = cube
    meta = {"generator": "critmoment.panda_demo.make_pick_place", "seed": int(seed),
            "options": dataclasses.asdict(opt), "scenario": "panda_pick_place"}
    return Trajectory(actions=actions, fps=opt.fps, start=start, qpos0=qpos0,
                      object_pose=cube, meta=meta, source=f"panda_pick_place(seed={seed})")


def _no_grasp(seed: int, model: mujoco.MjModel | None = None) -> Trajectory:
    """The nominal motion, with the cube 10 cm further along x than planned: never touched."""
    model = model or mujoco.MjModel.from_xml_path(str(scene_path()))
    traj = make_pick_place(seed, model=model)
    pose = traj.object_pose.copy()
    pose[0] += 0.10
    qpos0 = traj.qpos0.copy()
    adr = model.jnt_qposadr[model.joint("cube_joint").id]
    qpos0[adr:adr + 7] = pose
    return dataclasses.replace(traj, object_pose=pose, qpos0=qpos0,
                               meta={**traj.meta, "family": "no_grasp"})


def _with(options: PickPlaceOptions):
    def build(seed: int, model: mujoco.MjModel | None = None) -> Trajectory:
        return make_pick_place(seed, options=options, model=model)

    return build


#: family name -> function(seed, model=None) -> Trajectory, like :data:`critmoment.suite.FAMILIES`
FAMILIES = {
    "nominal": _with(PickPlaceOptions()),
    "fast": _with(PickPlaceOptions(time_scale=0.6)),
    "faster": _with(PickPlaceOptions(time_scale=0.4)),
    "slow": _with(PickPlaceOptions(time_scale=1.5)),
    "shallow_grasp": _with(PickPlaceOptions(grasp_offset=0.015)),
    "no_grasp": _no_grasp,
}


def make(family: str, *, seed: int = 0, model: mujoco.MjModel | None = None) -> Trajectory:
    """A Panda trajectory of ``family`` (see :data:`FAMILIES`) with ``seed``.

    ``fast`` and ``faster`` scale every waypoint time by 0.6 and 0.4 (peak lift acceleration
    1.9 and 4.3 m/s², so heavier cubes slip earlier); ``slow`` by 1.5; ``shallow_grasp`` holds
    the cube 1.5 cm below the TCP instead of 1 cm (less tip on the cube); ``no_grasp`` moves the
    cube 10 cm away from where the arm goes.

    Raises:
        ParameterError: unknown family.
    """
    if family not in FAMILIES:
        raise ParameterError(f"unknown Panda trajectory family {family!r}; known: "
                             f"{', '.join(FAMILIES)}")
    traj = FAMILIES[family](int(seed), model=model)
    meta = {**traj.meta, "family": family}
    return dataclasses.replace(traj, meta=meta, source=f"panda {family}(seed={seed})")
