"""Critical moments of a recorded trajectory.

A *critical moment* is a physics step at which the safety of a manipulation is
most likely to be decided: the cube leaves the table (lift-off), passes from
one gripper to the other (hand-over), is put down again, or the forces in the
system change abruptly.  This module finds such candidates in a
:class:`Recording`-like object (the output of a "frequent rollout") from two
sources, merges them and ranks them:

1. **Change points** of a standardised multichannel safety signal (object
   acceleration, normalised actuator forces, bounded contact load) found with
   penalised kernel change-point detection (:func:`detect_change_points`).
2. **Contact events**: debounced changes of the contact flags between the
   object, the support (table) and each gripper
   (:func:`detect_contact_events`).
3. Candidates closer than a time window are merged, contact events winning
   (:func:`merge_moments`), and the result is ranked either by a user-supplied
   sensitivity callable (e.g. the worst cost of cheap physics evaluations at
   the corners of the uncertainty box) or by a heuristic
   (:func:`rank_moments`).

The estimator :class:`MomentDetector` follows the ``ruptures`` convention: all
heavy work happens in :meth:`MomentDetector.fit`, :meth:`MomentDetector.predict`
only ranks.  :func:`find_moments` chains both.

Design choices
--------------

*Search method and cost.*  ``ruptures.KernelCPD(kernel="linear")`` with a
penalty (exact PELT-type dynamic programming, implemented in C).  The linear
kernel is the l2 cost: it detects shifts of the *mean* of the standardised
channels, which is what a step in a force, a load or an acceleration level
looks like.  Its cost is a sum of squared residuals, so after standardisation
its scale is known and an information-criterion penalty is meaningful.  The C
implementation needs O(n) memory (no Gram matrix).  The ``rbf`` kernel was not
chosen: it needs a bandwidth, its cost is bounded per sample so the penalty
has no such calibration, and the pure-Python ``Pelt(model="rbf")`` builds an
n x n Gram matrix (80 GiB at n = 100 000).

*Standardisation.*  Each channel (of the signal ruptures sees) is centred on
its median and divided by ``max(sigma_noise, noise_floor * spread)``, where
``sigma_noise = 1.4826 * MAD(diff(x)) / sqrt(2)`` is the usual change-robust
estimate of the white-noise level (differences cancel the piecewise-constant
part) and ``spread = 1.4826 * MAD(x)`` the robust spread of the channel.  The
floor (default ``noise_floor = 0.5``) matters for simulated signals, which are
often smooth or exactly constant (noise estimate 0): a smooth drift is then
judged against half the channel's spread instead of being cut into many
pieces.  When both vanish the standard deviation is used, and an exactly
constant channel is dropped.

*Penalty.*  ``pen = penalty_scale * (d + 1) * ln(n)`` where ``n`` is the
number of samples ruptures sees and ``d`` the number of non-constant channels:
each change point adds ``d`` segment means and one location.  With
``penalty_scale = 1`` (default) this is the Bayesian information criterion
(BIC) for Gaussian noise of unit variance; the standardisation makes the noise
variance at most one.  On white noise (n = 2000, d = 3 or 17) it gives no
false change point.  A jump of ``delta`` (standardised units, Euclidean norm
over channels) between segments of ``n1`` and ``n2`` samples is found roughly
when ``n1 * n2 / (n1 + n2) * delta**2 > pen``.

*Memory bound.*  Signals longer than ``max_samples`` (default 2000) physics
steps are block-averaged by the factor ``k = ceil(T / max_samples)`` before
ruptures sees them, so ruptures never sees more than ``max_samples`` samples
whatever ``T``.  Breakpoints are mapped back to physics steps
(``step = k * index``) and then refined to one-step resolution by an exact
single-split search within ``+-2k`` steps on the full-rate features projected
on the direction of the detected jump (a matched filter, so the refinement is
not swamped by the full-rate noise of the other channels).  The raw full-rate
feature matrix (``T x d`` floats, 14 MB for T = 100 000, d = 17) is the
largest allocation.

*Debounce.*  A contact flag only changes state when the new value persists for
at least ``debounce`` seconds (default 10 ms, 5 steps at 500 Hz).  The event is
placed at the *first* step of that persisting run, so debouncing removes
chatter without delaying events.
"""

from __future__ import annotations

import dataclasses
import enum
import math
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import ruptures

from critmoment.exceptions import CritmomentError, ParameterError, TrajectoryError

__all__ = [
    "MomentLabel",
    "Moment",
    "ChangePoints",
    "MomentDetector",
    "debounce",
    "safety_features",
    "detect_change_points",
    "detect_contact_events",
    "detect_peak_loads",
    "merge_moments",
    "rank_moments",
    "find_moments",
    "plot_moments",
]

_MAD_TO_SIGMA = 1.4826  # MAD of a Gaussian times this is its standard deviation
_INV_FOS_MAX = 2.0  # 1/FOS is clipped to [0, _INV_FOS_MAX]


class MomentLabel(enum.Enum):
    """What happens at a critical moment.

    The declaration order is the priority used when candidates are merged and
    when they are ranked without a sensitivity: the first label wins.
    """

    LIFT_OFF = "lift-off"
    """The object leaves the support (table)."""
    HAND_OVER = "hand-over"
    """A gripper releases the object while another gripper holds it."""
    DROP = "drop"
    """The object touches the support again while no gripper holds it."""
    PLACE = "place"
    """The object touches the support again while a gripper holds it."""
    GRASP = "grasp"
    """A gripper starts touching the object."""
    RELEASE = "release"
    """A gripper stops touching the object and no other gripper holds it."""
    PEAK_LOAD = "peak-load"
    """The motor load peaks over the whole motion (a low of the motor FOS, with or
    without a contact event nearby): where the arm alone, or a heavier payload, may
    overload a joint."""
    CHANGE_POINT = "change-point"
    """Abrupt change of the safety signals without a contact event."""

    def __str__(self) -> str:  # print(moment.label) says lift-off
        return self.value


_PRIORITY = {label: rank for rank, label in enumerate(MomentLabel)}


@dataclass(frozen=True)
class Moment:
    """One candidate critical moment.

    Attributes:
        step: index of the physics step, ``0 <= step < T``.
        time: time of that step [s] (``recording.time[step]``).
        label: what happens at that step.
        reason: human-readable reasons, joined by ``"; "``.
        score: sensitivity score (e.g. worst cost over the uncertainty box);
            ``nan`` until ranked with a sensitivity.
        gripper: name of the gripper whose contact changes (grasp, release,
            hand-over: the releasing gripper), else ``None``.
        magnitude: size of the merged change point, Euclidean norm of the jump
            of the standardised segment means [channel scales];
            ``nan`` when no change point was merged into this moment.
        reasons: the individual reasons, in order.
        critical: ``True`` when ``score`` exceeds (strictly) the threshold
            given to the ranking.
    """

    step: int
    time: float
    label: MomentLabel
    reason: str
    score: float = math.nan
    gripper: str | None = None
    magnitude: float = math.nan
    reasons: tuple[str, ...] = ()
    critical: bool = False

    @property
    def tag(self) -> str:
        """Short name such as ``"grasp-left"`` or ``"lift-off"``."""
        if self.gripper is None:
            return self.label.value
        return f"{self.label.value}-{self.gripper}"


@dataclass(frozen=True, eq=False)
class ChangePoints:
    """Result of :func:`detect_change_points`.

    Attributes:
        steps: (m,) int64, physics steps at which a new segment starts,
            increasing, in ``[1, T - 1]``.
        magnitudes: (m,) Euclidean norm of the jump of the standardised
            segment means at each change point [channel scales, see ``scale``].
        deltas: (m, d) the jump per channel (right mean minus left mean),
            standardised.
        decimation: block-averaging factor ``k`` (1 when ``T <= max_samples``).
        n_samples: number of samples ruptures saw (``ceil(T / k)``).
        penalty: penalty passed to ruptures.
        center: (d,) per-channel median used for standardisation.
        scale: (d,) per-channel scale used for standardisation (noise level
            floored at a fraction of the spread); 0 for constant channels
            (which are then ignored).
    """

    steps: np.ndarray
    magnitudes: np.ndarray
    deltas: np.ndarray
    decimation: int
    n_samples: int
    penalty: float
    center: np.ndarray
    scale: np.ndarray


# --------------------------------------------------------------------------
# validation helpers
# --------------------------------------------------------------------------


def _check_nonneg_seconds(name: str, value: Any, *, strict: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ParameterError(f"{name} must be a number of seconds, got {value!r}")
    value = float(value)
    if not math.isfinite(value) or value < 0 or (strict and value == 0):
        bound = "> 0" if strict else ">= 0"
        raise ParameterError(f"{name} must be finite and {bound} [s], got {value!r}")
    return value


def _check_int(name: str, value: Any, minimum: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise ParameterError(f"{name} must be an integer >= {minimum}, got {value!r}")
    if value < minimum:
        raise ParameterError(f"{name} must be an integer >= {minimum}, got {value!r}")
    return int(value)


def _check_positive(name: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ParameterError(f"{name} must be a positive number, got {value!r}")
    value = float(value)
    if not math.isfinite(value) or value <= 0:
        raise ParameterError(f"{name} must be finite and > 0, got {value!r}")
    return value


def _check_nonneg(name: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ParameterError(f"{name} must be a number >= 0, got {value!r}")
    value = float(value)
    if not math.isfinite(value) or value < 0:
        raise ParameterError(f"{name} must be finite and >= 0, got {value!r}")
    return value


def _check_threshold(value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ParameterError(f"threshold must be a real number, got {value!r}")
    value = float(value)
    if math.isnan(value):
        raise ParameterError("threshold must be a real number, got nan")
    return value


def _attr(recording: Any, name: str) -> Any:
    try:
        return getattr(recording, name)
    except AttributeError:
        raise TrajectoryError(
            f"recording has no attribute {name!r}; expected a Recording with dt, time, "
            "object_acc, actuator_norm, fos_contact, fos_motor, contact_support, "
            "contact_gripper, gripper_names"
        ) from None


def _steps_of(recording: Any) -> tuple[float, np.ndarray]:
    """Validated (dt, time) of a recording."""
    dt = _attr(recording, "dt")
    try:
        dt = float(dt)
    except (TypeError, ValueError):
        raise TrajectoryError(f"recording.dt must be a number of seconds, got {dt!r}") from None
    if not math.isfinite(dt) or dt <= 0:
        raise TrajectoryError(f"recording.dt must be finite and > 0 [s], got {dt!r}")
    time = np.asarray(_attr(recording, "time"), dtype=float)
    if time.ndim != 1 or time.size == 0:
        raise TrajectoryError(f"recording.time must have shape (T,) with T >= 1, got {time.shape}")
    if not np.all(np.isfinite(time)):
        raise TrajectoryError("recording.time contains non-finite values")
    if time.size > 1 and not np.all(np.diff(time) > 0):
        raise TrajectoryError("recording.time must be strictly increasing")
    return dt, time


def _array(recording: Any, name: str, shape: tuple[int | None, ...], *, dtype: Any = float) -> np.ndarray:
    arr = np.asarray(_attr(recording, name))
    if dtype is bool:
        if arr.dtype != bool:
            raise TrajectoryError(f"recording.{name} must be boolean, got dtype {arr.dtype}")
    else:
        arr = arr.astype(float, copy=False)
    if arr.ndim != len(shape) or any(s is not None and s != a for s, a in zip(shape, arr.shape, strict=False)):
        want = "(" + ", ".join("?" if s is None else str(s) for s in shape) + ")"
        raise TrajectoryError(f"recording.{name} must have shape {want}, got {arr.shape}")
    return arr


def _gripper_names(recording: Any, n_grippers: int) -> tuple[str, ...]:
    names = tuple(str(n) for n in _attr(recording, "gripper_names"))
    if len(names) != n_grippers:
        raise TrajectoryError(
            f"recording.gripper_names has {len(names)} names but the contact arrays have "
            f"{n_grippers} grippers"
        )
    return names


# --------------------------------------------------------------------------
# features
# --------------------------------------------------------------------------


def _actuator_names(recording: Any, n_actuators: int) -> tuple[str, ...]:
    """``recording.actuator_names`` when present and consistent, else numbers."""
    names = getattr(recording, "actuator_names", None)
    if names is not None and len(names) == n_actuators:
        return tuple(f"actuator {n}" for n in names)
    return tuple(f"actuator {j}" for j in range(n_actuators))


def safety_features(
    recording: Any, *, acc_components: bool = False
) -> tuple[np.ndarray, tuple[str, ...], tuple[str, ...]]:
    """Raw (unstandardised) safety feature matrix of a recording.

    Channels, in order: object acceleration (its norm, or its 3 world
    components), each actuator's normalised force, and for each gripper the
    bounded contact load ``1/FOS`` clipped to ``[0, 2]`` (0 when the gripper
    does not touch the object, so ``FOS = +inf`` maps to 0 and ``FOS = 0`` to
    2).

    Args:
        recording: object with ``object_acc`` (T, 3) [m/s^2],
            ``actuator_norm`` (T, nu), ``fos_contact`` (T, G),
            ``contact_gripper`` (T, G) bool and ``gripper_names``.
        acc_components: use the 3 acceleration components instead of the norm.

    Returns:
        ``(features, channel_names, channel_groups)``: features of shape
        (T, d) with ``d = 1 (or 3) + nu + G``; the name of each channel; the
        group of each channel ("object acceleration", "actuator forces",
        "contact load (<gripper>)"), used to phrase reasons.

    Raises:
        TrajectoryError: on missing attributes, wrong shapes or non-finite
            accelerations / actuator forces, NaN or negative contact FOS.
    """
    acc = _array(recording, "object_acc", (None, 3))
    n_steps = acc.shape[0]
    act = np.asarray(_attr(recording, "actuator_norm"), dtype=float)
    if act.ndim == 1:
        act = act[:, None]
    if act.ndim != 2 or act.shape[0] != n_steps:
        raise TrajectoryError(f"recording.actuator_norm must have shape ({n_steps}, nu), got {act.shape}")
    fos = _array(recording, "fos_contact", (n_steps, None))
    touch = _array(recording, "contact_gripper", (n_steps, fos.shape[1]), dtype=bool)
    names = _gripper_names(recording, fos.shape[1])
    if not np.all(np.isfinite(acc)):
        raise TrajectoryError("recording.object_acc contains non-finite values")
    if not np.all(np.isfinite(act)):
        raise TrajectoryError("recording.actuator_norm contains non-finite values")
    if np.any(np.isnan(fos)) or np.any(fos < 0):
        raise TrajectoryError("recording.fos_contact must be >= 0 or +inf, found NaN or negative values")

    with np.errstate(divide="ignore"):
        load = np.clip(1.0 / fos, 0.0, _INV_FOS_MAX)
    load[~touch] = 0.0

    if acc_components:
        acc_feat = acc
        acc_names = ("object acceleration x", "object acceleration y", "object acceleration z")
    else:
        acc_feat = np.linalg.norm(acc, axis=1)[:, None]
        acc_names = ("object acceleration |a|",)
    features = np.concatenate([acc_feat, act, load], axis=1)
    channel_names = (
        acc_names
        + _actuator_names(recording, act.shape[1])
        + tuple(f"contact load {n}" for n in names)
    )
    groups = (
        ("object acceleration",) * len(acc_names)
        + ("actuator forces",) * act.shape[1]
        + tuple(f"contact load ({n})" for n in names)
    )
    return features, channel_names, groups


# --------------------------------------------------------------------------
# change points
# --------------------------------------------------------------------------


def _block_average(signal: np.ndarray, k: int) -> np.ndarray:
    """Mean over consecutive blocks of ``k`` rows (the last block may be shorter)."""
    if k == 1:
        return signal
    starts = np.arange(0, signal.shape[0], k)
    sums = np.add.reduceat(signal, starts, axis=0)
    counts = np.diff(np.append(starts, signal.shape[0]))
    return sums / counts[:, None]


def _robust_scale(signal: np.ndarray, noise_floor: float) -> tuple[np.ndarray, np.ndarray]:
    """Per-channel median and scale; scale 0 marks a constant channel.

    ``scale = max(1.4826 MAD(diff) / sqrt(2), noise_floor * 1.4826 MAD)``;
    when that vanishes the standard deviation is used, and when that vanishes
    too the channel is constant and gets scale 0.
    """
    center = np.median(signal, axis=0)
    spread = _MAD_TO_SIGMA * np.median(np.abs(signal - center), axis=0)
    if signal.shape[0] > 1:
        diff = np.diff(signal, axis=0)
        noise = _MAD_TO_SIGMA * np.median(np.abs(diff - np.median(diff, axis=0)), axis=0) / math.sqrt(2.0)
    else:
        noise = np.zeros_like(spread)
    scale = np.maximum(noise, noise_floor * spread)
    tiny = 1e-12 * np.maximum(1.0, np.max(np.abs(signal), axis=0))
    low = scale <= tiny
    if np.any(low):
        std = np.std(signal[:, low], axis=0)
        scale[low] = np.where(std > tiny[low], std, 0.0)
    return center, scale


def _standardise(signal: np.ndarray, center: np.ndarray, scale: np.ndarray) -> np.ndarray:
    safe = np.where(scale > 0, scale, 1.0)
    out = (signal - center) / safe
    out[:, scale == 0] = 0.0
    return out


def _refine(x: np.ndarray, lo: int, hi: int, guess: int) -> int:
    """Best single split of ``x[lo:hi]`` for the l2 cost (exact, vectorised)."""
    if hi - lo < 2:
        return guess
    seg = x[lo:hi]
    m = seg.shape[0]
    csum = np.cumsum(seg, axis=0)
    total = csum[-1]
    left_n = np.arange(1, m)
    left = csum[:-1] / left_n[:, None]
    right = (total - csum[:-1]) / (m - left_n)[:, None]
    gain = left_n * (m - left_n) / m * np.sum((left - right) ** 2, axis=1)
    best = int(np.argmax(gain))
    if not gain[best] > 0:
        return guess
    return lo + 1 + best


def detect_change_points(
    signal: np.ndarray,
    *,
    penalty_scale: float = 1.0,
    min_size: int = 2,
    max_samples: int = 2000,
    noise_floor: float = 0.5,
) -> ChangePoints:
    """Penalised change-point detection on a standardised multichannel signal.

    The signal is block-averaged to at most ``max_samples`` rows, each channel
    is standardised robustly (median; noise level from the MAD of the
    differences, floored at ``noise_floor`` times 1.4826 MAD; constant
    channels dropped),
    and ``ruptures.KernelCPD(kernel="linear")`` is solved with the penalty
    ``penalty_scale * (d + 1) * ln(n)`` (BIC for ``penalty_scale = 1``; ``d``
    non-constant channels, ``n`` samples seen by ruptures).  Breakpoints are
    mapped back to rows of ``signal`` and refined to single-row resolution.

    Args:
        signal: (T,) or (T, d) finite samples, one row per physics step.
        penalty_scale: factor ``c`` of the penalty; larger gives fewer
            change points.
        min_size: minimal segment length [rows of ``signal``]; converted to
            at least 2 decimated samples.
        max_samples: most samples ruptures may see; bounds its time and
            memory.
        noise_floor: the scale of a channel is at least this fraction of its
            robust spread (1.4826 MAD); 0 uses the noise estimate alone.

    Returns:
        The change points with their per-channel jumps.

    Raises:
        ParameterError: on a non-positive penalty scale, ``min_size < 1``,
            ``max_samples < 16`` or a negative / non-finite ``noise_floor``.
        TrajectoryError: when the signal is empty, not 1-D/2-D or non-finite.
    """
    penalty_scale = _check_positive("penalty_scale", penalty_scale)
    min_size = _check_int("min_size", min_size, 1)
    max_samples = _check_int("max_samples", max_samples, 16)
    noise_floor = _check_nonneg("noise_floor", noise_floor)
    x = np.asarray(signal, dtype=float)
    if x.ndim == 1:
        x = x[:, None]
    if x.ndim != 2 or x.shape[0] == 0 or x.shape[1] == 0:
        raise TrajectoryError(f"signal must have shape (T,) or (T, d) with T, d >= 1, got {np.shape(signal)}")
    if not np.all(np.isfinite(x)):
        raise TrajectoryError("signal contains non-finite values")
    n_steps, n_dims = x.shape

    k = max(1, math.ceil(n_steps / max_samples))
    small = _block_average(x, k)
    n = small.shape[0]
    center, scale = _robust_scale(small, noise_floor)
    z = _standardise(small, center, scale)
    d_eff = int(np.count_nonzero(scale > 0))
    min_size_small = max(2, math.ceil(min_size / k))
    penalty = penalty_scale * (d_eff + 1) * math.log(max(n, 2))

    def empty() -> ChangePoints:
        return ChangePoints(
            steps=np.zeros(0, dtype=np.int64),
            magnitudes=np.zeros(0),
            deltas=np.zeros((0, n_dims)),
            decimation=k,
            n_samples=n,
            penalty=penalty,
            center=center,
            scale=scale,
        )

    if d_eff == 0 or n < 2 * min_size_small:
        return empty()
    algo = ruptures.KernelCPD(kernel="linear", min_size=min_size_small).fit(z[:, scale > 0])
    bkps = np.asarray(algo.predict(pen=penalty), dtype=np.int64)  # segment ends, last == n
    inner = bkps[:-1]
    if inner.size == 0:
        return empty()

    # jumps of the standardised segment means at each breakpoint
    bounds = np.concatenate(([0], bkps))
    seg_means = np.add.reduceat(z, bounds[:-1], axis=0) / np.diff(bounds)[:, None]
    deltas = seg_means[1:] - seg_means[:-1]
    magnitudes = np.linalg.norm(deltas, axis=1)

    # back to physics steps, refined on the full-rate signal projected on the
    # direction of each jump (matched filter: one channel of averaged noise)
    steps = np.minimum(inner * k, n_steps - 1)
    if k > 1:
        safe = np.where(scale > 0, scale, 1.0)
        edges = np.minimum(np.concatenate(([0], bkps * k)), n_steps)
        refined = np.empty_like(steps)
        for i, s in enumerate(steps):
            lo = max(int(edges[i]), int(s) - 2 * k)
            hi = min(int(edges[i + 2]), int(s) + 2 * k)
            direction = deltas[i] / magnitudes[i] if magnitudes[i] > 0 else deltas[i]
            projected = ((x[lo:hi] - center) / safe) @ direction
            refined[i] = lo + _refine(projected[:, None], 0, hi - lo, int(s) - lo)
        # several decimated breakpoints may refine to the same step (a change
        # inside a block yields two short segments): keep the largest jump
        order = np.lexsort((-magnitudes, refined))
        refined, deltas, magnitudes = refined[order], deltas[order], magnitudes[order]
        keep = np.concatenate(([True], np.diff(refined) > 0))
        steps, deltas, magnitudes = refined[keep], deltas[keep], magnitudes[keep]
        steps = np.clip(steps, 1, n_steps - 1)
    return ChangePoints(
        steps=steps.astype(np.int64),
        magnitudes=magnitudes,
        deltas=deltas,
        decimation=k,
        n_samples=n,
        penalty=penalty,
        center=center,
        scale=scale,
    )


def _change_point_reasons(delta: np.ndarray, groups: Sequence[str]) -> tuple[str, ...]:
    """Phrase the channel groups carrying at least 20 % of a jump's energy."""
    energy: dict[str, float] = {}
    for g, e in zip(groups, delta**2, strict=False):
        energy[g] = energy.get(g, 0.0) + float(e)
    total = sum(energy.values())
    if total <= 0:
        return ("change point in the safety signals",)
    ranked = sorted(energy.items(), key=lambda item: -item[1])
    def jump(e: float) -> str:
        # against a scale near 0 (a constant force held, then changed) the ratio is huge and
        # says only that the signal was flat before: "over 1000 sigma"
        return f"{math.sqrt(e):.1f} sigma" if e <= 1e6 else "over 1000 sigma, from a flat signal"

    return tuple(
        f"change point in {g} (jump {jump(e)})" for g, e in ranked if e >= 0.2 * total
    )


# --------------------------------------------------------------------------
# contact events
# --------------------------------------------------------------------------


def debounce(flags: np.ndarray, min_steps: int) -> np.ndarray:
    """Remove contact chatter from a boolean sequence.

    The state only changes when the new value persists for at least
    ``min_steps`` consecutive steps; the change is placed at the first step of
    that run (no delay).  Shorter runs (flickers) take the surrounding state.
    The initial state is the value of the first persisting run; when no run
    persists long enough, the sequence is constant ``flags[0]``.

    Args:
        flags: (T,) bool.
        min_steps: shortest run that counts [steps]; ``<= 1`` returns a copy.

    Returns:
        (T,) bool, the debounced flags.
    """
    x = np.asarray(flags, dtype=bool)
    if x.ndim != 1:
        raise TrajectoryError(f"flags must have shape (T,), got {x.shape}")
    n = x.size
    if min_steps <= 1 or n == 0:
        return x.copy()
    starts = np.concatenate(([0], np.flatnonzero(x[1:] != x[:-1]) + 1))
    lengths = np.diff(np.append(starts, n))
    stable = lengths >= min_steps
    if not np.any(stable):
        return np.full(n, x[0])
    s_starts = starts[stable]
    s_vals = x[s_starts]
    keep = np.concatenate(([True], s_vals[1:] != s_vals[:-1]))
    seg_starts = s_starts[keep].copy()
    seg_vals = s_vals[keep]
    seg_starts[0] = 0
    return np.repeat(seg_vals, np.diff(np.append(seg_starts, n)))


def _holders(state: np.ndarray, names: Sequence[str], exclude: int | None = None) -> list[str]:
    return [names[g] for g in np.flatnonzero(state) if g != exclude]


def _quote(names: Sequence[str]) -> str:
    return " and ".join(f"'{n}'" for n in names)


#: a gripper contact (or a gap in one) shorter than this [s] is described as a brush (or
#: chatter) in its event's reason, not as a grasp (or release)
BRIEF_CONTACT = 0.1


def detect_contact_events(recording: Any, *, debounce_time: float = 0.01) -> list[Moment]:
    """Contact events from the debounced contact flags of a recording.

    Labels, with the debounced flags *at* the event step:

    * support lost: :attr:`MomentLabel.LIFT_OFF` (reason says whether a
      gripper holds the object);
    * gripper ``g`` gains contact: :attr:`MomentLabel.GRASP`;
    * gripper ``g`` loses contact: :attr:`MomentLabel.HAND_OVER` when another
      gripper holds the object, else :attr:`MomentLabel.RELEASE`;
    * support regained: :attr:`MomentLabel.PLACE` when a gripper holds the
      object, else :attr:`MomentLabel.DROP`.

    Args:
        recording: object with ``dt`` [s], ``time`` (T,) [s],
            ``contact_support`` (T,) bool, ``contact_gripper`` (T, G) bool and
            ``gripper_names`` (G names).
        debounce_time: flickers shorter than this are ignored [s].

    Returns:
        Events sorted by step (support events first at equal steps).

    Raises:
        ParameterError: on a negative or non-finite ``debounce_time``.
        TrajectoryError: on missing attributes or wrong shapes / dtypes.
    """
    debounce_time = _check_nonneg_seconds("debounce", debounce_time)
    dt, time = _steps_of(recording)
    n_steps = time.size
    support = _array(recording, "contact_support", (n_steps,), dtype=bool)
    grip = _array(recording, "contact_gripper", (n_steps, None), dtype=bool)
    names = _gripper_names(recording, grip.shape[1])
    min_steps = max(1, int(round(debounce_time / dt)))

    sup = debounce(support, min_steps)
    grp = np.zeros(grip.shape, dtype=bool)
    for g in range(grip.shape[1]):
        grp[:, g] = debounce(grip[:, g], min_steps)

    events: list[Moment] = []

    def add(step: int, label: MomentLabel, reason: str, gripper: str | None = None) -> None:
        events.append(Moment(step, float(time[step]), label, reason, gripper=gripper, reasons=(reason,)))

    for s in np.flatnonzero(sup[1:] != sup[:-1]) + 1:
        s = int(s)
        held = _holders(grp[s], names)
        if not sup[s]:
            if held:
                why = f"object leaves its support (contact lost) while held by {_quote(held)}"
            else:
                why = "object leaves its support (contact lost) without gripper contact"
            add(s, MomentLabel.LIFT_OFF, why)
        elif held:
            add(s, MomentLabel.PLACE, f"object touches table again while held by {_quote(held)}")
        else:
            add(s, MomentLabel.DROP, "object touches table again without gripper contact (dropped)")

    brief = max(1, int(round(BRIEF_CONTACT / dt)))
    for g, name in enumerate(names):
        col = grp[:, g]
        switches = [int(s) for s in np.flatnonzero(col[1:] != col[:-1]) + 1]
        for k, s in enumerate(switches):
            others = _holders(grp[s], names, exclude=g)
            # a contact that ends (or a gap that closes) soon after is a brush or chatter,
            # not a grasp or a release: the event stays, its reason says what it was
            lasts = switches[k + 1] - s if k + 1 < len(switches) else n_steps
            short = f"{lasts * dt * 1e3:.0f} ms" if lasts < brief else ""
            if col[s]:
                why = (f"gripper '{name}' touches object" if not short else
                       f"gripper '{name}' touches object for {short} only (a brush, not a hold)")
                if others:
                    why += f" while {_quote(others)} holds it"
                add(s, MomentLabel.GRASP, why, name)
            elif short:
                add(s, MomentLabel.HAND_OVER if others else MomentLabel.RELEASE,
                    f"gripper '{name}' loses contact with the object for {short}, then touches "
                    f"it again (contact chatter, not a release)", name)
            elif others:
                add(s, MomentLabel.HAND_OVER,
                    f"gripper '{name}' releases object while {_quote(others)} holds it (hand-over)", name)
            elif sup[s]:
                add(s, MomentLabel.RELEASE, f"gripper '{name}' releases object onto the table", name)
            else:
                add(s, MomentLabel.RELEASE, f"gripper '{name}' releases object in the air", name)
    events.sort(key=lambda m: (m.step, _PRIORITY[m.label]))
    return events


def detect_peak_loads(
    fos: np.ndarray,
    *,
    dt: float,
    level: float = 1.5,
    max_peaks: int = 2,
    separation: float = 0.1,
    limiting: Sequence[str] | None = None,
    source: str = "nominal run",
    saturation: float = 0.999,
    min_duration: float = 0.05,
) -> list[Moment]:
    """Peak-load moments: the lows of a motor factor of safety over the whole motion.

    Returns, as :attr:`MomentLabel.PEAK_LOAD` moments: the first step at which ``fos``
    reaches ``1 / saturation`` for longer than ``min_duration`` (a joint at or over its
    limit: the first failing time), and the
    lowest local minima below ``level`` (each the lowest value within ``separation`` of
    it), lowest first, at least ``separation`` apart, ``max_peaks`` of them. Motor
    overloads need no contact event: the arm alone can overload a joint while it moves
    freely, or a heavier payload where the nominal one does not.

    Args:
        fos: (T,) motor FOS per step: the frequent rollout's ``fos_motor``, or an analytic
            bound such as :func:`critmoment.dynamics.trajectory_load_bound` at the
            heaviest payload. ``inf`` where nothing is loaded.
        dt: physics step [s].
        level: FOS below which a low counts (1.5: the cost's motor term is 0.37 there
            with β = 2).
        max_peaks: most local minima returned (besides the first overload).
        separation: shortest time between two returned lows [s].
        limiting: (T,) name of the limiting actuator per step, for the reasons.
        source: what ``fos`` describes, for the reasons.
        saturation: fraction of a limit that counts as an overload (the ground truth's
            0.999: an actuator held at its force range reads FOS 1).
        min_duration: how long an overload must last to be the first one [s] (the ground
            truth's ``motor_time``, 0.05 s, so that the first failing time agrees with it).

    Returns:
        The moments, sorted by step.

    Raises:
        ParameterError: bad options.
        TrajectoryError: ``fos`` not (T,) or NaN.
    """
    dt = _check_nonneg_seconds("dt", dt, strict=True)
    separation = _check_nonneg_seconds("separation", separation)
    min_duration = _check_nonneg_seconds("min_duration", min_duration)
    if not 0 < saturation <= 1:
        raise ParameterError(f"saturation: expected a fraction in (0, 1], got {saturation!r}")
    max_peaks = _check_int("max_peaks", max_peaks, 0)
    level = _check_positive("level", level)
    f = np.asarray(fos, dtype=float)
    if f.ndim != 1 or np.isnan(f).any():
        raise TrajectoryError(f"fos: expected a (T,) motor FOS without NaN, got shape {f.shape}")
    if limiting is not None and len(limiting) != f.size:
        raise TrajectoryError(f"limiting: expected {f.size} names, got {len(limiting)}")
    from scipy.ndimage import minimum_filter1d

    w = max(1, int(round(separation / dt)))

    def moment(step: int, what: str) -> Moment:
        at = f" at {limiting[step]}" if limiting is not None else ""
        reason = f"{what}: motor FOS {f[step]:.3g}{at} ({source}, t = {step * dt:.3f} s)"
        return Moment(step, step * dt, MomentLabel.PEAK_LOAD, reason, reasons=(reason,))

    out: list[Moment] = []
    # an actuator at its force range reads FOS 1 exactly: saturation is overload
    need = int(round(min_duration / dt)) + 1 if min_duration > 0 else 1
    edges = np.flatnonzero(np.diff(np.concatenate([[0], (f * saturation <= 1.0).astype(np.int8),
                                                   [0]])))
    lasting = [int(a) for a, b in zip(edges[::2], edges[1::2], strict=True) if b - a >= need]
    if lasting:
        out.append(moment(lasting[0], "first overload"))
    if f.size and max_peaks:
        lows = np.flatnonzero((f == minimum_filter1d(f, 2 * w + 1, mode="nearest"))
                              & (f < level))
        taken = [m.step for m in out]
        peaks = 0
        for step in lows[np.lexsort((lows, f[lows]))]:
            if peaks >= max_peaks:
                break
            if any(abs(int(step) - t) < w for t in taken):
                continue
            out.append(moment(int(step), "peak load"))
            taken.append(int(step))
            peaks += 1
    return sorted(out, key=lambda m: m.step)


# --------------------------------------------------------------------------
# merging and ranking
# --------------------------------------------------------------------------


def _clusters(moments: Sequence[Moment], window_steps: int) -> list[list[Moment]]:
    """Greedy left-to-right clusters spanning at most ``window_steps`` steps."""
    out: list[list[Moment]] = []
    for m in sorted(moments, key=lambda m: (m.step, _PRIORITY[m.label])):
        if out and m.step - out[-1][0].step <= window_steps:
            out[-1].append(m)
        else:
            out.append([m])
    return out


def _nanmax(a: float, b: float) -> float:
    if math.isnan(a):
        return b
    if math.isnan(b):
        return a
    return max(a, b)


def _combine(rep: Moment, others: Sequence[Moment]) -> Moment:
    reasons = list(rep.reasons or (rep.reason,))
    magnitude = rep.magnitude
    for m in others:
        for r in m.reasons or (m.reason,):
            if r not in reasons:
                reasons.append(r)
        magnitude = _nanmax(magnitude, m.magnitude)
    return dataclasses.replace(rep, reason="; ".join(reasons), reasons=tuple(reasons), magnitude=magnitude)


def merge_moments(moments: Sequence[Moment], *, window: float, dt: float) -> list[Moment]:
    """Merge candidates closer than a time window, preferring contact events.

    1. Contact events (every label but CHANGE_POINT) are clustered greedily
       from left to right, each cluster spanning at most ``window``; the
       cluster keeps the label, step and gripper of its highest-priority event
       (order of :class:`MomentLabel`, then earliest).
    2. Each change point within ``window`` of a merged contact event is
       absorbed by the nearest one (its reasons appended, magnitude kept as
       the maximum).
    3. Remaining change points are clustered the same way and represented by
       the one with the largest magnitude.

    Args:
        moments: candidates, in any order.
        window: merging window [s]; 0 merges only candidates at the same step.
        dt: physics step [s], converts ``window`` to ``round(window / dt)``
            steps.

    Returns:
        Merged moments sorted by step.

    Raises:
        ParameterError: on a negative window or a non-positive ``dt``.
    """
    window = _check_nonneg_seconds("window", window)
    dt = _check_nonneg_seconds("dt", dt, strict=True)
    w = int(round(window / dt))
    contact = [m for m in moments if m.label is not MomentLabel.CHANGE_POINT]
    cps = [m for m in moments if m.label is MomentLabel.CHANGE_POINT]

    merged_contact: list[tuple[Moment, list[Moment]]] = []
    for cluster in _clusters(contact, w):
        rep = min(cluster, key=lambda m: (_PRIORITY[m.label], m.step))
        merged_contact.append((rep, [m for m in cluster if m is not rep]))

    rep_steps = np.array([rep.step for rep, _ in merged_contact], dtype=np.int64)
    loose: list[Moment] = []
    for cp in sorted(cps, key=lambda m: m.step):
        if rep_steps.size:
            dist = np.abs(rep_steps - cp.step)
            i = int(np.argmin(dist))
            if dist[i] <= w:
                merged_contact[i][1].append(cp)
                continue
        loose.append(cp)

    out = [_combine(rep, others) for rep, others in merged_contact]
    for cluster in _clusters(loose, w):
        mags = [(-m.magnitude if not math.isnan(m.magnitude) else math.inf, m.step) for m in cluster]
        rep = cluster[min(range(len(cluster)), key=mags.__getitem__)]
        out.append(_combine(rep, [m for m in cluster if m is not rep]))
    out.sort(key=lambda m: m.step)
    return out


def _heuristic_key(m: Moment) -> tuple[int, float, int]:
    mag = 0.0 if math.isnan(m.magnitude) else m.magnitude
    return (_PRIORITY[m.label], -mag, m.step)


def rank_moments(
    moments: Sequence[Moment],
    scores: np.ndarray | Sequence[float] | None = None,
    *,
    threshold: float = 0.9,
    max_moments: int = 8,
) -> list[Moment]:
    """Order candidates by criticality and keep the first ``max_moments``.

    With ``scores``: by score descending, ties by step ascending; each
    returned moment carries its score and ``critical = score > threshold``.
    Without: by the heuristic "label priority (order of
    :class:`MomentLabel`: lift-off, hand-over, drop, place, grasp, release,
    change point), then change-point magnitude descending, then step";
    scores stay ``nan`` and nothing is critical.

    Args:
        moments: candidates.
        scores: (len(moments),) one score per candidate (e.g. worst cost over
            the uncertainty box), or ``None``; ``+-inf`` allowed, NaN not.
        threshold: score above which a moment is critical.
        max_moments: most moments returned.

    Returns:
        At most ``max_moments`` moments, most critical first.

    Raises:
        ParameterError: on a NaN threshold or ``max_moments < 1``.
        CritmomentError: when ``scores`` has the wrong shape or contains NaN.
    """
    threshold = _check_threshold(threshold)
    max_moments = _check_int("max_moments", max_moments, 1)
    moments = list(moments)
    if scores is None:
        return sorted(moments, key=_heuristic_key)[:max_moments]
    s = np.asarray(scores, dtype=float)
    if s.shape != (len(moments),):
        raise CritmomentError(f"expected {len(moments)} scores of shape ({len(moments)},), got shape {s.shape}")
    if np.any(np.isnan(s)):
        bad = [moments[i].step for i in np.flatnonzero(np.isnan(s))]
        raise CritmomentError(f"sensitivity scores contain NaN at steps {bad}")
    steps = np.array([m.step for m in moments], dtype=np.int64)
    order = np.lexsort((steps, -s))[:max_moments]
    return [
        dataclasses.replace(moments[i], score=float(s[i]), critical=bool(s[i] > threshold)) for i in order
    ]


# --------------------------------------------------------------------------
# estimator
# --------------------------------------------------------------------------


Sensitivity = Callable[[np.ndarray], Any]


class MomentDetector:
    """Find and rank the critical moments of a recorded trajectory.

    Follows the ``ruptures`` estimator style: construct with options,
    :meth:`fit` does all the heavy work (features, change points, contact
    events, merging), :meth:`predict` only ranks.

    Args:
        window: candidates closer than this are merged [s].
        debounce: contact flickers shorter than this are ignored [s].
        min_separation: shortest segment between two change points [s];
            at least 2 samples of the (decimated) signal ruptures sees.
        penalty_scale: factor ``c`` of the penalty
            ``c * (d + 1) * ln(n)``; 1 is the BIC, larger gives fewer change
            points.
        noise_floor: a channel's scale is at least this fraction of its
            robust spread (see :func:`detect_change_points`).
        max_samples: most samples ruptures sees; longer recordings are
            block-averaged (bounds time and memory of change-point search).
        max_moments: most moments :meth:`predict` returns.
        max_candidates: most candidates kept after merging (best by the
            heuristic of :func:`rank_moments`), i.e. the most steps passed to
            a sensitivity callable; ``None`` keeps all.
        acc_components: use the 3 components of the object acceleration
            instead of its norm.
        peak_level: motor FOS below which a low of the recording's motor FOS
            (or of ``load_fos`` given to :meth:`fit`) is a
            :attr:`MomentLabel.PEAK_LOAD` candidate (see
            :func:`detect_peak_loads`); ``None`` finds none.
        max_peaks: most peak-load lows per FOS series (besides its first
            overload).
        peak_separation: shortest time between two peak-load lows [s].

    Attributes:
        change_points_: (:class:`ChangePoints`) result of the change-point
            search, steps in physics steps.
        events_: (list[Moment]) debounced contact events.
        candidates_: (list[Moment]) merged candidates sorted by step.
        channel_names_: (tuple[str, ...]) name of each feature channel.
        n_samples_: (int) number of samples ruptures saw.
        decimation_: (int) block-averaging factor.
        dt_: (float) physics step of the fitted recording [s].
    """

    def __init__(
        self,
        *,
        window: float = 0.04,
        debounce: float = 0.01,
        min_separation: float = 0.02,
        penalty_scale: float = 1.0,
        noise_floor: float = 0.5,
        max_samples: int = 2000,
        max_moments: int = 8,
        max_candidates: int | None = 32,
        acc_components: bool = False,
        peak_level: float | None = 1.5,
        max_peaks: int = 2,
        peak_separation: float = 0.1,
    ) -> None:
        self.window = _check_nonneg_seconds("window", window)
        self.debounce = _check_nonneg_seconds("debounce", debounce)
        self.min_separation = _check_nonneg_seconds("min_separation", min_separation)
        self.penalty_scale = _check_positive("penalty_scale", penalty_scale)
        self.noise_floor = _check_nonneg("noise_floor", noise_floor)
        self.max_samples = _check_int("max_samples", max_samples, 16)
        self.max_moments = _check_int("max_moments", max_moments, 1)
        self.max_candidates = None if max_candidates is None else _check_int("max_candidates", max_candidates, 1)
        if not isinstance(acc_components, (bool, np.bool_)):
            raise ParameterError(f"acc_components must be True or False, got {acc_components!r}")
        self.acc_components = bool(acc_components)
        self.peak_level = None if peak_level is None else _check_positive("peak_level", peak_level)
        self.max_peaks = _check_int("max_peaks", max_peaks, 0)
        self.peak_separation = _check_nonneg_seconds("peak_separation", peak_separation)

    def __repr__(self) -> str:
        opts = ", ".join(
            f"{k}={getattr(self, k)!r}"
            for k in ("window", "debounce", "min_separation", "penalty_scale", "noise_floor", "max_samples",
                      "max_moments", "max_candidates", "acc_components", "peak_level", "max_peaks",
                      "peak_separation")
        )
        return f"MomentDetector({opts})"

    def fit(self, recording: Any, *, load_fos: np.ndarray | None = None,
            load_source: str = "analytic bound") -> MomentDetector:
        """Compute features, change points, contact events and peak loads, and merge them.

        Args:
            recording: a Recording (see :func:`safety_features` and
                :func:`detect_contact_events` for the attributes used).
            load_fos: (T,) another motor FOS over the whole motion whose lows are
                peak-load candidates too, e.g. the analytic bound at the heaviest
                payload (:func:`critmoment.dynamics.trajectory_load_bound`).
            load_source: what ``load_fos`` describes, for the reasons.

        Returns:
            self

        Raises:
            TrajectoryError: on missing attributes, wrong shapes or bad
                values in the recording.
        """
        dt, time = _steps_of(recording)
        features, channel_names, groups = safety_features(recording, acc_components=self.acc_components)
        if features.shape[0] != time.size:
            raise TrajectoryError(
                f"recording.time has {time.size} steps but object_acc has {features.shape[0]}"
            )
        min_size = max(1, int(round(self.min_separation / dt)))
        cps = detect_change_points(
            features,
            penalty_scale=self.penalty_scale,
            min_size=min_size,
            max_samples=self.max_samples,
            noise_floor=self.noise_floor,
        )
        del features
        cp_moments = []
        for step, mag, delta in zip(cps.steps, cps.magnitudes, cps.deltas, strict=False):
            reasons = _change_point_reasons(delta, groups)
            cp_moments.append(
                Moment(int(step), float(time[step]), MomentLabel.CHANGE_POINT, "; ".join(reasons),
                       magnitude=float(mag), reasons=reasons)
            )
        events = detect_contact_events(recording, debounce_time=self.debounce)
        events += self._peak_loads(recording, dt, time.size, load_fos, load_source)
        candidates = merge_moments(events + cp_moments, window=self.window, dt=dt)
        if self.max_candidates is not None and len(candidates) > self.max_candidates:
            candidates = sorted(sorted(candidates, key=_heuristic_key)[: self.max_candidates], key=lambda m: m.step)

        self.change_points_ = cps
        self.events_ = events
        self.candidates_ = candidates
        self.channel_names_ = channel_names
        self.n_samples_ = cps.n_samples
        self.decimation_ = cps.decimation
        self.dt_ = dt
        return self

    def _peak_loads(self, recording: Any, dt: float, n_steps: int, load_fos: Any,
                    load_source: str) -> list[Moment]:
        """Peak-load moments of the recording's motor FOS and of ``load_fos``."""
        if self.peak_level is None:
            return []
        names = getattr(recording, "actuator_names", None)
        argmax = getattr(getattr(recording, "signals", None), "motor_argmax", None)
        limiting = None
        if names is not None and argmax is not None and np.shape(argmax) == (n_steps,):
            limiting = [str(names[int(a)]) for a in np.asarray(argmax)]
        series = [(np.asarray(_attr(recording, "fos_motor"), dtype=float), limiting,
                   "nominal run")]
        if load_fos is not None:
            series.append((np.asarray(load_fos, dtype=float), None, load_source))
        out: list[Moment] = []
        for fos, lim, source in series:
            if fos.shape != (n_steps,):
                raise TrajectoryError(f"{source}: expected a motor FOS of shape ({n_steps},), "
                                      f"got {fos.shape}")
            out += detect_peak_loads(np.nan_to_num(fos, nan=np.inf), dt=dt,
                                     level=self.peak_level, max_peaks=self.max_peaks,
                                     separation=self.peak_separation, limiting=lim,
                                     source=source)
        return out

    def predict(
        self,
        *,
        sensitivity: Sensitivity | None = None,
        threshold: float = 0.9,
        max_moments: int | None = None,
    ) -> list[Moment]:
        """Rank the fitted candidates.

        Args:
            sensitivity: ``sensitivity(steps) -> scores``; called once with
                the (m,) int64 steps of all candidates in increasing order,
                must return m scores (e.g. the worst cost of physics
                evaluations at the corners of the uncertainty box).  ``None``
                ranks by the heuristic of :func:`rank_moments`.
            threshold: a moment whose score exceeds this is ``critical``.
            max_moments: most moments returned; defaults to the option given
                at construction.

        Returns:
            At most ``max_moments`` moments, most critical first.

        Raises:
            CritmomentError: when called before :meth:`fit`, or when the
                sensitivity returns the wrong number of scores or NaN.
            ParameterError: on a bad threshold or ``max_moments``.
        """
        if not hasattr(self, "candidates_"):
            raise CritmomentError("MomentDetector.predict() called before fit(recording)")
        if sensitivity is not None and not callable(sensitivity):
            raise ParameterError(f"sensitivity must be callable or None, got {sensitivity!r}")
        threshold = _check_threshold(threshold)
        max_moments = self.max_moments if max_moments is None else max_moments
        candidates = self.candidates_
        scores = None
        if sensitivity is not None and candidates:
            steps = np.array([m.step for m in candidates], dtype=np.int64)
            scores = np.asarray(sensitivity(steps.copy()), dtype=float)
        elif sensitivity is not None:
            scores = np.zeros(0)
        return rank_moments(candidates, scores, threshold=threshold, max_moments=max_moments)


_DETECTOR_OPTIONS = (
    "window", "debounce", "min_separation", "penalty_scale", "noise_floor", "max_samples",
    "max_moments", "max_candidates", "acc_components", "peak_level", "max_peaks",
    "peak_separation",
)


def find_moments(
    recording: Any,
    *,
    sensitivity: Sensitivity | None = None,
    threshold: float = 0.9,
    **options: Any,
) -> list[Moment]:
    """Find and rank the critical moments of a recording in one call.

    Equivalent to
    ``MomentDetector(**options).fit(recording).predict(sensitivity=..., threshold=...)``.

    Args:
        recording: a Recording.
        sensitivity: see :meth:`MomentDetector.predict`.
        threshold: see :meth:`MomentDetector.predict`.
        **options: options of :class:`MomentDetector`.

    Returns:
        At most ``max_moments`` moments, most critical first.

    Raises:
        ParameterError: on an unknown or invalid option.
    """
    unknown = sorted(set(options) - set(_DETECTOR_OPTIONS))
    if unknown:
        raise ParameterError(f"unknown option(s) {unknown}; valid options: {list(_DETECTOR_OPTIONS)}")
    return MomentDetector(**options).fit(recording).predict(sensitivity=sensitivity, threshold=threshold)


# --------------------------------------------------------------------------
# plotting
# --------------------------------------------------------------------------


_LABEL_COLORS = {
    MomentLabel.LIFT_OFF: "tab:red",
    MomentLabel.HAND_OVER: "tab:purple",
    MomentLabel.DROP: "black",
    MomentLabel.PLACE: "tab:green",
    MomentLabel.GRASP: "tab:blue",
    MomentLabel.RELEASE: "tab:cyan",
    MomentLabel.PEAK_LOAD: "tab:orange",
    MomentLabel.CHANGE_POINT: "tab:gray",
}


def plot_moments(
    recording: Any,
    moments: Sequence[Moment],
    *,
    ax: Any = None,
    path: str | os.PathLike[str] | None = None,
) -> Any:
    """Plot the safety signals with the moments as labelled vertical lines.

    Panels: object acceleration norm [m/s^2], normalised actuator forces, and
    contact load ``1/FOS`` per gripper (clipped to [0, 2]) with the motor
    ``1/FOS`` dashed.  Works with any matplotlib backend (no pyplot state is
    used, so it is safe under Agg and in threads).

    Args:
        recording: a Recording (``time``, ``object_acc``, ``actuator_norm``,
            ``fos_contact``, ``fos_motor``, ``contact_gripper``,
            ``gripper_names``).
        moments: moments to mark.
        ax: ``None`` (a new figure with 3 stacked panels), a sequence of 3
            Axes, or a single Axes (the 3 signals scaled to their maxima on
            one panel).
        path: when given, the figure is saved there (format from the
            extension).

    Returns:
        The matplotlib Figure.

    Raises:
        ParameterError: when ``ax`` is a sequence of length other than 3.
        TrajectoryError: on bad recordings.
    """
    from matplotlib.figure import Figure

    _, time = _steps_of(recording)
    acc = np.linalg.norm(_array(recording, "object_acc", (time.size, 3)), axis=1)
    act = np.asarray(_attr(recording, "actuator_norm"), dtype=float).reshape(time.size, -1)
    fos = _array(recording, "fos_contact", (time.size, None))
    touch = _array(recording, "contact_gripper", fos.shape, dtype=bool)
    names = _gripper_names(recording, fos.shape[1])
    motor = _array(recording, "fos_motor", (time.size,))
    with np.errstate(divide="ignore"):
        load = np.where(touch, np.clip(1.0 / fos, 0.0, _INV_FOS_MAX), 0.0)
        motor_load = np.clip(1.0 / motor, 0.0, _INV_FOS_MAX)

    if ax is None:
        fig = Figure(figsize=(10, 7), layout="constrained")
        axes = list(fig.subplots(3, 1, sharex=True))
    elif isinstance(ax, (list, tuple, np.ndarray)):
        axes = list(np.ravel(ax))
        if len(axes) != 3:
            raise ParameterError(f"ax must be one Axes or a sequence of 3 Axes, got {len(axes)}")
        fig = axes[0].figure
    else:
        axes = [ax]
        fig = ax.figure

    if len(axes) == 3:
        axes[0].plot(time, acc, lw=0.8, color="k")
        axes[0].set_ylabel("|object acc| [m/s²]")
        axes[1].plot(time, act, lw=0.6)
        axes[1].set_ylabel("actuator force / limit")
        for g, name in enumerate(names):
            axes[2].plot(time, load[:, g], lw=0.8, label=f"1/FOS contact {name}")
        axes[2].plot(time, motor_load, lw=0.8, ls="--", color="k", label="1/FOS motor")
        axes[2].set_ylabel("1/FOS (clipped)")
        axes[2].legend(loc="upper right", fontsize="small")
        axes[2].set_xlabel("time [s]")
    else:
        def scaled(y: np.ndarray) -> np.ndarray:
            top = float(np.max(np.abs(y))) if y.size else 0.0
            return y / top if top > 0 else y

        axes[0].plot(time, scaled(acc), lw=0.8, color="k", label="|object acc| (scaled)")
        if act.shape[1]:
            axes[0].plot(time, np.max(np.abs(act), axis=1), lw=0.8, label="max |actuator force / limit|")
        axes[0].plot(time, np.max(load, axis=1) / _INV_FOS_MAX if load.size else 0 * time, lw=0.8,
                     label="max contact 1/FOS (scaled)")
        axes[0].legend(loc="upper right", fontsize="small")
        axes[0].set_xlabel("time [s]")

    for m in moments:
        color = _LABEL_COLORS[m.label]
        for a in axes:
            a.axvline(m.time, color=color, lw=1.0, ls="-" if m.label is not MomentLabel.CHANGE_POINT else ":")
        text = m.tag if math.isnan(m.score) else f"{m.tag} ({m.score:.2f})"
        axes[0].annotate(
            text, xy=(m.time, 1.0), xycoords=("data", "axes fraction"), rotation=90,
            va="top", ha="right", fontsize="x-small", color=color,
        )
    if path is not None:
        fig.savefig(os.fspath(path))
    return fig
