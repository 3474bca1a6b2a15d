"""Tests for critmoment.twin: signals against hand-computed physics, parameters, action mapping.

Small scenes are written inline (MJCF + scenario.toml in tmp folders):

* a hinge arm holding a welded box at lever L (static torque = m·g·L),
* a box on a slope of angle θ with the slope as the "gripper" geom (static FOS = μ/tan θ,
  sliding FOS = 1, sliding acceleration g(sin θ − μ cos θ)).
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import mujoco
import mujoco.batch
import numpy as np
import pytest
from inline_models import arm_scenario_toml, arm_xml
from scenarios import one_actuator_toml

from critmoment.exceptions import ParameterError, ScenarioError, TrajectoryError
from critmoment.scenario import load_scenario
from critmoment.twin import CONTACT_SLOTS, Twin, lifted_flags

G = 9.81

# ---------------------------------------------------------------------------
# inline scenes
# ---------------------------------------------------------------------------

ARM_L = 0.5        # lever of the held box [m]
ARM_LINK_MASS = 1.0  # uniform link of length L: its own moment is m_link·g·L/2
ARM_BOX_MASS = 0.5
ARM_KP = 2000.0
ARM_LIMIT = 10.0

ARM_XML = f"""<mujoco model="hinge_arm">
  <compiler angle="radian" inertiafromgeom="true"/>
  <option timestep="0.001" integrator="implicitfast" cone="elliptic"/>
  <worldbody>
    <!-- the box's support: its bits meet the box's (a support that can never touch the
         object is refused) -->
    <geom name="floor" type="plane" size="2 2 0.1" pos="0 0 -1" conaffinity="3"/>
    <body name="arm" pos="0 0 0.5">
      <!-- joint damping speeds up settling and exerts no force at rest -->
      <joint name="hinge" type="hinge" axis="0 1 0" damping="20"/>
      <geom name="link" type="box" size="{ARM_L / 2} 0.02 0.02" pos="{ARM_L / 2} 0 0"
            mass="{ARM_LINK_MASS}" contype="0" conaffinity="0"/>
      <geom name="pad" type="box" size="0.01 0.03 0.03" pos="0 0 0.1" mass="0"
            contype="2" conaffinity="2"/>
    </body>
    <body name="box" pos="{ARM_L} 0 0.5">
      <joint name="box_joint" type="free" damping="2"/>
      <geom name="box" type="box" size="0.02 0.02 0.02" mass="{ARM_BOX_MASS}"
            contype="2" conaffinity="2"/>
    </body>
  </worldbody>
  <!-- switched on by the static-hold tests (_held): a scenario refuses an object that a
       weld holds from the start, and a pad that can never touch it -->
  <equality>
    <weld name="hold" body1="box" body2="arm" solref="0.002 1" active="false"/>
  </equality>
  <actuator>
    <position name="servo" joint="hinge" kp="{ARM_KP}" kv="50"/>
  </actuator>
</mujoco>
"""

ARM_TOML = one_actuator_toml("hinge_arm", mjcf="arm.xml", gripper="hand", gripper_geom="pad",
                             support="floor", actuator="servo", limit=ARM_LIMIT, label="hinge",
                             uncertainty=f"""[uncertainty.mass]
body = "box"
range = [0.1, 5.0]
nominal = {ARM_BOX_MASS}
""")

SLOPE_MU = 0.5          # the box's friction (it has priority over the slope)
SLOPE_OWN_MU = 0.3      # the slope's own friction, ignored thanks to the box's priority
BOX_HALF = 0.05


def _slope_xml(theta_deg: float, condim: int, pair_mu: float | None = None) -> str:
    """The box on a slope; with ``pair_mu`` its only contact is an explicit <pair> with the
    slope (the box's own contype and conaffinity 0) of that sliding friction."""
    th = math.radians(theta_deg)
    bits = ' contype="0" conaffinity="0"' if pair_mu is not None else ""
    # (the floor, the scenario's support far below, by a pair too: a support that can never
    # touch the object is refused)
    pair = (f'<contact><pair geom1="box" geom2="slope" condim="{condim}" '
            f'friction="{pair_mu} {pair_mu} 0.005 0.0001 0.0001"/>'
            f'<pair geom1="box" geom2="floor"/></contact>'
            if pair_mu is not None else "")
    # box centre one half-size above the slope plane (which passes through the origin)
    cx, cz = BOX_HALF * math.sin(th), BOX_HALF * math.cos(th)
    return f"""<mujoco model="slope">
  <compiler angle="radian" inertiafromgeom="true"/>
  <option timestep="0.001" integrator="implicitfast" cone="elliptic" impratio="10"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1" pos="0 0 -2"/>
    <geom name="slope" type="plane" size="1 1 0.05" euler="0 {th!r} 0"
          friction="{SLOPE_OWN_MU} 0.005 0.0001"/>
    <body name="box" pos="{cx!r} 0 {cz!r}" euler="0 {th!r} 0">
      <freejoint name="box_joint"/>
      <geom name="box" type="box" size="{BOX_HALF} {BOX_HALF} {BOX_HALF}" mass="1.0"
            condim="{condim}" priority="1" friction="{SLOPE_MU} 0.005 0.0001"{bits}/>
    </body>
    <body name="arm" pos="0 3 -1">
      <joint name="hinge" type="hinge" axis="0 1 0"/>
      <geom name="link" type="capsule" size="0.02" fromto="0 0 0 0.2 0 0" mass="0.1"
            contype="0" conaffinity="0"/>
    </body>
  </worldbody>
  <actuator>
    <position name="servo" joint="hinge" kp="10" kv="1"/>
  </actuator>
  {pair}
</mujoco>
"""


SLOPE_TOML = one_actuator_toml("slope", mjcf="slope.xml", gripper="slope", gripper_geom="slope",
                               support="floor", actuator="servo", limit=5.0,
                               uncertainty=f"""[uncertainty.mass]
body = "box"
range = [0.1, 20.0]
nominal = 1.0
[uncertainty.friction]
geom = "box"
range = [0.1, 1.5]
nominal = {SLOPE_MU}
""")


def _write(folder: Path, files: dict[str, str]) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (folder / name).write_text(text)
    return folder


@pytest.fixture(scope="module")
def arm_twin(tmp_path_factory):
    folder = _write(tmp_path_factory.mktemp("arm"), {"arm.xml": ARM_XML, "scenario.toml": ARM_TOML})
    return Twin(load_scenario(folder))


def _slope_twin(tmp_path_factory, theta_deg: float, condim: int = 3) -> Twin:
    folder = _write(tmp_path_factory.mktemp(f"slope{theta_deg}_{condim}"),
                    {"slope.xml": _slope_xml(theta_deg, condim), "scenario.toml": SLOPE_TOML})
    return Twin(load_scenario(folder))


def _run(model, data, steps: int) -> None:
    for _ in range(steps):
        mujoco.mj_step(model, data)


def _held(model) -> mujoco.MjData:
    """Data of the hinge arm with its box welded to the arm (the weld's relative pose is
    the reference configuration's)."""
    data = mujoco.MjData(model)
    data.eq_active[model.equality("hold").id] = 1
    return data


def _downslope(theta_deg: float) -> np.ndarray:
    th = math.radians(theta_deg)
    return np.array([math.cos(th), 0.0, -math.sin(th)])


# ---------------------------------------------------------------------------
# static hold: actuator torque = m·g·L
# ---------------------------------------------------------------------------


@pytest.mark.parametrize("box_mass", [ARM_BOX_MASS, 2.0])
def test_static_hold_torque_is_gravity_moment(arm_twin, box_mass):
    model = arm_twin.copy_model()
    arm_twin.write_parameters(model, [[box_mass]])
    data = _held(model)
    _run(model, data, 1500)
    sig = arm_twin.signals(data.sensordata)

    # gravity moment about the hinge (+y): link at L/2, box at L; the servo opposes it
    moment = G * (ARM_LINK_MASS * ARM_L / 2 + box_mass * ARM_L)
    assert sig.actuator_force.shape == (1,)
    assert sig.actuator_force[0] == pytest.approx(-moment, rel=1e-3)
    # exact static balance with the settled centres of mass (weld sag, servo deflection)
    arm_id, box_id = model.body("arm").id, model.body("box").id
    exact = G * (model.body_mass[arm_id] * data.xipos[arm_id, 0]
                 + model.body_mass[box_id] * data.xipos[box_id, 0])
    assert sig.actuator_force[0] == pytest.approx(-exact, rel=1e-5)
    # position servo: force = -kp·q at rest
    assert data.qpos[0] == pytest.approx(moment / ARM_KP, rel=1e-3)
    # motor FOS = limit / (m g L), the servo is the limiting actuator
    assert float(sig.fos_motor) == pytest.approx(ARM_LIMIT / moment, rel=1e-3)
    assert int(sig.motor_argmax) == 0
    assert float(sig.actuator_norm[0]) == pytest.approx(-moment / ARM_LIMIT, rel=1e-3)
    # at rest
    np.testing.assert_allclose(sig.object_acc, 0.0, atol=1e-4)
    # the pad never touches the box: no contact, contact FOS +inf
    assert np.isposinf(sig.fos_contact).all() and not sig.contact_gripper.any()


def test_static_hold_overload_has_fos_below_one(arm_twin):
    model = arm_twin.copy_model()
    arm_twin.write_parameters(model, [[4.0]])
    data = _held(model)
    _run(model, data, 1500)
    sig = arm_twin.signals(data.sensordata)
    moment = G * (ARM_LINK_MASS * ARM_L / 2 + 4.0 * ARM_L)  # 22.07 N·m > 10 N·m limit
    assert float(sig.fos_motor) == pytest.approx(ARM_LIMIT / moment, rel=1e-3)
    assert float(sig.fos_motor) < 1.0
    # the cost is dominated by the motor term: B·exp(−β(FOS − 1)) > B
    assert float(sig.cost) > arm_twin.scenario.cost.B


# ---------------------------------------------------------------------------
# box on a slope: contact FOS = μ / tan θ when it holds, 1 when it slides
# ---------------------------------------------------------------------------


@pytest.mark.parametrize("condim", [3, 4])
def test_box_resting_on_slope_has_fos_mu_over_tan(tmp_path_factory, condim):
    theta = 15.0
    twin = _slope_twin(tmp_path_factory, theta, condim)
    model = twin.copy_model()
    data = mujoco.MjData(model)
    _run(model, data, 300)
    sig = twin.signals(data.sensordata)
    expected = SLOPE_MU / math.tan(math.radians(theta))  # 1.866
    assert sig.fos_contact.shape == (1,)
    assert float(sig.fos_contact[0]) == pytest.approx(expected, rel=1e-4)
    assert bool(sig.contact_gripper[0])
    assert not bool(sig.contact_support)
    np.testing.assert_allclose(sig.object_acc, 0.0, atol=1e-3)
    # the box's friction governs (priority), not the slope's lower one
    box = twin.object_geom_id
    mus = [data.contact.friction[i, 0] for i in range(data.ncon) if box in data.contact.geom[i]]
    assert mus and np.allclose(mus, SLOPE_MU, rtol=0, atol=1e-15)


@pytest.mark.parametrize("condim", [3, 4])
def test_box_sliding_down_slope_has_fos_one(tmp_path_factory, condim):
    theta = 35.0  # tan 35° = 0.70 > μ = 0.5
    twin = _slope_twin(tmp_path_factory, theta, condim)
    model = twin.copy_model()
    data = mujoco.MjData(model)
    steps = 300
    fos = np.empty(steps)
    for k in range(steps):
        mujoco.mj_step(model, data)
        fos[k] = twin.signals(data.sensordata).fos_contact[0]
    touching = np.isfinite(fos)
    # a sliding box chatters on its corners; while it touches, every contact is on the cone
    assert touching[50:].mean() > 0.5
    np.testing.assert_allclose(fos[touching], 1.0, atol=1e-2)
    # mean acceleration down the slope: g (sin θ − μ cos θ) = 1.609 m/s²
    th = math.radians(theta)
    expected = G * (math.sin(th) - SLOPE_MU * math.cos(th))
    speed = data.qvel[:3] @ _downslope(theta)
    assert speed / (steps * model.opt.timestep) == pytest.approx(expected, rel=0.03)


def test_friction_parameter_changes_the_regime(tmp_path_factory):
    theta = 35.0
    twin = _slope_twin(tmp_path_factory, theta)
    mu = 0.8  # tan 35° = 0.70 < 0.8: now it holds
    model = twin.copy_model()
    twin.write_parameters(model, [[1.0, mu]])
    assert twin.object_friction(model) == mu
    assert twin.object_friction() == SLOPE_MU  # the nominal model is untouched
    data = mujoco.MjData(model)
    _run(model, data, 300)
    sig = twin.signals(data.sensordata, mu=mu)
    assert float(sig.fos_contact[0]) == pytest.approx(mu / math.tan(math.radians(theta)), rel=1e-4)
    speed = data.qvel[:3] @ _downslope(theta)
    assert abs(speed) < 1e-3
    # read with the wrong (nominal) μ the same forces give a FOS scaled by 0.5 / 0.8
    wrong = twin.signals(data.sensordata)
    assert float(wrong.fos_contact[0]) == pytest.approx(float(sig.fos_contact[0]) * SLOPE_MU / mu,
                                                        rel=1e-12)


SLOPE_MASS_ONLY_TOML = one_actuator_toml(
    "slope", mjcf="slope.xml", gripper="slope", gripper_geom="slope", support="floor",
    actuator="servo", limit=5.0, uncertainty="""[uncertainty.mass]
body = "box"
range = [0.1, 20.0]
nominal = 1.0
""")


def test_an_explicit_pair_sets_the_friction_the_fos_reads(tmp_path):
    """Contacts made only by an explicit <pair> (the box's contype and conaffinity 0) use the
    pair's friction, not the geoms': the box rests at 15° with FOS μ_pair / tan θ. It was
    refused ("takes part in no contact"), and without a friction parameter its FOS read the
    geom's 0.5: 0.5 / tan 15° = 1.87 where the contact holds with 0.9 (3.36)."""
    theta, pair_mu = 15.0, 0.9
    folder = _write(tmp_path / "mass", {"slope.xml": _slope_xml(theta, 3, pair_mu),
                                        "scenario.toml": SLOPE_MASS_ONLY_TOML})
    twin = Twin(load_scenario(folder))
    assert twin.object_friction() == pair_mu
    model = twin.copy_model()
    data = mujoco.MjData(model)
    _run(model, data, 300)
    box = twin.object_geom_id
    mus = [data.contact.friction[i, 0] for i in range(data.ncon) if box in data.contact.geom[i]]
    assert mus and np.allclose(mus, pair_mu, rtol=0, atol=1e-15)
    sig = twin.signals(data.sensordata)
    assert float(sig.fos_contact[0]) == pytest.approx(
        pair_mu / math.tan(math.radians(theta)), rel=1e-4)


def test_a_friction_parameter_writes_the_explicit_pairs_too(tmp_path):
    theta, pair_mu = 35.0, 0.9  # tan 35° = 0.70: the pair's 0.9 would hold the box
    folder = _write(tmp_path / "mu", {"slope.xml": _slope_xml(theta, 3, pair_mu),
                                      "scenario.toml": SLOPE_TOML})
    with pytest.warns(UserWarning, match=r"sliding friction 0\.9 \(slope–box 0\.9\), from "
                      r"explicit <pair>s in the MJCF.* nominal 0\.5"):
        twin = Twin(load_scenario(folder))
    assert twin.model.pair_friction[0, 0] == twin.model.pair_friction[0, 1] == SLOPE_MU
    assert twin.object_friction() == SLOPE_MU
    for mu, holds in ((SLOPE_MU, False), (0.8, True)):
        model = twin.copy_model()
        twin.write_parameters(model, [[1.0, mu]])
        assert twin.object_friction(model) == mu
        data = mujoco.MjData(model)
        _run(model, data, 300)
        speed = abs(data.qvel[:3] @ _downslope(theta))
        assert (speed < 1e-3) == holds
    # per simulation, in a batch
    batch = mujoco.batch.Batch(twin.model, 3)
    samples = np.array([[1.0, 0.2], [2.0, 0.8], [1.0, 1.4]])
    twin.write_parameters(batch, samples)
    np.testing.assert_array_equal(twin.grip_friction(batch.expanded("geom_friction"),
                                                     batch.expanded("pair_friction")),
                                  samples[:, 1])


# ---------------------------------------------------------------------------
# object acceleration
# ---------------------------------------------------------------------------


@pytest.mark.parametrize("mass", [1.0, 10.0, 0.1])
def test_free_fall_object_acc_is_gravity(tmp_path_factory, mass):
    twin = _slope_twin(tmp_path_factory, 15.0)
    model = twin.copy_model()
    twin.write_parameters(model, [[mass, SLOPE_MU]])
    data = twin.initial_data(object_pose=[0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0], model=model,
                             settle=False)
    for _ in range(5):
        mujoco.mj_step(model, data)
        sig = twin.signals(data.sensordata)
        np.testing.assert_allclose(sig.object_acc, [0.0, 0.0, -G], rtol=0, atol=1e-9)
        assert np.isposinf(sig.fos_contact).all()


def test_free_fall_detects_missing_set_const(tmp_path_factory):
    # the pitfall write_parameters guards against: mass changed without mj_setConst
    twin = _slope_twin(tmp_path_factory, 15.0)
    model = twin.copy_model()
    box = twin.object_body_id
    model.body_mass[box] *= 10.0
    model.body_inertia[box] *= 10.0
    data = twin.initial_data(object_pose=[0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0], model=model,
                             settle=False)
    mujoco.mj_step(model, data)
    acc = twin.signals(data.sensordata).object_acc
    assert abs(acc[2] + G) > 1.0  # wrong physics: the test above would catch it


def test_bundled_box_free_fall_heavy_and_resting(twin):
    start = np.array([0.0, -0.96, 1.16, 0.0, -0.3, 0.0, 0.0] * 2)
    model = twin.copy_model()
    twin.write_parameters(model, [[10.0, 1.0]])  # 200 × the nominal mass
    data = twin.initial_data(start=start, object_pose=[0.1, 0.5, 0.3, 1, 0, 0, 0], model=model,
                             settle=False)
    mujoco.mj_step(model, data)
    sig = twin.signals(data.sensordata)
    np.testing.assert_allclose(sig.object_acc, [0.0, 0.0, -G], rtol=0, atol=1e-9)
    assert not bool(sig.contact_support)
    # resting on the table
    data = twin.initial_data(start=start, object_pose=[0.1, 0.5, 0.02, 1, 0, 0, 0], model=model)
    _run(model, data, 300)
    sig = twin.signals(data.sensordata)
    np.testing.assert_allclose(sig.object_acc, 0.0, atol=1e-6)
    assert bool(sig.contact_support)
    assert int(sig.stage) == 0


# ---------------------------------------------------------------------------
# parameter writing
# ---------------------------------------------------------------------------


def _box_contact_friction(twin, model, mass, mu, steps=50):
    start = np.array([0.0, -0.96, 1.16, 0.0, -0.3, 0.0, 0.0] * 2)
    twin.write_parameters(model, [[mass, mu]])
    data = twin.initial_data(start=start, object_pose=[0.1, 0.5, 0.02, 1, 0, 0, 0], model=model)
    _run(model, data, steps)
    box = twin.object_geom_id
    return np.array([data.contact.friction[i] for i in range(data.ncon)
                     if box in data.contact.geom[i]])


def test_write_parameters_mass_and_inertia(twin):
    box = twin.object_body_id
    m0 = twin.model.body_mass[box]
    inertia0 = twin.model.body_inertia[box].copy()
    assert m0 == pytest.approx(0.05, rel=1e-15)
    # the 4 cm cube's inertia: m·(2a)²/6 with a = 0.02
    np.testing.assert_allclose(inertia0, 0.05 * 0.04 ** 2 / 6, rtol=1e-12)
    model = twin.copy_model()
    twin.write_parameters(model, [[2.0, 1.0]])
    assert model.body_mass[box] == 2.0
    np.testing.assert_allclose(model.body_inertia[box], inertia0 * 2.0 / 0.05, rtol=1e-12)
    # derived constants recomputed
    assert model.body_subtreemass[box] == pytest.approx(2.0, rel=1e-12)
    dof = model.body_dofadr[box]
    assert model.dof_M0[dof] == pytest.approx(2.0, rel=1e-12)
    # writing again starts from the MJCF's values, not the last write
    twin.write_parameters(model, [[0.1, 1.0]])
    np.testing.assert_allclose(model.body_inertia[box], inertia0 * 0.1 / 0.05, rtol=1e-12)
    # the nominal model is untouched
    assert twin.model.body_mass[box] == m0
    np.testing.assert_array_equal(twin.model.body_inertia[box], inertia0)


@pytest.mark.parametrize("mu", [0.2, 0.5, 1.5])
def test_write_parameters_sets_effective_contact_friction(twin, mu):
    # the table's friction is 1.0: with max-mixing μ = 0.2 or 0.5 would read 1.0
    table = twin.model.geom("table").id
    assert twin.model.geom_friction[table, 0] == 1.0
    friction = _box_contact_friction(twin, twin.copy_model(), 1.0, mu)
    assert len(friction) >= 4  # the cube's face on the table
    np.testing.assert_array_equal(friction[:, 0], mu)
    np.testing.assert_array_equal(friction[:, 1], mu)


def test_write_parameters_rejects_bad_samples(twin):
    model = twin.copy_model()
    with pytest.raises(ParameterError, match=r"shape \(1, k\)"):
        twin.write_parameters(model, [[1.0, 1.0], [2.0, 1.0]])
    with pytest.raises(ParameterError, match=r"expected samples of shape \(n, 2\)"):
        twin.write_parameters(model, [[1.0]])
    with pytest.raises(ParameterError, match="'mass'.*> 0"):
        twin.write_parameters(model, [[-1.0, 1.0]])
    with pytest.raises(ParameterError, match="'friction'.*finite"):
        twin.write_parameters(model, [[1.0, np.nan]])
    # nothing was written by the rejected calls
    assert model.body_mass[twin.object_body_id] == twin.model.body_mass[twin.object_body_id]


# ---------------------------------------------------------------------------
# action mapping (ALOHA convention)
# ---------------------------------------------------------------------------

CLOSE, OPEN = 0.01844, 0.05800


def _finger(g: float) -> float:
    return min(max(g * (OPEN - CLOSE) + CLOSE, 0.021), 0.057)


@pytest.mark.parametrize("g_left, g_right", [(0.0, 1.0), (0.5, 0.25), (0.06, 0.97), (1.0, 0.0)])
def test_controls_aloha_gripper_mapping(twin, g_left, g_right):
    arm = np.array([0.1, -0.5, 0.7, 0.2, -0.3, 0.4])
    action = np.concatenate([arm, [g_left], -arm, [g_right]])
    ctrl = twin.controls(action)
    assert ctrl.shape == (16,)
    names = twin.actuator_names
    np.testing.assert_array_equal(ctrl[[names.index(f"left/{j}") for j in
                                        ("waist", "shoulder", "elbow", "forearm_roll",
                                         "wrist_angle", "wrist_rotate")]], arm)
    np.testing.assert_array_equal(ctrl[[names.index(f"right/{j}") for j in
                                        ("waist", "shoulder", "elbow", "forearm_roll",
                                         "wrist_angle", "wrist_rotate")]], -arm)
    for side, g in (("left", g_left), ("right", g_right)):
        assert ctrl[names.index(f"{side}/left_finger")] == pytest.approx(_finger(g), abs=1e-15)
        assert ctrl[names.index(f"{side}/right_finger")] == pytest.approx(-_finger(g), abs=1e-15)


def test_controls_clamp_and_broadcast(twin):
    actions = np.zeros((5, 3, 14))
    actions[..., 6] = 0.5
    ctrl = twin.controls(actions)
    assert ctrl.shape == (5, 3, 16)
    # normalised 0 maps to 0.01844, below the finger's ctrlrange: clamped to 0.021
    assert np.all(ctrl[..., twin.actuator_names.index("right/left_finger")] == 0.021)
    np.testing.assert_allclose(ctrl[..., twin.actuator_names.index("left/left_finger")],
                               0.5 * (OPEN - CLOSE) + CLOSE, rtol=0, atol=1e-15)
    # joint targets beyond the ctrlrange are clamped too
    a = np.zeros(14)
    a[2] = 5.0
    assert twin.controls(a)[twin.actuator_names.index("left/elbow")] == pytest.approx(1.6057, abs=1e-12)


@pytest.mark.parametrize("width", [13, 15, 7])
def test_controls_wrong_width(twin, width):
    with pytest.raises(TrajectoryError, match=rf"expected actions with 14 values.*got {width}"):
        twin.controls(np.zeros((4, width)))


def test_channel_bounds_follow_joint_ranges(twin):
    assert twin.channel_lower.shape == (14,) and twin.channel_upper.shape == (14,)
    np.testing.assert_array_equal(twin.channel_normalised.nonzero()[0], [6, 13])
    assert (twin.channel_lower[[6, 13]] == 0).all() and (twin.channel_upper[[6, 13]] == 1).all()
    # elbow range from vx300s.xml
    assert twin.channel_lower[2] == pytest.approx(-1.76278, abs=1e-12)
    assert twin.channel_upper[9] == pytest.approx(1.6057, abs=1e-12)


# ---------------------------------------------------------------------------
# signals decoded from hand-made sensordata
# ---------------------------------------------------------------------------


def _sensor_rows(model, sensor_type, objid=None, refid=None):
    rows = []
    for s in range(model.nsensor):
        if model.sensor_type[s] != sensor_type:
            continue
        if objid is not None and model.sensor_objid[s] != objid:
            continue
        if refid is not None and model.sensor_refid[s] != refid:
            continue
        rows.append((int(model.sensor_adr[s]), int(model.sensor_dim[s])))
    return rows


def test_signals_from_hand_made_sensordata(twin):
    model = twin.model
    sd = np.zeros(twin.nsensordata)
    contact = mujoco.mjtSensor.mjSENS_CONTACT
    # left gripper: two contacts on its left pad, λn = (3, 1) N, λt = (1, 0.5) N
    (adr, dim), = _sensor_rows(model, contact, refid=model.geom("left/left_pad").id)
    assert dim == 4 * CONTACT_SLOTS  # found, normal, two tangential per slot
    sd[adr:adr + 4] = [2, 3.0, 0.6, 0.8]
    sd[adr + 4:adr + 8] = [2, 1.0, 0.3, -0.4]
    # support contact
    (adr_t, _), = _sensor_rows(model, contact, refid=model.geom("table").id)
    sd[adr_t] = 1
    # actuator forces: right/elbow at 7.5 of 15 N·m (FOS 2), a finger far above its limit
    frc = mujoco.mjtSensor.mjSENS_ACTUATORFRC
    names = twin.actuator_names
    for name, value in (("right/elbow", -7.5), ("left/waist", 1.0), ("right/left_finger", 100.0)):
        (a, _), = _sensor_rows(model, frc, objid=names.index(name))
        sd[a] = value

    sig = twin.signals(sd, mu=0.5)
    np.testing.assert_allclose(sig.fos_contact, [4.0 / 3.0, np.inf], rtol=1e-14)
    np.testing.assert_array_equal(sig.contact_gripper, [True, False])
    assert bool(sig.contact_support)
    # fingers are prismatic: they do not enter the motor FOS
    assert float(sig.fos_motor) == pytest.approx(2.0, rel=1e-15)
    assert names[int(sig.motor_argmax)] == "right/elbow"
    assert sig.actuator_norm[names.index("right/left_finger")] == pytest.approx(20.0, rel=1e-15)
    # the receiver (left) touches, the box is on the table: stage 3
    assert int(sig.stage) == 3
    p = twin.scenario.cost
    # on the support the grip carries nothing: only the motor term counts
    assert np.isposinf(sig.fos_grasp)
    assert float(sig.cost) == pytest.approx(p.B * math.exp(-p.beta * (2.0 - 1.0)), rel=1e-12)

    # lifted off the table, and the right gripper touches too, on its friction cone
    sd[adr_t] = 0
    (adr_r, _), = _sensor_rows(model, contact, refid=model.geom("right/right_pad").id)
    sd[adr_r:adr_r + 4] = [1, 2.0, 0.0, 1.0]
    sig = twin.signals(sd, mu=0.5)
    np.testing.assert_allclose(sig.fos_contact, [4.0 / 3.0, 1.0], rtol=1e-14)
    assert int(sig.stage) == 4
    # the grasp: eq. 12 over all five contacts: (3 + 1 + 2) / (2 + 1 + 2)
    assert float(sig.fos_grasp) == pytest.approx(6.0 / 5.0, rel=1e-14)
    expected_cost = p.A * math.exp(-p.alpha * 0.2) + p.B * math.exp(-p.beta * 1.0)
    assert float(sig.cost) == pytest.approx(expected_cost, rel=1e-12)
    # the nominal μ (1.0) is the default: FOS doubles
    assert float(twin.signals(sd).fos_grasp) == pytest.approx(12.0 / 5.0, rel=1e-14)
    # leading axes: (2, 3, nsensordata), μ per leading element
    mu = np.array([[0.5, 1.0, 0.25]] * 2)
    batch = twin.signals(np.broadcast_to(sd, (2, 3, sd.size)), mu=mu)
    assert batch.fos_contact.shape == (2, 3, 2) and batch.stage.shape == (2, 3)
    np.testing.assert_allclose(batch.fos_grasp, 6.0 / 5.0 * mu / 0.5, rtol=1e-14)


def test_signals_of_empty_sensordata(twin):
    sig = twin.signals(np.zeros((4, twin.nsensordata)))
    assert np.isposinf(sig.fos_contact).all() and np.isposinf(sig.fos_motor).all()
    np.testing.assert_array_equal(sig.cost, 0.0)
    np.testing.assert_array_equal(sig.stage, 0)
    # framelinacc reads 0 in free fall's frame: gravity is added back
    np.testing.assert_allclose(sig.object_acc, np.broadcast_to([0, 0, -G], (4, 3)), rtol=0, atol=1e-15)


# ---------------------------------------------------------------------------
# initial state
# ---------------------------------------------------------------------------


def test_initial_data_places_arms_and_object(twin):
    start = np.array([0.1, -0.9, 1.1, 0.0, -0.3, 0.2, 1.0, 0.0, -0.96, 1.16, 0.0, -0.3, 0.0, 0.0])
    pose = np.array([0.15, 0.45, 0.02, 1.0, 0.0, 0.0, 0.0])
    data = twin.initial_data(start=start, object_pose=pose)
    model = twin.model
    for i, j in enumerate(("waist", "shoulder", "elbow", "forearm_roll", "wrist_angle",
                           "wrist_rotate")):
        assert data.qpos[model.jnt_qposadr[model.joint(f"left/{j}").id]] == start[i]
        assert data.qpos[model.jnt_qposadr[model.joint(f"right/{j}").id]] == start[7 + i]
    # left gripper open (1.0 -> 0.058, clamped to the finger range 0.057)
    assert data.qpos[model.jnt_qposadr[model.joint("left/left_finger").id]] == pytest.approx(0.057, abs=1e-12)
    np.testing.assert_array_equal(data.qpos[twin.object_qposadr:twin.object_qposadr + 7], pose)
    np.testing.assert_array_equal(data.qvel, 0.0)
    np.testing.assert_array_equal(data.ctrl, twin.controls(start))
    np.testing.assert_allclose(data.xpos[twin.object_body_id], pose[:3], rtol=0, atol=1e-15)


def test_initial_data_rejects_bad_shapes(twin):
    with pytest.raises(TrajectoryError, match=r"object_pose \(7,\)"):
        twin.initial_data(object_pose=np.zeros(3))
    # the message names the trajectory's qpos0 and where the model's free joints sit (a
    # tool body added to the model said only "expected qpos0 of shape (23,), got (16,)")
    with pytest.raises(TrajectoryError, match=rf"the trajectory's qpos0: expected the model's "
                       rf"full joint positions, shape \({twin.model.nq},\), got \(5,\); the "
                       rf"model has \d+ joints, {twin.model.nq} coordinates, with free joint "
                       rf".* at qpos\[\d+:\d+\]"):
        twin.initial_data(qpos0=np.zeros(5))
    with pytest.raises(TrajectoryError, match="expected actions with 14 values"):
        twin.initial_data(start=np.zeros(6))


def test_state_round_trip(twin):
    data = twin.initial_data(start=np.zeros(14), object_pose=[0.1, 0.5, 0.02, 1, 0, 0, 0])
    _run(twin.model, data, 20)
    state = twin.get_state(twin.model, data)
    assert state.shape == (mujoco.mj_stateSize(twin.model, mujoco.mjtState.mjSTATE_INTEGRATION),)
    other = mujoco.MjData(twin.model)
    twin.set_state(twin.model, other, state)
    mujoco.mj_step(twin.model, data)
    mujoco.mj_step(twin.model, other)
    np.testing.assert_array_equal(twin.get_state(twin.model, other),
                                  twin.get_state(twin.model, data))


def test_carried_object_without_grip_is_falling(twin):
    # off the support and touched by no gripper: if the nominal run carries it here, it is
    # falling (FOS 0, the cost fails); if nobody carries it, there is no grip demand (inf)
    sd = np.zeros((2, twin.nsensordata))
    sig = twin.signals(sd, carried=np.array([True, False]))
    assert sig.fos_grasp[0] == 0.0 and np.isposinf(sig.fos_grasp[1])
    assert sig.cost[0] > twin.scenario.cost.threshold >= sig.cost[1]
    # the default (no nominal flags): carried only where a gripper holds it off the support
    assert np.isposinf(twin.signals(sd).fos_grasp).all()


def test_lifted_flags_keep_the_runs_that_rise():
    carried = np.array([0, 1, 1, 1, 0, 0, 1, 1, 1, 1, 0, 1], bool)
    height = np.array([0, 0, .001, .002, 0, 0, 0, .001, .003, .01, 0, 0.5])
    lifted = lifted_flags(carried, height)
    # a squeeze (rises 2 mm at most) is not a lift; a rise of 1 cm is; the last run has no
    # rise within it (it starts at its highest point)
    assert lifted.astype(int).tolist() == [0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 0, 0]
    assert not (lifted & ~carried).any()
    assert lifted_flags(carried, height, rise=0.02).sum() == 0
    # carried from the first step (a chunk that starts mid-carry): lifted before it began,
    # though it only goes down
    down = np.array([0.08, 0.07, 0.05, 0.03, 0.02, 0.02])
    assert lifted_flags(np.array([1, 1, 1, 1, 0, 0], bool), down).tolist() == [
        True, True, True, True, False, False]
    with pytest.raises(ParameterError, match=r"same shape \(T,\), got \(12,\) and \(11,\)"):
        lifted_flags(carried, height[:-1])


def test_a_compound_object_is_sensed_and_its_friction_varied_on_every_geom(tmp_path,
                                                                           demo_traj):
    """The bundled cube split into two halves (two geoms of one body; [object] geom names the
    upper one): the lower half's contacts with the table and the grip count too, and the
    friction parameter sets both halves. (With the named geom alone the cube never touched
    its support, and a gripped handle was never seen: SAFE over the whole box.)"""
    import shutil
    import warnings

    from critmoment.recording import rollout
    from critmoment.scenario import bundled_scenario_path

    folder = tmp_path / "split"
    shutil.copytree(bundled_scenario_path().parent, folder)
    xml = (folder / "scene.xml").read_text()
    cube = ('<geom name="box" type="box" size="0.02 0.02 0.02" mass="0.05" rgba="0.9 0.1 0.1 1"\n'
            '            contype="1" conaffinity="1" condim="4" priority="1" '
            'friction="1 0.005 0.0001"\n            solref="0.01 1"/>')
    assert xml.count(cube) == 1
    half = ('<geom name="{n}" type="box" size="0.02 0.02 0.01" pos="0 0 {z}" mass="0.025" '
            'contype="1" conaffinity="1" condim="4" priority="1" friction="1 0.005 0.0001" '
            'solref="0.01 1"/>')
    (folder / "scene.xml").write_text(xml.replace(
        cube, half.format(n="box", z=0.01) + "\n" + half.format(n="box_base", z=-0.01)))
    twin = Twin(load_scenario(folder))
    model = twin.model
    halves = [model.geom("box").id, model.geom("box_base").id]
    twin.write_parameters(model, np.array([[0.05, 0.4]]))
    np.testing.assert_array_equal(model.geom_friction[halves, 0], [0.4, 0.4])
    twin.write_parameters(model, twin.scenario.box.nominal[None, :])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rec = rollout(demo_traj, twin=twin)
    sig = rec.signals
    # at rest only the lower half touches the table
    assert sig.contact_support[0]
    assert rec.completed and sig.contact_gripper.any()


def test_a_zero_quaternion_in_qpos0_is_an_error(twin):
    """A full initial qpos whose free joint has a zero quaternion: MuJoCo would replace it
    by the identity without a word (the run then never touched the object)."""
    from critmoment.exceptions import TrajectoryError

    qpos0 = twin.model.qpos0.copy()
    adr = int(twin.model.jnt_qposadr[twin.model.body_jntadr[twin.object_body_id]]) + 3
    qpos0[adr:adr + 4] = 0.0
    with pytest.raises(TrajectoryError, match=r"qpos0: expected a unit quaternion \(w, x, y, "
                       rf"z\) for joint '.+' at qpos\[{adr}:{adr + 4}\], got \[0.0, 0.0, 0.0, "
                       r"0.0\] with norm 0"):
        twin.initial_data(qpos0=qpos0)
    qpos0[adr:adr + 4] = [1.0, 0.0, 0.0, 0.0]
    twin.initial_data(qpos0=qpos0)


def test_a_mass_range_mujoco_cannot_simulate_is_a_scenario_error(scenario):
    """A cube of 1e-12 kg at the low end of the box: MuJoCo finds its inertia singular
    (mjWARN_INERTIA) and every evaluation there diverged into an UNSAFE verdict; the twin
    now refuses the range, naming the parameter, the end and the warning."""
    from critmoment.exceptions import ScenarioError
    from critmoment.twin import Twin

    tiny = scenario.replace(box=scenario.box.with_range("mass", 1e-12, 1e-9, nominal=1e-9))
    with pytest.raises(ScenarioError, match=r"\[uncertainty.mass\]: at the low end of its "
                       r"range, 1e-12 kg, MuJoCo cannot simulate the model \(mjWARN_INERTIA"):
        Twin(tiny)
    Twin(scenario.replace(box=scenario.box.with_range("mass", 1e-6, 1e-3, nominal=1e-4)))


def test_a_qpos0_far_outside_a_joints_range_is_an_error(twin):
    """50 rad on the ±π waist diverged at step 6; now the joint is named."""
    from critmoment.exceptions import TrajectoryError

    qpos0 = twin.initial_data().qpos.copy()
    qpos0[twin.model.joint("left/waist").qposadr[0]] = 50.0
    with pytest.raises(TrajectoryError, match=r"joint 'left/waist' at 50 rad, outside its "
                       r"range \[-3.14158, 3.14158\]"):
        twin.initial_data(qpos0=qpos0)


def test_a_geared_servos_channel_spans_its_joints_range(tmp_path):
    # a position servo geared 2:1 holds its joint at ctrl / 2; with ctrl = 2·(joint
    # target) (init's scales = [2]) the channel's values are joint targets and span the
    # joint's own range, not half of it (valid targets were clipped, and the audit then
    # blamed the motors)
    xml = arm_xml().replace('joint="shoulder" kp="400"', 'joint="shoulder" gear="2" kp="400"')
    (tmp_path / "arm.xml").write_text(xml)
    (tmp_path / "scenario.toml").write_text(arm_scenario_toml(shoulder="scales = [2.0]"))
    twin = Twin(load_scenario(tmp_path))
    joint = math.radians(3.0)  # MJCF's default degrees
    np.testing.assert_allclose([twin.channel_lower[0], twin.channel_upper[0]], [-joint, joint])
    np.testing.assert_allclose([twin.channel_lower[1], twin.channel_upper[1]], [-joint, joint])
    # a target at the joint's end reaches the joint's end
    model = twin.model
    data = twin.initial_data()
    data.ctrl[:] = twin.controls(np.array([0.9 * joint, 0.0, 1.0]))
    for _ in range(2000):
        mujoco.mj_step(model, data)
    assert data.qpos[model.joint("shoulder").qposadr[0]] == pytest.approx(0.9 * joint, abs=2e-3)


def test_qpos0_and_start_that_disagree_are_warned_of(twin):
    """A file with both: qpos0 wins, and a start 0.3 rad away from it was dropped without a
    word (object_pose against qpos0 was warned of). A chunk with qpos0 and no start is not
    warned of: its first action, a target that leads the joint, is not a second start."""
    from critmoment.exceptions import CritmomentWarning
    from critmoment.recording import initial_state
    from critmoment.trajectory import Trajectory

    data = twin.initial_data(settle=False)
    qpos0 = data.qpos.copy()
    conv = twin.scenario.actions
    start = np.zeros(conv.width)
    for c, acts in enumerate(twin._chan_act):
        a = int(acts[0])
        j = twin.model.actuator_trnid[a, 0]
        start[c] = 1.0 if conv.normalised[c] else qpos0[twin.model.jnt_qposadr[j]]
    actions = np.tile(start, (10, 1))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        initial_state(twin, Trajectory(actions, fps=50.0, start=start, qpos0=qpos0))
    waist = conv.labels.index("left/waist")
    moved = start.copy()
    moved[waist] += 0.3
    with pytest.warns(CritmomentWarning, match=r"qpos0 and start disagree: joint 'left/waist' "
                                               r"at .* in qpos0, .* by start; the run starts "
                                               r"from qpos0"):
        initial_state(twin, Trajectory(actions, fps=50.0, start=moved, qpos0=qpos0))
    leading = actions.copy()
    leading[:, waist] += 0.3  # the first target leads the joint: no start was given
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        initial_state(twin, Trajectory(leading, fps=50.0, qpos0=qpos0))


def test_a_short_qpos0_beside_a_start_is_named(twin):
    """A qpos0 of 1-13 values beside a start (every demo file has one) crashed with an
    IndexError in the start comparison, before its length was checked."""
    from critmoment.exceptions import TrajectoryError
    from critmoment.recording import initial_state
    from critmoment.trajectory import Trajectory

    width = twin.scenario.actions.width
    traj = Trajectory(np.zeros((10, width)), fps=50.0, start=np.zeros(width),
                      qpos0=np.zeros(3))
    with pytest.raises(TrajectoryError, match=r"qpos0: expected the model's full joint "
                                              r"positions, shape \(23,\), got \(3,\)"):
        initial_state(twin, traj)


def test_qpos0_and_object_pose_that_disagree_are_warned_of(twin):
    """Both place the object; object_pose wins (a caller's override), silently until now,
    so a file whose two records disagree started from a pose the user did not check."""
    from critmoment.exceptions import CritmomentWarning

    qpos0 = twin.initial_data(settle=False).qpos.copy()
    adr = twin.object_qposadr
    pose = qpos0[adr:adr + 7].copy()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        twin.initial_data(qpos0=qpos0, object_pose=pose, settle=False)
    moved = pose.copy()
    moved[1] += 0.05
    with pytest.warns(CritmomentWarning, match=r"replaces the object's pose in qpos0.*differ "
                      r"by 50.0 mm and 0.0 deg; the run starts from object_pose"):
        data = twin.initial_data(qpos0=qpos0, object_pose=moved, settle=False)
    np.testing.assert_allclose(data.qpos[adr:adr + 7], moved)


def test_an_object_start_no_gripper_can_reach_is_an_error(twin):
    """An object pose in millimetres (446.3, 150, 568.6) ran 256 full rollouts into an
    UNSAFE verdict, "the object ends 494467 mm from the goal"; now the start is refused,
    naming how far the arms reach. A start merely out of reach (an object set aside on
    purpose) stays allowed: the nominal run warns that it is never touched."""
    far = np.array([446.3, 150.0, 568.6, 1.0, 0.0, 0.0, 0.0])
    with pytest.raises(TrajectoryError, match=r"the object starts at \(446.3, 150, 568.6\) m, "
                       r".* reaches at most [0-9.]+ m from there: no gripper can ever touch "
                       r"it, by far.*\(is it in mm\?\)"):
        twin.initial_data(object_pose=far, settle=False)
    twin.initial_data(object_pose=np.array([0.2, 0.5, 0.05, 1.0, 0.0, 0.0, 0.0]), settle=False)
    twin.initial_data(object_pose=np.array([3.0, 0.5, 0.05, 1.0, 0.0, 0.0, 0.0]), settle=False)


def test_a_gripper_that_opens_during_a_hold_is_letting_go(twin):
    """ACT's scripted hand-over opens the picker 0.95 s before the receiver touches the
    cube: the cube slid 5-6 mm down the opening fingers into the receiver, the hand-over
    succeeded, and the ground truth had counted a slip. The release is the opening that
    ends a hold, from its last rise through halfway; a grip that tightens, a command that
    jitters or opens partly and closes again, or stays partly open until a later release,
    is no release there (a cube falling out of a jittering grip had been called a success
    once its slip stopped counting)."""
    t = 1200
    conv = twin.scenario.actions
    right = twin._grip_channels[1][0]
    u = np.full(t, 0.3)
    u[100:200] = np.linspace(0.3, 0.05, 100)  # tightens
    u[200:400] = 0.05 + 0.2 * (np.arange(200) % 20 < 5)  # jitters past a tenth, and back
    u[400:500] = 0.35  # partly open, a while
    u[500:600] = np.linspace(0.35, 0.95, 100)  # the release, still touching
    u[600:] = 0.95
    u[800:] = 0.2  # a new hold after a gap, that never opens
    controls = twin.controls(np.zeros((t, conv.width)))
    for a, scale, offset in zip(twin._chan_act[right], conv.scales[right], conv.offsets[right],
                                strict=True):
        controls[:, a] = offset + scale * u
    touching = np.zeros((t, 2), bool)
    touching[50:650, 1] = True
    touching[300:310, 1] = False  # a flicker bridged
    touching[800:, 1] = True
    touching[:, 0] = True  # the left gripper's command never opens
    out = twin.letting_go(controls, touching)
    np.testing.assert_allclose(twin.gripper_opening(controls)[:, 1], u, atol=1e-12)
    assert not out[:, 0].any()
    # halfway from the tightest (0.05) to the release's opening (0.95) is 0.5
    first = int(np.flatnonzero(out[:, 1])[0])
    assert 520 <= first <= 530 and u[first] > 0.5 >= u[first - 1]
    assert out[first:650, 1].all() and not out[:first, 1].any() and not out[650:, 1].any()


def test_a_grasp_has_formed_once_the_gripper_command_has_closed(twin, demo_recording):
    """``Twin.grasp_formed``: from the first step after a hold's first touch at which the
    gripper's command has done all but GRASP_CLOSING of its closing and no longer tightens
    by GRASP_RATE within GRASP_SETTLE; a command that jitters reaches its lows within a few
    steps, and a later dip does not move the start."""
    from critmoment.twin import GRASP_CLOSING, GRASP_RATE, GRASP_SETTLE

    rec = demo_recording
    touching = rec.signals.contact_gripper
    formed = twin.grasp_formed(rec.controls, touching)
    opening = twin.gripper_opening(rec.controls)
    w = int(round(GRASP_SETTLE / rec.dt))
    for g in range(touching.shape[1]):
        touch = int(np.argmax(touching[:, g]))
        start = int(np.argmax(formed[:, g]))
        assert start >= touch and formed[start:, g].all()
        window = opening[touch:touch + int(1.0 / rec.dt), g]
        span = opening[:touch + 1, g].max() - window.min()
        assert opening[start, g] <= window.min() + GRASP_CLOSING * span
        assert opening[start:start + w, g].min() >= opening[start, g] - GRASP_RATE
    # the receiver touches the cube while its command is still closing: 0.4 s later
    receiver = twin.scenario.gripper_names.index(twin.task.receiver)
    touch = int(np.argmax(touching[:, receiver]))
    assert int(np.argmax(formed[:, receiver])) - touch > int(0.1 / rec.dt)
    # a jittering command (±0.15 of its range, every step) reaches its lows soon after
    plain = int(np.argmax(formed[:, receiver]))
    jitter = np.array(rec.controls, dtype=np.float64)
    acts = [a for c in twin._grip_channels[receiver] for a in twin._chan_act[c]]
    rng = np.random.default_rng(0)
    span = np.ptp(jitter[:, acts], axis=0)
    jitter[:, acts] += rng.uniform(-0.15, 0.15, (jitter.shape[0], len(acts))) * span
    noisy = twin.grasp_formed(jitter, touching)
    assert abs(int(np.argmax(noisy[:, receiver])) - plain) < int(0.1 / rec.dt)
    # a closed command that dips 2 % of its closing tighter 0.5 s later, once, does not
    # move the grasp's start there (it had: a Panda's slip during the lift went uncounted)
    dip = np.array(rec.controls, dtype=np.float64)
    opened, closed = dip[touch - int(0.5 / rec.dt), acts], dip[plain, acts]
    dip[plain + int(0.5 / rec.dt), acts] = closed + 0.02 * (closed - opened)
    assert (twin.gripper_opening(dip)[plain + int(0.5 / rec.dt), receiver]
            < twin.gripper_opening(rec.controls)[plain, receiver])
    assert int(np.argmax(twin.grasp_formed(dip, touching)[:, receiver])) == plain


def test_a_grasp_has_formed_once_the_fingers_have_stopped(twin, demo_recording):
    """With the run's readings, ``Twin.grasp_formed`` also waits for the fingers: no geom of
    the gripper moving more than FINGERS_STILL relative to its first within GRASP_SETTLE,
    up to GRASP_FORMING after the touch. Slow finger servos go on pushing the object after
    their command is done (a Wonik Allegro's for about 100 ms: 18 of 32 samples that held
    the ball were "slipped" by that push). The bundled ALOHA's fingers are still when its
    command has closed: the same steps as the command's rule."""
    from critmoment.twin import FINGERS_STILL, GRASP_FORMING, GRASP_SETTLE

    rec = demo_recording
    touching = rec.signals.contact_gripper
    plain = twin.grasp_formed(rec.controls, touching)
    sd = np.array(rec.sensordata, dtype=np.float64)
    np.testing.assert_array_equal(twin.grasp_formed(rec.controls, touching, sd), plain)
    receiver = twin.scenario.gripper_names.index(twin.task.receiver)
    start = int(np.argmax(plain[:, receiver]))
    adr = twin._finger_adr[receiver]
    assert adr.shape[0] == len(twin.scenario.grippers[receiver].geoms) - 1 >= 1
    # a finger that goes on closing 12 mm over the 0.2 s after the command's moment
    steps = int(round(0.2 / rec.dt))
    moving = sd.copy()
    ramp = np.clip((np.arange(sd.shape[0]) - start) / steps, 0.0, 1.0)
    moving[:, adr[0, 1]] += 0.012 * ramp
    late = int(np.argmax(twin.grasp_formed(rec.controls, touching, moving)[:, receiver]))
    w = int(round(GRASP_SETTLE / rec.dt))
    # the first step from which it moves at most FINGERS_STILL within the window
    speed = 0.012 / steps
    assert start + steps - FINGERS_STILL / speed - w - 1 <= late <= start + steps
    assert late > start + steps // 2
    # fingers that never stop within GRASP_FORMING of the touch: the command's moment stands
    creeping = sd.copy()
    creeping[:, adr[0, 1]] += 0.05 * np.arange(sd.shape[0]) * rec.dt
    never = twin.grasp_formed(rec.controls, touching, creeping)
    assert int(np.argmax(never[:, receiver])) == start
    assert GRASP_FORMING > 0.5
    with pytest.raises(ParameterError, match="sensordata"):
        twin.grasp_formed(rec.controls, touching, sd[1:])


def test_the_closing_window_starts_where_the_command_starts_closing(twin, demo_recording):
    """probe r36 (Shadow Hand): the palm touched the ball 0.3 s before the fingers began to
    close; a window of GRASP_FORMING counted from the touch ended inside the closing, and
    the grasp "formed" with the command still 22 % open. The window runs from where the
    command starts closing: a touch 0.9 s early leaves the receiver's grasp where it was, within
    GRASP_SETTLE."""
    rec = demo_recording
    touching = rec.signals.contact_gripper.copy()
    plain = twin.grasp_formed(rec.controls, touching)
    receiver = twin.scenario.gripper_names.index(twin.task.receiver)
    touch = int(np.argmax(touching[:, receiver]))
    start = int(np.argmax(plain[:, receiver]))
    opening = twin.gripper_opening(rec.controls)[:, receiver]
    early = touch - int(round(0.9 / rec.dt))
    assert opening[early] >= opening[:touch + 1].max() - 1e-9  # still wide open then
    touching[early:touch, receiver] = True
    moved = twin.grasp_formed(rec.controls, touching)
    # within the closing's last few steps (its window now ends 1 s after the closing's
    # start, a little before the real touch's); from the early touch it was 0.32 s early
    assert abs(int(np.argmax(moved[:, receiver])) - start) <= int(round(0.05 / rec.dt))


def test_grip_points_fix_the_object_up_to_its_own_symmetry():
    """The points whose motion in a grip is slip: a box's corners (a turn moves them), a
    capsule's axis ends, a spheroid's own axis ends, a sphere's centre only (its spin is not
    slip), in the body's frame with each geom's own pose; a body of many geoms falls back to
    the corners of their bounding box."""
    import mujoco

    from critmoment.twin import MAX_GRIP_POINTS, grip_points

    def points(geoms):
        xml = (f'<mujoco><worldbody><geom type="plane" size="1 1 .1"/><body pos="0 0 .2">'
               f'<freejoint/>{geoms}</body></worldbody></mujoco>')
        return grip_points(mujoco.MjModel.from_xml_string(xml), 1)

    box = points('<geom type="box" size="0.06 0.01 0.02"/>')
    assert box.shape == (9, 3) and np.array_equal(box[0], np.zeros(3))
    assert np.allclose(np.abs(box[1:]), [0.06, 0.01, 0.02])
    assert points('<geom type="sphere" size="0.03"/>').tolist() == [[0.0, 0.0, 0.0]]
    np.testing.assert_allclose(points('<geom type="sphere" size="0.01" pos="0 0 0.05"/>'),
                               [[0, 0, 0], [0, 0, 0.05]])
    capsule = points('<geom type="capsule" size="0.01 0.04" euler="90 0 0"/>')
    np.testing.assert_allclose(sorted(capsule[:, 1]), [-0.04, 0.0, 0.04], atol=1e-12)
    np.testing.assert_allclose(capsule[:, [0, 2]], 0.0, atol=1e-12)
    spheroid = points('<geom type="ellipsoid" size="0.02 0.02 0.05"/>')
    np.testing.assert_allclose(sorted(spheroid[:, 2]), [-0.05, 0.0, 0.05])
    many = points("".join(f'<geom type="box" size="0.01 0.01 0.01" pos="{0.03 * i} 0 0"/>'
                          for i in range(6)))
    assert len(many) == 9 < 6 * 8  # the origin and the 8 corners of all the boxes
    assert MAX_GRIP_POINTS < 6 * 8
    np.testing.assert_allclose(many[1:].min(axis=0), [-0.01, -0.01, -0.01])
    np.testing.assert_allclose(many[1:].max(axis=0), [0.16, 0.01, 0.01])


def test_a_ctrlrange_that_misses_its_joints_range_is_named(tmp_path):
    # a ctrlrange written in degrees under angle="degree" (MuJoCo converts joint ranges to
    # radians, never controls) leaves no value the channel may take: the error named only
    # "bounds: expected lower <= upper" when the trajectory was checked
    xml = arm_xml().replace('joint="shoulder" kp="400"',
                            'joint="shoulder" kp="400" ctrlrange="20 40"')
    (tmp_path / "arm.xml").write_text(xml)
    (tmp_path / "scenario.toml").write_text(arm_scenario_toml())
    with pytest.raises(ScenarioError, match=r"channel '.*shoulder.*' \(index 0\): expected its "
                                            r"actuators' ctrlrange and joint range to share "
                                            r".*actuator 'shoulder_act' "
                                            r"\(ctrlrange 20 40; joint 'shoulder' range "
                                            r"-0.0523599 0.0523599 compiled\)"):
        Twin(load_scenario(tmp_path))
