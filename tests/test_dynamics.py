"""Tests of critmoment.dynamics against MuJoCo and against closed-form physics."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin
import pytest
from inline_models import SWING_MJCF

from critmoment import dynamics as dyn
from critmoment.exceptions import ParameterError, ScenarioError, TrajectoryError

TOL = 1e-9
SCENE = Path(__file__).resolve().parents[1] / "models" / "aloha_transfer_cube" / "scene.xml"


# --------------------------------------------------------------------------
# inline test models
# --------------------------------------------------------------------------


def _arm_xml(prefix: str = "", pos: str = "0.1 -0.2 0.3", quat: str = "0.9 0.1 0.3 -0.2", payload: str = "") -> str:
    """A 6-hinge arm with offset bodies/anchors/axes, a jointless link and two slide fingers."""
    p = prefix
    return f"""
    <body name="{p}base" pos="{pos}" quat="{quat}">
      <inertial pos="0.01 0.02 0.03" mass="2" diaginertia="0.01 0.02 0.03"/>
      <body name="{p}l1" pos="0 0 0.1" euler="0.1 0.2 0.3">
        <joint name="{p}j1" axis="0 0 1" pos="0.01 0 0" armature="0.05" damping="0.7" stiffness="3"/>
        <inertial pos="0.02 0.01 0.05" quat="0.8 0.2 -0.3 0.1" mass="1.2" diaginertia="0.011 0.013 0.007"/>
        <body name="{p}l2" pos="0.03 0.01 0.12" euler="0.5 -0.2 0.1">
          <joint name="{p}j2" axis="0 1 0" ref="0.3" armature="0.04" frictionloss="0.5"/>
          <inertial pos="0.1 0 0.01" quat="0.7 -0.1 0.4 0.2" mass="0.9" diaginertia="0.02 0.018 0.004"/>
          <body name="{p}l3" pos="0.25 0.02 -0.01" quat="0.95 0.05 -0.1 0.2">
            <joint name="{p}j3" axis="1 1 0" pos="-0.02 0.01 0.03" armature="0.03"/>
            <inertial pos="0.08 0.01 0" quat="0.6 0.3 0.2 -0.4" mass="0.6" diaginertia="0.008 0.007 0.003"/>
            <body name="{p}l3b" pos="0.15 0 0.02" euler="0.3 0 -0.4">
              <inertial pos="0.01 0.03 -0.02" quat="0.5 0.5 -0.5 0.5" mass="0.3" diaginertia="0.002 0.0015 0.001"/>
              <body name="{p}l4" pos="0.05 0.01 0" euler="-0.2 0.4 0.1">
                <joint name="{p}j4" axis="0.2 -0.5 1" pos="0.01 0.02 -0.01" armature="0.02"/>
                <inertial pos="0.03 0 0.01" quat="0.9 -0.2 0.1 0.3" mass="0.4" diaginertia="0.003 0.0025 0.002"/>
                <body name="{p}l5" pos="0.07 0 0" euler="0.2 0.1 0.6">
                  <joint name="{p}j5" axis="1 0 0" armature="0.01"/>
                  <inertial pos="0.02 0.01 0" quat="0.3 0.1 0.9 -0.2" mass="0.25" diaginertia="0.001 0.0012 0.0008"/>
                  <body name="{p}hand" pos="0.06 0.01 0.02" quat="0.8 -0.3 0.2 0.4">
                    <joint name="{p}j6" axis="0 -1 0.2" pos="0.01 -0.01 0" armature="0.01"/>
                    <inertial pos="0.04 0 0.005" quat="0.6 0.6 -0.3 0.2" mass="0.35" diaginertia="0.0011 0.0013 0.0009"/>
                    <site name="{p}tcp" pos="0.12 0.01 0" quat="0.7 0.1 0.7 0.1"/>
                    <body name="{p}finger_l" pos="0.07 0.01 0" euler="0.1 0 0.2">
                      <joint name="{p}fl" type="slide" axis="0 1 0" armature="0.01" damping="2"/>
                      <inertial pos="0.03 -0.01 0" quat="0.9 0 0.3 0.1" mass="0.04" diaginertia="2e-5 3e-5 1.5e-5"/>
                    </body>
                    <body name="{p}finger_r" pos="0.07 -0.01 0" euler="-0.1 0.2 0">
                      <joint name="{p}fr" type="slide" axis="0.1 -1 0.2" ref="0.01" pos="0.02 0 0" armature="0.01"/>
                      <inertial pos="0.03 0.01 0" quat="0.8 0.1 -0.3 0.1" mass="0.04" diaginertia="2e-5 3e-5 1.5e-5"/>
                    </body>
                    {payload}
                  </body>
                </body>
              </body>
            </body>
          </body>
        </body>
      </body>
    </body>"""


_BOX = """
    <body name="box" pos="0.3 0.4 0.5" quat="0.9 -0.2 0.3 0.1">
      <freejoint name="box_joint"/>
      <inertial pos="0.01 -0.02 0.015" quat="0.7 0.3 -0.5 0.2" mass="0.35" diaginertia="0.002 0.0016 0.001"/>
    </body>"""


def _mjcf(body: str, gravity: str = "0.3 -0.2 -9.81") -> str:
    return f"""
    <mujoco>
      <compiler angle="radian"/>
      <option gravity="{gravity}"/>
      <worldbody>{body}
      </worldbody>
    </mujoco>"""


ARM = _mjcf(_arm_xml())
FREE_BOX = _mjcf(_BOX)
TWO_ARMS_BOX = _mjcf(
    _arm_xml("l/", pos="-0.4 0.5 0", quat="1 0 0 0")
    + _arm_xml("r/", pos="0.4 0.5 0", quat="0 0 0 1")
    + _BOX
)
BALL_MULTI = _mjcf(
    """
    <body name="p" pos="0 0.1 1" quat="0.9 0.2 0 -0.1">
      <joint name="ball" type="ball" pos="0 0.02 0.1" armature="0.02"/>
      <inertial pos="0.01 0 -0.1" quat="0.8 0.1 0.2 0.3" mass="1.1" diaginertia="0.01 0.012 0.004"/>
      <body name="q" pos="0.02 0 -0.3" euler="0.2 -0.1 0.3">
        <joint name="h1" axis="1 0 0" pos="0 0 0.05"/>
        <joint name="h2" axis="0 1 1" pos="0.02 0 0" ref="-0.2"/>
        <joint name="s1" type="slide" axis="0.3 0 1" pos="0 0.1 0"/>
        <inertial pos="0.01 0.02 -0.12" quat="0.6 -0.2 0.3 0.1" mass="0.7" diaginertia="0.006 0.005 0.002"/>
      </body>
    </body>"""
)


def _load(xml: str) -> mujoco.MjModel:
    m = mujoco.MjModel.from_xml_string(xml)
    _rigid_only(m)
    return m


def _rigid_only(m: mujoco.MjModel) -> None:
    """Disable everything mj_inverse adds beyond M qacc + bias."""
    m.opt.disableflags |= int(
        mujoco.mjtDisableBit.mjDSBL_CONSTRAINT
        | mujoco.mjtDisableBit.mjDSBL_SPRING
        | mujoco.mjtDisableBit.mjDSBL_DAMPER
        | mujoco.mjtDisableBit.mjDSBL_FRICTIONLOSS
    )


def _random_state(m: mujoco.MjModel, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    qpos = m.qpos0.copy()
    for j in range(m.njnt):
        a = m.jnt_qposadr[j]
        t = m.jnt_type[j]
        if t == mujoco.mjtJoint.mjJNT_FREE:
            qpos[a : a + 3] = rng.uniform(-1, 1, 3)
            quat = rng.normal(size=4)
            qpos[a + 3 : a + 7] = quat / np.linalg.norm(quat)
        elif t == mujoco.mjtJoint.mjJNT_BALL:
            quat = rng.normal(size=4)
            qpos[a : a + 4] = quat / np.linalg.norm(quat)
        else:
            qpos[a] += rng.uniform(-1.5, 1.5)
    return qpos, rng.normal(size=m.nv) * 1.5, rng.normal(size=m.nv) * 3.0


def _mj_inverse(m: mujoco.MjModel, qpos, qvel, qacc) -> np.ndarray:
    d = mujoco.MjData(m)
    d.qpos[:], d.qvel[:], d.qacc[:] = qpos, qvel, qacc
    mujoco.mj_inverse(m, d)
    assert np.all(d.qfrc_passive == 0.0) and np.all(d.qfrc_constraint == 0.0)
    return d.qfrc_inverse.copy()


def _mj_mass(m: mujoco.MjModel, qpos) -> np.ndarray:
    d = mujoco.MjData(m)
    d.qpos[:] = qpos
    mujoco.mj_forward(m, d)
    full = np.zeros((m.nv, m.nv))
    mujoco.mj_fullM(m, d, full)
    return full


def _scale(x: np.ndarray) -> float:
    return max(1.0, float(np.abs(x).max()))


MODELS = {"arm": ARM, "free_box": FREE_BOX, "two_arms_box": TWO_ARMS_BOX, "ball_multi": BALL_MULTI}


# --------------------------------------------------------------------------
# rnea and mass matrix vs MuJoCo
# --------------------------------------------------------------------------


@pytest.mark.parametrize("name", sorted(MODELS))
def test_rnea_matches_mj_inverse(name):
    m = _load(MODELS[name])
    pm = dyn.from_mujoco(m)
    assert (pm.nq, pm.nv) == (m.nq, m.nv)
    rng = np.random.default_rng(1)
    for _ in range(10):
        qpos, qvel, qacc = _random_state(m, rng)
        ref = _mj_inverse(m, qpos, qvel, qacc)
        got = pm.rnea(qpos, qvel, qacc, include_armature=True)
        np.testing.assert_allclose(got, ref, rtol=0, atol=TOL * _scale(ref))
        rigid = pm.rnea(qpos, qvel, qacc)
        np.testing.assert_allclose(rigid + pm.armature * qacc, ref, rtol=0, atol=TOL * _scale(ref))


@pytest.mark.parametrize("name", sorted(MODELS))
def test_mass_matrix_matches_mj_fullM(name):
    m = _load(MODELS[name])
    pm = dyn.from_mujoco(m)
    rng = np.random.default_rng(2)
    for _ in range(5):
        qpos, _, _ = _random_state(m, rng)
        ref = _mj_mass(m, qpos)
        got = pm.mass_matrix(qpos, include_armature=True)
        np.testing.assert_allclose(got, ref, rtol=0, atol=TOL * _scale(ref))
        np.testing.assert_allclose(pm.mass_matrix(qpos) + np.diag(pm.armature), ref, rtol=0, atol=TOL * _scale(ref))


def test_rnea_batch_equals_loop():
    m = _load(TWO_ARMS_BOX)
    pm = dyn.from_mujoco(m)
    rng = np.random.default_rng(3)
    states = [_random_state(m, rng) for _ in range(4)]
    qpos, qvel, qacc = (np.stack(x) for x in zip(*states, strict=False))
    batch = pm.rnea(qpos, qvel, qacc, include_armature=True)
    assert batch.shape == (4, m.nv)
    for k in range(4):
        one = pm.rnea(qpos[k], qvel[k], qacc[k], include_armature=True)
        np.testing.assert_allclose(batch[k], one, rtol=0, atol=1e-12)
    assert pm.mass_matrix(qpos).shape == (4, m.nv, m.nv)


def test_gravity_disabled_flag_gives_zero_gravity():
    m = mujoco.MjModel.from_xml_string(FREE_BOX)
    m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_GRAVITY)
    pm = dyn.from_mujoco(m)
    np.testing.assert_array_equal(pm.gravity, np.zeros(3))
    qpos = m.qpos0.copy()
    np.testing.assert_allclose(pm.rnea(qpos, np.zeros(6), np.zeros(6)), np.zeros(6), rtol=0, atol=1e-15)


def test_free_box_static_weight_and_free_fall():
    """A free body held still needs a world-frame force -m g; in free fall it needs nothing."""
    m = _load(FREE_BOX)
    pm = dyn.from_mujoco(m)
    g = np.array([0.3, -0.2, -9.81])
    rng = np.random.default_rng(4)
    qpos, qvel, _ = _random_state(m, rng)
    hold = pm.rnea(qpos, np.zeros(6), np.zeros(6))
    # the torque about the body origin is the lever of the COM: c x (-m g) in the local frame
    rot = pm.body_placement(qpos, "box").rotation
    com_local = m.body_ipos[1]
    np.testing.assert_allclose(hold[:3], -0.35 * g, rtol=0, atol=1e-12)
    np.testing.assert_allclose(hold[3:], np.cross(com_local, rot.T @ (-0.35 * g)), rtol=0, atol=1e-12)
    # free fall with zero angular velocity: the COM accelerates with g, which for a body
    # origin off the COM and no rotation is qacc_lin = g
    qvel[3:] = 0.0
    fall = pm.rnea(qpos, qvel, np.concatenate([g, np.zeros(3)]))
    np.testing.assert_allclose(fall, np.zeros(6), rtol=0, atol=1e-12)


# --------------------------------------------------------------------------
# conventions
# --------------------------------------------------------------------------


def test_conversions_round_trip_and_duality():
    m = _load(TWO_ARMS_BOX)
    m2 = _load(BALL_MULTI)
    rng = np.random.default_rng(5)
    for model in (m, m2):
        pm = dyn.from_mujoco(model)
        qpos, qvel, qacc = _random_state(model, rng)
        q = pm.q_mj_to_pin(qpos)
        np.testing.assert_allclose(pm.q_pin_to_mj(q), qpos, rtol=0, atol=1e-15)
        v = pm.v_mj_to_pin(qpos, qvel)
        np.testing.assert_allclose(pm.v_pin_to_mj(qpos, v), qvel, rtol=0, atol=1e-14)
        tau = rng.normal(size=model.nv)
        qfrc = pm.tau_pin_to_mj(qpos, tau)
        np.testing.assert_allclose(pm.tau_mj_to_pin(qpos, qfrc), tau, rtol=0, atol=1e-14)
        # power is convention independent: qfrc . qvel == tau . v
        assert abs(qfrc @ qvel - tau @ v) < 1e-12 * _scale(tau) * _scale(qvel)
        jac = pm.velocity_map(qpos)
        np.testing.assert_allclose(jac @ qvel, v, rtol=0, atol=1e-14)
        np.testing.assert_allclose(jac.T @ tau, qfrc, rtol=0, atol=1e-14)
        # a is the time derivative of v along the motion (central difference)
        h = 1e-6
        plus, minus = qpos.copy(), qpos.copy()
        mujoco.mj_integratePos(model, plus, qvel + h * qacc, h)
        mujoco.mj_integratePos(model, minus, qvel - h * qacc, -h)
        dv = (pm.v_mj_to_pin(plus, qvel + h * qacc) - pm.v_mj_to_pin(minus, qvel - h * qacc)) / (2 * h)
        np.testing.assert_allclose(pm.a_mj_to_pin(qpos, qvel, qacc), dv, rtol=0, atol=1e-6)


def test_free_joint_conversion_known_values():
    """Body yawed by 90 deg: world x velocity is local -y; quaternion order flips."""
    m = _load(FREE_BOX)
    pm = dyn.from_mujoco(m)
    s = np.sqrt(0.5)
    qpos = np.array([1.0, 2.0, 3.0, s, 0.0, 0.0, s])
    np.testing.assert_allclose(pm.q_mj_to_pin(qpos), [1, 2, 3, 0, 0, s, s], rtol=0, atol=1e-15)
    v = pm.v_mj_to_pin(qpos, np.array([1.0, 0, 0, 0, 0, 0.5]))
    np.testing.assert_allclose(v, [0, -1, 0, 0, 0, 0.5], rtol=0, atol=1e-15)
    # qacc = 0 while spinning at 0.5 rad/s about z with world velocity x: the local
    # velocity (0,-1,0) rotates, d/dt v_loc = -omega x v_loc = (-0.5, 0, 0)
    a = pm.a_mj_to_pin(qpos, np.array([1.0, 0, 0, 0, 0, 0.5]), np.zeros(6))
    np.testing.assert_allclose(a, [-0.5, 0, 0, 0, 0, 0], rtol=0, atol=1e-15)
    qfrc = pm.tau_pin_to_mj(qpos, np.array([0, -1.0, 0, 0, 0, 0]))
    np.testing.assert_allclose(qfrc, [1, 0, 0, 0, 0, 0], rtol=0, atol=1e-15)


def test_joint_map_and_names():
    m = _load(TWO_ARMS_BOX)
    pm = dyn.from_mujoco(m)
    assert len(pm.joints) == m.njnt
    for jm in pm.joints:
        assert jm.name == mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_JOINT, jm.mj_id)
        assert pm.model.joints[jm.pin_id].idx_q == jm.idx_q
        assert pm.model.joints[jm.pin_id].idx_v == jm.idx_v
    box = pm.joint("box_joint")
    assert (box.kind, box.nq, box.nv, box.dofadr) == ("free", 7, 6, 16)
    assert pm.joint("l/j2").qpos0 == pytest.approx(0.3, abs=1e-15)
    assert pm.body_id("r/hand") == mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, "r/hand")
    np.testing.assert_array_equal(pm.dofs_supporting("r/hand"), np.arange(8, 14))
    np.testing.assert_array_equal(pm.dofs_supporting("box"), np.arange(16, 22))
    assert pm.dofs_supporting("l/base").size == 0
    np.testing.assert_array_equal(pm.armature, m.dof_armature)
    with pytest.raises(ScenarioError, match="valid names"):
        pm.body_id("no_such_body")
    with pytest.raises(ScenarioError):
        pm.joint(999)
    with pytest.raises(TrajectoryError):
        pm.rnea(np.zeros(3), np.zeros(m.nv), np.zeros(m.nv))
    with pytest.raises(TrajectoryError):
        pm.rnea(m.qpos0 * np.nan, np.zeros(m.nv), np.zeros(m.nv))


def test_unsupported_structures_are_rejected():
    inertial = '<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>'
    nested_free = _mjcf(
        f"""<body name="a"><joint axis="0 0 1"/>{inertial}
              <body name="b" pos="0.1 0 0"><freejoint/>{inertial}</body></body>"""
    )
    # MuJoCo itself or the builder refuses a free joint below a moving body
    with pytest.raises((ValueError, ScenarioError)):
        dyn.from_mujoco(mujoco.MjModel.from_xml_string(nested_free))
    under_mocap = _mjcf(
        f"""<body name="mc" mocap="true" pos="0 0 1">
              <body name="c"><joint axis="1 0 0"/>{inertial}</body></body>"""
    )
    with pytest.raises(ScenarioError, match="mocap"):
        dyn.from_mujoco(mujoco.MjModel.from_xml_string(under_mocap))


@pytest.mark.parametrize("name", ["arm", "two_arms_box", "ball_multi"])
def test_placements_match_mujoco_kinematics(name):
    m = _load(MODELS[name])
    pm = dyn.from_mujoco(m)
    d = mujoco.MjData(m)
    rng = np.random.default_rng(6)
    qpos, _, _ = _random_state(m, rng)
    d.qpos[:] = qpos
    mujoco.mj_kinematics(m, d)
    for b in range(m.nbody):
        pose = pm.body_placement(qpos, b)
        np.testing.assert_allclose(pose.translation, d.xpos[b], rtol=0, atol=1e-12)
        np.testing.assert_allclose(pose.rotation, d.xmat[b].reshape(3, 3), rtol=0, atol=1e-12)
        ipose = pm.body_placement(qpos, b, inertial=True)
        np.testing.assert_allclose(ipose.translation, d.xipos[b], rtol=0, atol=1e-12)
        np.testing.assert_allclose(ipose.rotation, d.ximat[b].reshape(3, 3), rtol=0, atol=1e-12)
    for s in range(m.nsite):
        pose = pm.site_placement(qpos, s)
        np.testing.assert_allclose(pose.translation, d.site_xpos[s], rtol=0, atol=1e-12)
        np.testing.assert_allclose(pose.rotation, d.site_xmat[s].reshape(3, 3), rtol=0, atol=1e-12)
    # Pinocchio's own frames agree with the helpers
    pin.framesForwardKinematics(pm.model, pm.data, pm.q_mj_to_pin(qpos))
    for b in range(1, m.nbody):
        fid = pm.model.getFrameId(pm.body_names[b], pin.FrameType.BODY)
        np.testing.assert_allclose(pm.data.oMf[fid].translation, d.xpos[b], rtol=0, atol=1e-12)


# --------------------------------------------------------------------------
# payload-affine inverse dynamics
# --------------------------------------------------------------------------

ONE_HINGE = _mjcf(
    """
    <body name="link" pos="0 0 0.5">
      <joint name="j" axis="0 -1 0"/>
      <inertial pos="0.2 0 0" mass="1.3" diaginertia="0.01 0.01 0.01"/>
    </body>""",
    gravity="0 0 -9.81",
)


def _quat_of(rot: np.ndarray) -> np.ndarray:
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, np.ascontiguousarray(rot).ravel())
    return quat


@pytest.mark.parametrize("angle", [0.0, 0.7, -1.2])
def test_payload_static_hold_is_m_g_L(angle):
    """A payload held at lever L on a link at angle theta above the horizontal
    needs tau = m g L cos(theta) at the hinge, whatever its orientation."""
    m = _load(ONE_HINGE)
    pm = dyn.from_mujoco(m)
    lever = 0.35
    qpos = np.array([angle])
    link = pm.body_placement(qpos, "link")
    # the hinge axis is -y, so a positive angle lifts the link's x axis towards +z
    np.testing.assert_allclose(link.rotation[:, 0], [np.cos(angle), 0.0, np.sin(angle)], rtol=0, atol=1e-15)
    held = link * pin.SE3(mujoco_quat_mat([0.8, 0.0, 0.6, 0.0]), np.array([lever, 0.0, 0.0]))
    pose = np.concatenate([held.translation, _quat_of(held.rotation)])
    unit = np.diag([1e-4, 2e-4, 3e-4])
    tau0, y = dyn.payload_regressor(
        pm, qpos, np.zeros(1), np.zeros(1), attach_body="link", payload_pose_world=pose, unit_inertia=unit
    )
    assert y[0] == pytest.approx(9.81 * lever * np.cos(angle), abs=1e-12)
    assert tau0[0] == pytest.approx(1.3 * 9.81 * 0.2 * np.cos(angle), abs=1e-12)
    mass = 2.5
    assert tau0[0] + mass * y[0] == pytest.approx((1.3 * 0.2 + mass * lever) * 9.81 * np.cos(angle), abs=1e-12)


def mujoco_quat_mat(quat) -> np.ndarray:
    """Rotation matrix of a (w, x, y, z) quaternion, computed by MuJoCo."""
    quat = np.asarray(quat, dtype=float)
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, quat / np.linalg.norm(quat))
    return mat.reshape(3, 3)


def _with_payload(pm: dyn.PinocchioModel, qpos, body: str, pose: np.ndarray, inertia_per_kg: np.ndarray, mass: float):
    """A copy of pm.model with the payload appended to the holding joint as a body."""
    model = pin.Model(pm.model)
    b = pm.body_id(body)
    jid = int(pm.body_joint[b])
    joint_world = pm.body_placement(qpos, b) * pm.body_in_joint[b].inverse()
    joint_pose = joint_world.actInv(pin.SE3(mujoco_quat_mat(pose[3:]), pose[:3].copy()))
    # the inertia is given in the payload frame; appendBodyToJoint moves it to the joint frame
    model.appendBodyToJoint(jid, pin.Inertia(mass, np.zeros(3), mass * inertia_per_kg), joint_pose)
    return model


def test_payload_regressor_matches_model_with_payload_body():
    m = _load(ARM)
    pm = dyn.from_mujoco(m)
    rng = np.random.default_rng(7)
    unit = np.array([[3e-3, 4e-4, -2e-4], [4e-4, 2e-3, 1e-4], [-2e-4, 1e-4, 1.5e-3]])
    for _ in range(5):
        qpos, qvel, qacc = _random_state(m, rng)
        quat = rng.normal(size=4)
        pose = np.concatenate([rng.uniform(-0.5, 0.5, 3), quat / np.linalg.norm(quat)])
        tau0, y = dyn.payload_regressor(
            pm, qpos, qvel, qacc, attach_body="hand", payload_pose_world=pose, unit_inertia=unit
        )
        np.testing.assert_allclose(tau0, pm.rnea(qpos, qvel, qacc), rtol=0, atol=1e-12)
        # the fingers do not carry the hand
        np.testing.assert_array_equal(y[6:], 0.0)
        model = _with_payload(pm, qpos, "hand", pose, unit, 2.5)
        q, v, a = pm.q_mj_to_pin(qpos), pm.v_mj_to_pin(qpos, qvel), pm.a_mj_to_pin(qpos, qvel, qacc)
        ref = pm.tau_pin_to_mj(qpos, pin.rnea(model, model.createData(), q, v, a))
        np.testing.assert_allclose(tau0 + 2.5 * y, ref, rtol=0, atol=TOL * _scale(ref))


def _welded_payload_xml(mass: float) -> str:
    dims = np.array([0.04, 0.03, 0.06])  # box side lengths [m]
    diag = mass * np.array([dims[1] ** 2 + dims[2] ** 2, dims[0] ** 2 + dims[2] ** 2, dims[0] ** 2 + dims[1] ** 2]) / 12
    payload = f"""
                    <body name="payload" pos="0.11 0.005 -0.01" quat="0.9 0.3 -0.2 0.1">
                      <inertial pos="0.01 -0.005 0.002" quat="0.8 -0.1 0.5 0.2" mass="{float(mass)!r}"
                                diaginertia="{float(diag[0])!r} {float(diag[1])!r} {float(diag[2])!r}"/>
                    </body>"""
    return _mjcf(
        _arm_xml("l/", pos="-0.4 0.5 0", quat="1 0 0 0")
        + _arm_xml("r/", pos="0.4 0.5 0", quat="0 0 0 1", payload=payload)
        + _BOX
    )


def test_payload_regressor_matches_mujoco_welded_box():
    m_free = _load(TWO_ARMS_BOX)
    pm = dyn.from_mujoco(m_free)
    dims = np.array([0.04, 0.03, 0.06])
    unit = np.diag([dims[1] ** 2 + dims[2] ** 2, dims[0] ** 2 + dims[2] ** 2, dims[0] ** 2 + dims[1] ** 2]) / 12
    box = pm.joint("box_joint")
    arm_dofs = np.arange(box.dofadr)
    rng = np.random.default_rng(8)
    for mass in (0.05, 1.0, 10.0):
        m_weld = _load(_welded_payload_xml(mass))
        assert (m_weld.nq, m_weld.nv) == (m_free.nq, m_free.nv)
        d = mujoco.MjData(m_weld)
        for _ in range(3):
            qpos, qvel, qacc = _random_state(m_free, rng)
            d.qpos[:] = qpos
            mujoco.mj_kinematics(m_weld, d)
            pid = mujoco.mj_name2id(m_weld, mujoco.mjtObj.mjOBJ_BODY, "payload")
            pose = np.concatenate([d.xipos[pid], _quat_of(d.ximat[pid].reshape(3, 3))])
            tau0, y = dyn.payload_regressor(
                pm,
                qpos,
                qvel,
                qacc,
                attach_body="r/hand",
                payload_pose_world=pose,
                unit_inertia=unit,
                include_armature=True,
            )
            ref = _mj_inverse(m_weld, qpos, qvel, qacc)
            got = tau0 + mass * y
            np.testing.assert_allclose(got[arm_dofs], ref[arm_dofs], rtol=0, atol=TOL * _scale(ref[arm_dofs]))
            # the free box's dofs are excluded; the left arm does not feel the payload
            np.testing.assert_array_equal(tau0[box.dofadr :], 0.0)
            np.testing.assert_array_equal(y[box.dofadr :], 0.0)
            np.testing.assert_array_equal(y[:8], 0.0)


def test_payload_regressor_batch_and_options():
    m = _load(TWO_ARMS_BOX)
    pm = dyn.from_mujoco(m)
    rng = np.random.default_rng(9)
    states = [_random_state(m, rng) for _ in range(3)]
    qpos, qvel, qacc = (np.stack(x) for x in zip(*states, strict=False))
    pose = np.array([0.1, 0.5, 0.3, 1.0, 0.0, 0.0, 0.0])
    unit = np.eye(3) * 1e-4
    held = {"attach_body": "l/hand", "payload_pose_world": pose, "unit_inertia": unit}
    tau0, y = dyn.payload_regressor(pm, qpos, qvel, qacc, **held)
    assert tau0.shape == y.shape == (3, m.nv)
    t1, y1 = dyn.payload_regressor(pm, qpos[1], qvel[1], qacc[1], **held)
    np.testing.assert_allclose(tau0[1], t1, rtol=0, atol=1e-12)
    np.testing.assert_allclose(y[1], y1, rtol=0, atol=1e-12)
    # one pose per time step gives the same as the shared pose
    t_rows, y_rows = dyn.payload_regressor(
        pm, qpos, qvel, qacc, attach_body="l/hand", payload_pose_world=np.tile(pose, (3, 1)), unit_inertia=unit
    )
    np.testing.assert_allclose(y_rows, y, rtol=0, atol=1e-15)
    # keeping the box's dofs returns its own inverse dynamics there
    t_all, _ = dyn.payload_regressor(pm, qpos[1], qvel[1], qacc[1], **held, exclude_joints=())
    np.testing.assert_allclose(t_all, pm.rnea(qpos[1], qvel[1], qacc[1]), rtol=0, atol=1e-12)
    # a payload on a body fixed to the world loads no dof
    on_base = dict(held, attach_body="l/base")
    _, y_fixed = dyn.payload_regressor(pm, qpos[0], qvel[0], qacc[0], **on_base)
    np.testing.assert_array_equal(y_fixed, 0.0)
    with pytest.raises(ParameterError):
        dyn.payload_regressor(pm, qpos[0], qvel[0], qacc[0], **dict(held, unit_inertia=-unit))
    with pytest.raises(ParameterError):
        dyn.payload_regressor(pm, qpos[0], qvel[0], qacc[0], **dict(held, unit_inertia=np.triu(np.ones((3, 3)))))
    with pytest.raises(ScenarioError):
        dyn.payload_regressor(pm, qpos[0], qvel[0], qacc[0], **dict(held, attach_body="nope"))
    with pytest.raises(TrajectoryError):
        dyn.payload_regressor(pm, qpos[0], qvel[0], qacc[0], **dict(held, payload_pose_world=pose[:3]))


# --------------------------------------------------------------------------
# critical mass and motor FOS
# --------------------------------------------------------------------------


def test_critical_mass_known_values():
    tau0 = np.array([1.0, -1.0, 1.0, 0.5, 6.0, -2.0])
    y = np.array([2.0, 2.0, -2.0, 0.0, 1.0, 0.0])
    got = dyn.critical_mass(tau0, y, 5.0)
    np.testing.assert_allclose(got, [2.0, 3.0, 3.0, np.inf, 0.0, np.inf], rtol=0, atol=1e-15)
    assert dyn.critical_mass(1.0, 1.0, np.inf) == np.inf
    with pytest.raises(ParameterError):
        dyn.critical_mass(tau0, y, -1.0)


def test_critical_mass_reaches_the_limit():
    rng = np.random.default_rng(10)
    tau0, y = rng.normal(size=50), rng.normal(size=50)
    tau_max = np.abs(tau0) + rng.uniform(0.1, 3.0, 50)
    mc = dyn.critical_mass(tau0, y, tau_max)
    assert np.all(mc > 0)
    np.testing.assert_allclose(np.abs(tau0 + mc * y), tau_max, rtol=1e-12, atol=0)
    # just below the critical mass every joint is within its limit
    assert np.all(np.abs(tau0 + 0.999 * mc * y) < tau_max)


def test_motor_fos_known_values_and_vectorised():
    tau0, y, tau_max = np.array([1.0, -2.0]), np.array([1.0, 1.0]), np.array([4.0, 4.0])
    fos = dyn.motor_fos(tau0, y, tau_max, np.array([0.0, 2.0, 6.0]))
    np.testing.assert_allclose(fos, [2.0, 4.0 / 3.0, 4.0 / 7.0], rtol=1e-15, atol=0)
    assert dyn.motor_fos(tau0, y, tau_max, 0.0) == pytest.approx(2.0, rel=1e-15)
    assert dyn.motor_fos(np.zeros(2), np.zeros(2), tau_max, 1.0) == np.inf
    # with a time axis the minimum runs over time as well
    traj0 = np.array([[1.0, 0.0], [0.0, 3.0]])
    assert dyn.motor_fos(traj0, np.zeros((2, 2)), 6.0, 1.0) == pytest.approx(2.0, rel=1e-15)
    # at the critical mass the FOS is exactly 1
    mc = dyn.critical_mass(tau0, y, tau_max).min()
    assert dyn.motor_fos(tau0, y, tau_max, mc) == pytest.approx(1.0, rel=1e-14)
    assert dyn.motor_fos(tau0, y, tau_max, np.ones((2, 3))).shape == (2, 3)
    with pytest.raises(ParameterError):
        dyn.motor_fos(tau0, y, tau_max, -1.0)


# --------------------------------------------------------------------------
# analytic contact FOS
# --------------------------------------------------------------------------


def test_analytic_contact_fos_known_values():
    g = np.array([0.0, 0.0, -9.81])
    static = dyn.analytic_contact_fos(0.05, 1.0, acc_world=np.zeros(3), gravity=g, normal_force_total=10.0)
    assert static == pytest.approx(10.0 / (0.05 * 9.81), rel=1e-14)
    lift = dyn.analytic_contact_fos(0.05, 0.5, acc_world=np.array([0, 0, 2.0]), gravity=g, normal_force_total=10.0)
    assert lift == pytest.approx(0.5 * 10.0 / (0.05 * 11.81), rel=1e-14)
    side = dyn.analytic_contact_fos(2.0, 0.8, acc_world=np.array([3.0, 0, 0]), gravity=g, normal_force_total=40.0)
    assert side == pytest.approx(0.8 * 40.0 / (2.0 * np.hypot(3.0, 9.81)), rel=1e-14)
    assert dyn.analytic_contact_fos(1.0, 1.0, acc_world=g, gravity=g, normal_force_total=5.0) == np.inf
    masses, mus = np.array([[0.05], [0.5], [5.0]]), np.array([0.2, 1.0])
    grid = dyn.analytic_contact_fos(masses, mus, acc_world=np.zeros(3), gravity=g, normal_force_total=10.0)
    assert grid.shape == (3, 2)
    np.testing.assert_allclose(grid, mus * 10.0 / (masses * 9.81), rtol=1e-14, atol=0)
    traj = dyn.analytic_contact_fos(0.05, 1.0, acc_world=np.zeros((4, 3)), gravity=g, normal_force_total=10.0)
    assert traj.shape == (4,)
    with pytest.raises(ParameterError):
        dyn.analytic_contact_fos(-1.0, 1.0, acc_world=np.zeros(3), gravity=g, normal_force_total=10.0)


# --------------------------------------------------------------------------
# the real scenario model
# --------------------------------------------------------------------------


@pytest.mark.skipif(not SCENE.exists(), reason="scenario model not present")
def test_scene_rnea_and_mass_matrix_match_mujoco():
    m = mujoco.MjModel.from_xml_path(str(SCENE))
    _rigid_only(m)
    pm = dyn.from_mujoco(m)
    assert (pm.nq, pm.nv) == (m.nq, m.nv)
    rng = np.random.default_rng(11)
    for _ in range(5):
        qpos, qvel, qacc = _random_state(m, rng)
        ref = _mj_inverse(m, qpos, qvel, qacc)
        got = pm.rnea(qpos, qvel, qacc, include_armature=True)
        np.testing.assert_allclose(got, ref, rtol=0, atol=TOL * _scale(ref))
        full = _mj_mass(m, qpos)
        got = pm.mass_matrix(qpos, include_armature=True)
        np.testing.assert_allclose(got, full, rtol=0, atol=TOL * _scale(full))


@pytest.mark.skipif(not SCENE.exists(), reason="scenario model not present")
def test_scene_payload_regressor_loads_only_the_holding_arm():
    m = mujoco.MjModel.from_xml_path(str(SCENE))
    pm = dyn.from_mujoco(m)
    qpos = m.key("home").qpos.copy()
    gripper = "right/gripper_link"
    tcp = pm.site_placement(qpos, "right/tcp")
    pose = np.concatenate([tcp.translation, _quat_of(tcp.rotation)])
    zero = np.zeros(m.nv)
    tau0, y = dyn.payload_regressor(
        pm, qpos, zero, zero, attach_body=gripper, payload_pose_world=pose, unit_inertia=np.eye(3) * 0.04**2 / 6
    )
    arm = pm.dofs_supporting(gripper)
    assert arm.size == 6
    others = np.setdiff1d(np.arange(m.nv), arm)
    np.testing.assert_array_equal(y[others], 0.0)
    box = pm.joint("box_joint")
    np.testing.assert_array_equal(tau0[box.dofadr : box.dofadr + 6], 0.0)
    # statics: the waist axis is vertical, so gravity loads it with nothing
    assert abs(y[arm[0]]) < 1e-12
    # statics: the shoulder carries the payload's weight times its horizontal lever arm
    shoulder = pm.body_placement(qpos, "right/upper_arm_link")
    axis = shoulder.rotation @ m.jnt_axis[pm.joint("right/shoulder").mj_id]
    lever = tcp.translation - shoulder.translation
    expected = -np.dot(axis, np.cross(lever, pm.gravity))
    assert y[arm[1]] == pytest.approx(expected, abs=1e-12)


# --------------------------------------------------------------------------
# loads over the whole motion
# --------------------------------------------------------------------------

#: a 0.3 m, 1 kg hinge arm about y with a stiff, force-limited position servo (±5 N·m), a
#: pad at its tip, and a box resting on the table far from it: the arm never touches it


def _swing_twin(folder, xml: str = SWING_MJCF, *, uncertainty: str = "", rated: bool = True):
    """The twin of the swing arm in ``xml`` (written to ``folder``), the box's mass
    uncertain, ``uncertainty`` tables added; ``rated``: ``[limits]`` rates the hinge at
    5 N·m (else its limit is the MJCF's forcerange alone)."""
    from scenarios import one_actuator_toml

    from critmoment.scenario import load_scenario
    from critmoment.twin import Twin

    (folder / "scene.xml").write_text(xml)
    text = one_actuator_toml(
        "swing", mjcf="scene.xml", gripper="hand", gripper_geom="pad", support="table",
        actuator="hinge", limit=5.0, task=True, uncertainty="""[uncertainty.mass]
body = "box"
range = [0.05, 2.0]
nominal = 0.05
""" + uncertainty)
    if not rated:
        assert "[limits]\nhinge = 5.0\n" in text
        text = text.replace("[limits]\nhinge = 5.0\n", "")
    (folder / "scenario.toml").write_text(text)
    return Twin(load_scenario(folder))


def _swing(folder, xml: str = SWING_MJCF, target: float = -1.2):
    """(twin, recording) of the swing arm in ``xml``: it rests, then swings to ``target``
    [rad] from t = 0.14 s on."""
    from critmoment import recording as rollout
    from critmoment.trajectory import Trajectory

    twin = _swing_twin(folder, xml)
    fps = 50.0
    t = np.arange(30) / fps
    actions = np.where(t < 0.15, 0.0, target)[:, None]
    return twin, rollout.rollout(Trajectory(actions=actions, fps=fps, start=np.zeros(1)),
                                 twin=twin)


@pytest.fixture(scope="module")
def swing(tmp_path_factory):
    """(twin, recording): the arm rests, then swings 1.2 rad from t = 0.14 s on."""
    return _swing(tmp_path_factory.mktemp("swing"))


def test_load_bound_finds_the_free_arms_overload_where_the_full_rollout_saturates(swing):
    from critmoment.moments import MomentDetector, MomentLabel

    twin, rec = swing
    # ground truth from the rollout itself: the first saturation that lasts over 50 ms
    saturated = np.abs(rec.actuator_norm[:, 0]) >= 0.999
    need = int(round(0.05 / rec.dt)) + 1
    runs = np.flatnonzero(np.diff(np.concatenate([[0], saturated.astype(np.int8), [0]])))
    truth = next(int(a) for a, b in zip(runs[::2], runs[1::2], strict=True) if b - a >= need)
    # the swing (the upsampling spline starts the target moving a sample early), before
    # any contact with the object
    assert 0.1 <= truth * rec.dt <= 0.2
    assert not rec.signals.contact_gripper.any()
    bound = dyn.trajectory_load_bound(rec, twin, masses=[0.05, 2.0])
    assert not bound.carried.any()
    # the arm alone: the payload never rides on it, so every mass fails at the same time
    first = bound.first_failing_step
    assert abs(int(first[0]) - truth) <= 3, (first, truth)
    np.testing.assert_array_equal(first[0], first[1])
    np.testing.assert_allclose(bound.first_failing_time, first * rec.dt)
    assert bound.critical_mass[truth + 5] == 0.0  # overloaded without any payload
    assert bound.limiting_at(0, truth + 5) == "hinge"
    # the bound agrees with the recorded servo force where the arm is not saturated
    calm = np.arange(10, int(0.1 / rec.dt))
    np.testing.assert_allclose(bound.fos[0, calm], rec.fos_motor[calm], rtol=0.02)
    # the peak-load candidates include the overload, though no contact event is near it
    detector = MomentDetector().fit(rec)
    peaks = [m for m in detector.candidates_ if m.label is MomentLabel.PEAK_LOAD]
    assert peaks and min(abs(m.step - truth) for m in peaks) <= 3, [m.step for m in peaks]
    assert not [m for m in detector.events_ if m.label is MomentLabel.GRASP]


def test_load_bound_subtracts_gravity_compensation_and_springs(tmp_path):
    """An arm whose weight MuJoCo half compensates (``gravcomp="0.5"``) and whose joint
    spring pulls it (stiffness 2 N·m/rad towards 0.3 rad): the servo carries only the rest,
    and so does the bound (it counted the whole weight and no spring: 1.62 N·m where the
    servo holds 0.21)."""
    from critmoment.twin import state_slice

    xml = SWING_MJCF.replace('<body name="arm" pos="0 0 0.8">',
                             '<body name="arm" pos="0 0 0.8" gravcomp="0.5">')
    xml = xml.replace('<joint name="hinge" type="hinge" axis="0 1 0"/>',
                      '<joint name="hinge" type="hinge" axis="0 1 0" stiffness="2" '
                      'springref="0.3" damping="0.1"/>')
    twin, rec = _swing(tmp_path, xml, target=-0.6)
    bound = dyn.trajectory_load_bound(rec, twin, masses=[0.05])
    force = np.abs(rec.signals.actuator_force[:, 0])
    steps = np.flatnonzero(force[: int(0.5 / rec.dt)] < 4.9)  # the servo not saturated
    assert steps.size > 40
    np.testing.assert_allclose(5.0 / bound.fos[0, steps], force[steps], rtol=0.02, atol=0.01)
    # what the bound would miss without them: the compensation and the spring, 0.2-1.4 N·m
    model = twin.model
    passive = dyn.passive_forces(model, rec.states[:-1])[:, 0]
    qvel = rec.states[:-1, state_slice(model, mujoco.mjtState.mjSTATE_QVEL)]
    damping = -model.dof_damping[0] * qvel[:, 0]
    assert np.abs(passive - damping)[steps].min() > 0.15


def test_load_bound_subtracts_gravity_compensation_the_actuators_take(tmp_path):
    """trossen-arm-sim's WidowX AI: ``gravcomp`` with ``actuatorgravcomp`` routes MuJoCo's
    compensation through ``qfrc_actuator``, not ``qfrc_passive``; the bound counted the
    whole weight as the servo's (its shoulder: 13.5 N·m where the servo held 0.87). The
    servo carries the rest, and so does the bound, here and in the moments' analytic
    bound."""
    xml = SWING_MJCF.replace('<body name="arm" pos="0 0 0.8">',
                             '<body name="arm" pos="0 0 0.8" gravcomp="1">')
    xml = xml.replace('<joint name="hinge" type="hinge" axis="0 1 0"/>',
                      '<joint name="hinge" type="hinge" axis="0 1 0" actuatorgravcomp="true"/>')
    twin, rec = _swing(tmp_path, xml, target=-0.6)
    assert twin.model.jnt_actgravcomp[twin.model.joint("hinge").id]
    bound = dyn.trajectory_load_bound(rec, twin, masses=[0.05])
    force = np.abs(rec.signals.actuator_force[:, 0])
    steps = np.flatnonzero(force[: int(0.5 / rec.dt)] < 4.9)  # the servo not saturated
    assert steps.size > 40
    np.testing.assert_allclose(5.0 / bound.fos[0, steps], force[steps], rtol=0.02, atol=0.01)
    # the compensation is real: the weight's torque is far above what the servo holds
    data = mujoco.MjData(twin.model)
    mujoco.mj_setState(twin.model, data, rec.states[steps[-1]], mujoco.mjtState.mjSTATE_INTEGRATION)
    mujoco.mj_forward(twin.model, data)
    assert abs(data.qfrc_gravcomp[0]) > 0.5 and \
        abs(dyn.unactuated_force(twin.model, data)[0] - data.qfrc_passive[0]) > 0.5


def test_a_force_limit_parameter_is_each_samples_limit_everywhere(tmp_path):
    """A box that varies an arm servo's force limit (1..8 N·m, nominal 5; the MJCF's
    forcerange, no ``[limits]`` rating) moved MuJoCo's forcerange per sample, but the motor
    FOS, the ground truth's saturation rule and the analytic load bound kept dividing by
    the fixed 5 N·m: a servo clamped at 1 N·m for the whole hold read FOS 3 and no
    saturation. Each sample's limit is its own value; the load bound, over the whole box,
    takes the range's low end. (With a ``[limits]`` rating the parameter is a protective
    clamp and the checks divide by the rating: test_sparse's closed-form force limit.)"""
    from critmoment import groundtruth, recording
    from critmoment.sparse import SparseEvaluator
    from critmoment.trajectory import Trajectory

    # the limit is the parameter's alone (a [limits] rating would make it a clamp)
    twin = _swing_twin(tmp_path, rated=False, uncertainty="""[uncertainty.hinge_limit]
kind = "force_limit"
actuator = "hinge"
range = [1.0, 8.0]
nominal = 5.0
""")
    hinge = twin.actuator_names.index("hinge")
    np.testing.assert_allclose(twin.sample_limits([[0.05, 1.0], [0.05, 8.0]])[:, hinge],
                               [1.0, 8.0])
    assert twin.lowest_limits[hinge] == 1.0
    traj = Trajectory(actions=np.zeros((30, 1)), fps=50.0, start=np.zeros(1))  # a hold
    rec = recording.rollout(traj, twin=twin)
    held = float(np.abs(rec.signals.actuator_force[-50:, hinge]).mean())
    assert 1.3 < held < 2.0  # the arm's weight at its lever, well under the nominal 5 N·m
    samples = np.array([[0.05, 1.0], [0.05, 5.0]])
    # the sparse evaluation's motor FOS: clamped at 1 N·m, the servo is at its limit
    ev = SparseEvaluator(rec, twin, horizon=10)
    fos = ev.evaluate([20], samples).fos_motor[0]
    assert fos[0] == pytest.approx(1.0, abs=0.01) and fos[1] > 1.5
    # the ground truth: saturated for the whole hold at 1 N·m, never at 5
    bf = groundtruth.brute_force(traj, twin=twin, samples=samples)
    sat = bf.classification.saturation_time
    assert sat[0] > 0.3 and sat[1] == 0.0
    assert bf.classification.outcome[0] is groundtruth.Outcome.MOTOR
    # the analytic bound over the box: the low end's 1 N·m is exceeded without a payload
    bound = dyn.trajectory_load_bound(rec, twin, masses=[0.05])
    assert np.median(bound.fos[0, -100:]) < 1.0  # the hold, 1.3-2 N·m against 1 N·m


def test_load_bound_rejects_bad_options(swing):
    twin, rec = swing
    with pytest.raises(ParameterError, match="masses"):
        dyn.trajectory_load_bound(rec, twin, masses=[-1.0])
    with pytest.raises(ParameterError, match="saturation"):
        dyn.trajectory_load_bound(rec, twin, saturation=1.5)


@pytest.mark.parametrize(("low", "lowest"), [(1.0, 1.0), (6.0, 5.0)])
def test_a_rated_actuators_clamp_bounds_the_load_where_tighter(tmp_path, low, lowest):
    """With a ``[limits]`` rating (5 N·m) a force_limit parameter is a protective clamp;
    the analytic bounds took the rating alone and said "no motor saturates" beside runs
    whose clamped shoulder lost its tracking. The box's worst corner is the tighter of the
    two."""
    twin = _swing_twin(tmp_path, uncertainty=f"""[uncertainty.hinge_limit]
kind = "force_limit"
actuator = "hinge"
range = [{low}, 8.0]
nominal = 8.0
""")
    hinge = twin.actuator_names.index("hinge")
    assert twin.limits[hinge] == 5.0  # the checks divide by the rating
    assert twin.lowest_limits[hinge] == lowest
