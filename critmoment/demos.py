"""Scripted pick-and-transfer demonstrations for the bundled ALOHA scenario.

Like ACT's scripted ``PickAndTransferPolicy``: the right arm picks the cube and
hands it to the left arm. ACT drives mocap bodies through weld constraints and
records the joint angles, which on MuJoCo ≥ 3 loses about 30° of gripper pitch
(facts §0.3). Here the waypoints are tool-centre-point (TCP) poses, turned into
joint targets by damped-least-squares inverse kinematics on MuJoCo's site
Jacobians, with a static gravity offset so the position servos settle on the
planned pose. The result is a plain joint-space :class:`Trajectory` at 50 Hz.

Timeline (control steps at 50 Hz, 8 s):

====  ==========================================================================
step  right arm (picker)                       left arm (receiver)
====  ==========================================================================
0     start pose, gripper closed               start pose, gripper closed
90    above the cube, opened, pitched 60° down
100                                            waiting pose, rolled 90°, opened
130   down to the grasp height
170   closed on the cube
195   lifted straight up
220   at the meeting point
260                                            at the cube
300                                            closed on the cube
340   opened (the hand-over)
370   retreated                                back with the cube, unrolled
400   hold                                     hold
====  ==========================================================================
"""

from __future__ import annotations

import dataclasses

import mujoco
import numpy as np
from scipy.spatial.transform import Rotation, Slerp

from critmoment import budget
from critmoment.exceptions import ParameterError
from critmoment.scenario import Scenario, load_scenario
from critmoment.trajectory import Trajectory
from critmoment.twin import Twin

__all__ = ["DemoOptions", "sample_box_pose", "scripted_transfer", "ik_arm"]

#: ACT's box spawn range: x ~ U[0, 0.2], y ~ U[0.4, 0.6] [m]; the cube rests at z = 0.02
BOX_X = (0.0, 0.2)
BOX_Y = (0.4, 0.6)
BOX_REST_Z = 0.02
#: ACT's start pose of each arm [rad]
START_POSE = np.array([0.0, -0.96, 1.16, 0.0, -0.3, 0.0])
#: IK seed for the approach pose: forearm unrolled, wrist pitched down
_APPROACH_SEED = np.array([0.0, -0.5, 1.0, 0.0, 0.6, 0.0])
_ARM_JOINTS = ("waist", "shoulder", "elbow", "forearm_roll", "wrist_angle", "wrist_rotate")


@dataclasses.dataclass(frozen=True)
class DemoOptions:
    """Shape of the scripted demonstration.

    Attributes:
        meet: where the picker holds the cube for the hand-over, world [m], (3,).
        grasp_height: TCP height above the cube centre at the grasp [m]; the pads reach
            down from the TCP, so lower means a deeper grasp.
        lift_height: TCP height above the cube for the approach [m].
        time_scale: multiplies every waypoint time (< 1 is faster).
        release_opening: normalised opening the picker reaches when it lets go.
        receiver_offset: how far behind the cube centre the receiver's TCP stops, along
            −x [m].
        carry_opening: normalised picker gripper command while it carries the cube to the
            meeting point (0 = fully closed; a partial opening weakens the grip).
        jitter: standard deviation of white noise added to the arm joint targets [rad], like
            an imperfect learned policy (seeded with the demo's seed).
        n_steps: number of 50 Hz actions (before time scaling).
        fps: action rate [Hz].
    """

    meet: tuple[float, float, float] = (0.0, 0.5, 0.25)
    grasp_height: float = 0.017
    lift_height: float = 0.08
    time_scale: float = 1.0
    release_opening: float = 1.0
    receiver_offset: float = 0.01
    carry_opening: float = 0.0
    jitter: float = 0.0
    n_steps: int = 400
    fps: float = 50.0

    def __post_init__(self):
        if not 0.2 <= self.time_scale <= 5.0:
            raise ParameterError(f"time_scale: expected 0.2..5, got {self.time_scale}")
        if not 0.0 <= self.carry_opening <= 1.0:
            raise ParameterError(f"carry_opening: expected 0..1, got {self.carry_opening}")
        if not 0.0 <= self.jitter <= 0.1:
            raise ParameterError(f"jitter: expected 0..0.1 rad, got {self.jitter}")
        if not 0.0 <= self.release_opening <= 1.0:
            raise ParameterError(f"release_opening: expected 0..1, got {self.release_opening}")
        if self.n_steps < 100:
            raise ParameterError(f"n_steps: expected >= 100, got {self.n_steps}")


def sample_box_pose(seed: int | np.random.Generator) -> np.ndarray:
    """ACT's cube spawn, sampled with ``seed``: (7,) xyz [m] + quat (w, x, y, z) at rest."""
    rng = (seed if isinstance(seed, np.random.Generator)
           else np.random.default_rng(budget.check_seed(seed)))
    x = rng.uniform(*BOX_X)
    y = rng.uniform(*BOX_Y)
    return np.array([x, y, BOX_REST_Z, 1.0, 0.0, 0.0, 0.0])


def _frame(x_axis, y_axis) -> Rotation:
    x = np.asarray(x_axis, float)
    x = x / np.linalg.norm(x)
    y = np.asarray(y_axis, float)
    y = y - x * (x @ y)
    y = y / np.linalg.norm(y)
    return Rotation.from_matrix(np.stack([x, y, np.cross(x, y)], axis=1))


# TCP orientations in the world: the right gripper points toward −x, pitched 60° down, fingers
# closing along world y; the left one points toward +x rolled 90° so its fingers close along z.
_PITCH = np.deg2rad(60.0)
RIGHT_PICK = _frame([-np.cos(_PITCH), 0, -np.sin(_PITCH)], [0, -1, 0])
LEFT_MEET = _frame([1, 0, 0], [0, 0, 1])
LEFT_REST = _frame([1, 0, 0], [0, 1, 0])


def ik_arm(model: mujoco.MjModel, data: mujoco.MjData, site: int, dofs: np.ndarray,
           qadr: np.ndarray, pos: np.ndarray, rot: Rotation, *, iters: int = 100,
           damping: float = 1e-6, tol: float = 1e-7) -> float:
    """Damped-least-squares IK of one arm's site to a pose; updates ``data.qpos`` in place.

    Args:
        model: the model.
        data: data whose qpos is the start guess; the arm's joints are changed.
        site: the TCP site id.
        dofs: the arm's dof indices, (6,).
        qadr: the arm's qpos addresses, (6,).
        pos: target position, world [m], (3,).
        rot: target orientation.
        iters: maximum Gauss-Newton iterations.
        damping: Levenberg damping λ² [m², rad²].
        tol: stop when the pose error is below this [m or rad].

    Returns:
        The final pose error norm.
    """
    jacp = np.zeros((3, model.nv))
    jacr = np.zeros((3, model.nv))
    lo = model.jnt_range[model.dof_jntid[dofs], 0]
    hi = model.jnt_range[model.dof_jntid[dofs], 1]
    x, y, z, w = rot.as_quat()
    target = np.array([w, x, y, z])
    cur, local = np.empty(4), np.empty(3)
    err = np.empty(6)
    err_norm = np.inf
    for _ in range(iters):
        mujoco.mj_kinematics(model, data)
        mujoco.mj_comPos(model, data)
        xmat = data.site_xmat[site]
        mujoco.mju_mat2Quat(cur, xmat)
        mujoco.mju_subQuat(local, target, cur)  # rotation from current to target, local frame
        err[:3] = pos - data.site_xpos[site]
        err[3:] = xmat.reshape(3, 3) @ local
        err_norm = float(np.linalg.norm(err))
        if err_norm < tol:
            break
        mujoco.mj_jacSite(model, data, jacp, jacr, site)
        jac = np.vstack([jacp[:, dofs], jacr[:, dofs]])
        dq = np.linalg.solve(jac.T @ jac + damping * np.eye(6), jac.T @ err)
        data.qpos[qadr] = np.clip(data.qpos[qadr] + dq, lo, hi)
    return err_norm


def _waypoints(box: np.ndarray, opt: DemoOptions, start_right, start_left):
    """(steps, positions, rotations, gripper) per arm."""
    cube = box[:3]
    meet = np.asarray(opt.meet, float)
    above = cube + [0, 0, opt.lift_height]
    grasp = cube + [0, 0, opt.grasp_height]
    lifted = grasp + [0, 0, opt.lift_height]
    retreat = meet + [0.1, 0, 0]
    right = [
        (0, start_right[0], start_right[1], 0.0),
        (90, above, RIGHT_PICK, 1.0),
        (130, grasp, RIGHT_PICK, 1.0),
        (170, grasp, RIGHT_PICK, 0.0),
        (195, lifted, RIGHT_PICK, 0.0),
        (220, meet, RIGHT_PICK, opt.carry_opening),
        (260, meet, RIGHT_PICK, opt.carry_opening),
        (300, meet, RIGHT_PICK, 0.0),
        (340, meet, RIGHT_PICK, opt.release_opening),
        (370, retreat, RIGHT_PICK, opt.release_opening),
        (400, retreat, RIGHT_PICK, opt.release_opening),
    ]
    # the picker holds the cube grasp_height below its TCP: the receiver goes to the cube
    held = meet - [0, 0, opt.grasp_height]
    wait = held + [-0.12, 0, 0]
    take = held + [-opt.receiver_offset, 0, 0]
    back = held + [-0.12, 0, -0.02]
    left = [
        (0, start_left[0], start_left[1], 0.0),
        (100, wait, LEFT_MEET, 1.0),
        (220, wait, LEFT_MEET, 1.0),
        (260, take, LEFT_MEET, 1.0),
        (300, take, LEFT_MEET, 0.0),
        (340, take, LEFT_MEET, 0.0),
        (370, back, LEFT_REST, 0.0),
        (400, back, LEFT_REST, 0.0),
    ]
    return right, left


def _interpolate(points, n: int, scale: float):
    """Pose and gripper at each control step 0..n-1 (linear position/gripper, slerp rotation)."""
    times = np.array([p[0] for p in points], float) * scale
    t = np.minimum(np.arange(n, dtype=float), times[-1])
    pos = np.stack([np.interp(t, times, [p[1][k] for p in points]) for k in range(3)], axis=1)
    grip = np.interp(t, times, [p[3] for p in points])
    rots = Rotation.concatenate([p[2] for p in points])
    # slerp needs strictly increasing times: interpolate segment by segment
    rot = Slerp(times, rots)(t)
    return pos, rot, grip


def scripted_transfer(seed: int = 0, scenario: Scenario | None = None, *,
                      options: DemoOptions | None = None, twin: Twin | None = None
                      ) -> Trajectory:
    """A scripted pick-and-transfer trajectory for the bundled ALOHA scenario.

    Args:
        seed: seeds the cube's spawn pose (ACT's range).
        scenario: the scenario (default: bundled ``aloha_transfer_cube``).
        options: the demonstration's shape (default :class:`DemoOptions`).
        twin: a twin to reuse.

    Returns:
        A 50 Hz, 14-channel trajectory with ``start`` and ``object_pose`` set.
    """
    opt = options or DemoOptions()
    twin = twin or Twin(scenario or load_scenario())
    model = twin.model
    box = sample_box_pose(seed)
    n = int(round(opt.n_steps * opt.time_scale))
    start = np.concatenate([START_POSE, [0.0], START_POSE, [0.0]])
    data = twin.initial_data(start=start, object_pose=box)
    arms = {}
    for arm in ("left", "right"):
        joints = [model.joint(f"{arm}/{j}").id for j in _ARM_JOINTS]
        site = model.site(f"{arm}/tcp").id
        arms[arm] = dict(
            dofs=model.jnt_dofadr[joints], qadr=model.jnt_qposadr[joints], site=site,
            kp=np.array([model.actuator_gainprm[model.actuator(f"{arm}/{j}").id, 0]
                         for j in _ARM_JOINTS]),
            start=(data.site_xpos[site].copy(),
                   Rotation.from_matrix(data.site_xmat[site].reshape(3, 3))))
    right_pts, left_pts = _waypoints(box, opt, arms["right"]["start"], arms["left"]["start"])
    actions = np.zeros((n, 14))
    for arm, points, col in (("left", left_pts, 0), ("right", right_pts, 7)):
        a = arms[arm]
        q = _joint_path(model, data, a, points, n, opt.time_scale)
        actions[:, col:col + 6] = q + _gravity_offset(model, data, a, q)
        actions[:, col + 6] = _interpolate(points, n, opt.time_scale)[2]
    if opt.jitter > 0:
        noise = np.random.default_rng(seed).normal(0.0, opt.jitter, size=(n, 12))
        actions[:, [0, 1, 2, 3, 4, 5, 7, 8, 9, 10, 11, 12]] += noise
        for arm, col in (("left", 0), ("right", 7)):
            rng = model.jnt_range[[model.joint(f"{arm}/{j}").id for j in _ARM_JOINTS]]
            actions[:, col:col + 6] = np.clip(actions[:, col:col + 6], rng[:, 0], rng[:, 1])
    actions[0] = start
    meta = {"generator": "critmoment.demos.scripted_transfer", "seed": int(seed),
            "options": dataclasses.asdict(opt)}
    return Trajectory(actions=actions, fps=opt.fps, start=start, object_pose=box, meta=meta,
                      source=f"scripted_transfer(seed={seed})")


def _joint_path(model, data, arm, points, n: int, scale: float) -> np.ndarray:
    """Joint targets (n, 6): a joint-space move to the first waypoint, then Cartesian moves.

    The first move (from the start pose, wrist pitched up, to the approach pose, wrist pitched
    down) would cross the wrist singularity if it were Cartesian; in joint space it does not.
    """
    pos, rot, _ = _interpolate(points, n, scale)
    t1 = min(int(round(points[1][0] * scale)), n - 1)
    data.qpos[arm["qadr"]] = _APPROACH_SEED
    err = ik_arm(model, data, arm["site"], arm["dofs"], arm["qadr"], pos[t1], rot[t1], iters=500)
    if err > 1e-4:
        raise ParameterError(
            f"IK found no pose for the approach waypoint {np.round(pos[t1], 3).tolist()} "
            f"(pose error {err:.3g}): is the object within the arm's reach?")
    q1 = data.qpos[arm["qadr"]].copy()
    q = np.empty((n, 6))
    s = np.arange(t1 + 1) / max(t1, 1)
    q[:t1 + 1] = START_POSE + (q1 - START_POSE) * s[:, None]
    for i in range(t1 + 1, n):
        ik_arm(model, data, arm["site"], arm["dofs"], arm["qadr"], pos[i], rot[i])
        q[i] = data.qpos[arm["qadr"]]
    return q


def _gravity_offset(model, data, arm, q: np.ndarray) -> np.ndarray:
    """Static target offset g(q)/kp so that a position servo settles on q (no payload)."""
    saved = data.qpos.copy()
    qvel = data.qvel.copy()
    data.qvel[:] = 0
    out = np.empty_like(q)
    for i in range(len(q)):
        data.qpos[arm["qadr"]] = q[i]
        mujoco.mj_kinematics(model, data)
        mujoco.mj_comPos(model, data)
        mujoco.mj_comVel(model, data)
        mujoco.mj_rne(model, data, 0, data.qfrc_bias)
        out[i] = data.qfrc_bias[arm["dofs"]] / arm["kp"]
    data.qpos[:] = saved
    data.qvel[:] = qvel
    return out
