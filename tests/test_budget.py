"""Resource bounds: limits from the environment and options, refused before any work."""

from __future__ import annotations

import numpy as np
import pytest

from critmoment import budget
from critmoment.exceptions import ParameterError, ResourceLimitError


def test_defaults_environment_and_overrides(monkeypatch):
    assert budget.active() == budget.Budget()
    monkeypatch.setenv("CRITMOMENT_MAX_STEPS", "1000")
    assert budget.active().max_steps == 1000
    with budget.limits(max_steps=20, max_batch_steps=None) as b:
        assert budget.active() is b and b.max_steps == 20
        assert b.max_batch_steps == budget.Budget().max_batch_steps
    assert budget.active().max_steps == 1000
    monkeypatch.setenv("CRITMOMENT_MAX_STEPS", "lots")
    with pytest.raises(ParameterError, match="CRITMOMENT_MAX_STEPS: expected an integer >= 1"):
        budget.active()


@pytest.mark.parametrize("value", [0, -1, 1.5, True, "x", float("inf")])
def test_limits_are_positive_integers(value):
    with pytest.raises(ParameterError, match="expected an integer >= 1"):
        budget.Budget(max_steps=value)


def test_steps_are_duration_over_timestep():
    assert budget.check_steps(8.0, 0.002, what="demo") == 4000
    with budget.limits(max_steps=3999):
        with pytest.raises(ResourceLimitError, match=r"at most 3,999 physics steps.*got 4,000"
                                                     r".*--max-steps.*CRITMOMENT_MAX_STEPS"):
            budget.check_steps(8.0, 0.002, what="demo")
    with pytest.raises(ParameterError, match="time step"):
        budget.check_steps(8.0, 0.0, what="demo")


def test_astronomical_declarations_are_refused_quickly():
    with pytest.raises(ResourceLimitError, match="--max-input-bytes"):
        budget.check_bytes(8.0 * 10**13 * 10**6, what="a 72 TiB header")


@pytest.mark.parametrize("seed", [-1, 2**32, 2**64, 1.5, "7", None, True])
def test_seed_domain(seed):
    with pytest.raises(ParameterError, match="seed"):
        budget.check_seed(seed)


def test_seed_bounds_accepted():
    assert budget.check_seed(0) == 0
    assert budget.check_seed(np.uint32(2**32 - 1)) == 2**32 - 1


def test_analyze_refuses_before_any_work():
    """A seed numpy would reject, and a sweep beyond the limit, fail before the rollout."""
    import critmoment as cm
    from critmoment import analysis

    twin = cm.Twin(cm.load_scenario())
    traj = cm.Trajectory(np.zeros((400, 14)), fps=50.0, object_pose=[0, 0.5, 0.02, 1, 0, 0, 0])
    with pytest.raises(ParameterError, match=r"seed: expected an integer in \[0, 2\*\*32 - 1"):
        analysis.analyze(traj, twin=twin, options=analysis.AnalyzeOptions(seed=-1))
    with pytest.raises(ResourceLimitError, match="sparse sweep"):
        analysis.analyze(traj, twin=twin, options=analysis.AnalyzeOptions(n_samples=10**9))
    with budget.limits(max_steps=100), pytest.raises(ResourceLimitError, match="rollout"):
        analysis.analyze(traj, twin=twin)


def test_limits_hold_in_the_audits_own_threads(monkeypatch, twin, demo_traj):
    """The budget lives in a context variable: the audit's physics thread and its shared-out
    sweeps ran with the environment's limit, so `--max-steps 10000` over
    CRITMOMENT_MAX_STEPS=3000 failed the verification rollouts with "raise the limit with
    --max-steps" (a one-thread audit and rollout/validate passed)."""
    from critmoment.analysis import AnalyzeOptions, analyze

    monkeypatch.setenv("CRITMOMENT_MAX_STEPS", "3000")
    assert demo_traj.duration / twin.model.opt.timestep > 3000
    with budget.limits(max_steps=10_000):
        res = analyze(demo_traj, twin=twin, options=AnalyzeOptions(n_samples=16, nthread=2))
    assert res.verdict is not None


def test_an_audit_stopped_in_its_main_thread_stops_its_physics_thread(twin, demo_traj):
    """An interrupt or a timeout in the caller's thread waited for the physics thread to
    finish its stage (4 s on the demo, minutes on a long run: past a CI runner's grace
    before SIGKILL). The physics thread now stops at its next batch: its stage never says
    it is done, and no worker is left running."""
    import threading
    import time

    from critmoment.analysis import AnalyzeOptions, analyze

    class Stop(Exception):
        pass

    said = []

    def progress(text):
        said.append((threading.current_thread() is threading.main_thread(), text))
        if said[-1][0] and "critical values ..." in text:
            raise Stop

    before = threading.active_count()
    with pytest.raises(Stop):
        analyze(demo_traj, twin=twin, progress=progress,
                options=AnalyzeOptions(n_samples=64, nthread=2))
    time.sleep(0.5)
    assert threading.active_count() == before
    worker = [text for main, text in said if not main]
    assert any("chained segments ..." in t or "verification ..." in t for t in worker)
    assert not any("chained segments done" in t for t in worker)
