"""Each sample's own history: chained segments, and a drift detector (measured: not selective).

Sparse evaluation restores the *nominal* state at every moment, so it cannot see what a
sample's own parameters did to its state between moments: a heavier cube carried sideways
shifts a few millimetres in a force-limited grip, an arm sags, and the shifted pads collide
at the hand-over although the nominal moments look safe. :func:`estimate_drift` measures,
at every audited moment where the nominal run holds the object with one gripper, how far
each sample's own state moves away from the nominal run over a short trace (``horizon``
steps from the restored state, the sample's parameters, the recorded controls): the
object's position in the holding gripper's frame (all three axes: an off-centre shift
between the fingers counts here, unlike slip) and the actuated joints' positions. The
drift and its rate at the trace's end are extrapolated linearly over the rest of that
gripper's hold in the nominal run; a sample whose predicted drift exceeds
``drift_tolerance`` (or its joint lag ``lag_tolerance``) is *escalated*: its own full
rollout should decide it, like the audit's verification of near-threshold samples.

The linear extrapolation is a heuristic, and measured it is not selective: on the bundled
twin a 25-step trace from the nominal state mostly sees the heavier cube settling in the
grip right after the restore, the same in every seed, so it escalates nearly every sample
predicted safe (``benchmarks/history_study.py``).

:func:`chained_failures` carries each sample's own state instead: from the nominal state at
the first moment it runs the recorded controls with the sample's parameters through every
later moment and applies the sparse decision there, from the state the sample reached. It
costs the stepping from the first to the last moment per sample (under half a full rollout
on the bundled demo), so it is meant for the samples the sparse sweep predicts safe.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from critmoment.exceptions import ParameterError
from critmoment.sparse import SparseEvaluator, _object_in_grippers

__all__ = ["DriftEstimate", "estimate_drift", "ChainedResult", "chained_failures",
           "DRIFT_TOLERANCE", "LAG_TOLERANCE"]

#: predicted displacement of the object in its grip that escalates a sample [m]: half the
#: 3–5 mm off-centre shift that makes the bundled robot's pads collide at the hand-over
DRIFT_TOLERANCE = 0.002
#: predicted extra lag of an actuated joint that escalates a sample [rad]
LAG_TOLERANCE = 0.05


@dataclasses.dataclass(frozen=True, eq=False)
class DriftEstimate:
    """How far each sample's own state drifts from the nominal run, per moment.

    Attributes:
        steps: the moments traced, (m,) int64 (those where one gripper holds the object).
        samples: the parameter values, (n, k).
        horizon: steps of each trace.
        drift: object displacement in the holding gripper relative to the nominal run at the
            trace's end [m], (m, n).
        drift_rate: its rate of change over the trace's second half [m/s], (m, n).
        lag: largest actuated-joint position difference to the nominal run [rad or m],
            (m, n).
        lag_rate: its rate [rad/s], (m, n).
        remaining: time the gripper keeps holding alone in the nominal run after the
            trace [s], (m,).
        predicted_drift: drift + drift_rate × remaining [m], (m, n).
        predicted_lag: lag + lag_rate × remaining, (m, n).
        drift_tolerance: escalation limit of the predicted drift [m].
        lag_tolerance: escalation limit of the predicted lag.
    """

    steps: np.ndarray
    samples: np.ndarray
    horizon: int
    drift: np.ndarray
    drift_rate: np.ndarray
    lag: np.ndarray
    lag_rate: np.ndarray
    remaining: np.ndarray
    predicted_drift: np.ndarray
    predicted_lag: np.ndarray
    drift_tolerance: float
    lag_tolerance: float

    @property
    def escalate(self) -> np.ndarray:
        """(n,) bool: the sample's predicted drift or lag exceeds its tolerance at some
        moment: its own full rollout should decide it."""
        if self.steps.size == 0:
            return np.zeros(self.samples.shape[0], dtype=bool)
        bad = (self.predicted_drift > self.drift_tolerance) | (
            self.predicted_lag > self.lag_tolerance)
        return bad.any(axis=0)


def estimate_drift(evaluator: SparseEvaluator, steps: Any, samples: Any, *, horizon: int = 25,
                   drift_tolerance: float = DRIFT_TOLERANCE,
                   lag_tolerance: float = LAG_TOLERANCE) -> DriftEstimate:
    """Trace each sample from every moment where one gripper holds the object and predict
    its drift over the rest of that hold.

    Args:
        evaluator: the audit's sparse evaluator (its recording, twin and batches).
        steps: moments, physics step indices (m,) (moments where no gripper holds the
            object alone in the nominal run are skipped).
        samples: parameter values (n, k).
        horizon: steps of each trace (at least 4).
        drift_tolerance: predicted drift that escalates [m].
        lag_tolerance: predicted joint lag that escalates [rad].

    Returns:
        The :class:`DriftEstimate`; its ``escalate`` names the samples to roll out in full.
    """
    if isinstance(horizon, bool) or not isinstance(horizon, int) or horizon < 4:
        raise ParameterError(f"horizon: expected an integer >= 4 steps, got {horizon!r}")
    for name, value in (("drift_tolerance", drift_tolerance), ("lag_tolerance", lag_tolerance)):
        if not value > 0:
            raise ParameterError(f"{name}: expected a value > 0, got {value!r}")
    ev = evaluator
    samples = ev.check_samples(samples)
    steps = np.unique(np.asarray([int(s) for s in np.atleast_1d(steps)], dtype=np.int64))
    steps = steps[(steps >= 0) & (steps < ev.n_steps - 1)]
    twin = ev.twin
    model = twin.model
    dt = float(model.opt.timestep)
    alone = ev._alone
    holder = np.where(alone.any(axis=1), np.argmax(alone, axis=1), -1)
    traced = [int(k) for k in steps if holder[k] >= 0]
    rot = np.flatnonzero(twin.rotational)
    joints = model.actuator_trnid[rot, 0]
    qadr = model.jnt_qposadr[joints]
    m, n = len(traced), samples.shape[0]
    out = {name: np.zeros((m, n)) for name in ("drift", "drift_rate", "lag", "lag_rate")}
    remaining = np.zeros(m)
    time_offset = 1  # mjSTATE_INTEGRATION starts with the time
    for i, k in enumerate(traced):
        g = int(holder[k])
        tr = ev.trace(k, samples, nstep=horizon)
        s = tr["xpos"].shape[1]
        rel = _object_in_grippers(tr["xpos"], tr["xmat"], twin.object_body_id,
                                  ev._anchors[g:g + 1])[:, :, 0]  # (n, s, 3)
        nominal = ev._nominal_positions(k, s)[:, g]  # (s, 3)
        disp = rel - nominal[None]
        half = max(1, s // 2)
        out["drift"][i] = np.linalg.norm(disp[:, -1], axis=-1)
        out["drift_rate"][i] = np.linalg.norm(disp[:, -1] - disp[:, -1 - half], axis=-1) / (
            half * dt)
        # qpos is recorded after the step's integration: the nominal states one step on
        q_nom = ev._states[k + 1:k + 1 + s, time_offset + qadr]  # (s, J)
        dq = np.abs(tr["qpos"][:, :, qadr] - q_nom[None])
        out["lag"][i] = dq[:, -1].max(axis=-1)
        out["lag_rate"][i] = np.abs(dq[:, -1] - dq[:, -1 - half]).max(axis=-1) / (half * dt)
        run = alone[k:, g]
        end = int(np.argmin(run)) if not run.all() else run.size
        remaining[i] = max(0, end - s) * dt
    predicted_drift = out["drift"] + out["drift_rate"] * remaining[:, None]
    predicted_lag = out["lag"] + out["lag_rate"] * remaining[:, None]
    return DriftEstimate(steps=np.array(traced, dtype=np.int64), samples=samples,
                         horizon=int(horizon), remaining=remaining,
                         predicted_drift=predicted_drift, predicted_lag=predicted_lag,
                         drift_tolerance=float(drift_tolerance),
                         lag_tolerance=float(lag_tolerance), **out)


@dataclasses.dataclass(frozen=True, eq=False)
class ChainedResult:
    """Each sample carried through the moments on its own state (:func:`chained_failures`).

    Attributes:
        steps: the moments evaluated, in time order, (m,) int64.
        samples: the parameter values, (n, k).
        failure: the sparse decision (``sparse.Failure`` values) at each moment from the
            sample's own state, (m, n) int8.
        start: the step the chain starts from (the nominal state there).
        stepped: physics steps each sample took.
    """

    steps: np.ndarray
    samples: np.ndarray
    failure: np.ndarray
    start: int
    stepped: int

    @property
    def failed(self) -> np.ndarray:
        """(n,) bool: the sample fails at some moment of its own chain."""
        return (self.failure > 0).any(axis=0)


def chained_failures(evaluator: SparseEvaluator, steps: Any, samples: Any, *,
                     start: int | None = None) -> ChainedResult:
    """Carry each sample's own state from one nominal state through every later moment.

    The simulations start from the recorded state at ``start`` (default: the first
    moment), run the recorded controls with the sample's own parameters, and at each moment
    (in time order; one whose window overlaps the previous one's is skipped) are decided by
    the sparse decision over the horizon from the state they reached, not the nominal one.
    The cost is the stepping from ``start`` to the last moment's horizon, per sample.

    Args:
        evaluator: the audit's sparse evaluator.
        steps: moments, physics step indices (m,).
        samples: parameter values (n, k).
        start: the step the chain starts from.

    Returns:
        The :class:`ChainedResult`.
    """
    import mujoco

    ev = evaluator
    samples = ev.check_samples(samples)
    steps = np.unique(ev.check_steps(steps))
    first = int(steps[0]) if start is None else int(ev.check_steps([start])[0])
    steps = steps[steps >= first]
    h = ev.horizon
    kept: list[int] = []
    failures = []
    out = np.zeros((0, samples.shape[0]), dtype=np.int8)
    stepped = 0
    for lo in range(0, samples.shape[0], ev.chunk):
        chunk = samples[lo:lo + ev.chunk]
        batch, mu = ev._batch(chunk)
        batch.state[:] = ev._start_row(first)
        current = first
        part, kept = [], []
        stepped = 0
        for k in (int(s) for s in steps):
            if k < current:
                continue  # overlaps the previous window
            if k > current:
                batch.rollout(k - current, control=ev._controls[current:k][None],
                              control_spec=int(mujoco.mjtState.mjSTATE_CTRL),
                              record=(mujoco.mjtState.mjSTATE_TIME,))
                stepped += k - current
            sim = ev._simulate(batch, k, np.arange(batch.nsim), mu, keep_state=False,
                               restore=False)
            part.append(sim.failure)
            kept.append(k)
            current = k + h
            stepped += h
        failures.append(np.array(part, dtype=np.int8).reshape(len(kept), -1))
    out = np.concatenate(failures, axis=1) if failures else out
    return ChainedResult(steps=np.array(kept, dtype=np.int64), samples=samples, failure=out,
                         start=first, stepped=stepped)
