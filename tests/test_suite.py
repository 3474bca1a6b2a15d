"""Tests for critmoment.suite: families per bundled scenario, and the scenario a demo names."""

from __future__ import annotations

import json

import numpy as np
import pytest

from critmoment import suite
from critmoment.cli import main
from critmoment.exceptions import ParameterError


def test_families_per_scenario_name_their_scenario():
    aloha = suite.make("nominal", seed=0)
    assert aloha.meta["scenario"] == "aloha_transfer_cube" and aloha.actions.shape[1] == 14
    panda = suite.make("nominal", seed=0, scenario="panda_pick_place")
    assert panda.meta["scenario"] == "panda_pick_place" and panda.actions.shape[1] == 8
    fast = suite.make("fast", seed=0, scenario="panda_pick_place")
    assert fast.n_steps < panda.n_steps
    np.testing.assert_array_equal(panda.object_pose, suite.make(
        "nominal", seed=0, scenario="panda_pick_place").object_pose)


def test_unknown_family_or_scenario():
    with pytest.raises(ParameterError, match="unknown trajectory family 'jitter' for "
                                             "panda_pick_place; known: nominal, fast"):
        suite.make("jitter", scenario="panda_pick_place")
    with pytest.raises(ParameterError, match="unknown trajectory family 'faster' for "
                                             "aloha_transfer_cube"):
        suite.make("faster")
    with pytest.raises(ParameterError, match="unknown bundled scenario 'ur5'"):
        suite.make("nominal", scenario="ur5")


def test_a_panda_demo_is_audited_against_the_panda_scenario(tmp_path, capsys):
    traj = tmp_path / "panda.npz"
    assert main(["demo", "--scenario", "panda_pick_place", "--seed", "1", "--out",
                 str(traj)]) == 0
    capsys.readouterr()
    # no --scenario: the trajectory's meta names the bundled Panda scenario
    assert main(["rollout", str(traj), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["completed"] is True
