"""The public API: every exported name exists, errors form one hierarchy."""

from __future__ import annotations

import importlib
import sys
from pathlib import Path

import pytest

import critmoment
from critmoment import exceptions

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

MODULES = ["exceptions", "params", "scenario", "safety", "twin", "recording", "trajectory", "demos",
           "task", "actuators", "modelinfo", "feasibility", "groundtruth", "verdict", "suite",
           "panda_demo"]


@pytest.mark.parametrize("name", critmoment.__all__)
def test_top_level_names_exist(name):
    assert hasattr(critmoment, name), name
    exec(f"from critmoment import {name}", {})


def test_all_has_no_duplicates():
    assert len(set(critmoment.__all__)) == len(critmoment.__all__)


@pytest.mark.parametrize("module", MODULES)
def test_module_all_names_exist(module):
    mod = importlib.import_module(f"critmoment.{module}")
    assert mod.__all__, module
    missing = [n for n in mod.__all__ if not hasattr(mod, n)]
    assert not missing, f"critmoment.{module}.__all__ names missing: {missing}"


def test_error_hierarchy():
    for name in exceptions.__all__:
        cls = getattr(exceptions, name)
        assert issubclass(cls, exceptions.CritmomentError), name
    assert issubclass(exceptions.InputFileError, FileNotFoundError)
    for name in ("TrajectoryError", "ScenarioError", "ParameterError"):
        assert issubclass(getattr(exceptions, name), ValueError)
    err = exceptions.SimulationDivergedError("diverged at physics step 7", step=7)
    assert isinstance(err, RuntimeError) and err.step == 7
    assert exceptions.SimulationDivergedError("x").step is None


def test_version_matches_pyproject():
    from importlib.metadata import PackageNotFoundError, version

    pyproject = Path(__file__).resolve().parent.parent / "pyproject.toml"
    meta = tomllib.loads(pyproject.read_text())
    assert critmoment.__version__ == meta["project"]["version"]
    try:  # the installed distribution, when there is one, carries the same version
        assert version("critmoment") == critmoment.__version__
    except PackageNotFoundError:
        pass


def test_a_twin_or_a_wrong_type_in_the_scenario_position(twin, demo_traj):
    """rollout(traj, twin) works (the twin is the scenario); anything else that is not a
    scenario, a path or a name is a ScenarioError, not a TypeError from pathlib."""
    import critmoment as cm
    from critmoment.exceptions import ScenarioError

    rec = cm.rollout(demo_traj, twin)
    assert rec.completed
    with pytest.raises(ScenarioError, match="expected a Scenario, a Twin"):
        cm.rollout(demo_traj, 42)
    with pytest.raises(ScenarioError, match="twin: expected a critmoment Twin"):
        cm.analyze(demo_traj, twin="aloha")


@pytest.mark.parametrize("kwargs, message", [
    (dict(n_samples="16"), r"n_samples: expected an integer >= 8, got str '16'"),
    (dict(n_samples=16.5), r"n_samples: expected an integer >= 8, got float 16.5"),
    (dict(n_samples=None), r"n_samples: expected an integer >= 8, got NoneType None"),
    (dict(seed="x"), r"seed: expected an integer in \[0, 4294967295\], got str 'x'"),
    (dict(seed=-1), r"seed: expected an integer in \[0, 2\*\*32 - 1"),
    (dict(nthread=-3), r"nthread: expected an integer >= 0, got int -3"),
    (dict(horizon=2.5), r"horizon: expected an integer >= 1 or None, got float 2.5"),
    (dict(critical_grid=5.5), r"critical_grid: expected an integer >= 5"),
    (dict(map_resolution=float("nan")), r"map_resolution: expected an integer >= 0"),
    (dict(confidence="0.9"), r"confidence: expected a number in \(0, 1\), got str '0.9'"),
    (dict(verify="0.5"), r"verify: expected a number in \(0, 1\] \(a fraction of the threshold\) "
                         r"or None, got str '0.5'"),
    (dict(verify=float("nan")), r"verify: expected a number"),
    (dict(search_trials="x"), r"search_trials: expected an integer >= 1, got str 'x'"),
    (dict(chain="yes"), r"chain: expected True or False, got str 'yes'"),
])
def test_analyze_options_refuse_wrong_types(kwargs, message):
    """Every option is checked for its type and range when the options are made: a
    ParameterError that names it, never a TypeError from a comparison inside the audit."""
    with pytest.raises(critmoment.ParameterError, match=message):
        critmoment.AnalyzeOptions(**kwargs)


def test_library_calls_refuse_what_is_not_their_input(demo_traj, tmp_path):
    """A path where a Trajectory goes, options as a dict, a seed that is not an integer, a
    number as a path or a scenario: each a CritmomentError that says what was expected."""
    import numpy as np

    import critmoment as cm

    with pytest.raises(cm.ParameterError, match=r"trajectory: expected a critmoment "
                       r"Trajectory \(read a file with critmoment.load_trajectory\(path\)\), "
                       r"got str"):
        cm.analyze("traj.npz")
    for wrong in (None, np.zeros((5, 14))):
        with pytest.raises(cm.ParameterError, match="expected a critmoment Trajectory"):
            cm.analyze(wrong)
    with pytest.raises(cm.ParameterError, match="options: expected AnalyzeOptions"):
        cm.analyze(demo_traj, options={"n_samples": 8})
    with pytest.raises(cm.ParameterError, match="seed: expected an integer"):
        cm.analyze(demo_traj, seed="x")
    for wrong in (None, 5, b"traj.npz"):
        with pytest.raises(cm.ParameterError, match="path: expected a trajectory file"):
            cm.load_trajectory(wrong)
    with pytest.raises(cm.ScenarioError, match="scenario: expected a scenario.toml, its "
                       "folder or a bundled scenario's name"):
        cm.load_scenario(5)
    with pytest.raises(cm.ScenarioError, match="Twin: expected a Scenario"):
        cm.Twin(5)
    assert cm.Twin("aloha_transfer_cube").scenario.name == "aloha_transfer_cube"
    with pytest.raises(cm.ParameterError, match="expected a critmoment Trajectory"):
        cm.validate("traj.npz", twin=cm.Twin(None), n_samples=4)


@pytest.mark.parametrize("call", ["rollout", "check_feasibility", "evaluate", "brute_force"])
@pytest.mark.parametrize("bad", ["traj.npz", None])
def test_stage_functions_refuse_a_path_or_none_with_a_critmoment_error(twin, demo_recording,
                                                                      call, bad):
    """They raised AttributeError ('str' object has no attribute 'n_channels')."""
    import numpy as np

    calls = {
        "rollout": lambda: critmoment.rollout(bad, twin=twin),
        "check_feasibility": lambda: critmoment.check_feasibility(bad, twin),
        "evaluate": lambda: critmoment.evaluate(bad, twin, [10], np.array([[0.05, 1.0]])),
        "brute_force": lambda: critmoment.brute_force(bad, twin=twin,
                                                      samples=np.array([[0.05, 1.0]])),
    }
    with pytest.raises(exceptions.ParameterError, match=r"expected a critmoment "
                       r"(Trajectory|Recording)"):
        calls[call]()
    with pytest.raises(exceptions.ScenarioError, match="expected a critmoment Twin"):
        critmoment.check_feasibility(demo_recording, "twin")
