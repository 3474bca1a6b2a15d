"""The frequent rollout and its Recording: replay a trajectory, record state and safety signals.

:func:`simulate` steps one or many full trajectories through
``mujoco.batch.Batch.rollout`` (C loop, thread pool, per-simulation parameters):
the frequent rollout is the case n = 1 at nominal parameters, and brute-force
validation (``critmoment.validation``) is the same call with n parameter samples.

:func:`rollout` returns a :class:`Recording`: the integration state before every
physics step (restorable bit-exactly, warmstart included), the sensor data of
every step and the safety signals derived from it.
"""

from __future__ import annotations

import dataclasses
import json
import math
import warnings
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import mujoco
import mujoco.batch
import numpy as np

from critmoment import budget, safety
from critmoment import trajectory as trajectory_mod
from critmoment.exceptions import (
    CritmomentWarning,
    InputFileError,
    ParameterError,
    ScenarioError,
    SimulationDivergedError,
    TrajectoryError,
)
from critmoment.scenario import Scenario
from critmoment.task import Task, TaskEvidence
from critmoment.trajectory import Trajectory
from critmoment.twin import (
    STATE_SPEC,
    Signals,
    Twin,
    entry_point,
    model_digest,
    resolve_twin,
    warn_once,
)

__all__ = [
    "Recording",
    "check_recording",
    "rollout",
    "simulate",
    "prepare_controls",
    "initial_state",
    "task_completed",
    "ends_completed",
    "batched_rollouts",
    "model_hash",
]

_WARNING_NAMES = [mujoco.mjtWarning(i).name for i in range(mujoco.mjtWarning.mjNWARNING)]


def model_hash(source: Twin | Scenario | mujoco.MjModel) -> str:
    """SHA-256 of the model MuJoCo compiled (its binary MJB form: every number and name it
    simulates with, whatever the files it came from, includes and meshes included, and
    whatever lies beside them), for a :class:`Twin` (its model as it loaded, kept at
    construction), an ``MjModel``, or a :class:`Scenario` (compiled here). It had hashed the
    ``*.xml`` files beside the scene when the report was written: an unrelated XML there
    changed it, an included file in a subfolder or a mesh did not, nor did a file edited
    during the audit."""
    if isinstance(source, Twin):
        return source.model_sha256
    if not isinstance(source, mujoco.MjModel):
        return Twin(source).model_sha256
    return model_digest(source)


def _range_policy(range_policy: Any, twin: Twin) -> trajectory_mod.RangePolicy:
    """The range policy asked for (None: the scenario's), checked."""
    value = twin.scenario.range_policy if range_policy is None else range_policy
    names = [p.name.lower() for p in trajectory_mod.RangePolicy]
    if not isinstance(value, str) or value.lower() not in names:
        raise ParameterError(f"range_policy: expected one of {', '.join(names)} (or None for "
                             f"the scenario's [actions] range_policy), got {value!r}")
    return trajectory_mod.RangePolicy[value.upper()]


def prepare_controls(twin: Twin, traj: Trajectory, *, range_policy: str | None = None) -> np.ndarray:
    """Validate a trajectory against the twin and upsample it to controls at the physics rate.

    Args:
        twin: the twin.
        traj: the trajectory (actions at ``traj.fps``).
        range_policy: "error", "clip" or "warn" for targets outside joint ranges
            (default: the scenario's).

    Returns:
        (n_steps, nu) controls, one row per physics step.
    """
    conv = twin.scenario.actions
    if traj.n_channels != conv.width:
        raise TrajectoryError(
            f"expected {conv.width} action values per step for convention {conv.name!r} "
            f"({', '.join(conv.labels)}), got {traj.n_channels}")
    policy = _range_policy(range_policy, twin)
    actions = trajectory_mod.check_ranges(traj.actions, twin.channel_lower, twin.channel_upper,
                                          policy=policy, names=conv.labels)
    _check_rate(traj, float(twin.model.opt.timestep))
    return _upsampled_controls(twin, actions, traj.fps)


def _upsampled_controls(twin: Twin, rows: np.ndarray, fps: float) -> np.ndarray:
    """Control-rate rows in the action convention, one control per physics step."""
    # the interpolation stays within the channel's range or the values the policy kept
    # beyond it: a target past a joint's limit that the policy kept (a heavy hand's lift
    # slide, ADROIT's ARTy, commanded past its range to hold its weight) is replayed as
    # recorded, as MuJoCo would get it, not clipped after being reported kept
    lower = np.minimum(twin.channel_lower, rows.min(axis=0))
    upper = np.maximum(twin.channel_upper, rows.max(axis=0))
    targets = trajectory_mod.upsample(rows, fps=fps, physics_dt=float(twin.model.opt.timestep),
                                      bounded=twin.channel_normalised,
                                      lower=lower, upper=upper)
    return twin.controls(targets)


def observed_controls(twin: Twin, traj: Trajectory) -> np.ndarray | None:
    """The controls that would make each servo's target the joints' observed path
    (``traj.observed``, upsampled as the actions are), (n_steps, nu), or None without one:
    what :func:`critmoment.feasibility.check_feasibility` compares the joints with where
    their targets lead them by design."""
    if traj.observed is None or traj.n_channels != twin.scenario.actions.width:
        return None
    return _upsampled_controls(twin, np.asarray(traj.observed, dtype=np.float64), traj.fps)


def _check_rate(traj: Trajectory, dt: float) -> None:
    if traj.fps * dt > 1.0 + 1e-9:
        # the targets are held over the physics steps between two rows (upsampled); a
        # faster trajectory would skip rows without saying so
        raise TrajectoryError(
            f"trajectory at {traj.fps:g} Hz{_source(traj)}: expected at most the physics rate, "
            f"{1.0 / dt:g} Hz (the model's timestep {dt:g} s); resample it to {1.0 / dt:g} Hz "
            f"or less (e.g. keep one row in {math.ceil(traj.fps * dt - 1e-9)}), or lower the "
            f"model's timestep")



def in_channel_order(traj: Trajectory, twin: Twin) -> Trajectory:
    """The trajectory's columns in the scenario's channel order, where its file names them
    (``meta["action_names"]``: a LeRobot dataset's ``features.action.names``) and the names
    are the scenario's channel labels in another order (compared as
    :func:`critmoment.trajectory._channel_keys` does: ``left_waist`` is ``left/waist``),
    with a warning; the same order, or names that are not the labels, leave it as it is.

    Raises:
        TrajectoryError: some names are channel labels at other positions, but not all of
            them are labels (the order cannot be mapped).
    """
    names = (traj.meta or {}).get("action_names")
    labels = list(twin.scenario.actions.labels)
    if not isinstance(names, list) or len(names) != len(labels):
        return traj
    have, want = trajectory_mod._channel_keys(names), trajectory_mod._channel_keys(labels)
    if have == want:
        return traj
    if sorted(have) == sorted(want) and len(set(have)) == len(have):
        order = [have.index(k) for k in want]
        moved = [f"{labels[i]} <- column {j} ({names[j]})" for i, j in enumerate(order)
                 if i != j]
        warn_once(f"the trajectory{_source(traj)} names its action columns in another order "
                  f"than the scenario's channels; mapped by name: {', '.join(moved[:6])}"
                  f"{' ...' if len(moved) > 6 else ''}", CritmomentWarning, stacklevel=3)
        start = None if traj.start is None else np.asarray(traj.start)[order]
        observed = None if traj.observed is None else np.asarray(traj.observed)[:, order]
        meta = dict(traj.meta)
        meta["action_names"] = [names[j] for j in order]  # as the columns now are
        return dataclasses.replace(traj, actions=np.asarray(traj.actions)[:, order],
                                   start=start, meta=meta, observed=observed)
    astray = [f"{names[j]!r} (column {j}, the scenario's channel {want.index(k)})"
              for j, k in enumerate(have) if k in want and want.index(k) != j]
    if astray:
        raise TrajectoryError(
            f"the trajectory{_source(traj)} names its action columns {names}, the scenario's "
            f"channels are {labels}: {', '.join(astray[:4])} sit at other positions, and not "
            f"every column is one of the channels; expected the scenario's order (reorder the "
            f"data, or the scenario's [[actions.channel]] tables)")
    return traj


def at_scenario_rate(traj: Trajectory, twin: Twin) -> Trajectory:
    """The trajectory at the scenario's ``[actions] fps`` where its file recorded no rate
    (:meth:`Trajectory.with_rate_from`), its columns in the scenario's channel order where
    the file names them (:func:`in_channel_order`); a recorded rate, or a scenario that
    states none, leaves the rate as it is (a recorded rate other than the scenario's by more
    than 1 % is warned of). Every entry point (``analyze``, ``rollout``, ``validate``, the
    CLI) applies it, so a library call reads a file as the command line does."""
    traj = in_channel_order(traj, twin)
    sc = twin.scenario
    if not sc.fps_given:
        return traj
    rated = traj.with_rate_from(sc.fps)
    _check_rate(rated, float(twin.model.opt.timestep))  # refused before it is warned of
    if not traj.fps_assumed and not trajectory_mod._rates_agree(traj.fps, sc.fps):
        warn_once(f"the trajectory{_source(traj)} records {traj.fps:g} Hz, the scenario's "
                  f"[actions] fps says {sc.fps:g} Hz: the recorded rate is used",
                  CritmomentWarning, stacklevel=2)
    return rated


def _too_short(duration: float) -> str:
    """A hint where the trajectory, not the scenario, is the likely mistake."""
    return (f": a trajectory of {duration:g} s is too short to audit (a chunk of a few "
            "samples? give the whole motion)" if duration < 0.2 else "")


def check_task_window(twin: Twin, traj: Trajectory) -> None:
    """The task's final window (``settle_time``) must be at most half the motion, or its
    success rule reaches back toward the start, where the object rests untouched on its
    support, and no run can succeed (an audit or validation would blame every sample).
    The sparse ``persistence`` likewise: an excursion that must last most of the motion
    to count would pass nearly any slip.

    Raises:
        ScenarioError: naming both durations.
    """
    if float(traj.fps) * float(twin.model.opt.timestep) > 1.0 + 1e-9:
        return  # rows faster than the physics steps: the rollout refuses it, naming both rates
    duration = traj.n_steps / traj.fps
    if twin.task.settle_time > 0.5 * duration:
        raise ScenarioError(
            f"[task] settle_time: {twin.task.settle_time:g} s, but the trajectory{_source(traj)} "
            f"lasts {duration:g} s; expected a final window of at most half the motion "
            f"(default 0.05 s, where [task] sets none){_too_short(duration)}")
    persistence = twin.scenario.sparse.persistence
    if persistence > 0.5 * duration:
        raise ScenarioError(
            f"[sparse] persistence: {persistence:g} s, but the trajectory{_source(traj)} lasts "
            f"{duration:g} s; expected a time a contact-FOS excursion must last to count "
            f"(default 0.02 s, where [sparse] sets none), at most half the motion (else almost "
            f"no excursion counts){_too_short(duration)}")
    creep = twin.scenario.sparse.creep_horizon * float(twin.model.opt.timestep)
    if creep >= duration:
        raise ScenarioError(
            f"[sparse] creep_horizon: {twin.scenario.sparse.creep_horizon} physics steps = "
            f"{creep:g} s, but the trajectory{_source(traj)} lasts {duration:g} s; expected "
            f"a creep window shorter than the motion (0 for off)")


def checked_start(twin: Twin, traj: Trajectory, *, range_policy: str | None = None,
                  tolerance: float = 0.05) -> np.ndarray:
    """The trajectory's start (its joints' and grippers' first positions, in action units)
    after the range policy (default: the scenario's): a value outside its channel's range
    (the joint's range; a gripper's normalised [0, 1]) is an error, a warning, or clipped
    with a warning, as an action would be. The actions' own check names the step; the
    start has none, and a start far outside a joint's range otherwise shows only later, as a
    motor that cannot follow. ``tolerance`` is a fraction of each channel's range: a
    recorded start (an observed position, a gripper a little past its normalised end) may
    lie just outside it.

    Raises:
        TrajectoryError: a value out of range under the ``error`` policy.
    """
    start = np.asarray(traj.start, dtype=np.float64)
    lo, hi = np.asarray(twin.channel_lower), np.asarray(twin.channel_upper)
    slack = tolerance * np.where(np.isfinite(hi - lo), hi - lo, 0.0)
    bad = (start < lo - slack) | (start > hi + slack)
    if not bad.any():
        return start
    labels = twin.scenario.actions.labels
    items = "; ".join(f"{labels[c]} = {start[c]:g} (range [{lo[c]:g}, {hi[c]:g}])"
                      for c in np.flatnonzero(bad)[:6])
    more = int(bad.sum()) - 6
    message = (f"trajectory start{_source(traj)}: {int(bad.sum())} value(s) outside their "
               f"channel's range: {items}{f'; and {more} more' if more > 0 else ''}")
    policy = _range_policy(range_policy, twin)
    if policy is trajectory_mod.RangePolicy.ERROR:
        raise TrajectoryError(
            f"{message}; expected the robot's first positions within its joint ranges (a "
            f"start in other units, degrees or mm?), or set [actions] range_policy = "
            f"\"clip\" or \"warn\"")
    clip = policy is trajectory_mod.RangePolicy.CLIP
    warnings.warn(message + ("; clipped into range" if clip else ""), CritmomentWarning,
                  stacklevel=3)
    return np.clip(start, lo, hi) if clip else start


def _source(traj: Trajectory) -> str:
    return f" ({traj.source})" if traj.source else ""


def initial_state(twin: Twin, traj: Trajectory, model: mujoco.MjModel | None = None) -> np.ndarray:
    """Integration state (nstate,) at the start of the trajectory, controls set to its first
    action. A start (``traj.start``) outside its channels' ranges is treated by the
    scenario's range policy, as the actions are: an error, a warning, or clipped."""
    start = (checked_start(twin, traj) if traj.start is not None else traj.actions[0])
    model = model or twin.model
    if traj.start is not None and traj.qpos0 is not None:
        twin.warn_start_disagreement(traj.qpos0, start, model)
    data = twin.initial_data(start=start, qpos0=traj.qpos0, object_pose=traj.object_pose,
                             model=model, qvel0=traj.qvel0)
    return twin.get_state(model, data)


def _divergence_words(warning: str) -> str:
    """How a simulation diverged, from :func:`simulate`'s ``warnings`` entry."""
    if warning.startswith("the object reached"):
        return f" ({warning})"
    words = f" with MuJoCo warnings [{warning or 'non-finite values'}]"
    if "mjWARN_CNSTRFULL" in warning or "mjWARN_CONTACTFULL" in warning:
        words += (" (the model's arena is full: it had no room for the contacts and "
                  "constraints, which MuJoCo then dropped; raise <size memory=\"...\"/> in "
                  "the MJCF)")
    return words


#: the fastest an object may move [m/s], beyond the speed a fall from the highest point it
#: has reached gives it (sqrt(2·|g|·drop): a fall is physical however long), before its
#: simulation counts as diverged; a manipulated object moves at a few m/s
MAX_OBJECT_SPEED = 10.0


def simulate(twin: Twin, state0: np.ndarray, controls: np.ndarray, *,
             samples: np.ndarray | None = None, record_state: bool = False,
             nthread: int = 0, batch: mujoco.batch.Batch | None = None) -> dict[str, np.ndarray]:
    """Roll out full trajectories, batched over parameter samples.

    Args:
        twin: the twin.
        state0: initial integration state, (nstate,) or (n, nstate).
        controls: controls per physics step, (T, nu) or (n, T, nu).
        samples: parameter values (n, k) in the box's order, or None for nominal (n = 1
            unless state0/controls say otherwise).
        record_state: also return the integration state after every step.
        nthread: threads (0: all CPUs).
        batch: a Batch of the twin's model with ``n`` simulations to reuse.

    Returns:
        ``sensordata`` (n, T, nsensordata), ``time`` (n, T) (time after each step),
        ``diverged`` (n,) bool, ``diverged_step`` (n,) int (−1 when fine),
        ``warnings`` (n,) str, and with ``record_state`` ``state`` (n, T, nstate).

    Raises:
        ParameterError: arrays of the wrong shape or kind, different numbers of
            simulations, a reused ``batch`` of another size, or too many threads.
        ResourceLimitError: more than ``max_steps`` per simulation, or ``max_batch_steps``
            in all (:mod:`critmoment.budget`).
    """
    state0, controls, samples, n = _simulate_inputs(twin, state0, controls, samples)
    nstep = controls.shape[-2]
    budget.check_step_count(nstep, n=n, what=f"simulate: {n} rollout(s) of {nstep:,} "
                                             f"physics steps")
    if batch is None:
        batch = mujoco.batch.Batch(twin.model, n, nthread=budget.check_nthread(nthread))
    elif batch.nsim != n:
        raise ParameterError(f"batch: expected a Batch of {n} simulations (the samples, "
                             f"states or controls given), got one of {batch.nsim}")
    if samples is not None:
        twin.write_parameters(batch, samples)
    batch.state[:] = state0
    # a reused batch keeps its simulations' warning counters: a simulation that went
    # unstable in an earlier call would mark the next one in its slot diverged
    batch.warning[...] = 0
    ctrl = np.broadcast_to(controls, (n, nstep, controls.shape[-1]))
    ctrl = np.ascontiguousarray(ctrl)
    record: list = ["sensordata"]
    if record_state:
        record.append(int(STATE_SPEC))
    else:
        record.append(int(mujoco.mjtState.mjSTATE_TIME))
    out = batch.rollout(nstep, control=ctrl, control_spec=int(mujoco.mjtState.mjSTATE_CTRL),
                        record=record)
    result = {"sensordata": out["sensordata"]}
    if record_state:
        states = out[int(STATE_SPEC)]
        result["state"] = states
        time = states[:, :, 0]
    else:
        time = out[int(mujoco.mjtState.mjSTATE_TIME)][:, :, 0]
    result["time"] = time
    counts = batch.warning[:, :, 1]
    diverged = (counts > 0).any(axis=1) | ~np.isfinite(out["sensordata"]).all(axis=(1, 2))
    # an object thrown faster than MAX_OBJECT_SPEED: a solver that did not converge (a
    # Panda with tolerance 0.01 and 3 line-search iterations launched its cube at 21 m/s
    # and on to 245 km away, with no MuJoCo warning; audited as UNSAFE with invented causes)
    with np.errstate(invalid="ignore", over="ignore"):
        speed = np.linalg.norm(out["sensordata"][..., twin._vel_adr], axis=-1)  # (n, T)
    # a fall is physical however long (an object posed off its support falls through the
    # world, an input error the rollout's checks name): the speed a fall from the highest
    # point the object has reached gives it is allowed on top
    gravity = np.asarray(twin.model.opt.gravity, dtype=np.float64)
    g = float(np.linalg.norm(gravity))
    with np.errstate(invalid="ignore", over="ignore"):
        height = (out["sensordata"][..., twin._pos_adr] @ (-gravity / g) if g > 0
                  else np.zeros(speed.shape))
        drop = np.maximum.accumulate(np.nan_to_num(height, nan=0.0), axis=1) - height
        thrown = speed > MAX_OBJECT_SPEED + np.sqrt(2.0 * g * np.maximum(drop, 0.0))
    flung = thrown.any(axis=1) & ~diverged
    diverged |= flung
    stopped = np.zeros(n, dtype=np.int64) - 1
    for i in np.flatnonzero(diverged):
        if flung[i]:
            stopped[i] = int(np.argmax(thrown[i]))
        elif counts[i].any():
            # the batch stops a simulation after the step whose warning counters rose and
            # repeats that step's record: that step is the last one whose time changed
            changed = np.flatnonzero(np.diff(time[i]) != 0)
            stopped[i] = int(changed[-1] + 1) if changed.size else 0
        else:
            stopped[i] = int(np.argmax(~np.isfinite(out["sensordata"][i]).all(axis=-1)))
    result["diverged"] = diverged
    result["diverged_step"] = stopped
    result["warnings"] = np.array([
        f"the object reached {float(np.nanmax(speed[i])):.3g} m/s, over {MAX_OBJECT_SPEED:g} "
        f"m/s beyond a fall's speed: not a physical motion (the solver's iterations, "
        f"tolerance or the contacts' solref)"
        if flung[i] else
        ", ".join(_WARNING_NAMES[w] for w in np.flatnonzero(counts[i])) for i in range(n)])
    return result


def _simulate_inputs(twin: Twin, state0: Any, controls: Any, samples: Any
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray | None, int]:
    """:func:`simulate`'s arrays, checked: (state0, controls, samples, simulations)."""
    from critmoment.sparse import check_samples

    nstate = mujoco.mj_stateSize(twin.model, STATE_SPEC)
    nu = twin.model.nu
    arrays = {}
    for name, value, shapes in (("state0", state0, f"({nstate},) or (n, {nstate})"),
                                ("controls", controls, f"(T, {nu}) or (n, T, {nu})")):
        try:
            arr = np.asarray(value, dtype=np.float64)
        except (TypeError, ValueError):
            raise ParameterError(f"{name}: expected a real array of shape {shapes}, got "
                                 f"{type(value).__name__}") from None
        arrays[name] = arr
    state0, controls = arrays["state0"], arrays["controls"]
    if state0.ndim not in (1, 2) or state0.shape[-1] != nstate:
        raise ParameterError(f"state0: expected shape ({nstate},) or (n, {nstate}) (the "
                             f"twin's integration state), got {state0.shape}")
    if controls.ndim not in (2, 3) or controls.shape[-1] != nu or controls.shape[-2] < 1:
        raise ParameterError(f"controls: expected shape (T, {nu}) or (n, T, {nu}) with T >= 1 "
                             f"(one row per physics step), got {controls.shape}")
    if samples is not None:
        samples = check_samples(twin.scenario.box, samples)
    sizes = {name: size for name, size in (
        ("samples", None if samples is None else samples.shape[0]),
        ("state0", state0.shape[0] if state0.ndim == 2 else None),
        ("controls", controls.shape[0] if controls.ndim == 3 else None)) if size is not None}
    if len(set(sizes.values())) > 1:
        raise ParameterError(f"samples, state0 and controls: expected the same number of "
                             f"simulations n, got {sizes}")
    return state0, controls, samples, max(sizes.values(), default=1)


def task_completed(stage: np.ndarray, *, dt: float, debounce: float = 0.02) -> np.ndarray:
    """Whether the task reached stage 4 and kept it to the end.

    Drops out of stage 4 shorter than ``debounce`` [s] (contact chatter of a firm grasp) are
    ignored; a longer drop, or a final stage below 4, means the task failed.

    Args:
        stage: task stage per step, (..., T).
        dt: physics step [s].
        debounce: longest ignored drop [s].

    Returns:
        (...) bool.
    """
    stage = np.asarray(stage)
    at4 = stage >= 4
    reached = at4.any(axis=-1)
    first = np.argmax(at4, axis=-1)
    width = max(1, int(round(debounce / dt)))
    t = stage.shape[-1]
    idx = np.arange(t)
    after = idx >= first[..., None]
    lost = after & ~at4
    # length of each run of lost steps: a run longer than `width` (or one that reaches the
    # end of the recording) breaks completion
    ok = np.empty(stage.shape[:-1], dtype=bool)
    flat_lost = lost.reshape(-1, t)
    flat_ok = ok.reshape(-1)
    for i, row in enumerate(flat_lost):
        if not row.any():
            flat_ok[i] = True
            continue
        edges = np.diff(np.concatenate([[0], row.astype(np.int8), [0]]))
        starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
        flat_ok[i] = bool(((ends - starts) <= width).all() and ends[-1] < t)
    return ok & reached


def ends_completed(stage: np.ndarray) -> np.ndarray:
    """Whether each run *ends* with the task completed (stage 4 at its last step).

    The outcome rule of brute-force validation (:mod:`critmoment.validation`) and of the
    audit's verification rollouts. It is more lenient than :func:`task_completed` in one
    way: a loss of stage 4 before the final acquisition does not count, so a receiver that
    bumps into the object before it closes on it (stage 4 for a few steps, then 2 again, then
    4 to the end) completes the task. ACT itself counts an episode as a success once stage 4
    is reached at all.

    Args:
        stage: task stage per step, (..., T).

    Returns:
        (...) bool.
    """
    stage = np.asarray(stage)
    if stage.ndim == 0 or stage.shape[-1] == 0:
        return np.zeros(stage.shape[:-1] if stage.ndim else (), dtype=bool)
    return stage[..., -1] >= 4


def batched_rollouts(twin: Twin, state0: np.ndarray, controls: np.ndarray, samples: np.ndarray,
                     *, model: mujoco.MjModel | None = None, chunk: int = 16,
                     nthread: int = 0) -> Iterator[tuple[int, dict[str, np.ndarray], np.ndarray]]:
    """Full rollouts of many parameter samples, in equal chunks of at most ``chunk``.

    A whole 8 s rollout records (T, nsensordata) floats per simulation (about 6 MB for the
    bundled scenario), so the samples go through :func:`simulate` a chunk at a time, each
    chunk batched over MuJoCo's thread pool; at most two Batch objects are made.

    Args:
        twin: the twin.
        state0: initial integration state, (nstate,).
        controls: controls per physics step, (T, nu).
        samples: parameter values, (n, k).
        model: the twin's model or one with sensors appended after the twin's
            (:meth:`Twin.add_sensors`); default the twin's.
        chunk: most simulations per batch call.
        nthread: threads (0: all CPUs).

    Yields:
        (index of the chunk's first sample, :func:`simulate`'s result, the friction of the
        object's contacts per simulation (c,)).
    """
    model = twin.model if model is None else model
    total = samples.shape[0]
    if total == 0:
        return
    size = -(-total // -(-total // max(1, int(chunk))))  # equal chunks: two sizes at most
    batches: dict[int, mujoco.batch.Batch] = {}
    for start in range(0, total, size):
        rows = samples[start:start + size]
        batch = batches.get(rows.shape[0])
        if batch is None:
            batch = batches[rows.shape[0]] = mujoco.batch.Batch(
                model, rows.shape[0], nthread=budget.check_nthread(nthread))
        out = simulate(twin, state0, controls, samples=rows, nthread=nthread, batch=batch)
        mu = np.broadcast_to(twin.grip_friction(batch.expanded("geom_friction"),
                                                batch.expanded("pair_friction")),
                             (rows.shape[0],)).copy()
        yield start, out, mu


@dataclasses.dataclass(frozen=True)
class Recording:
    """What the frequent rollout recorded.

    Step k is the physics step from ``state[k]`` to ``state[k + 1]``; ``sensordata[k]`` and the
    signals at k are the forces of that step (MuJoCo computes them at the start of the step).

    Attributes:
        dt: physics step [s].
        states: integration state before each step and after the last, (T + 1, nstate).
        sensordata: sensor readings of each step, (T, nsensordata).
        controls: controls applied at each step, (T, nu).
        signals: safety signals, leading shape (T,).
        nominal: nominal parameter values, (k,).
        parameter_names: names of the parameters.
        gripper_names: names of the grippers (order of fos_contact's columns).
        actuator_names: names of the actuators.
        scenario_name: the scenario's name.
        model_sha256: hash of the MJCF files.
        source: the trajectory's source.
        task: the scenario's task (decides :attr:`completed`).
        base_axis: the up axes of the robot's free-floating bases at each step, (T, B, 3),
            or None (a robot fixed to the world; ``Twin.base_axis``), for the task's rule.
    """

    dt: float
    states: np.ndarray
    sensordata: np.ndarray
    controls: np.ndarray
    signals: Signals
    nominal: np.ndarray
    parameter_names: tuple[str, ...]
    gripper_names: tuple[str, ...]
    actuator_names: tuple[str, ...]
    scenario_name: str
    model_sha256: str
    source: str = ""
    task: Task | None = None
    base_axis: np.ndarray | None = None

    # signal shortcuts, as read by moments.py
    @property
    def n_steps(self) -> int:
        return int(self.sensordata.shape[0])

    @property
    def time(self) -> np.ndarray:
        return np.arange(self.n_steps) * self.dt

    @property
    def object_acc(self) -> np.ndarray:
        return self.signals.object_acc

    @property
    def actuator_norm(self) -> np.ndarray:
        return self.signals.actuator_norm

    @property
    def fos_contact(self) -> np.ndarray:
        return self.signals.fos_contact

    @property
    def fos_motor(self) -> np.ndarray:
        return self.signals.fos_motor

    @property
    def cost(self) -> np.ndarray:
        return self.signals.cost

    @property
    def contact_support(self) -> np.ndarray:
        return self.signals.contact_support

    @property
    def contact_gripper(self) -> np.ndarray:
        return self.signals.contact_gripper

    @property
    def stage(self) -> np.ndarray:
        return self.signals.stage

    @property
    def completed(self) -> bool:
        """The scenario's task succeeded in this run (:meth:`critmoment.task.Task.success`)."""
        return bool(self.task.success(self.task_evidence()))

    def task_evidence(self) -> TaskEvidence:
        """What this run shows of the object, for the task's rule."""
        if self.task is None:
            raise ParameterError("this recording carries no task; expected one from rollout() "
                                 "or Recording.load(path, twin)")
        return TaskEvidence(
            contact_gripper=self.signals.contact_gripper,
            contact_support=self.signals.contact_support, object_pos=self.signals.object_pos,
            object_vel=self.signals.object_vel, dt=self.dt, base_axis=self.base_axis)

    def shortfalls(self) -> list[str]:
        """What this run lacks of the task's rule, in words (:meth:`Task.shortfalls`);
        empty when it completes the task (each task's shortfalls are the parts of its
        success rule)."""
        return self.task.shortfalls(self.task_evidence())

    def stage_first_step(self) -> dict[int, int | None]:
        """First step at which each of the task's stages after 0 is reached (None if
        never): 1..4 for handover and pick_place, 1..2 for pick_hold."""
        out: dict[int, int | None] = {}
        names = getattr(self.task, "stage_names", None)
        last = len(names) - 1 if names else 4
        for k in range(1, last + 1):
            hits = np.flatnonzero(self.stage >= k)
            out[k] = int(hits[0]) if hits.size else None
        return out

    def summary(self) -> dict:
        """The JSON summary printed by ``critmoment rollout --json``."""
        sig = self.signals
        finite_c = sig.fos_grasp[np.isfinite(sig.fos_grasp)]
        return {
            "steps": self.n_steps,
            "dt": self.dt,
            "duration": self.n_steps * self.dt,
            "max_stage": int(sig.stage.max()),
            "final_stage": int(sig.stage[-1]),
            "completed": self.completed,
            "shortfalls": self.shortfalls(),
            "stage_first_step": {str(k): v for k, v in self.stage_first_step().items()},
            "min_fos_contact": float(finite_c.min()) if finite_c.size else None,
            "min_fos_motor": float(sig.fos_motor.min()),
            # no actuator limits anything where every motor FOS is infinite (no force limit)
            "limiting_actuator": (
                self.actuator_names[int(sig.motor_argmax[np.argmin(sig.fos_motor)])]
                if np.isfinite(sig.fos_motor).any() else None),
            "max_cost": float(sig.cost.max()),
            "max_cost_step": int(np.argmax(sig.cost)),
        }

    def sustained(self, scenario: Scenario) -> dict:
        """The contact FOS and cost held over ``scenario``'s ``[sparse] persistence`` (a
        one-step dip, contact chatter, does not count): what the audit's nominal cost
        compares with, where the one-step figures of :meth:`summary` can cross the
        threshold on a grasp that holds."""
        steps = max(1, int(round(scenario.sparse.persistence / self.dt)))
        sig = self.signals
        held = safety.sustained_fos(sig.fos_grasp, steps)
        finite = held[np.isfinite(held)]
        cost = safety.cost(held, sig.fos_motor, scenario.cost)
        return {"persistence": steps * self.dt,
                "min_fos_contact_sustained": float(finite.min()) if finite.size else None,
                "max_cost_sustained": float(cost.max()) if cost.size else 0.0,
                "max_cost_sustained_time": float(np.argmax(cost) * self.dt) if cost.size
                else 0.0,
                "threshold": float(scenario.cost.threshold)}

    def save(self, path: str | Path) -> Path:
        """Write the recording to an ``.npz`` file (signals are recomputed on load)."""
        path = Path(path)
        meta = {
            "dt": self.dt, "parameter_names": list(self.parameter_names),
            "gripper_names": list(self.gripper_names),
            "actuator_names": list(self.actuator_names), "scenario_name": self.scenario_name,
            "model_sha256": self.model_sha256, "source": self.source,
            "schema": "critmoment.recording/1",
        }
        np.savez_compressed(path, states=self.states, sensordata=self.sensordata,
                            controls=self.controls, nominal=self.nominal,
                            meta=np.array(json.dumps(meta)))
        return path

    @classmethod
    def load(cls, path: str | Path, twin: Twin) -> Recording:
        """Read a recording written by :meth:`save`; ``twin`` recomputes the signals."""
        path = Path(path)
        if not path.is_file():
            raise InputFileError(f"recording not found: {path}")
        try:
            with np.load(path, allow_pickle=False) as z:
                meta = json.loads(str(z["meta"]))
                arrays = {k: z[k] for k in ("states", "sensordata", "controls", "nominal")}
        except (OSError, ValueError, KeyError, RecursionError) as exc:
            raise InputFileError(f"{path}: not a critmoment recording ({exc})") from exc
        if arrays["sensordata"].shape[-1] != twin.nsensordata:
            raise InputFileError(
                f"{path}: recorded {arrays['sensordata'].shape[-1]} sensor values per step, the "
                f"scenario's twin has {twin.nsensordata}: recorded with another scenario?")
        mu = _friction_of(twin, arrays["nominal"])
        limits = twin.sample_limits(arrays["nominal"])
        signals = twin.signals(arrays["sensordata"], mu,
                               limits=None if limits is None else limits[0])
        return cls(dt=meta["dt"], states=arrays["states"], sensordata=arrays["sensordata"],
                   controls=arrays["controls"], signals=signals,
                   nominal=arrays["nominal"], parameter_names=tuple(meta["parameter_names"]),
                   gripper_names=tuple(meta["gripper_names"]),
                   actuator_names=tuple(meta["actuator_names"]),
                   scenario_name=meta["scenario_name"], model_sha256=meta["model_sha256"],
                   source=meta["source"], task=twin.task,
                   base_axis=twin.base_axis(arrays["sensordata"]))


def _friction_of(twin: Twin, values: np.ndarray) -> float:
    """Object contact friction for parameter values (k,): the friction parameter if any."""
    model = twin.copy_model()
    twin.write_parameters(model, np.asarray(values)[None])
    return twin.object_friction(model)


def check_recording(value: Any, what: str = "recording") -> Recording:
    """``value`` itself when it is a :class:`Recording`.

    Raises:
        ParameterError: anything else (a trajectory, a path), with what to call instead.
    """
    if not isinstance(value, Recording):
        raise ParameterError(f"{what}: expected a critmoment Recording (the frequent rollout: "
                             f"critmoment.rollout(trajectory, scenario)), got "
                             f"{type(value).__name__}")
    return value


@entry_point
def rollout(traj: Trajectory, scenario: Scenario | str | Path | None = None, *,
            twin: Twin | None = None, range_policy: str | None = None) -> Recording:
    """Run the frequent rollout of a trajectory at nominal parameters.

    The run is what was asked for: it is not checked against the scenario beyond what it
    cannot run at all (the width, the rate, out-of-range targets under ``range_policy =
    "error"``). ``critmoment rollout`` also warns of a run that does not fit its scenario
    (an object never touched, a start inside the table, a joint that cannot follow):
    :func:`critmoment.feasibility.check_fit` and
    :func:`critmoment.feasibility.check_feasibility` on the recording do that in Python;
    ``analyze`` refuses such runs.

    Args:
        traj: the trajectory.
        scenario: a Scenario, a path/name to load one, or None for the bundled scenario.
        twin: a twin to reuse (its scenario wins over ``scenario``).
        range_policy: override of the scenario's policy for out-of-range targets.

    Returns:
        The recording.

    Raises:
        SimulationDivergedError: the physics diverged; the message names the step.
        ResourceLimitError: more physics steps than ``max_steps``
            (:func:`critmoment.budget.check_rollout`), before anything is allocated.
    """
    traj = trajectory_mod.check_trajectory(traj)
    twin = resolve_twin(scenario, twin)
    traj = at_scenario_rate(traj, twin)
    budget.check_rollout(traj, twin)  # as the CLI: 10⁶ rows would ask for 11 GiB of states
    controls = prepare_controls(twin, traj, range_policy=range_policy)
    state0 = initial_state(twin, traj)
    out = simulate(twin, state0, controls, record_state=True, nthread=1)
    if out["diverged"][0]:
        step = int(out["diverged_step"][0])
        raise SimulationDivergedError(
            f"simulation diverged at physics step {step} (t = {step * twin.model.opt.timestep:.3f} s)"
            f"{_divergence_words(out['warnings'][0])}; expected a "
            f"stable rollout: check the trajectory's targets and the model", step=step)
    states = np.concatenate([state0[None], out["state"][0]], axis=0)
    sd = out["sensordata"][0]
    return Recording(
        dt=float(twin.model.opt.timestep), states=states, sensordata=sd, controls=controls,
        signals=twin.signals(sd), nominal=twin.scenario.box.nominal,
        parameter_names=twin.scenario.box.names, gripper_names=twin.scenario.gripper_names,
        actuator_names=twin.actuator_names, scenario_name=twin.scenario.name,
        model_sha256=twin.model_sha256, source=traj.source, task=twin.task,
        base_axis=twin.base_axis(sd))
