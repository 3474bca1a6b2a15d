"""Shared fixtures: the bundled scenario, its twin, a demo trajectory and its recording.

Session-scoped so that the IK demo and the frequent rollout run once per test session.
"""

import warnings

import numpy as np
import pytest

from critmoment import demos
from critmoment import recording as rollout
from critmoment.scenario import load_scenario
from critmoment.twin import Twin


@pytest.fixture(scope="session")
def scenario():
    return load_scenario()


@pytest.fixture(scope="session")
def twin(scenario):
    return Twin(scenario)


@pytest.fixture(scope="session")
def demo_traj(twin):
    return demos.scripted_transfer(0, twin=twin)


@pytest.fixture(scope="session")
def demo_recording(twin, demo_traj):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return rollout.rollout(demo_traj, twin=twin)


@pytest.fixture
def rng():
    return np.random.default_rng(12345)
