"""Tests of critmoment.groundtruth: it sits below the audit, takes the task's success rule,
and a reused nominal reference gives the same outcomes."""

from __future__ import annotations

import ast
from pathlib import Path

import numpy as np
import pytest

from critmoment import groundtruth as gt
from critmoment import validation as val
from critmoment.exceptions import ParameterError

PACKAGE = Path(gt.__file__).resolve().parent


def _imports(module: str) -> set[str]:
    tree = ast.parse((PACKAGE / f"{module}.py").read_text())
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module:
            out.add(node.module)
            out.update(f"{node.module}.{a.name}" for a in node.names)
        elif isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
    return out


def test_layering_has_no_cycle():
    """Ground truth below the audit, the validation study above both."""
    for low in ("groundtruth", "verdict"):
        imported = _imports(low)
        assert not {m for m in imported if m.startswith(("critmoment.analysis",
                                                         "critmoment.validation",
                                                         "critmoment.report"))}, low
    assert not {m for m in _imports("analysis") if m.startswith("critmoment.validation")}
    assert "critmoment.groundtruth" in _imports("analysis")
    assert "critmoment.verdict" in _imports("analysis")


def test_old_names_stay_importable_from_validation():
    for name in ("Outcome", "OutcomeCriteria", "Classification", "classify", "grip_slip",
                 "BruteForce", "brute_force", "rerun_in_full", "ends_completed"):
        assert getattr(val, name) is getattr(gt, name)


def _run(n=1, t=200):
    stage = np.zeros((n, t), np.int8)
    stage[:, 100:] = 4
    grip = np.zeros((n, t, 2), bool)
    grip[:, 50:, 0] = True
    support = np.zeros((n, t), bool)
    support[:, :100] = True
    carried = np.zeros(t, bool)
    carried[100:] = True
    return dict(dt=0.002, stage=stage, contact_gripper=grip, contact_support=support,
                nominal_carried=carried, actuator_norm=np.full((n, t, 1), 0.3))


def test_classify_takes_the_tasks_success_rule():
    """``completed`` (the task's success per run) wins over the stage-4 rule."""
    sig = _run(2)
    by_stage = gt.classify(**sig)
    assert by_stage.outcome == (gt.Outcome.SUCCESS, gt.Outcome.SUCCESS)
    ruled = gt.classify(**sig, completed=np.array([True, False]))
    assert ruled.outcome == (gt.Outcome.SUCCESS, gt.Outcome.NOT_COMPLETED)
    assert ruled.completed.tolist() == [True, False]
    with pytest.raises(ParameterError, match="completed"):
        gt.classify(**sig, completed=np.array([True]))


def test_a_reused_reference_gives_the_same_outcomes(twin, demo_traj):
    samples = np.array([[0.1, 1.0], [0.6, 0.3], [3.0, 1.0]])
    first = gt.brute_force(demo_traj, twin=twin, samples=samples[:1])
    assert first.reference is not None and first.reference.completed
    again = gt.brute_force(demo_traj, twin=twin, samples=samples[1:],
                           reference=first.reference)
    whole = gt.brute_force(demo_traj, twin=twin, samples=samples)
    assert first.outcome + again.outcome == whole.outcome
    np.testing.assert_array_equal(np.concatenate([first.classification.max_slip,
                                                  again.classification.max_slip]),
                                  whole.classification.max_slip)
    assert whole.outcome[0] is gt.Outcome.SUCCESS and whole.outcome[2] is not gt.Outcome.SUCCESS
