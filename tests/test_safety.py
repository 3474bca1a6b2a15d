"""Tests for critmoment.safety: factors of safety, cost and task stage on hand-computed inputs."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from critmoment.safety import contact_fos, cost, motor_fos, sustained_fos, task_stage
from critmoment.scenario import CostParams

# ---------------------------------------------------------------------------
# contact FOS (eq. 12)
# ---------------------------------------------------------------------------


def test_contact_fos_two_contacts_without_cohesion():
    # Σλn / Σ(λt/μ) = (3 + 1) / (1/0.5 + 0.5/0.5) = 4 / 3
    fos = contact_fos([3.0, 1.0], [1.0, 0.5], 0.5)
    assert fos.shape == ()
    assert float(fos) == pytest.approx(4.0 / 3.0, rel=1e-14)


def test_contact_fos_with_cohesion():
    # capacity c + μλn = (1 + 1.5, 1 + 0.5) = (2.5, 1.5)
    # Σ λn λt / capacity = 3·1/2.5 + 1·0.5/1.5 = 1.2 + 1/3
    fos = contact_fos([3.0, 1.0], [1.0, 0.5], 0.5, cohesion=1.0)
    assert float(fos) == pytest.approx(4.0 / (1.2 + 1.0 / 3.0), rel=1e-14)
    # cohesion adds capacity: the FOS grows with it
    assert float(fos) > 4.0 / 3.0


def test_contact_fos_per_contact_mu_and_cohesion():
    # μ = (0.5, 1.0), c = (0, 2): Σλn λt/(c + μλn) = 3·1/1.5 + 1·0.5/3 = 2 + 1/6
    fos = contact_fos([3.0, 1.0], [1.0, 0.5], [0.5, 1.0], cohesion=[0.0, 2.0])
    assert float(fos) == pytest.approx(4.0 / (2.0 + 1.0 / 6.0), rel=1e-14)


def test_contact_fos_empty_slots_change_nothing():
    full = contact_fos([3.0, 1.0], [1.0, 0.5], 0.5)
    padded = contact_fos([3.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                         [1.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0], 0.5)
    assert float(padded) == float(full)
    # with cohesion the empty slots have capacity c > 0 and still demand nothing
    padded_c = contact_fos([3.0, 0.0, 1.0], [1.0, 0.0, 0.5], 0.5, cohesion=1.0)
    assert float(padded_c) == pytest.approx(4.0 / (1.2 + 1.0 / 3.0), rel=1e-14)


def test_contact_fos_no_contact_is_inf():
    with np.errstate(all="raise"):  # no warning may leak out
        fos = contact_fos(np.zeros(8), np.zeros(8), 0.7)
    assert np.isposinf(fos)


def test_contact_fos_zero_tangential_is_inf():
    fos = contact_fos([2.0, 5.0], [0.0, 0.0], 0.3)
    assert np.isposinf(fos)


def test_contact_fos_at_the_cone_boundary_is_one():
    # every contact on the cone, λt = μ λn: FOS = 1 whatever the distribution of load
    normal = np.array([0.2, 3.0, 7.5, 0.0])
    mu = 0.8
    fos = contact_fos(normal, mu * normal, mu)
    assert float(fos) == pytest.approx(1.0, abs=1e-14)


def test_contact_fos_broadcasts_over_leading_axes():
    rng = np.random.default_rng(7)
    normal = rng.uniform(0.0, 5.0, size=(4, 3, 6))
    tangential = rng.uniform(0.0, 2.0, size=(4, 3, 6))
    mu = rng.uniform(0.2, 1.5, size=(4, 3, 1))
    fos = contact_fos(normal, tangential, mu)
    assert fos.shape == (4, 3)
    for i, j in itertools.product(range(4), range(3)):
        expected = normal[i, j].sum() / (tangential[i, j] / mu[i, j, 0]).sum()
        assert fos[i, j] == pytest.approx(expected, rel=1e-12)


def test_contact_fos_mixed_rows_contact_and_no_contact():
    normal = np.array([[3.0, 1.0], [0.0, 0.0], [2.0, 0.0]])
    tangential = np.array([[1.0, 0.5], [0.0, 0.0], [0.0, 0.0]])
    fos = contact_fos(normal, tangential, 0.5)
    assert fos[0] == pytest.approx(4.0 / 3.0, rel=1e-14)
    assert np.isposinf(fos[1]) and np.isposinf(fos[2])


# ---------------------------------------------------------------------------
# motor FOS (eq. 13-14)
# ---------------------------------------------------------------------------


def test_motor_fos_min_and_argmin():
    # ratios 10/2 = 5, 20/8 = 2.5, 1/1 = 1 -> limiting actuator 2
    fos, idx = motor_fos([2.0, -8.0, 1.0], [10.0, 20.0, 1.0])
    assert float(fos) == pytest.approx(1.0, rel=1e-15)
    assert int(idx) == 2


def test_motor_fos_uses_absolute_force():
    fos, idx = motor_fos([-12.0, 3.0], [15.0, 15.0])
    assert float(fos) == pytest.approx(15.0 / 12.0, rel=1e-15)
    assert int(idx) == 0


def test_motor_fos_all_zero_is_inf():
    with np.errstate(all="raise"):
        fos, _ = motor_fos(np.zeros(4), np.ones(4))
    assert np.isposinf(fos)


def test_motor_fos_zero_force_on_one_actuator_is_ignored():
    fos, idx = motor_fos([0.0, 4.0], [0.5, 10.0])
    assert float(fos) == pytest.approx(2.5, rel=1e-15)
    assert int(idx) == 1


def test_motor_fos_broadcasts_over_time():
    force = np.array([[1.0, 1.0], [10.0, 1.0], [1.0, 40.0]])
    limit = np.array([10.0, 20.0])
    fos, idx = motor_fos(force, limit)
    np.testing.assert_allclose(fos, [10.0, 1.0, 0.5], rtol=1e-15)
    np.testing.assert_array_equal(idx, [0, 0, 1])


# ---------------------------------------------------------------------------
# cost (eq. 15)
# ---------------------------------------------------------------------------


def test_cost_at_fos_one_is_a_plus_b():
    p = CostParams(A=0.8, B=1.0, alpha=0.7, beta=2.0)
    assert float(cost(1.0, 1.0, p)) == pytest.approx(1.8, rel=1e-15)
    p2 = CostParams(A=0.3, B=2.5, alpha=1.1, beta=0.4)
    assert float(cost(1.0, 1.0, p2)) == pytest.approx(2.8, rel=1e-15)


def test_cost_at_infinite_fos_is_zero():
    p = CostParams()
    assert float(cost(np.inf, np.inf, p)) == 0.0
    # each term alone
    assert float(cost(np.inf, 1.0, p)) == pytest.approx(p.B, rel=1e-15)
    assert float(cost(1.0, np.inf, p)) == pytest.approx(p.A, rel=1e-15)


def test_cost_hand_value():
    p = CostParams(A=0.8, B=1.0, alpha=0.7, beta=2.0)
    expected = 0.8 * math.exp(-0.7 * (2.0 - 1.0)) + 1.0 * math.exp(-2.0 * (3.0 - 1.0))
    assert float(cost(2.0, 3.0, p)) == pytest.approx(expected, rel=1e-14)
    assert expected == pytest.approx(0.415584, abs=1e-6)


def test_cost_is_monotone_decreasing_in_each_fos():
    p = CostParams(A=0.8, B=1.0, alpha=0.7, beta=2.0)
    f = np.linspace(0.2, 10.0, 200)
    c_contact = cost(f, 2.0, p)
    c_motor = cost(2.0, f, p)
    assert np.all(np.diff(c_contact) < 0)
    assert np.all(np.diff(c_motor) < 0)


def test_cost_broadcasts():
    p = CostParams(A=0.8, B=1.0, alpha=0.7, beta=2.0)
    c = cost(np.array([[1.0], [np.inf]]), np.array([1.0, np.inf]), p)
    np.testing.assert_allclose(c, [[1.8, 0.8], [1.0, 0.0]], rtol=1e-15)


@pytest.mark.parametrize("key, value", [("A", 0.0), ("B", -1.0), ("alpha", np.nan),
                                        ("threshold", np.inf)])
def test_cost_params_reject_bad_constants(key, value):
    from critmoment.exceptions import ScenarioError

    with pytest.raises(ScenarioError, match=rf"\[cost\] {key}: expected a finite number > 0"):
        CostParams(**{key: value})


# ---------------------------------------------------------------------------
# task stage (ACT's reward)
# ---------------------------------------------------------------------------

# (picker touches, receiver touches, object touches support) -> ACT reward
STAGE_TABLE = {
    (False, False, False): 0,  # in the air, nobody holds it (falling)
    (False, False, True): 0,   # resting on the table
    (True, False, True): 1,    # picker touches it on the table
    (True, False, False): 2,   # picker lifted it
    (False, True, True): 3,    # receiver touches it on the table
    (True, True, True): 3,     # both touch it on the table
    (False, True, False): 4,   # receiver holds it in the air
    (True, True, False): 4,    # both hold it in the air (hand-over)
}


@pytest.mark.parametrize("flags, expected", sorted(STAGE_TABLE.items()))
def test_task_stage_truth_table(flags, expected):
    stage = task_stage(*flags)
    assert stage.shape == ()
    assert stage.dtype == np.int8
    assert int(stage) == expected


def test_task_stage_vectorised_truth_table():
    flags = np.array(list(STAGE_TABLE.keys()))
    stage = task_stage(flags[:, 0], flags[:, 1], flags[:, 2])
    np.testing.assert_array_equal(stage, list(STAGE_TABLE.values()))
    # (T, batch) leading axes
    tiled = np.broadcast_to(flags[:, None, :], (8, 3, 3))
    stage2 = task_stage(tiled[..., 0], tiled[..., 1], tiled[..., 2])
    assert stage2.shape == (8, 3)
    np.testing.assert_array_equal(stage2, np.repeat(stage[:, None], 3, axis=1))


def test_format_fos_caps_the_ratio_of_an_unloaded_joint():
    from critmoment.safety import format_fos

    assert format_fos(1.23456) == "1.23"
    assert format_fos(1.0, ".3f") == "1.000"
    assert format_fos(999.0) == "999"
    # a nearly unloaded hinge's ratio (seen: 3.7e6, 5.4e20) says only "far from its limit"
    assert format_fos(3678315.9, ".3f") == "> 1000"
    assert format_fos(5.42e20) == "> 1000"
    assert format_fos(float("inf")) == "inf"
    assert format_fos(None) == format_fos(float("nan")) == "n/a"


def test_sustained_fos_ignores_chatter_shorter_than_the_window_and_keeps_a_held_dip():
    fos = np.full(100, 5.0)
    fos[10] = 1.0            # one step of chatter
    fos[40:45] = 0.8         # 5 steps, shorter than the 10-step window
    fos[70:85] = 0.9         # 15 steps: held over a whole window
    held = sustained_fos(fos, 10)
    assert held.shape == fos.shape
    assert held.min() == pytest.approx(0.9)
    assert np.flatnonzero(held == 0.9).tolist() == list(range(70, 76))
    assert held[:40].min() == 5.0 and held[-5:].min() == 5.0  # the short tail: what is left
    np.testing.assert_array_equal(sustained_fos(fos, 1), fos)
    assert np.isinf(sustained_fos(np.full(5, np.inf), 3)).all()  # no contact stays +inf
