"""Tests for critmoment.scenario (TOML loading and validation) and critmoment.params."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import numpy as np
import pytest

from critmoment.exceptions import (
    InputFileError,
    ParameterError,
    ScenarioError,
)
from critmoment.params import (
    ComOffsetParameter,
    FrictionParameter,
    MassParameter,
    Prior,
    UncertaintyBox,
)
from critmoment.scenario import BUNDLED_SCENARIOS, Scenario, bundled_scenario_path, load_scenario
from critmoment.twin import Twin

BUNDLED = bundled_scenario_path().parent


def _copy(tmp_path: Path, edits: dict[str, list[tuple[str, str]]] | None = None,
          source: Path = BUNDLED) -> Path:
    """Copy a bundled scenario folder (default ALOHA's) to tmp_path and apply text
    replacements per file.

    Each (old, new) must occur exactly once in the file, so that a test cannot silently stop
    testing what it says when the bundled files change.
    """
    folder = tmp_path / "scn"
    shutil.copytree(source, folder)
    for name, pairs in (edits or {}).items():
        path = folder / name
        text = path.read_text()
        for old, new in pairs:
            assert text.count(old) == 1, f"{old!r} is not once in the bundled {name}"
            text = text.replace(old, new, 1)
        path.write_text(text)
    return folder


def _toml(tmp_path, *pairs):
    return _copy(tmp_path, {"scenario.toml": list(pairs)})


# ---------------------------------------------------------------------------
# the bundled scenario
# ---------------------------------------------------------------------------


def test_bundled_scenario_fields(scenario):
    assert isinstance(scenario, Scenario)
    assert scenario.name == "aloha_transfer_cube"
    assert scenario.mjcf.name == "scene.xml" and scenario.mjcf.is_file()
    assert scenario.keyframe == "home"
    assert (scenario.object_body, scenario.object_geom) == ("box", "box")
    assert scenario.gripper_names == ("left", "right")
    assert scenario.grippers[1].geoms == ("right/left_pad", "right/right_pad")
    assert scenario.support_geoms == ("table",)
    assert (scenario.task.kind, scenario.task.picker, scenario.task.receiver) == (
        "handover", "right", "left")
    assert scenario.actions.name == "aloha14" and scenario.actions.width == 14
    assert scenario.actions.labels[6] == "left/gripper"
    assert scenario.actions.labels[13] == "right/gripper"
    assert scenario.fps == 50.0 and scenario.range_policy == "error"
    # a short key matches the actuator of both arms
    assert scenario.limits["left/elbow"] == 15.0 and scenario.limits["right/elbow"] == 15.0
    assert scenario.limits["right/wrist_rotate"] == 1.0
    assert scenario.limits["left/right_finger"] == 5.0
    assert len(scenario.limits) == 16
    assert scenario.box.names == ("mass", "friction")
    np.testing.assert_array_equal(scenario.box.nominal, [0.05, 1.0])
    np.testing.assert_array_equal(scenario.box.low, [0.05, 0.2])
    np.testing.assert_array_equal(scenario.box.high, [10.0, 1.5])
    assert scenario.horizon == 10


def test_load_scenario_accepts_name_folder_and_file():
    by_default = load_scenario()
    for arg in ("aloha_transfer_cube", BUNDLED, BUNDLED / "scenario.toml", str(BUNDLED)):
        s = load_scenario(arg)
        assert s.mjcf == by_default.mjcf and s.limits == by_default.limits
        assert s.box == by_default.box


def test_bundled_scenario_path_unknown_name():
    assert BUNDLED_SCENARIOS == ("aloha_transfer_cube", "panda_pick_place")
    with pytest.raises(ScenarioError, match="unknown bundled scenario 'nope'.*aloha_transfer_cube"):
        bundled_scenario_path("nope")


def test_scenario_replace_box(scenario):
    narrowed = scenario.replace(box=scenario.box.with_range("mass", 0.1, 2.0, nominal=0.5))
    np.testing.assert_array_equal(narrowed.box.nominal, [0.5, 1.0])
    np.testing.assert_array_equal(scenario.box.nominal, [0.05, 1.0])  # the original is frozen


# ---------------------------------------------------------------------------
# files
# ---------------------------------------------------------------------------


def test_missing_scenario_file(tmp_path):
    with pytest.raises(InputFileError, match="scenario file not found.*nope.toml"):
        load_scenario(tmp_path / "nope.toml")
    # a folder without scenario.toml
    with pytest.raises(InputFileError, match="scenario file not found"):
        load_scenario(tmp_path)


def test_missing_mjcf(tmp_path):
    folder = _toml(tmp_path, ('mjcf = "scene.xml"', 'mjcf = "gone.xml"'))
    with pytest.raises(InputFileError, match=r"\[model\] mjcf: file not found: .*gone.xml"):
        load_scenario(folder)


def test_bad_toml(tmp_path):
    folder = _toml(tmp_path, ("[object]", "[object"))
    with pytest.raises(ScenarioError, match="not valid TOML"):
        load_scenario(folder)


def test_mjcf_that_does_not_compile(tmp_path):
    folder = _copy(tmp_path, {"scene.xml": [('type="box" size="0.02 0.02 0.02"',
                                             'type="box" size="oops"')]})
    with pytest.raises(ScenarioError, match="could not (compile|read) MJCF"):
        load_scenario(folder)


# ---------------------------------------------------------------------------
# structure
# ---------------------------------------------------------------------------


@pytest.mark.parametrize("old, new, message", [
    ('[object]\nbody = "box"\ngeom = "box"\n', "", "missing required key 'object'"),
    ('[model]\nmjcf = "scene.xml"', '[model]\nfile = "scene.xml"', r"\[model\]: unknown key 'file'; valid keys: mjcf, keyframe"),
    ('name = "aloha_transfer_cube"', 'colour = "red"\nname = "x"', r"scenario: unknown key 'colour'; valid keys: name"),
    ("threshold = 0.9", "threshold = 0.9\ngamma = 3.0", r"\[cost\]: unknown key 'gamma'; valid keys: A, B"),
    ('convention = "aloha14"', 'convention = "aloha16"', r"\[actions\] convention: expected one of"),
    ('range_policy = "error"', 'range_policy = "ignore"', r"\[actions\] range_policy"),
    ("fps = 50.0", "fps = 0.0", r"\[actions\] fps: expected a finite number > 0"),
    ("fps = 50.0", "fps = true", r"\[actions\] fps"),
    ('arms = ["left", "right"]', 'arms = ["left"]', "expected two arm prefixes"),
    ("gripper_close = 0.01844", "gripper_close = 0.07", "expected gripper_open > gripper_close"),
    ('picker = "right"', 'picker = "middle"', r"\[task\] picker: expected one of the grippers"),
    ("waist = 10.0", "waist = -1.0", r"\[limits\] waist: expected a finite force limit > 0"),
    ("waist = 10.0", "waist = inf", r"\[limits\] waist: expected a finite force limit > 0"),
    ("waist = 10.0", 'waist = "ten"', r"\[limits\] waist: expected a finite force limit > 0"),
    ('kind = "handover"', 'kind = "juggle"', r"\[task\] kind: expected one of handover, pick_place"),
    ('kind = "handover"', 'kind = ["handover"]', r"\[task\] kind: expected one of"),
    ('receiver = "left"', 'receiver = "right"', r"two different grippers for picker and receiver"),
    ('receiver = "left"', 'receiver = "left"\nreciever = "left"', r"\[task\]: unknown key 'reciever' \(did you mean 'receiver'\?\)"),
    ("horizon = 10", "horizn = 10", r"\[sparse\]: unknown key 'horizn' \(did you mean 'horizon'\?\)"),
    ('nominal = 0.05\nprior = "uniform"', 'nominal = 0.05\npriors = "loguniform"', r"\[uncertainty.mass\]: unknown key 'priors' \(did you mean 'prior'\?\)"),
    ('[model]\nmjcf = "scene.xml"', '[model]\nmjcf = "scene.xml"\nkeyfame = "home"', r"\[model\]: unknown key 'keyfame' \(did you mean 'keyframe'\?\)"),
    ('geoms = ["table"]', 'geoms = ["table"]\ngeom = "table"', r"\[support\]: unknown key 'geom'"),
    ('mjcf = "scene.xml"', "mjcf = 3", r"\[model\] mjcf: expected a string, got 3"),
    ("[object]\nbody", "object = \"box\"\n[objectx]\nbody", r"scenario: unknown key 'objectx'"),
    ("horizon = 10", 'horizon = "10"', r"\[sparse\] horizon: expected an integer"),
    ("horizon = 10", "horizon = 10\npersistence = -1.0", r"\[sparse\] persistence: expected a time >= 0"),
    ("threshold = 0.9", "threshold = 0.0", r"\[cost\] threshold: expected a finite number > 0"),
    ("threshold = 0.9", "threshold = 100.0", r"\[cost\] threshold: expected below the largest "
     r"cost the formula gives, A·exp\(α\) \+ B·exp\(β\) = 9.403 \(both factors of safety "
     r"at 0\), got 100.0: no grip and no motor could ever fail"),
    ("alpha = 0.7", "alpha = 1000.0", r"\[cost\] alpha: expected at most 50 .*got 1000.0"),
    ("waist = 10.0", 'waist = 10.0\n"left/waist" = 3.0',
     r"\[limits\] 'waist' = 10.0 and 'left/waist' = 3.0 both set actuator 'left/waist'; "
     r"expected one limit per actuator"),
    ("gripper_close = 0.01844", "gripper_close = -0.5",
     r"\[actions\] channel 'left/gripper': the closed \(action 0\) control of actuator "
     r"'left/left_finger' is -0.5, far outside its ctrlrange \[0.021, 0.057\]; expected "
     r"values in the actuator's own units"),
    # both ends past the same end of the range (within a width of it): MuJoCo clamps both
    # alike and the gripper never closes
    ("gripper_close = 0.01844", "gripper_close = 0.0575",
     r"\[actions\] channel 'left/gripper': actuator 'left/left_finger'\'s closed and open "
     r"controls \(0.0575, 0.058\) both lie beyond the same end of its ctrlrange \[0.021, "
     r"0.057\]; MuJoCo clamps both to 0.057 and the gripper never moves"),
    ('[uncertainty.friction]\ngeom = "box"',
     '[uncertainty.mass2]\nkind = "mass"\nbody = "box"\nrange = [0.05, 1.0]\nnominal = 0.1\n'
     '[uncertainty.friction]\ngeom = "box"',
     r"\[uncertainty.mass2\] and \[uncertainty.mass\]: both vary mass of 'box'; expected one "
     r"parameter per quantity"),
    ("horizon = 10", "horizon = 0", r"\[sparse\] horizon: expected an integer >= 1"),
])
def test_malformed_scenario(tmp_path, old, new, message):
    folder = _toml(tmp_path, (old, new))
    with pytest.raises(ScenarioError, match=message):
        load_scenario(folder)


def test_missing_task_is_an_error(tmp_path):
    text = (BUNDLED / "scenario.toml").read_text()
    start, end = text.index("[task]"), text.index("# Force limits")
    folder = _toml(tmp_path, (text[start:end], ""))
    with pytest.raises(ScenarioError, match=r"missing \[task\] table; expected kind = one of "
                                            r"handover, pick_place, pick_hold"):
        load_scenario(folder)
    folder = _toml(tmp_path / "b", ('kind = "handover"     # handover | pick_place | pick_hold '
                                    '(critmoment.task)\n', ""))
    with pytest.raises(ScenarioError, match=r"\[task\]: missing kind"):
        load_scenario(folder)


def test_empty_grippers_table(tmp_path):
    text = (BUNDLED / "scenario.toml").read_text()
    start, end = text.index("[grippers.left]"), text.index("[support]")
    folder = _toml(tmp_path, (text[start:end], ""),
                   ('name = "aloha_transfer_cube"', 'grippers = {}\nname = "x"'))
    with pytest.raises(ScenarioError, match=r"\[grippers\]: expected at least one"):
        load_scenario(folder)


# ---------------------------------------------------------------------------
# names checked against the model
# ---------------------------------------------------------------------------


def test_unknown_gripper_geom_lists_valid_names(tmp_path):
    folder = _toml(tmp_path, ('"left/left_pad", "left/right_pad"', '"left/left_pad", "left/thumb"'))
    with pytest.raises(ScenarioError, match="unknown geom 'left/thumb'") as info:
        load_scenario(folder)
    msg = str(info.value)
    assert "[grippers.left] geoms: unknown geom 'left/thumb'" in msg
    for valid in ("left/left_pad", "right/right_pad", "table", "box"):
        assert valid in msg


@pytest.mark.parametrize("edit, message", [
    (('body = "box"\ngeom', 'body = "cube"\ngeom'),
     r"\[object\] body: unknown body 'cube'; valid names: .*box"),
    (('geoms = ["table"]', 'geoms = ["floor"]'), r"\[support\] geoms: unknown geom 'floor'.*table"),
    (("waist = 10.0", "waist = 10.0\nhip = 3.0"),
     r"\[limits\] 'hip' matches no actuator \(by name, or by the joint/tendon it drives\); "
     r"actuators: left/waist \(position on joint left/waist\)"),
    (('keyframe = "home"', 'keyframe = "away"'), r"unknown keyframe 'away'; valid: home or an index"),
    (('[uncertainty.mass]\nbody = "box"', '[uncertainty.mass]\nbody = "brick"'),
     r"\[uncertainty\.mass\]: unknown body 'brick'; the model has: .*box"),
], ids=["object body", "support geom", "limit actuator", "keyframe",
        "parameter target"])
def test_unknown_names_say_what_is_valid(tmp_path, edit, message):
    folder = _toml(tmp_path, edit)
    with pytest.raises(ScenarioError, match=message):
        load_scenario(folder)


# ---------------------------------------------------------------------------
# the uncertainty box in the scenario
# ---------------------------------------------------------------------------


@pytest.mark.parametrize("old, new, message", [
    ("range = [0.05, 10.0]", "range = [10.0, 0.05]", "expected range low < high"),
    ("range = [0.05, 10.0]", "range = [0.05, 0.05]", "expected range low < high"),
    ("range = [0.05, 10.0]", "range = [-1.0, 10.0]", r"expected values > 0.0 kg"),
    ("range = [0.05, 10.0]", "range = [0.05, 10.0, 3.0]", r"range: expected \[low, high\]"),
    ("range = [0.05, 10.0]", 'range = "wide"', r"range: expected \[low, high\]"),
    ("nominal = 0.05", "nominal = 20.0", "expected nominal inside the range"),
    ("nominal = 0.05", 'nominal = "light"', "nominal: expected"),
    ('nominal = 0.05\nprior = "uniform"', 'nominal = 0.05\nprior = "normal"', r"prior: expected one of \['uniform', 'loguniform'\]"),
    ("[uncertainty.mass]", "[uncertainty.weight]", "unknown parameter kind 'weight'"),
    ('[uncertainty.mass]\nbody = "box"', '[uncertainty.mass]\nbody = 3', r'expected body = "<name>"'),
])
def test_bad_uncertainty(tmp_path, old, new, message):
    folder = _toml(tmp_path, (old, new))
    with pytest.raises(ScenarioError, match=r"\[uncertainty\.(mass|weight)\].*" + message):
        load_scenario(folder)


@pytest.mark.parametrize("body, message", [
    ("table", r"body 'table' is fixed to the world .* changes nothing"),
    ("world", r"body 'world' is fixed to the world"),
    ("left/base_link", r"body 'left/base_link' is fixed to the world"),
])
def test_a_mass_on_a_body_that_cannot_move_is_rejected(tmp_path, body, message):
    folder = _toml(tmp_path, ('[uncertainty.mass]\nbody = "box"',
                              f'[uncertainty.mass]\nbody = "{body}"'))
    with pytest.raises(ScenarioError, match=r"\[uncertainty\.mass\]: " + message):
        load_scenario(folder)


def test_a_mass_on_an_arm_link_is_accepted(tmp_path):
    folder = _toml(tmp_path, ('[uncertainty.mass]\nbody = "box"',
                              '[uncertainty.mass]\nbody = "left/wrist_link"'))
    assert load_scenario(folder).box.parameters[0].target == "left/wrist_link"


def test_named_parameter_with_kind(tmp_path):
    folder = _toml(tmp_path, ('[uncertainty.mass]\nbody = "box"',
                              '[uncertainty.payload]\nkind = "mass"\nbody = "box"'))
    s = load_scenario(folder)
    assert s.box.names == ("payload", "friction")
    assert isinstance(s.box.parameters[0], MassParameter)


def test_friction_parameter_works_on_the_model_as_shipped(tmp_path):
    """The shipped MJCF gives the cube no priority: MuJoCo would mix friction with max() and
    the parameter could not lower it. Raising the cube's priority would also give its
    condim and solver parameters to every contact it makes, so critmoment's copy makes each
    of the cube's contacts an explicit pair with the parameters MuJoCo gives it, and the
    parameter writes their friction."""
    import mujoco

    from critmoment import actuators as act_info

    folder = _copy(tmp_path, {"scene.xml": [('priority="1"', 'priority="0"')]})
    plain = mujoco.MjModel.from_xml_path(str(folder / "scene.xml"))
    twin = Twin(load_scenario(folder))
    model = twin.copy_model()
    box = model.geom("box").id
    partners = act_info.dynamic_partners(plain, plain.geom("box").id)
    assert len(act_info.geom_pairs(model, [box])) == len(partners) > 10
    assert model.geom_priority[box] == 0
    twin.write_parameters(model, [[0.05, 0.3]])
    data = twin.initial_data(start=np.zeros(14), model=model)
    mujoco.mj_forward(model, data)
    table = [c for c in data.contact[:data.ncon] if box in (c.geom1, c.geom2)]
    assert table
    mixed = act_info.contact_parameters(plain, plain.geom("box").id, plain.geom("table").id)
    for c in table:
        assert c.friction[0] == c.friction[1] == 0.3
        assert tuple(c.solref) == mixed.solref and tuple(c.solimp) == mixed.solimp
        assert c.dim == mixed.condim


def test_friction_parameter_on_a_geom_that_never_wins_is_rejected(tmp_path):
    # a pad's friction loses to the cube's priority: its costs could not change
    folder = _toml(tmp_path, ('[uncertainty.friction]\ngeom = "box"',
                              '[uncertainty.friction]\ngeom = "left/left_pad"'))
    with pytest.raises(ScenarioError, match=r"friction of geom 'left/left_pad' never governs its "
                                            r"contacts"):
        load_scenario(folder)


def test_a_pads_friction_that_governs_its_grip_is_accepted_beside_an_equal_pad(tmp_path):
    """Both pads of one priority above the cube's (symmetric rubber pads): the left pad's
    friction governs every pad-cube contact, its only rival being the other pad, whose
    contact with it is not the grip's; it was refused as "never governs its contacts"."""
    text = (BUNDLED / "scenario.toml").read_text()
    start = text.index("[uncertainty.friction]")
    end = text.index("\n\n", start)
    pad = '[uncertainty.friction]\ngeom = "left/left_pad"\nrange = [0.3, 1.5]\nnominal = 1.0'
    folder = _copy(tmp_path, {
        "vx300s.xml": [('name="left_pad" class="finger"', 'name="left_pad" class="finger" '
                        'priority="3"'),
                       ('name="right_pad" class="finger"', 'name="right_pad" class="finger" '
                        'priority="3"')],
        "scenario.toml": [(text[start:end], pad)]})
    sc = load_scenario(folder)
    assert sc.box.names == ("mass", "friction")


def test_friction_parameter_without_priority_is_fine_without_friction_parameter(tmp_path):
    text = (BUNDLED / "scenario.toml").read_text()
    start = text.index("[uncertainty.friction]")
    end = text.index("\n\n", start)
    folder = _copy(tmp_path, {"scene.xml": [('priority="1"', 'priority="0"')],
                              "scenario.toml": [(text[start:end], "")]})
    assert load_scenario(folder).box.names == ("mass",)


# ---------------------------------------------------------------------------
# validation gaps (these tests document bugs found while writing them)
# ---------------------------------------------------------------------------


def test_empty_support_list_is_rejected(tmp_path):
    # BUG: an empty [support] geoms list loads, and Twin.signals then fails with an IndexError
    # (np.array([]) of float64 used as an index); the task stages need a support.
    folder = _toml(tmp_path, ('geoms = ["table"]', "geoms = []"))
    with pytest.raises(ScenarioError, match=r"\[support\] geoms"):
        twin = Twin(load_scenario(folder))
        twin.signals(np.zeros(twin.nsensordata))


@pytest.mark.parametrize("old, new, where", [
    ("beta = 2.0", 'beta = "steep"', r"\[cost\] beta"),
    ("horizon = 10", 'horizon = "two" ', r"\[sparse\] horizon"),
    ("horizon = 10", "horizon = 1.5 ", r"\[sparse\] horizon"),
    ('keyframe = "home"', "keyframe = 3", r"\[model\] keyframe"),
])
def test_wrongly_typed_values_raise_scenario_error(tmp_path, old, new, where):
    # BUG: these raise a bare ValueError/TypeError (or truncate 1.5 to 1) instead of a
    # ScenarioError that names the key.
    folder = _toml(tmp_path, (old, new))
    with pytest.raises(ScenarioError, match=where):
        load_scenario(folder)


def test_duplicate_gripper_geom_is_a_scenario_error(tmp_path):
    # BUG: a geom listed twice loads, and Twin() fails with MuJoCo's bare ValueError
    # "repeated name 'critmoment:grip:left:left/left_pad' in sensor".
    folder = _toml(tmp_path, ('"left/left_pad", "left/right_pad"', '"left/left_pad", "left/left_pad"'))
    with pytest.raises(ScenarioError, match="left/left_pad"):
        Twin(load_scenario(folder))


def test_object_body_must_be_free(tmp_path):
    # BUG: a jointless object body loads; Twin.object_qposadr is then jnt_qposadr[-1], the
    # address of whatever joint comes last, and initial_data(object_pose=...) writes the
    # object's pose into that joint's qpos.
    folder = _toml(tmp_path, ('[uncertainty.mass]\nbody = "box"', '[uncertainty.mass]\nbody = "table"'),
                   ('body = "box"\ngeom = "box"', 'body = "table"\ngeom = "table"'),
                   ('[uncertainty.friction]\ngeom = "box"', '[uncertainty.com_offset]\nbody = "box"'),
                   ("range = [0.2, 1.5]", "range = [-0.01, 0.01]"), ("nominal = 1.0", "nominal = 0.0"))
    with pytest.raises(ScenarioError, match=r"\[object\] body.*free joint"):
        Twin(load_scenario(folder))


def test_object_geom_must_belong_to_object_body(tmp_path):
    # BUG: [object] geom is not checked against [object] body; the contact sensors then
    # watch a geom of another body.
    text = (BUNDLED / "scenario.toml").read_text()
    start = text.index("[uncertainty.friction]")
    end = text.index("\n\n", start)
    folder = _toml(tmp_path, ('body = "box"\ngeom = "box"', 'body = "box"\ngeom = "left/base"'),
                   (text[start:end], ""))
    with pytest.raises(ScenarioError, match=r"\[object\] geom"):
        load_scenario(folder)


# ---------------------------------------------------------------------------
# params: parameters and the uncertainty box
# ---------------------------------------------------------------------------


@pytest.mark.parametrize("kwargs, message", [
    (dict(low=1.0, high=1.0, nominal=1.0), "expected range low < high"),
    (dict(low=0.0, high=1.0, nominal=0.5), r"expected values > 0.0 kg"),
    (dict(low=0.1, high=1.0, nominal=2.0), "expected nominal inside the range"),
    (dict(low=0.1, high=np.inf, nominal=0.5), "expected finite range and nominal"),
    (dict(low=np.nan, high=1.0, nominal=0.5), "expected finite range and nominal"),
])
def test_mass_parameter_validation(kwargs, message):
    with pytest.raises(ParameterError, match=message):
        MassParameter(name="mass", target="box", **kwargs)


def test_loguniform_prior_needs_positive_low():
    with pytest.raises(ParameterError, match="log-uniform prior needs low > 0"):
        ComOffsetParameter(name="com", target="box", low=-0.01, high=0.01, nominal=0.0,
                           prior=Prior.LOGUNIFORM)


def _box():
    return UncertaintyBox((
        MassParameter("mass", "box", 0.05, 10.0, 0.05, Prior.LOGUNIFORM),
        FrictionParameter("friction", "box", 0.2, 1.5, 1.0),
    ))


def test_box_unit_mapping_round_trip():
    box = _box()
    u = np.random.default_rng(3).uniform(size=(50, 2))
    x = box.from_unit(u)
    np.testing.assert_allclose(box.to_unit(x), u, rtol=0, atol=1e-12)
    # ends and hand values: log-uniform midpoint is the geometric mean
    ends = box.from_unit(np.array([[0.0, 0.0], [1.0, 1.0], [0.5, 0.5]]))
    np.testing.assert_allclose(ends[0], [0.05, 0.2], rtol=1e-12)
    np.testing.assert_allclose(ends[1], [10.0, 1.5], rtol=1e-12)
    np.testing.assert_allclose(ends[2], [np.sqrt(0.05 * 10.0), 0.85], rtol=1e-12)


def test_box_corners_index_and_with_range():
    box = _box()
    np.testing.assert_array_equal(box.corners(),
                                  [[0.05, 0.2], [0.05, 1.5], [10.0, 0.2], [10.0, 1.5]])
    assert box.index("friction") == 1 and box.ndim == 2
    with pytest.raises(ParameterError, match="unknown parameter 'colour'; the box has mass, friction"):
        box.index("colour")
    narrowed = box.with_range("friction", 0.5, 0.9, nominal=0.7)
    np.testing.assert_array_equal(narrowed.low, [0.05, 0.5])
    np.testing.assert_array_equal(narrowed.nominal, [0.05, 0.7])
    with pytest.raises(ParameterError, match="expected nominal inside the range"):
        box.with_range("friction", 0.1, 0.5)  # the nominal 1.0 falls outside


def test_box_check_samples():
    box = _box()
    out = box.check_samples([[1, 1]])
    assert out.dtype == np.float64 and out.flags.c_contiguous and out.shape == (1, 2)
    with pytest.raises(ParameterError, match=r"expected samples of shape \(n, 2\).*got shape \(3,\)"):
        box.check_samples([1.0, 2.0, 3.0])
    with pytest.raises(ParameterError, match=r"'friction': expected finite values > 0.0"):
        box.check_samples([[1.0, 0.0]])
    with pytest.raises(ParameterError, match="names must be unique"):
        UncertaintyBox((box.parameters[0], box.parameters[0]))


def _panda(tmp_path: Path, *pairs: tuple[str, str]) -> Path:
    """A copy of the bundled Panda scenario (explicit channels) with text replacements."""
    return _copy(tmp_path, {"scenario.toml": list(pairs)},
                 source=bundled_scenario_path("panda_pick_place").parent)


def test_an_actuator_in_two_channels_is_a_scenario_error(tmp_path):
    # a copy-paste slip: joint2 twice, joint3 driven by nothing; it used to load and audit
    # a motion the policy never commanded (UNSAFE, blaming the object)
    folder = _panda(tmp_path, ('actuators = ["joint3"]', 'actuators = ["joint2"]'))
    with pytest.raises(ScenarioError, match=r"'joint2' is driven by two channels \(#1 "
                                            r"'joint2' and #2 'joint3'\)"):
        load_scenario(folder)


def test_an_actuator_no_channel_drives_is_named_in_a_warning(tmp_path):
    from critmoment.scenario import ScenarioWarning

    folder = _panda(tmp_path, ('[[actions.channel]]\nactuators = ["joint7"]\nlabel = "joint7"\n',
                               ""))
    with pytest.warns(ScenarioWarning, match=r"no channel drives actuator\(s\) \['joint7'\]"):
        sc = load_scenario(folder)
    assert sc.actions.width == 7
    assert sc.undriven_actuators(Twin(sc).model) == ("joint7",)


@pytest.mark.parametrize("name", BUNDLED_SCENARIOS)
def test_bundled_scenarios_drive_every_actuator(name):
    sc = load_scenario(name)
    assert sc.undriven_actuators(Twin(sc).model) == ()


@pytest.mark.parametrize("old, new, message", [
    ('geoms = ["left/left_pad", "left/right_pad"]', 'geoms = ["box"]',
     r"\[grippers.left\]: geoms \['box'\] belong to the object body 'box'"),
    ('[support]\ngeoms = ["table"]', '[support]\ngeoms = ["table", "box"]',
     r"\[support\]: geoms \['box'\] belong to the object body"),
    ('[support]\ngeoms = ["table"]', '[support]\ngeoms = ["table", "left/left_pad"]',
     r"\[grippers.left\] and \[support\]: geoms \['left/left_pad'\] are in both"),
    ('geoms = ["right/left_pad", "right/right_pad"]', 'geoms = ["right/left_pad", "left/left_pad"]',
     r"\[grippers.left\] and \[grippers.right\]: geoms \['left/left_pad'\] are in both"),
])
def test_object_grippers_and_supports_are_different_geoms(tmp_path, old, new, message):
    # a gripper made of the object itself loaded and audited SAFE (contact FOS inf: the
    # object never touches "its gripper"), exit 0
    with pytest.raises(ScenarioError, match=message):
        load_scenario(_toml(tmp_path, (old, new)))


def test_cost_weights_that_fail_a_comfortable_grip_are_warned_of():
    """A = 1000 (α 0.7, threshold 0.9): the contact term alone reaches the threshold at a
    contact factor of safety of 11, every grip fails and the contact term is then set aside
    as chatter; the scenario warns with the number. The bundled weights reach it at 1.15
    (contact) and 1.05 (motor)."""
    import warnings

    from critmoment.scenario import CostParams, ScenarioWarning

    with pytest.warns(ScenarioWarning, match=r"the contact term alone reaches the threshold "
                      r"0.9 at a contact factor of safety of 11 \(A = 1000, α = 0.7\): a "
                      r"contact with 11× margin counts as failing"):
        CostParams(A=1000.0, B=1.0, alpha=0.7, beta=2.0, threshold=0.9)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        cost = CostParams(A=1.0, B=1.0, alpha=0.7, beta=2.0, threshold=0.9)
    assert cost.failing_fos("contact") == pytest.approx(1.0 + np.log(1 / 0.9) / 0.7)
    assert 1.0 < cost.failing_fos("motor") < 1.06


def test_a_force_limit_on_a_hinge_is_a_torque_and_on_a_slide_a_force(tmp_path):
    """The unit a force limit prints with comes from the actuator's joint: N·m for the
    shoulder's hinge (it printed "shoulder_limit ≥ 19.5 N"), N for a finger's slide."""
    from critmoment.scenario import load_scenario

    folder = _toml(tmp_path, ('[uncertainty.friction]\ngeom = "box"',
                              '[uncertainty.shoulder]\nkind = "force_limit"\n'
                              'actuator = "right/shoulder"\nrange = [5.0, 20.0]\nnominal = 20.0\n'
                              '[uncertainty.grip]\nkind = "force_limit"\n'
                              'actuator = "right/left_finger"\nrange = [2.0, 8.0]\nnominal = 5.0\n'
                              '[uncertainty.friction]\ngeom = "box"'))
    units = {p.name: p.unit for p in load_scenario(folder).box.parameters}
    assert units["shoulder"] == "N·m" and units["grip"] == "N"
    box = load_scenario(folder).box.with_range("shoulder", 10.0, 20.0)
    assert box.parameters[box.index("shoulder")].unit == "N·m"


def test_a_joint_actuatorfrcrange_under_the_forcerange_is_the_limit(tmp_path):
    """A joint's actuatorfrcrange 50 under its actuator's forcerange 87: MuJoCo holds the
    joint at 50 N·m, and the motor checks read 87 (twenty-fifth round). [limits] of 87
    above it is warned of, the gear named where the actuator has one."""
    from critmoment.scenario import ScenarioWarning

    j2 = '<joint name="joint2" axis="0 0 1" range="-1.7628 1.7628"/>'
    limited = j2.replace('/>', ' actuatorfrcrange="-50 50"/>')
    folder = _copy(tmp_path / "mjcf", {"panda.xml": [(j2, limited)],
                                       "scenario.toml": [("joint2 = 87.0\n", "")]},
                   source=bundled_scenario_path("panda_pick_place").parent)
    sc = load_scenario(folder)
    assert sc.limits["joint2"] == 50.0 and sc.limit_sources["joint2"] == "mjcf"
    folder = _copy(tmp_path / "rated", {"panda.xml": [(j2, limited)]},
                   source=bundled_scenario_path("panda_pick_place").parent)
    with pytest.warns(ScenarioWarning, match=r"\[limits\] joint2 = 87 \(actuator 'joint2' "
                      r"gives at most 50\): above what"):
        load_scenario(folder)
    servo = '<position name="joint2" joint="joint2" kp="4500" kv="450" forcerange="-87 87"'
    geared = ('<position name="joint2" joint="joint2" gear="50" kp="1.8" kv="0.18" '
              'forcerange="-1.74 1.74"')
    folder = _copy(tmp_path / "geared", {"panda.xml": [(servo, geared)]},
                   source=bundled_scenario_path("panda_pick_place").parent)
    with pytest.warns(ScenarioWarning, match=r"a joint rating R is R / gear there "
                      r"\('joint2' gear 50: 87 / 50 = 1.74\)"):
        load_scenario(folder)


def test_a_force_limit_on_a_geared_actuator_says_its_unit(tmp_path):
    """A force_limit on a gear-50 hinge actuator is in the actuator's units: 0.94 of them
    are 47 N·m at the joint; it printed "≥ 0.94 N·m"."""
    servo = '<position name="joint2" joint="joint2" kp="4500" kv="450" forcerange="-87 87"'
    geared = ('<position name="joint2" joint="joint2" gear="50" kp="1.8" kv="0.18" '
              'forcerange="-1.74 1.74"')
    folder = _copy(tmp_path, {"panda.xml": [(servo, geared)], "scenario.toml": [
        ("joint2 = 87.0\n", ""),
        ("[uncertainty.friction]", '[uncertainty.j2]\nkind = "force_limit"\nactuator = '
         '"joint2"\nrange = [0.5, 1.74]\nnominal = 1.74\n[uncertainty.friction]')]},
        source=bundled_scenario_path("panda_pick_place").parent)
    sc = load_scenario(folder)
    assert sc.box.parameters[sc.box.index("j2")].unit == "×50 N·m"


def test_a_friction_range_beyond_real_materials_is_warned_of(tmp_path):
    from critmoment.scenario import ScenarioWarning, load_scenario

    folder = _toml(tmp_path, ("range = [0.2, 1.5]", "range = [0.2, 1e6]"))
    with pytest.warns(ScenarioWarning, match=r"\[uncertainty.friction\] range: a sliding "
                      r"friction coefficient up to 1e\+06 is far beyond real materials"):
        load_scenario(folder)


@pytest.mark.parametrize("goal", ["[500.0, 150.0, 20.0]", "[0.5, 0.15, 1.5]",
                                  "[-1.3, 0.0, 0.02]"])
def test_a_goal_the_arm_cannot_reach_is_an_error(tmp_path, goal):
    """A goal in millimetres, or beyond any joint values (the bound sums the chain's link
    offsets: 1.15 m from the Panda's shoulder, whose real reach is about 0.86 m + the hand)."""
    folder = _copy(tmp_path, {"scenario.toml": [("goal = [0.5, 0.15, 0.02]", f"goal = {goal}")]},
                   source=bundled_scenario_path("panda_pick_place").parent)
    with pytest.raises(ScenarioError, match=r"\[task\] goal: .* the fixed base of the "
                       r"arm that carries gripper 'hand'; .*at most 1\.\d+ m"):
        load_scenario(folder)


def test_a_far_but_reachable_goal_loads(tmp_path):
    folder = _copy(tmp_path, {"scenario.toml": [("goal = [0.5, 0.15, 0.02]",
                                                 "goal = [0.0, 0.9, 0.02]")]},
                   source=bundled_scenario_path("panda_pick_place").parent)
    assert load_scenario(folder).task.goal == (0.0, 0.9, 0.02)
    # far below the arm: released above it, the object may fall there (a bin on the floor)
    folder = _copy(tmp_path / "low", {"scenario.toml": [("goal = [0.5, 0.15, 0.02]",
                                                         "goal = [0.5, 0.15, -3.0]")]},
                   source=bundled_scenario_path("panda_pick_place").parent)
    assert load_scenario(folder).task.goal == (0.5, 0.15, -3.0)


def test_a_friction_parameter_on_frictionless_contacts_is_an_error(tmp_path):
    folder = _copy(tmp_path, {"scene.xml": [('condim="4" priority="2"', 'condim="1" priority="2"')]},
                   source=bundled_scenario_path("panda_pick_place").parent)
    with pytest.raises(ScenarioError, match=r"\[uncertainty\.friction\]: geom 'cube' makes "
                       r"frictionless contacts \(condim 1\)"):
        load_scenario(folder)


def test_the_contact_override_makes_a_friction_parameter_an_error(tmp_path):
    """``<flag override="enable"/>`` gives every contact ``o_friction``: a friction parameter
    changes nothing, and without one the FOS reads o_friction (the geoms' friction is not
    used)."""
    option = '<option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>'
    override = ('<option timestep="0.002" integrator="implicitfast" cone="elliptic" '
                'impratio="10" o_friction="0.7 0.7 0.005 0.0001 0.0001">'
                '<flag override="enable"/></option>')
    source = bundled_scenario_path("panda_pick_place").parent
    folder = _copy(tmp_path, {"scene.xml": [(option, override)]}, source=source)
    with pytest.raises(ScenarioError, match=r"contact override .* o_friction = 0\.7"):
        load_scenario(folder)
    text = (folder / "scenario.toml").read_text()
    start = text.index("[uncertainty.friction]")
    (folder / "scenario.toml").write_text(text[:start] + text[text.index("\n[", start) + 1:])
    assert Twin(load_scenario(folder)).object_friction() == 0.7


def test_a_lift_height_the_arm_cannot_reach_is_an_error(tmp_path):
    source = bundled_scenario_path("panda_pick_place").parent
    folder = _copy(tmp_path, {"scenario.toml": [("lift_height = 0.02        # [m]",
                                                 "lift_height = 5.0        # [m]")]},
                   source=source)
    with pytest.raises(ScenarioError, match=r"\[task\] lift_height: 5 m above the object's "
                       r"start, but .* raises it at most 1\.\d+ m"):
        load_scenario(folder)


@pytest.mark.parametrize("settle", ["100.0", "7.9", "4.5"])
def test_a_settle_time_as_long_as_the_motion_is_an_error(tmp_path, demo_traj, settle):
    """The success rule's final window would reach back to the untouched start: every run
    failed and the audit said UNSAFE (exit 1) where the scenario was wrong (exit 2)."""
    from critmoment.analysis import AnalyzeOptions, analyze

    folder = _toml(tmp_path, ('receiver = "left"', f'receiver = "left"\nsettle_time = {settle}'))
    with pytest.raises(ScenarioError, match=rf"settle_time: {float(settle):g} s, but the "
                       r"trajectory .*lasts 8 s; expected a final window of at most half"):
        analyze(demo_traj, twin=Twin(load_scenario(folder)),
                options=AnalyzeOptions(n_samples=8, check_feasibility=False))


def test_a_scenario_file_with_a_byte_order_mark_loads(tmp_path):
    folder = _copy(tmp_path)
    path = folder / "scenario.toml"
    path.write_bytes(b"\xef\xbb\xbf" + path.read_bytes())
    assert load_scenario(folder).name == "aloha_transfer_cube"


def test_the_tasks_up_is_against_the_models_gravity(tmp_path):
    option = '<option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>'
    sideways = option.replace('impratio="10"/>', 'impratio="10" gravity="0 -9.81 0"/>')
    source = bundled_scenario_path("panda_pick_place").parent
    folder = _copy(tmp_path, {"scene.xml": [(option, sideways)]}, source=source)
    assert load_scenario(folder).task.up == (0.0, 1.0, 0.0)
    assert load_scenario(source).task.up == (0.0, 0.0, 1.0)


@pytest.mark.parametrize("persistence", ["100.0", "7.9"])
def test_a_persistence_as_long_as_the_motion_is_an_error(tmp_path, demo_traj, persistence):
    """No contact-FOS excursion could ever last that long: the criterion would be off."""
    from critmoment.analysis import AnalyzeOptions, analyze

    folder = _toml(tmp_path, ("[sparse]", f"[sparse]\npersistence = {persistence}"))
    with pytest.raises(ScenarioError, match=rf"\[sparse\] persistence: {float(persistence):g} s, "
                       r"but the trajectory .*lasts 8 s"):
        analyze(demo_traj, twin=Twin(load_scenario(folder)),
                options=AnalyzeOptions(n_samples=8, check_feasibility=False))


def test_a_creep_window_as_long_as_the_motion_is_an_error(tmp_path, demo_traj):
    """creep_horizon = 1e9 steps ran 44 s and moved the stated region."""
    from critmoment.analysis import AnalyzeOptions, analyze

    folder = _toml(tmp_path, ("[sparse]", "[sparse]\ncreep_horizon = 1000000000"))
    with pytest.raises(ScenarioError, match=r"\[sparse\] creep_horizon: 1000000000 physics "
                       r"steps = 2e\+06 s, but the trajectory .*lasts 8 s"):
        analyze(demo_traj, twin=Twin(load_scenario(folder)),
                options=AnalyzeOptions(n_samples=8, check_feasibility=False))


@pytest.mark.parametrize("offset", ["[-100.0, 100.0]", "[-0.01, 0.05]", "[-0.03, 0.03]"])
def test_a_centre_of_mass_outside_the_body_is_an_error(tmp_path, offset):
    """A CoM offset of ±100 m (or 5 cm on the 4 cm cube) was audited: every sample tipped
    the cube before any grasp and the report blamed the grip. A rigid body's centre of mass
    lies inside its matter. ±3 cm on the cube had passed a check against the cube's
    bounding sphere (3.46 cm): the cube's faces are 2 cm from its centre, and every sample
    past 2 cm dropped it at lift-off. ±1 cm, and ±2 cm to its faces, stay accepted."""
    edits = (('[uncertainty.friction]\ngeom = "box"', '[uncertainty.com_offset]\nbody = "box"'),
             ("range = [0.2, 1.5]", f"range = {offset}"), ("nominal = 1.0", "nominal = 0.0"))
    with pytest.raises(ScenarioError, match=r"\[uncertainty.com_offset\]: an offset of "
                       r"[-0-9.]+ m along x puts the centre of mass of body 'box' outside "
                       r"every geom it has \(along its x axis through its centre of mass they "
                       r"span offsets -0.02 to 0.02 m\)"):
        load_scenario(_toml(tmp_path, *edits))
    for i, span in enumerate(("[-0.01, 0.01]", "[-0.02, 0.02]")):
        ok = _toml(tmp_path / f"ok{i}", edits[0], ("range = [0.2, 1.5]", f"range = {span}"),
                   edits[2])
        assert load_scenario(ok).box.high[-1] == float(span.split(", ")[1][:-1])


def test_a_centre_of_mass_offset_on_a_massless_body_is_an_error(tmp_path):
    """A CoM offset on a body without mass changes nothing: it was audited as if it did
    (a ±0.5 m range on a marker body gave "safe for mass ≤ 1.67 kg" over it)."""
    folder = _copy(tmp_path, {
        "scenario.toml": [('[uncertainty.friction]\ngeom = "box"',
                           '[uncertainty.com_offset]\nbody = "marker"'),
                          ("range = [0.2, 1.5]", "range = [-0.5, 0.5]"),
                          ("nominal = 1.0", "nominal = 0.0")],
        "scene.xml": [('<freejoint name="box_joint"/>',
                       '<freejoint name="box_joint"/><body name="marker" pos="0 0 0.05"/>')]})
    with pytest.raises(ScenarioError, match=r"\[uncertainty.com_offset\]: body 'marker' has "
                       r"no mass in the MJCF \(0 kg\), so moving its centre of mass changes "
                       r"nothing"):
        Twin(load_scenario(folder))


def test_a_slip_tolerance_beyond_the_objects_size_is_an_error(tmp_path):
    """slip_tolerance = 1e9 m was accepted: no slip could ever count."""
    folder = _toml(tmp_path, ("horizon = 10\n", "horizon = 10\nslip_tolerance = 1e9\n"))
    with pytest.raises(ScenarioError, match=r"\[sparse\] slip_tolerance: 1e\+09 m, but the "
                       r"object 'box' is at most 0.0693 m across"):
        load_scenario(folder)


def test_an_uncertainty_table_naming_its_target_twice_is_an_error(tmp_path):
    """body = "box" and object = "table" together: object was silently ignored."""
    folder = _toml(tmp_path, ('[uncertainty.mass]\nbody = "box"',
                              '[uncertainty.mass]\nbody = "box"\nobject = "table"'))
    with pytest.raises(ScenarioError, match=r"\[uncertainty.mass\]: expected one of body = "
                       r"\.\.\. and object = \.\.\., got both \('box', 'table'\)"):
        load_scenario(folder)


@pytest.mark.parametrize("flag, match", [
    ("contact", r"no contact is made: no gripper can hold the object"),
    ("constraint", r"no contact, joint limit or equality acts"),
    ("actuation", r"no actuator acts: the robot cannot follow any trajectory"),
])
def test_a_model_that_disables_contacts_or_actuation_is_an_error(tmp_path, flag, match):
    """With <flag contact="disable"/> every run dropped the cube and the audit said UNSAFE
    for every sample, blaming the grip, where the model could hold nothing."""
    option = '<option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>'
    off = option.replace("/>", f'><flag {flag}="disable"/></option>')
    folder = _copy(tmp_path, {"scene.xml": [(option, off)]},
                   source=bundled_scenario_path("panda_pick_place").parent)
    with pytest.raises(ScenarioError, match=rf'<flag {flag}="disable"/>: {match}'):
        Twin(load_scenario(folder))


def test_a_saturation_under_an_explicit_integrator_names_it(tmp_path):
    """Under RK4 the Panda's stiff servos reach their limits at 2 ms (their velocity damping
    is explicit there), and RK4's last-stage forces do not flip from step to step: the
    message said only "too weak for the load"."""
    from critmoment import panda_demo
    from critmoment.feasibility import check_feasibility
    from critmoment.recording import rollout

    option = '<option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>'
    source = bundled_scenario_path("panda_pick_place").parent
    folder = _copy(tmp_path, {"scene.xml": [(option, option.replace("implicitfast", "RK4"))]},
                   source=source)
    scenario = load_scenario(folder)
    twin = Twin(scenario)
    problems = check_feasibility(rollout(panda_demo.make_pick_place(0), twin=twin), twin,
                                 raise_on_failure=False).problems
    # the joint keeps its target at the limit: the integrator is named first, the load after
    assert problems and all("the model's RK4 integrator" in p and "it treats a stiff servo's "
                            "velocity damping explicitly" in p and "too weak for the load" in p
                            for p in problems)
    plain = Twin(load_scenario(source))
    assert not check_feasibility(rollout(panda_demo.make_pick_place(0), twin=plain), plain,
                                 raise_on_failure=False).problems


def test_a_relative_model_path_two_folders_up_compiles_its_meshes(tmp_path, monkeypatch):
    """genesis' franka_sim Panda from a scenario two folders away (mjcf = "../../...", its
    meshes "../meshes/..." in an included assets file): MuJoCo resolved the meshes against
    the relative folder twice and the scenario did not compile from its own folder (it
    did with an absolute path)."""
    from critmoment.scenario import compile_spec, prepare_spec

    cube = "\n".join(f"v {x} {y} {z}" for x in (-0.01, 0.01) for y in (-0.01, 0.01)
                     for z in (-0.01, 0.01))
    faces = "f 1 2 4 3\nf 5 7 8 6\nf 1 5 6 2\nf 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4"
    sub = tmp_path / "sub"
    (sub / "assets").mkdir(parents=True)
    (sub / "meshes").mkdir()
    (sub / "meshes" / "box.obj").write_text(cube + "\n" + faces + "\n")
    (sub / "assets" / "assets.xml").write_text(
        '<mujocoinclude><asset><mesh name="m" file="../meshes/box.obj"/></asset>'
        '</mujocoinclude>')
    (sub / "robot.xml").write_text(
        '<mujoco><include file="assets/assets.xml"/><compiler meshdir=""/><worldbody>'
        '<body name="b"><geom type="mesh" mesh="m"/></body></worldbody></mujoco>')
    (sub / "scene.xml").write_text('<mujoco><include file="robot.xml"/></mujoco>')
    cwd = tmp_path / "a" / "b"
    cwd.mkdir(parents=True)
    monkeypatch.chdir(cwd)
    path = Path("../../sub/scene.xml")
    assert compile_spec(prepare_spec(path), path).ngeom == 1


def test_a_mass_range_in_grams_is_warned_of(tmp_path):
    """`range = [50, 10000]` for a 0.05 kg cube (grams) was audited as 50 kg to 10 t."""
    from critmoment.scenario import ScenarioWarning

    folder = _toml(tmp_path, ("range = [0.05, 10.0]", "range = [50.0, 10000.0]"),
                   ("nominal = 0.05", "nominal = 50.0"))
    with pytest.warns(ScenarioWarning, match=r"\[uncertainty.mass\] range: 50..10000 kg, at "
                                             r"least 100 times the body's 0.05 kg in the MJCF; "
                                             r"is the range in grams"):
        load_scenario(folder)


def test_a_linked_scenario_finds_its_model_beside_the_file_it_points_to(tmp_path, monkeypatch):
    folder = _copy(tmp_path)
    link = tmp_path / "elsewhere" / "link.toml"
    link.parent.mkdir()
    link.symlink_to(folder / "scenario.toml")
    assert load_scenario(link).mjcf.resolve() == (folder / "scene.xml").resolve()
    (folder / "scenario.toml").write_text((folder / "scenario.toml").read_text().replace(
        'mjcf = "scene.xml"', 'mjcf = "nowhere.xml"'))
    monkeypatch.chdir(tmp_path)
    with pytest.raises(InputFileError, match=r"file not found: .*nowhere.xml \(looked for /"):
        Twin(load_scenario(Path("elsewhere") / "link.toml"))


def test_the_objects_position_is_its_body_frame_not_its_centre_of_mass(tmp_path):
    """A compound object placed exactly at its goal read 31 mm off: the position sensor was
    the body's centre of mass (and a CoM-offset parameter moved the task's goal)."""
    import mujoco

    source = bundled_scenario_path("panda_pick_place").parent
    body = '<freejoint name="cube_joint"/>'
    folder = _copy(tmp_path, {"scene.xml": [(body, body + '\n      <inertial pos="0.012 0 0" '
                                              'mass="0.1" diaginertia="3e-5 3e-5 3e-5"/>')]},
                   source=source)
    twin = Twin(load_scenario(folder))
    data = mujoco.MjData(twin.model)
    mujoco.mj_resetDataKeyframe(twin.model, data, 0)
    mujoco.mj_forward(twin.model, data)
    obj = twin.model.body(twin.scenario.object_body).id
    assert np.linalg.norm(data.xipos[obj] - data.xpos[obj]) == pytest.approx(0.012)
    np.testing.assert_allclose(data.sensordata[twin._pos_adr], data.xpos[obj], atol=1e-12)


def test_a_frictionless_grip_is_warned_of(tmp_path):
    """Pads of condim 1 with a priority above the object: every grip contact frictionless,
    the friction parameter acting on the table only, and the one warning said the nominal
    run "never lifts it: too heavy or slippery"."""
    from critmoment.exceptions import CritmomentWarning

    folder = _copy(tmp_path)
    arm = folder / "vx300s.xml"
    text = arm.read_text()
    old = 'rgba="0.85 0.85 0.85 1" condim="4"'
    assert old in text
    arm.write_text(text.replace(old, 'rgba="0.85 0.85 0.85 1" condim="1" priority="2"'))
    with pytest.warns(CritmomentWarning, match=r"every contact of the object 'box' with the "
                                              r"grippers' geoms is frictionless \(condim 1"):
        Twin(load_scenario(folder))


def test_an_anisotropic_pair_made_isotropic_by_the_friction_parameter_is_warned_of(tmp_path):
    from critmoment.exceptions import CritmomentWarning

    pair = ('  <contact>\n    <pair geom1="box" geom2="left/left_pad" condim="4" '
            'friction="1.2 0.3 0.005 0.0001 0.0001"/>\n  </contact>\n')
    folder = _copy(tmp_path, {"scene.xml": [("  </worldbody>\n", "  </worldbody>\n" + pair)]})
    with pytest.warns(CritmomentWarning, match=r"explicit <pair> left/left_pad–box has "
                                              r"anisotropic sliding friction \(1.2, 0.3\)"):
        Twin(load_scenario(folder))


def test_a_trajectory_of_a_few_samples_is_named_too_short(twin):
    """Two samples at 50 Hz passed the T >= 2 check and then failed on "[task] settle_time",
    a key the user never set."""
    import critmoment as cm
    from critmoment.trajectory import Trajectory

    actions = np.tile(np.r_[np.zeros(6), 1.0, np.zeros(6), 1.0], (2, 1))
    with pytest.raises(ScenarioError, match=r"\(default 0.05 s, where \[task\] sets none\): a "
                                            r"trajectory of 0.04 s is too short to audit"):
        cm.analyze(Trajectory(actions, fps=50.0), twin=twin)


def test_a_centre_of_mass_offset_is_checked_against_the_bodys_solid_geoms(tmp_path):
    """A 40 cm visual geom (no collisions, no mass) beside the 4 cm cube counted as its
    matter, and a centre of mass in no geom (a frame, two separate parts) skipped the
    check: ±0.1 m loaded on both."""
    edits = [('[uncertainty.friction]\ngeom = "box"', '[uncertainty.com_offset]\nbody = "box"'),
             ("range = [0.2, 1.5]", "range = [-0.1, 0.1]"), ("nominal = 1.0", "nominal = 0.0")]
    visual = _copy(tmp_path / "visual", {"scenario.toml": edits, "scene.xml": [(
        '<freejoint name="box_joint"/>', '<freejoint name="box_joint"/><geom type="box" '
        'size="0.2 0.2 0.2" contype="0" conaffinity="0" mass="0" group="1"/>')]})
    with pytest.raises(ScenarioError, match=r"span offsets -0.02 to 0.02 m"):
        load_scenario(visual)
    apart = _copy(tmp_path / "apart", {"scenario.toml": edits, "scene.xml": [(
        '<freejoint name="box_joint"/>', '<freejoint name="box_joint"/><geom type="sphere" '
        'size="0.01" pos="0 0.05 0" mass="0.05"/>')]})
    with pytest.raises(ScenarioError, match=r"outside every geom it has \(they lie within"):
        load_scenario(apart)


def test_a_mesh_objects_centre_of_mass_range_is_checked_against_its_hull(tmp_path):
    """A square pyramid (base 4 cm, 4 cm high) as the object: through its centroid, a
    quarter of the way up, it spans ±1.5 cm along x, its bounding box ±2 cm. ±1.8 cm had
    passed against the box; MuJoCo collides a mesh's convex hull, and that is its matter."""
    pyramid = ('<mesh name="pyramid" vertex="-0.02 -0.02 0  0.02 -0.02 0  0.02 0.02 0  '
               '-0.02 0.02 0  0 0 0.04"/>')
    geom = ('<geom name="box" type="box" size="0.02 0.02 0.02" mass="0.05" rgba="0.9 0.1 '
            '0.1 1"')
    edits = {"scene.xml": [("<asset>", "<asset>" + pyramid),
                           (geom, '<geom name="box" type="mesh" mesh="pyramid" mass="0.05" '
                                  'rgba="0.9 0.1 0.1 1"')]}

    def scenario(name, span):
        return _copy(tmp_path / name, {**edits, "scenario.toml": [
            ('[uncertainty.friction]\ngeom = "box"', '[uncertainty.com_offset]\nbody = "box"'),
            ("range = [0.2, 1.5]", f"range = {span}"), ("nominal = 1.0", "nominal = 0.0")]})

    with pytest.raises(ScenarioError, match=r"span offsets -0.015 to 0.015 m"):
        load_scenario(scenario("wide", "[-0.018, 0.018]"))
    assert load_scenario(scenario("ok", "[-0.014, 0.014]")).box.high[-1] == 0.014


@pytest.mark.parametrize("where", ["body", "geom"])
def test_a_name_that_is_not_utf8_names_the_file_and_the_name(tmp_path, where):
    """MuJoCo keeps a Latin-1 name as bytes; Python then failed on it with "expected UTF-8
    text, got bytes that are not: ... position 1", naming neither the file nor the name."""
    from critmoment.modelinfo import inspect_model

    body, geom = (b"b\xfe", b"g") if where == "body" else (b"b", b"g\xfe")
    path = tmp_path / "latin1.xml"
    path.write_bytes(b'<mujoco model="m"><worldbody><body name="' + body + b'"><freejoint/>'
                     b'<geom name="' + geom + b'" type="box" size=".1 .1 .1"/></body>'
                     b'</worldbody></mujoco>')
    bad = body if where == "body" else geom
    with pytest.raises(ScenarioError, match=re.escape(
            f"could not read MJCF {path}: the name {bad!r} is not UTF-8 text")):
        inspect_model(path)


def test_the_task_reads_the_scenarios_gripper_order(scenario, demo_recording):
    """A task built in code with its grippers in another order reads the contact columns in
    the scenario's order: before, HandoverTask(grippers=('left', 'right'), picker='right', ...)
    on ALOHA read the right gripper's contacts as the left's, and an audit said SAFE, P = 1,
    for a hand-over the trajectory does not perform."""
    from critmoment.task import HandoverTask

    names = scenario.gripper_names
    task = scenario.task
    reordered = HandoverTask(grippers=names[::-1], picker=task.picker, receiver=task.receiver,
                             up=task.up)
    bound = scenario.replace(task=reordered).task
    assert bound == task
    rec = demo_recording
    want = task.stage(rec.contact_gripper, rec.signals.contact_support, rec.signals.object_pos)
    assert (want[-1] == task.final_stage)
    assert not np.array_equal(
        reordered.stage(rec.contact_gripper, rec.signals.contact_support,
                        rec.signals.object_pos), want)
    # the scenario's grippers reordered, the task as loaded: the same roles, same stages
    swapped = scenario.replace(grippers=scenario.grippers[::-1])
    assert swapped.task.grippers == names[::-1]
    got = swapped.task.stage(rec.contact_gripper[:, ::-1], rec.signals.contact_support,
                             rec.signals.object_pos)
    np.testing.assert_array_equal(got, want)


def test_a_task_naming_a_gripper_the_scenario_lacks_is_refused(scenario):
    from critmoment.task import PickHoldTask

    with pytest.raises(ScenarioError, match=r"Scenario task: expected grippers of the scenario "
                       r".*'claw' not among them"):
        scenario.replace(task=PickHoldTask(grippers=("claw",), gripper="claw"))


def test_a_task_of_no_kind_is_refused(scenario):
    """The base Task has no success rule: it was accepted and raised NotImplementedError
    from inside a rollout."""
    from critmoment.task import Task

    with pytest.raises(ScenarioError, match=r"Scenario task: expected a task of a kind .*got "
                       r"Task without stage, success, shortfalls, describe"):
        scenario.replace(task=Task(grippers=scenario.gripper_names))


def test_a_local_copy_named_like_a_bundled_scenario_is_the_one_loaded(tmp_path, monkeypatch):
    """A copy of the bundled folder made to edit it, passed by its name: the bundled
    scenario had been loaded and the edits silently not audited."""
    import shutil
    import warnings

    from critmoment.scenario import ScenarioWarning, bundled_scenario_path

    bundled = bundled_scenario_path("aloha_transfer_cube").parent
    copy = tmp_path / "aloha_transfer_cube"
    shutil.copytree(bundled, copy)
    toml = copy / "scenario.toml"
    text = toml.read_text()
    assert "\nname = " in text
    toml.write_text("\n".join('name = "my_copy"' if line.startswith("name = ") else line
                              for line in text.splitlines()) + "\n")
    monkeypatch.chdir(tmp_path)
    with pytest.warns(ScenarioWarning, match="names both a bundled scenario"):
        assert load_scenario("aloha_transfer_cube").name == "my_copy"
    # from the bundled models' own folder the name is the bundled scenario, without a word
    monkeypatch.chdir(bundled.parent)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert load_scenario("aloha_transfer_cube").name != "my_copy"


def test_a_gripper_that_can_never_touch_the_object_is_refused(tmp_path):
    """<contact><exclude> between the object and the gripper's bodies, or contype/
    conaffinity bits the object shares with none of its geoms: the grip could never form,
    and the audit said only "never touches the object: is the object pose right?"."""
    from inline_models import arm_scenario_toml, arm_xml

    (tmp_path / "scenario.toml").write_text(arm_scenario_toml())
    plain = arm_xml()
    bodies = ["hand", "finger_a", "finger_b"]
    assert all(f'body name="{b}"' in plain for b in bodies)
    excluded = plain.replace("</worldbody>", "</worldbody>\n  <contact>" + "".join(
        f'<exclude body1="cube" body2="{b}"/>' for b in bodies) + "</contact>")
    (tmp_path / "arm.xml").write_text(excluded)
    with pytest.raises(ScenarioError, match=r"\[grippers\.\w+\]: none of its geoms can touch "
                                            r"the object 'cube': <contact><exclude> between the "
                                            r"object and 'finger_a', 'finger_b', 'hand'"):
        load_scenario(tmp_path)
    bits = plain.replace('mass="0.1" friction="0.8"/>',
                         'mass="0.1" friction="0.8" contype="4" conaffinity="4"/>')
    bits = bits.replace('size="0.5 0.5 0.02"/>', 'size="0.5 0.5 0.02" contype="5" '
                                                 'conaffinity="5"/>')
    assert bits.count('contype="4"') == 1 and bits.count('contype="5"') == 1
    (tmp_path / "arm.xml").write_text(bits)
    with pytest.raises(ScenarioError, match=r"none of its geoms can touch the object 'cube': "
                                            r"their contype/conaffinity bits and the object's "
                                            r"share no bit"):
        load_scenario(tmp_path)
    # an explicit <pair> makes them collide whatever the bits
    pair = bits.replace("</worldbody>", '</worldbody>\n  <contact><pair geom1="cube" '
                                        'geom2="pad_a"/></contact>')
    (tmp_path / "arm.xml").write_text(pair)
    load_scenario(tmp_path)
    # one finger that can touch it is enough
    one = plain.replace("</worldbody>", '</worldbody>\n  <contact><exclude body1="cube" '
                                        'body2="finger_a"/></contact>')
    (tmp_path / "arm.xml").write_text(one)
    load_scenario(tmp_path)
