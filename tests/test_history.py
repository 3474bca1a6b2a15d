"""Tests of critmoment.history: each sample's own drift from the nominal run."""

from __future__ import annotations

import numpy as np
import pytest

from critmoment import history, sparse
from critmoment.exceptions import ParameterError


def _carry_steps(recording):
    """Steps where the picker alone holds the cube off the table (a carry)."""
    held = recording.signals.contact_gripper & ~recording.signals.contact_support[:, None]
    alone = held & (held.sum(axis=1, keepdims=True) == 1)
    carry = np.flatnonzero(alone[:, 1])
    return [int(carry[100]), int(carry[len(carry) // 2])]


def test_nominal_sample_does_not_drift_and_heavier_ones_do(scenario, twin, demo_recording):
    ev = sparse.SparseEvaluator(demo_recording, twin)
    samples = np.tile(scenario.box.nominal, (3, 1))
    samples[:, scenario.box.index("mass")] = [0.05, 0.5, 1.5]
    est = history.estimate_drift(ev, _carry_steps(demo_recording), samples, horizon=20)
    assert est.steps.size == 2 and est.drift.shape == (2, 3)
    # the nominal sample's own run is the nominal run, bit for bit
    np.testing.assert_array_equal(est.drift[:, 0], 0.0)
    np.testing.assert_array_equal(est.lag[:, 0], 0.0)
    assert (est.drift[:, 2] > est.drift[:, 1]).all() and (est.drift[:, 1] > 0).all()
    assert (est.remaining > 0).all()
    np.testing.assert_allclose(est.predicted_drift,
                               est.drift + est.drift_rate * est.remaining[:, None])
    assert not est.escalate[0] and est.escalate[2]
    # moments where no gripper holds the cube alone are not traced
    none = history.estimate_drift(ev, [0], samples)
    assert none.steps.size == 0 and not none.escalate.any()


def test_bad_options_raise(twin, demo_recording, scenario):
    ev = sparse.SparseEvaluator(demo_recording, twin)
    with pytest.raises(ParameterError, match="horizon"):
        history.estimate_drift(ev, [100], scenario.box.nominal[None], horizon=2)
    with pytest.raises(ParameterError, match="drift_tolerance"):
        history.estimate_drift(ev, [100], scenario.box.nominal[None], drift_tolerance=0.0)


def test_a_nominal_chain_is_the_nominal_run(scenario, twin, demo_recording):
    ev = sparse.SparseEvaluator(demo_recording, twin)
    steps = np.array(_carry_steps(demo_recording) + [_carry_steps(demo_recording)[0] - 400])
    samples = np.tile(scenario.box.nominal, (2, 1))
    samples[1, scenario.box.index("mass")] = 1.0
    chain = history.chained_failures(ev, steps, samples)
    np.testing.assert_array_equal(chain.steps, np.sort(steps))
    assert chain.start == steps.min()
    assert chain.stepped == steps.max() + ev.horizon - steps.min()
    # carried on its own state, the nominal sample is the nominal run: the same decision
    # as restoring the nominal state at every moment
    plain = ev.evaluate(chain.steps, samples[:1])
    np.testing.assert_array_equal(chain.failure[:, 0], plain.failure[:, 0])
    assert chain.failure.shape == (3, 2) and chain.failed.shape == (2,)
    # the first moment starts from the nominal state for every sample: the plain decision
    first = ev.evaluate(chain.steps[:1], samples)
    np.testing.assert_array_equal(chain.failure[0], first.failure[0])
    heavy = history.chained_failures(ev, steps, _mass(scenario, 10.0))
    assert heavy.failed[0]  # a 10 kg cube fails in the carry


def _mass(scenario, mass):
    sample = scenario.box.nominal[None].copy()
    sample[0, scenario.box.index("mass")] = mass
    return sample
