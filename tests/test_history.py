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
