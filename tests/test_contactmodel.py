"""Tests of critmoment.contactmodel: a box pinched between two force-limited pads."""

from __future__ import annotations

import warnings

import mujoco
import numpy as np
import pytest

from critmoment import contactmodel as cm
from critmoment.exceptions import ParameterError


def _pinch_xml(cone: str, impratio: float, noslip: int = 0, solref: str = "0.02 1") -> str:
    """Two pads on slide joints, each pressed on a 4 cm box by a 10 N motor, under gravity;
    nothing else touches the box."""
    return f"""
<mujoco model="pinch">
  <option timestep="0.002" gravity="0 0 -9.81" cone="{cone}" impratio="{impratio}"
          noslip_iterations="{noslip}"/>
  <worldbody>
    <body name="hand" pos="0 0 0.3">
      <body name="left_finger" pos="-0.03 0 0">
        <joint name="left_slide" type="slide" axis="1 0 0" range="-0.02 0.02"/>
        <geom name="left_pad" type="box" size="0.01 0.02 0.02" mass="0.05" solref="{solref}"/>
      </body>
      <body name="right_finger" pos="0.03 0 0">
        <joint name="right_slide" type="slide" axis="-1 0 0" range="-0.02 0.02"/>
        <geom name="right_pad" type="box" size="0.01 0.02 0.02" mass="0.05" solref="{solref}"/>
      </body>
    </body>
    <body name="box" pos="0 0 0.3">
      <freejoint/>
      <geom name="box" type="box" size="0.02 0.02 0.02" mass="0.05" solref="{solref}"/>
    </body>
  </worldbody>
  <actuator>
    <motor name="left" joint="left_slide"/>
    <motor name="right" joint="right_slide"/>
  </actuator>
</mujoco>"""


def _held(xml: str) -> tuple[mujoco.MjModel, mujoco.MjData]:
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    data.ctrl[:] = 10.0
    for _ in range(50):  # let the pads close on the box
        mujoco.mj_step(model, data)
    return model, data


def _probe(xml: str, **options) -> cm.ContactModelReport:
    model, data = _held(xml)
    # slide axes are x: squeezing is not creep
    projector = np.diag([0.0, 1.0, 1.0])
    return cm.probe_contact_model(
        model, data, object_body="box", object_geom="box", pad_geoms=["left_pad", "right_pad"],
        anchor_body="hand", carry_time=2.0, projector=projector, **options)


def test_soft_contacts_creep_and_warn_hard_ones_do_not():
    with warnings.catch_warnings():
        warnings.simplefilter("error", cm.ContactModelWarning)
        hard = _probe(_pinch_xml("elliptic", 10), mass=0.3)
    with pytest.warns(cm.ContactModelWarning, match=r"creeps .* mm/s"):
        soft = _probe(_pinch_xml("pyramidal", 1), mass=0.3)
    # 20 N of squeeze at μ = 1 holds 0.3 kg with a force ratio of 6.8, yet the soft model
    # lets it creep; the hard one barely moves
    assert soft.creep_rate > 10 * hard.creep_rate
    assert soft.creep_rate * 2.0 > cm.DROP_TOLERANCE > hard.creep_rate * 2.0
    assert soft.soft and not hard.soft
    assert hard.creep_horizon == 0 and 1 < soft.creep_horizon <= cm.MAX_CREEP_HORIZON
    # sized so that the ground truth's 1 cm over the carry is 5 mm over the horizon (1 s),
    # at most MAX_CREEP_HORIZON steps
    assert soft.creep_horizon == min(cm.MAX_CREEP_HORIZON, round(2.0 * 0.005 / 0.01 / 0.002))
    codes = {f.code for f in soft.findings}
    assert {"pyramidal-cone", "low-impratio", "creep"} <= codes
    assert "creep" not in {f.code for f in hard.findings}
    assert "mm/s" in soft.summary() and "creep_horizon" in soft.summary()


def test_noslip_removes_the_creep():
    with warnings.catch_warnings():
        warnings.simplefilter("error", cm.ContactModelWarning)
        report = _probe(_pinch_xml("pyramidal", 1, noslip=10), mass=0.3)
    assert report.creep_rate < 1e-4 and not report.soft
    assert "noslip" in {f.code for f in report.findings}


def test_creep_grows_with_mass_and_the_default_probe_mass_is_the_fos_2_mass():
    light = _probe(_pinch_xml("pyramidal", 1), mass=0.1, warn=False)
    heavy = _probe(_pinch_xml("pyramidal", 1), mass=0.5, warn=False)
    assert heavy.creep_rate > 2 * light.creep_rate
    auto = _probe(_pinch_xml("pyramidal", 1), warn=False)
    # ΣFn ≈ 20 N, μ = 1: FOS 2 at 20 / (2 g) ≈ 1.02 kg
    assert auto.probe_mass == pytest.approx(20.0 / (2 * 9.81), rel=0.05)
    capped = _probe(_pinch_xml("pyramidal", 1), warn=False, max_mass=0.4)
    assert capped.probe_mass == pytest.approx(0.4)


def test_inspection_reports_soft_solref_and_pairs():
    model = mujoco.MjModel.from_xml_string(_pinch_xml("elliptic", 10, solref="0.05 1"))
    report = cm.inspect_contact_model(model, object_geom="box", pad_geoms=["left_pad",
                                                                          "right_pad"])
    assert report.cone == "elliptic" and report.impratio == 10
    np.testing.assert_allclose(report.solref, [[0.05, 1.0], [0.05, 1.0]])
    assert report.solimp.shape == (2, 5)
    assert "soft-solref" in {f.code for f in report.findings}
    assert not report.soft and np.isnan(report.creep_rate)
    with pytest.raises(ParameterError, match="pad_geoms"):
        cm.inspect_contact_model(model, object_geom="box", pad_geoms=[])


def test_bad_probe_options_raise():
    model, data = _held(_pinch_xml("elliptic", 10))
    with pytest.raises(ParameterError, match="carry_time"):
        cm.probe_contact_model(model, data, object_body="box", object_geom="box",
                               pad_geoms=["left_pad"], anchor_body="hand", carry_time=0.0)
    with pytest.raises(ParameterError, match="steps"):
        cm.measure_creep(model, data, object_body="box", anchor_body="hand", steps=1)


def test_bundled_demo_is_hard(twin, demo_recording):
    with warnings.catch_warnings():
        warnings.simplefilter("error", cm.ContactModelWarning)
        report = cm.check_contact_model(twin, demo_recording)
    assert report.cone == "elliptic" and report.impratio == 10
    assert np.isfinite(report.creep_rate) and not report.soft and report.creep_horizon == 0
    assert report.carry_time > 0.5 and 0 < report.probe_mass <= 10.0


def test_a_direct_solref_and_the_override_are_read_as_mujoco_uses_them():
    """solref="-500 -45" (stiffness, damping: a 0.047 s time constant) was not flagged
    soft, while "0.047 1" was; under the contact override the report showed the geoms'
    solref, which MuJoCo then ignores."""
    soft = mujoco.MjModel.from_xml_string(_pinch_xml("elliptic", 10, solref="-500 -45"))
    report = cm.inspect_contact_model(soft, object_geom="box", pad_geoms=["left_pad"])
    assert report.solref[0, 0] == pytest.approx(2.0 / (45 * 0.95))
    assert "soft-solref" in {f.code for f in report.findings}
    stiff = mujoco.MjModel.from_xml_string(_pinch_xml("elliptic", 10, solref="-11080 -210"))
    report = cm.inspect_contact_model(stiff, object_geom="box", pad_geoms=["left_pad"])
    assert report.solref[0, 0] == pytest.approx(0.01, rel=0.01)
    assert "soft-solref" not in {f.code for f in report.findings}
    xml = _pinch_xml("elliptic", 10).replace(
        'noslip_iterations="0"/>', 'noslip_iterations="0" o_solref="0.05 1"><flag '
                                   'override="enable"/></option>')
    over = mujoco.MjModel.from_xml_string(xml)
    report = cm.inspect_contact_model(over, object_geom="box", pad_geoms=["left_pad"])
    np.testing.assert_allclose(report.solref, [[0.05, 1.0]])


_SETTLING_XML = """
<mujoco model="settling">
  <option timestep="0.002" gravity="0 0 -9.81" cone="elliptic" impratio="10"/>
  <worldbody>
    <body name="hand" pos="0 0 0.3">
      <geom name="left_pad" type="box" size="0.01 0.02 0.02" pos="-0.03 0 0"
            contype="0" conaffinity="0"/>
      <geom name="right_pad" type="box" size="0.01 0.02 0.02" pos="0.03 0 0"
            contype="0" conaffinity="0"/>
      <body name="box">
        <joint name="sag" type="slide" axis="0 0 1" stiffness="200" damping="80"/>
        <geom name="box" type="box" size="0.02 0.02 0.02" mass="0.05"
              contype="0" conaffinity="0"/>
      </body>
    </body>
  </worldbody>
</mujoco>"""


def test_a_grip_that_settles_is_not_called_soft():
    """A load that sinks into its grip and stops (an overdamped 200 N/m spring: 12 mm with
    a time constant of 0.4 s) moves fast over the probe's second quarter-second. Its rate
    then was extrapolated over the whole carry (a 2F-85 under a new load: "20.3 mm/s, 123 mm
    over the 6.1 s carry", while its runs crept 0.2 mm/s). The rate is measured on while it
    keeps falling."""
    model = mujoco.MjModel.from_xml_string(_SETTLING_XML)
    data = mujoco.MjData(model)
    once = mujoco.MjModel.from_xml_string(_SETTLING_XML)
    cm._scale_mass(once, once.body("box").id, 0.3)
    first = cm.measure_creep(once, mujoco.MjData(once), object_body="box", anchor_body="hand")
    assert first * 2.0 > cm.DROP_TOLERANCE  # the first window alone: "soft"
    with warnings.catch_warnings():
        warnings.simplefilter("error", cm.ContactModelWarning)
        report = cm.probe_contact_model(
            model, data, object_body="box", object_geom="box",
            pad_geoms=["left_pad", "right_pad"], anchor_body="hand", carry_time=2.0,
            mass=0.3)
    assert not report.soft and report.creep_rate < 0.2 * first


def _panda_variant(folder, old: str, new: str, seed: int = 0, extra_qpos: str = ""):
    """A copy of the bundled Panda scenario with ``old`` (once in its scene) replaced by
    ``new`` (and ``extra_qpos`` appended to its keyframe, for an added free body); its twin
    and the demo's nominal run of ``seed`` in it."""
    import shutil

    import critmoment
    from critmoment import panda_demo
    from critmoment.scenario import bundled_scenario_path, load_scenario

    shutil.copytree(bundled_scenario_path("panda_pick_place").parent, folder)
    scene = folder / "scene.xml"
    text = scene.read_text()
    assert text.count(old) == 1
    text = text.replace(old, new)
    if extra_qpos:
        key = "0.5 -0.15 0.02 1 0 0 0"
        assert text.count(key) == 1
        text = text.replace(key, key + extra_qpos)
    scene.write_text(text)
    twin = critmoment.Twin(load_scenario(folder))
    return twin, critmoment.rollout(panda_demo.make_pick_place(seed, model=twin.model),
                                    twin=twin)


def test_a_nominal_grip_that_creeps_past_the_slip_tolerance_is_warned_of(tmp_path):
    """With a soft cube contact (solref 0.05) the bundled Panda's nominal cube moves about
    14 mm in its grip; slip counts beyond the nominal's own motion, so every sample could
    too and pass, and the contact-model check had said nothing (its probe: 2 mm)."""
    twin, rec = _panda_variant(tmp_path / "soft", 'solref="0.01 1"/>', 'solref="0.05 1"/>')
    with pytest.warns(cm.ContactModelWarning, match=r"the nominal run's own object moves "
                                                    r"1\d\.\d mm in the grip"):
        report = cm.check_contact_model(twin, rec)
    assert report.nominal_creep > 0.01
    assert "nominal-creep" in {f.code for f in report.findings}
    assert "slip is counted beyond that" in report.summary()


def test_an_object_that_slides_out_of_the_grip_onto_a_table_stays_soft():
    """The window-by-window probe kept the last rate: a Panda's mesh object slid out at 90.7
    mm/s in the first window and then lay on the table, at 0 mm/s, and the model was called
    rigid (the creep warning and the chains' slip watch gone). A rate measured while the
    object leaves the pads stands."""
    xml = _pinch_xml("pyramidal", 1).replace(
        "<worldbody>", '<worldbody>\\n    <geom name="floor" type="plane" pos="0 0 0.2" '
                       'size="1 1 0.1"/>')
    report = _probe(xml, mass=2.0, warn=False)
    assert report.soft and report.creep_rate * 2.0 > cm.DROP_TOLERANCE


def test_a_probe_at_the_solver_iteration_cap_is_no_creep_measure(tmp_path):
    """With iterations="3" the bundled Panda's creep probe read 423 mm/s ("1.67e+03 mm over
    the carry", soft) while the full run at that mass slips 9 mm: its solver stopped at the
    cap on most steps. The check says so instead of calling the model soft."""
    twin, rec = _panda_variant(tmp_path / "it3", 'impratio="10"/>',
                               'impratio="10" iterations="3"/>', seed=3)
    with pytest.warns(cm.ContactModelWarning, match="3-iteration cap"):
        report = cm.check_contact_model(twin, rec)
    assert "solver-cap" in {f.code for f in report.findings}
    assert not report.soft and "creeps" not in report.summary()


def test_a_nominal_collision_that_moves_the_object_in_the_grip_is_named(tmp_path):
    """A free 50 g bottle stands under the bundled Panda's carry path with its top 1.7 mm
    above the carried cube's bottom: the nominal cube knocks it over and moves 15 mm in its
    grip. The warning said only that the nominal grasp is not good enough (a soft contact's
    words), not that a collision did it; it now names what the object touched."""
    twin, rec = _panda_variant(
        tmp_path / "bottle", "  </worldbody>",
        '<body name="bottle" pos="0.507 0.0 0.06075"><freejoint/><geom name="bottle" '
        'type="box" size="0.02 0.02 0.06075" mass="0.05" condim="4" '
        'friction="1 0.005 0.0001"/></body>\n  </worldbody>',
        extra_qpos=" 0.507 0.0 0.06075 1 0 0 0")
    with pytest.warns(cm.ContactModelWarning, match=r"moves 1\d\.\d mm in the grip over its "
                                                    r"\S+ s hold, where it touches 'bottle'"):
        report = cm.check_contact_model(twin, rec)
    assert report.nominal_creep > 0.01


def test_nominal_creep_tells_a_turn_in_the_grip_from_a_slide():
    """probe r35 (OpenMANIPULATOR-X): the nominal cube pivoted about 60° in the fingers
    before its set-down, and the warning read "moves 61.4 mm in the grip" as if it had slid.
    ``_nominal_creep`` also gives the origin's displacement at the worst step: a turn about
    the fingers moves the object's corners far more than its middle."""
    from critmoment.twin import STATE_SPEC, grip_points

    model = mujoco.MjModel.from_xml_string("""<mujoco><worldbody>
      <body name="hand" pos="0 0 0.5"><geom type="box" size="0.01 0.01 0.01"/></body>
      <body name="cube" pos="0 0 0.4"><freejoint/><geom type="box" size="0.04 0.04 0.04"/>
      </body></worldbody></mujoco>""")
    data = mujoco.MjData(model)
    body, hand = model.body("cube").id, model.body("hand").id
    points = grip_points(model, body)
    states = []
    for angle in np.linspace(0.0, np.pi / 3, 5):   # a turn about the cube's own x axis
        data.qpos[3:7] = [np.cos(angle / 2), np.sin(angle / 2), 0.0, 0.0]
        mujoco.mj_forward(model, data)
        state = np.empty(mujoco.mj_stateSize(model, STATE_SPEC))
        mujoco.mj_getState(model, data, state, STATE_SPEC)
        states.append(state)
    states = np.array(states)
    moved, touched, origin = cm._nominal_creep(model, states, 0, np.arange(4), body, hand,
                                               np.eye(3), points)
    # states[k + 1] follows step k: from the state after step 0 (15°) to the last (60°)
    assert moved == pytest.approx(2 * 0.04 * np.sqrt(2) * np.sin(np.pi / 8), rel=1e-6)
    assert origin == pytest.approx(0.0, abs=1e-12) and touched == ()
    data.qpos[:] = model.qpos0
    slid = states.copy()
    for i in range(5):
        data.qpos[2] = 0.4 - 0.005 * i             # a slide down the fingers
        mujoco.mj_forward(model, data)
        mujoco.mj_getState(model, data, slid[i], STATE_SPEC)
    moved, _, origin = cm._nominal_creep(model, slid, 0, np.arange(4), body, hand,
                                         np.eye(3), points)
    assert moved == pytest.approx(0.015) and origin == pytest.approx(0.015)
