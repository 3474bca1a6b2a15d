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
