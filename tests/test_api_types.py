"""Objects built or changed in code get the checks a scenario.toml gets: a wrong type or a
missing part is a CritmomentError naming the field, never a traceback deep in the audit or
a silent answer (a fuzz round found `prior="loguniform"` sampled as uniform and
`support_geoms=()` audited into a different verdict)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from critmoment.exceptions import ParameterError, ScenarioError, TrajectoryError
from critmoment.params import MassParameter, Prior, UncertaintyBox
from critmoment.scenario import CostParams, SparseSettings
from critmoment.trajectory import Trajectory


def test_a_prior_given_by_name_is_the_prior(scenario):
    mass = dataclasses.replace(scenario.box.parameters[0], prior="loguniform")
    assert mass.prior is Prior.LOGUNIFORM
    with pytest.raises(ParameterError, match=r"parameter 'mass' prior: expected one of "
                       r"\['uniform', 'loguniform'\].*got 'bogus'"):
        dataclasses.replace(mass, prior="bogus")
    with pytest.raises(ParameterError, match="prior"):
        dataclasses.replace(mass, prior=None)


@pytest.mark.parametrize(("changes", "match"), [
    ({"low": "0.1"}, r"parameter 'm' low: expected a number, got '0.1'"),
    ({"high": None}, r"parameter 'm' high: expected a number, got None"),
    ({"nominal": True}, r"parameter 'm' nominal: expected a number, got True"),
    ({"name": ""}, r"parameter name: expected a non-empty string, got ''"),
    ({"target": 3}, r"parameter target: expected a non-empty string, got 3"),
    ({"high": 10**400}, r"parameter 'm': expected finite range and nominal"),
])
def test_a_parameter_of_the_wrong_type_is_named(changes, match):
    fields = {"name": "m", "target": "box", "low": 0.1, "high": 1.0, "nominal": 0.5, **changes}
    with pytest.raises(ParameterError, match=match):
        MassParameter(**fields)


def test_a_box_holds_parameters():
    with pytest.raises(ParameterError, match="expected at least one critmoment Parameter"):
        UncertaintyBox(())
    with pytest.raises(ParameterError, match=r"got \['dict'\]"):
        UncertaintyBox(({"name": "mass"},))
    from critmoment.params import Parameter

    # the base class has no resolve/write: refused here, not NotImplementedError in a Twin
    with pytest.raises(ParameterError, match=r"expected parameters of a kind .*MassParameter"
                       r".*got the base Parameter for \['m'\]"):
        UncertaintyBox((Parameter("m", "box", 0.1, 1.0, 0.5),))


@pytest.mark.parametrize(("changes", "match"), [
    ({"support_geoms": ()}, r"Scenario support_geoms: expected the names of the supports"),
    ({"support_geoms": "table"}, r"Scenario support_geoms"),
    ({"settle": "no"}, r"Scenario settle: expected True or False, got str 'no'"),
    ({"fps": -1.0}, r"Scenario fps: expected an action rate > 0 Hz, got float -1.0"),
    ({"fps": math.nan}, r"Scenario fps"),
    ({"grippers": ()}, r"Scenario grippers: expected at least one Gripper"),
    ({"task": None}, r"Scenario task: expected a Task, got NoneType None"),
    ({"cost": None}, r"Scenario cost: expected a CostParams"),
    ({"box": None}, r"Scenario box: expected a UncertaintyBox"),
    ({"range_policy": "bogus"}, r"Scenario range_policy: expected one of 'error', 'clip', "
                                r"'warn', got str 'bogus'"),
    ({"object_body": ""}, r"Scenario object_body: expected a non-empty string"),
    ({"keyframe": 0.0}, r"Scenario keyframe: expected a keyframe name, an index of an unnamed "
                        r"one, or None, got float 0.0"),
])
def test_a_scenario_changed_in_code_is_checked(scenario, changes, match):
    with pytest.raises(ScenarioError, match=match):
        scenario.replace(**changes)


@pytest.mark.parametrize("value", [math.nan, -5.0, 0.0, "20"])
def test_a_force_limit_changed_in_code_must_be_positive(scenario, value):
    limits = {**scenario.limits, "left/elbow": value}
    with pytest.raises(ScenarioError, match=r"Scenario limits: expected a force limit > 0 .*"
                       r"'left/elbow'"):
        scenario.replace(limits=limits)


def test_a_twin_needs_a_limit_for_every_actuator(scenario):
    from critmoment.twin import Twin

    with pytest.raises(ScenarioError, match=r"expected a force limit for every actuator .*"
                       r"missing \['left/waist'"):
        Twin(scenario.replace(limits={}))


def test_the_bundled_twin_is_the_default():
    from critmoment.twin import Twin

    assert Twin().scenario.name == "aloha_transfer_cube"


@pytest.mark.parametrize(("make", "match"), [
    (lambda: CostParams(A="x"), r"\[cost\] A: expected a finite number > 0, got 'x'"),
    (lambda: CostParams(threshold=None), r"\[cost\] threshold"),
    (lambda: SparseSettings(persistence="x"), r"\[sparse\] persistence: expected a time"),
    (lambda: SparseSettings(slip_tolerance=None), r"\[sparse\] slip_tolerance"),
])
def test_cost_and_sparse_settings_of_the_wrong_type_are_named(make, match):
    with pytest.raises(ScenarioError, match=match):
        make()


def test_a_friction_below_mujocos_smallest_is_an_error():
    """range = [1e-320, 1.5] ran into NaN gradients in the worst-case search (8 lines of
    CasADi warnings) before a verdict: MuJoCo raises any friction below 1e-5 to 1e-5."""
    from critmoment.params import FrictionParameter

    with pytest.raises(ParameterError, match=r"expected a friction coefficient >= 1e-05 "
                       r"\(MuJoCo raises any smaller one to that, mjMINMU\), got range "
                       r"\[1e-300, 1.5\]"):
        FrictionParameter("friction", "box", 1e-300, 1.5, 1.0)
    assert FrictionParameter("friction", "box", 1e-5, 1.5, 1.0).low == 1e-5


def test_a_scenario_beside_a_twin_of_another_is_warned_of(twin):
    """analyze(traj, "panda_pick_place", twin=<ALOHA twin>) audited the ALOHA twin
    silently (documented: the twin's scenario wins)."""
    import warnings

    from critmoment.exceptions import CritmomentWarning
    from critmoment.twin import resolve_twin

    with pytest.warns(CritmomentWarning, match=r"both a scenario \('panda_pick_place'\) and a "
                      r"twin \(of 'aloha_transfer_cube'\) were given; the twin's scenario is "
                      r"used"):
        assert resolve_twin("panda_pick_place", twin) is twin
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for same in ("aloha_transfer_cube", twin.scenario, twin, twin.scenario.path):
            assert resolve_twin(same, twin) is twin


def test_an_empty_scenario_path_is_an_error_not_the_current_folder():
    from critmoment.scenario import load_scenario

    with pytest.raises(ScenarioError, match=r"scenario: expected a scenario.toml, its folder "
                       r"or a bundled scenario's name .*got str ''"):
        load_scenario("")


@pytest.mark.parametrize("fps", ["50", b"50", np.array("50")])
def test_a_rate_typed_as_text_is_named(fps):
    with pytest.raises(TrajectoryError, match=r"fps: expected a finite number > 0 \[Hz\], got text"):
        Trajectory(np.zeros((10, 2)), fps=fps)


def test_a_rate_past_floats_range_is_named():
    with pytest.raises(TrajectoryError, match=r"fps: expected a finite number > 0 \[Hz\], got inf"):
        Trajectory(np.zeros((10, 2)), fps=10**400)


def test_a_recorded_rate_other_than_the_scenarios_is_warned_of(twin, demo_traj):
    """A trajectory recording 50 Hz audited with a scenario stating 30 Hz used 50 Hz silently."""
    import warnings as _w

    from critmoment.exceptions import CritmomentWarning
    from critmoment.recording import at_scenario_rate
    from critmoment.twin import Twin

    thirty = Twin(twin.scenario.replace(fps=30.0, fps_given=True))
    with pytest.warns(CritmomentWarning, match=r"records 50 Hz, the scenario's \[actions\] fps "
                                              r"says 30 Hz: the recorded rate is used"):
        assert at_scenario_rate(demo_traj, thirty).fps == 50.0
    with _w.catch_warnings():
        _w.simplefilter("error")
        assert at_scenario_rate(demo_traj, twin) is demo_traj


def test_a_trajectory_built_without_a_rate_takes_the_scenarios(twin, demo_traj, tmp_path):
    """`Trajectory(actions)` played at 50 Hz against a scenario stating 30 Hz, with only a
    warning that it "records 50 Hz" (it recorded none): a policy's chunk audited 1.67×
    too fast. It now takes the scenario's rate, as a file without one does, and keeps
    the rate unrecorded through save and load."""
    import warnings as _w

    from critmoment.recording import at_scenario_rate
    from critmoment.trajectory import load_trajectory, save_trajectory
    from critmoment.twin import Twin

    thirty = Twin(twin.scenario.replace(fps=30.0, fps_given=True))
    bare = Trajectory(demo_traj.actions)
    assert bare.fps == 50.0 and bare.fps_assumed
    with _w.catch_warnings():
        _w.simplefilter("error")
        assert at_scenario_rate(bare, thirty).fps == 30.0
    save_trajectory(bare, tmp_path / "bare.npz")
    again = load_trajectory(tmp_path / "bare.npz")
    assert again.fps_assumed and at_scenario_rate(again, thirty).fps == 30.0
    # a rate given is kept, and saved
    given = Trajectory(demo_traj.actions, fps=50.0)
    assert not given.fps_assumed
    save_trajectory(given, tmp_path / "given.npz")
    assert not load_trajectory(tmp_path / "given.npz").fps_assumed


def test_scenario_replace_names_an_unknown_field(scenario):
    with pytest.raises(ScenarioError, match=r"Scenario.replace: unknown key 'boxx' \(did you "
                                            r"mean 'box'\?\)"):
        scenario.replace(boxx=1)
    assert scenario.replace(horizon=5).sparse.horizon == 5


def test_validate_takes_a_scenario_as_analyze_does(scenario):
    """`cm.validate(traj, scenario)` was a TypeError: it took only twin=."""
    import inspect

    import critmoment as cm

    params = inspect.signature(cm.validate).parameters
    assert list(params)[:2] == ["traj", "scenario"] and params["twin"].default is None


def test_times_in_milliseconds_are_named(tmp_path):
    """`time` in ms gave "expected at most 500,000 physics steps ... raise the limit"."""
    from critmoment.trajectory import load_trajectory

    path = tmp_path / "ms.npz"
    np.savez(path, actions=np.zeros((20, 14)), time=np.arange(20) * 20.0)
    with pytest.raises(TrajectoryError, match=r"times 20 apart, a control rate of 0.05 Hz; "
                                              r"expected times in seconds \(milliseconds"):
        load_trajectory(path)


def test_times_one_apart_are_sample_indices(tmp_path):
    """Timestamps 0, 1, 2, ... (a LeRobot episode's frame indices) were played at 1 Hz, a
    50-frame episode over 50 s, while 1.0001 apart was refused."""
    from critmoment.trajectory import load_trajectory

    path = tmp_path / "idx.npz"
    np.savez(path, actions=np.zeros((20, 14)), time=np.arange(20.0))
    with pytest.raises(TrajectoryError, match=r"times 1 apart, a control rate of 1 Hz; "
                                              r"expected times in seconds \(milliseconds, or "
                                              r"sample indices\?\)"):
        load_trajectory(path)


def test_a_near_bundled_name_is_suggested(tmp_path, monkeypatch):
    from critmoment.exceptions import InputFileError
    from critmoment.scenario import load_scenario

    monkeypatch.chdir(tmp_path)
    with pytest.raises(InputFileError, match=r"did you mean 'panda_pick_place'\?"):
        load_scenario("panda")


def test_a_range_with_units_in_it_says_plain_numbers(tmp_path):
    import shutil

    from critmoment.scenario import bundled_scenario_path, load_scenario

    folder = tmp_path / "s"
    shutil.copytree(bundled_scenario_path().parent, folder)
    toml = folder / "scenario.toml"
    toml.write_text(toml.read_text().replace("range = [0.05, 10.0]", 'range = ["0.05 kg", "10 kg"]'))
    with pytest.raises(ScenarioError, match=r"\[uncertainty.mass\] range: expected \[low, high\], "
                                            r"two plain numbers in the parameter's unit \(kg; no "
                                            r"unit text\)"):
        load_scenario(folder)


def test_the_public_enums_print_as_their_values():
    """README's ``print(report.verdict, ...)`` printed ``Verdict.CONDITIONAL`` and the
    tutorial's moments ``MomentLabel.CHANGE_POINT`` (twenty-fifth round)."""
    from critmoment.groundtruth import Outcome
    from critmoment.moments import MomentLabel
    from critmoment.verdict import Verdict

    assert str(Verdict.CONDITIONAL) == "CONDITIONAL" and f"{Verdict.SAFE}" == "SAFE"
    assert str(MomentLabel.CHANGE_POINT) == "change-point"
    assert f"{Outcome.DROPPED}" == "dropped"


def test_a_demo_seed_and_an_mjcf_given_as_scenario_are_named(tmp_path):
    """demos.scripted_transfer(seed=-1) raised numpy's ValueError, and --scenario scene.xml
    said only "not valid TOML: Invalid statement"."""
    from critmoment import demos
    from critmoment.exceptions import ParameterError, ScenarioError
    from critmoment.scenario import load_scenario

    for seed in (-1, "a", 1.5):
        with pytest.raises(ParameterError, match=r"seed: expected an integer"):
            demos.sample_box_pose(seed)
    xml = tmp_path / "scene.xml"
    xml.write_text("<mujoco><worldbody/></mujoco>\n")
    with pytest.raises(ScenarioError, match=r"not valid TOML: .*; this is an MJCF model: a "
                                            r"scenario is a scenario.toml naming it"):
        load_scenario(xml)


def test_a_rate_the_physics_cannot_play_is_refused_without_a_warning_first(twin, demo_traj):
    """`Trajectory(actions, fps=1000)` on a 500 Hz twin with a 30 Hz scenario: the rate was
    warned of twice ("the recorded rate is used"), then refused; and a rate the physics
    can play is warned of once per call, not once more by analyze's own rollout."""
    import warnings as _w

    from critmoment.analysis import AnalyzeOptions, analyze
    from critmoment.twin import Twin

    thirty = Twin(twin.scenario.replace(fps=30.0, fps_given=True))
    fast = Trajectory(demo_traj.actions, fps=1000.0)
    with _w.catch_warnings(record=True) as caught:
        _w.simplefilter("always")
        with pytest.raises(TrajectoryError, match="expected at most the physics rate"):
            analyze(fast, twin=thirty, options=AnalyzeOptions(n_samples=8))
    assert not [w for w in caught if "recorded rate" in str(w.message)]
    with _w.catch_warnings(record=True) as caught:
        _w.simplefilter("always")
        analyze(demo_traj, twin=thirty, options=AnalyzeOptions(n_samples=8, max_moments=2))
    assert len([w for w in caught if "records 50 Hz" in str(w.message)]) == 1


def test_a_masked_array_with_masked_cells_is_refused():
    """np.asarray drops a mask: a probe's masked 1e6 was audited as an action of 1e6."""
    actions = np.ma.masked_array(np.zeros((10, 2)), mask=np.zeros((10, 2), bool))
    assert np.array_equal(Trajectory(actions, fps=50.0).actions, np.zeros((10, 2)))
    actions[3, 1] = np.ma.masked
    with pytest.raises(TrajectoryError, match=r"actions: expected every value given, got a "
                       r"masked array with 1 masked cell\(s\) \(the first at index \(3, 1\)\)"):
        Trajectory(actions, fps=50.0)
