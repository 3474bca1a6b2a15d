"""Robot trajectories: the container, file readers, range checks, upsampling.

A :class:`Trajectory` is a sequence of joint-position targets ("actions") sent
to a robot at a fixed control rate, in the action convention of the scenario it
is replayed in. For the ALOHA bimanual setup one action is 14 values::

    [left joint 0..5 [rad], left gripper [normalised 0..1],
     right joint 0..5 [rad], right gripper [normalised 0..1]]

Readers (:func:`load_trajectory`) accept

* ``.npz`` archives in critmoment's own schema (see :func:`save_trajectory`),
* ACT episode files (``.hdf5`` / ``.h5``) with ``/action`` and
  ``/observations/qpos``,
* LeRobot-format parquet, either one episode file or a whole dataset
  directory (``<root>/meta/info.json`` plus ``<root>/data/**.parquet``).

:func:`check_ranges` enforces joint limits under an explicit
:class:`RangePolicy`, and :func:`upsample` turns control-rate actions into one
control per physics step.
"""

from __future__ import annotations

import copy
import enum
import hashlib
import json
import logging
import math
import os
import re
import warnings
import zipfile
import zlib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any

import numpy as np
from scipy.interpolate import CubicSpline, PchipInterpolator

from critmoment import budget
from critmoment.exceptions import (
    CritmomentError,
    CritmomentWarning,
    InputFileError,
    ParameterError,
    ResourceLimitError,
    TrajectoryError,
)

__all__ = [
    "DEFAULT_FPS",
    "SUPPORTED_SUFFIXES",
    "Trajectory",
    "check_trajectory",
    "RangePolicy",
    "load_trajectory",
    "save_trajectory",
    "Episode",
    "list_episodes",
    "as_object_pose",
    "input_identity",
    "check_ranges",
    "upsample",
]

logger = logging.getLogger(__name__)

#: Control rate assumed when a file does not record one [Hz].
DEFAULT_FPS: float = 50.0

#: File suffixes :func:`load_trajectory` understands (a LeRobot dataset
#: directory is accepted as well).
SUPPORTED_SUFFIXES: tuple[str, ...] = (".npz", ".hdf5", ".h5", ".parquet")

_SUPPORTED_TEXT = (
    "'.npz' (critmoment schema), '.hdf5'/'.h5' (ACT episode), "
    "'.parquet' (LeRobot episode file), or a LeRobot dataset directory "
    "containing meta/info.json"
)

# Relative tolerance for "uniform" sample spacing and for two frame rates
# that should agree.
_RATE_RTOL = 0.01

# Quaternions whose norm is within this of 1 are taken as already normalised
# (keeps save/load round trips bit-exact).
_QUAT_NORM_TOL = 1e-12

# A physics step whose time lies within this fraction of a control period of a
# sample time is treated as hitting the sample exactly.
_SNAP_TOL = 1e-9

_NPZ_KEYS = frozenset({"actions", "fps", "time", "start", "qpos0", "qvel0", "object_pose",
                       "meta", "observed"})
#: unknown npz keys (lower case) that can only be a time base: refused when no 'fps' or
#: 'time' says the rate
_TIME_BASE_KEYS = frozenset({"fps", "timestamp", "timestamps", "times", "t", "dt", "hz",
                             "freq", "frequency", "rate", "frame_rate", "framerate",
                             "control_freq", "control_frequency", "sample_rate", "period",
                             "time_s", "seconds", "control_dt", "time", "time_step",
                             "timestep"})
#: the root attributes an ACT episode's rate [Hz] is read from
_ACT_RATE_KEYS = ("fps", "frame_rate", "control_freq")


def _is_time_base(key: str) -> bool:
    """A key or attribute name that names a time base (a rate, a period or times)."""
    return key.lower().replace("-", "_") in _TIME_BASE_KEYS


# ---------------------------------------------------------------------------
# Validation helpers
# ---------------------------------------------------------------------------


def _describe_dtype(arr: np.ndarray) -> str:
    return f"dtype {arr.dtype}"


def _as_float_array(value: Any, *, what: str, error: type[Exception]) -> np.ndarray:
    """Converts ``value`` to a float64 array, rejecting non-numeric input."""
    if isinstance(value, np.ma.MaskedArray):
        # np.asarray drops the mask and keeps whatever the masked cells hold
        masked = np.ma.getmaskarray(value)
        if masked.any():
            first = tuple(int(i) for i in np.argwhere(masked)[0])
            raise error(
                f"{what}: expected every value given, got a masked array with "
                f"{int(masked.sum())} masked cell(s) (the first at index {first}); a masked "
                f"cell has no value to audit: fill it (array.filled(...)) or cut those steps")
        value = np.ma.getdata(value)
    try:
        arr = np.asarray(value)
    except (ValueError, TypeError) as exc:  # ragged nested lists, odd objects
        raise error(
            f"{what}: expected a numeric array, got {type(value).__name__} "
            f"that numpy cannot convert ({exc})"
        ) from None
    if arr.dtype.kind in "iuf":
        return np.array(arr, dtype=np.float64, copy=True)
    raise error(
        f"{what}: expected a real numeric array (integer or float), got "
        f"{_describe_dtype(arr)}; valid dtype kinds are signed/unsigned integer "
        f"and floating point"
    )


def _check_finite_rows(values: np.ndarray, *, what: str) -> None:
    """A (T, na) array of finite values, or a TrajectoryError naming the first bad one's row
    and column and how many there are."""
    bad = _first_nonfinite(values)
    if bad is not None:
        n_bad = int(np.count_nonzero(~np.isfinite(values)))
        raise TrajectoryError(
            f"{what}: expected finite values, got {values[bad]} at row (step) {bad[0]}, "
            f"column (channel) {bad[1]} ({n_bad} non-finite value(s) in total)")


def _first_nonfinite(arr: np.ndarray) -> tuple[int, ...] | None:
    bad = np.argwhere(~np.isfinite(arr))
    if bad.size == 0:
        return None
    return tuple(int(i) for i in bad[0])


def _check_finite_vector(arr: np.ndarray, *, what: str) -> None:
    where = _first_nonfinite(arr)
    if where is not None:
        raise TrajectoryError(
            f"{what}: expected finite values, got {float(arr[where])!r} at index {where[0]}"
        )


def _read_only(arr: np.ndarray) -> np.ndarray:
    arr.flags.writeable = False
    return arr


def _as_rate(value: Any, *, what: str, error: type[Exception]) -> float:
    """Converts a frame rate to a finite positive float [Hz]."""
    if isinstance(value, (bool, np.bool_)):
        raise error(f"{what}: expected a finite number > 0 [Hz], got bool {value!r}")
    if isinstance(value, (str, bytes, np.str_, np.bytes_)) or (
            isinstance(value, np.ndarray) and value.dtype.kind in "USO"):
        # "50" would convert, but a rate typed as text is a caller's slip worth naming
        raise error(f"{what}: expected a finite number > 0 [Hz], got text {value!r}")
    try:
        rate = float(value)
    except OverflowError:
        rate = math.inf
    except (TypeError, ValueError):
        raise error(
            f"{what}: expected a finite number > 0 [Hz], got "
            f"{type(value).__name__} {value!r}"
        ) from None
    if not math.isfinite(rate) or rate <= 0.0:
        raise error(f"{what}: expected a finite number > 0 [Hz], got {rate!r}")
    return rate


def _rates_agree(a: float, b: float) -> bool:
    return abs(a - b) <= _RATE_RTOL * max(abs(a), abs(b))


def _given_or_recorded(fps: float | None, recorded: float | None, where: str) -> float | None:
    """The rate a file records, else the ``fps`` argument (None when neither is known).

    Raises:
        TrajectoryError: both are given and disagree.
    """
    if recorded is None:
        return fps
    if fps is not None and not _rates_agree(fps, recorded):
        raise TrajectoryError(
            f"fps argument {fps:g} Hz disagrees with the rate {recorded:g} Hz recorded in "
            f"{where} (expected agreement within {_RATE_RTOL:.0%}); omit fps= to use the "
            f"recorded rate")
    return recorded


def _check_json(meta: Any) -> dict:
    if not isinstance(meta, Mapping):
        raise TrajectoryError(
            f"meta: expected a JSON-serialisable dict, got {type(meta).__name__}"
        )
    meta = dict(meta)
    try:
        json.dumps(meta, allow_nan=False)
    except (TypeError, ValueError) as exc:
        raise TrajectoryError(
            f"meta: expected a JSON-serialisable dict (str keys; str, int, float, "
            f"bool, None, list and dict values; no NaN/inf), got a value json "
            f"cannot encode: {exc}"
        ) from None
    return copy.deepcopy(meta)


def _fps_from_times(times: Any, n_steps: int, *, what: str) -> float:
    """Validates sample times [s] and returns the frame rate they imply [Hz].

    Args:
        times: (T,) sample times [s].
        n_steps: expected T.
        what: where the times came from, for error messages.

    Raises:
        TrajectoryError: wrong length, non-finite, not strictly increasing, or
            spacing deviating more than 1 % from the median spacing.
    """
    raw_dtype = getattr(times, "dtype", None)
    t = _as_float_array(times, what=what, error=TrajectoryError)
    if t.shape != (n_steps,):
        raise TrajectoryError(
            f"{what}: expected shape ({n_steps},) to match the {n_steps} actions, "
            f"got shape {t.shape}"
        )
    _check_finite_vector(t, what=what)
    if t.size < 2:
        raise TrajectoryError(f"{what}: expected at least 2 time steps to give a rate, got "
                              f"{t.size}")
    dt = np.diff(t)
    # the resolution of the times as stored: float32 epoch seconds (1.7e9) are 128 s apart,
    # so every 20 ms frame rounds alike; float32 seconds from 1000 s resolve 61 µs, which
    # biases one 20 ms step by up to 0.3 %
    quantum, hint = 0.0, ""
    if raw_dtype is not None and np.dtype(raw_dtype).kind == "f" \
            and np.dtype(raw_dtype).itemsize < 8:
        largest = float(np.abs(t).max())
        quantum = float(np.spacing(np.asarray(largest, dtype=raw_dtype)))
        hint = (f"; the times are {np.dtype(raw_dtype).name}, which at {largest:.3g} s "
                f"resolves only {quantum:.3g} s: store them as float64, or relative to the "
                f"first")
    nonpos = np.flatnonzero(dt <= 0.0)
    if nonpos.size and np.all(dt < -quantum) and dt.size > 1:
        # every step back by about a frame: rows stored newest first, not times too coarse
        raise TrajectoryError(
            f"{what}: expected increasing times, got times that fall by "
            f"{float(-np.median(dt)):.3g} s at every row: rows stored newest first? order "
            f"them by time (or by frame_index)")
    if nonpos.size:
        i = int(nonpos[0])
        raise TrajectoryError(
            f"{what}: expected strictly increasing times, got t[{i}] = {float(t[i])!r} "
            f"followed by t[{i + 1}] = {float(t[i + 1])!r} ({nonpos.size} non-increasing "
            f"step(s) in total){hint}"
        )
    median = float(np.median(dt))
    # a step of 1 is a sample index as much as a second: a control rate of 1 Hz or less is
    # no robot's (50 frames indexed 0..49 had been played over 50 s)
    if median >= 1.0:
        raise TrajectoryError(
            f"{what}: times {median:g} apart, a control rate of {1.0 / median:.3g} Hz; "
            f"expected times in seconds (milliseconds, or sample indices?)")
    # a step may differ from the median by the rounding of its two ends, unless that
    # rounding is too coarse to tell a uniform rate from another
    coarse = 2.0 * quantum > 0.25 * median
    off = np.flatnonzero(np.abs(dt - median) > _RATE_RTOL * median
                         + (0.0 if coarse else 2.0 * quantum))
    if off.size:
        i = int(off[0])
        advice = hint if coarse else "; resample the trajectory to a fixed rate first"
        raise TrajectoryError(
            f"{what}: expected uniform spacing (within {_RATE_RTOL:.0%} of the "
            f"median {median!r} s), got t[{i + 1}] - t[{i}] = {float(dt[i])!r} s "
            f"({off.size} irregular step(s) in total){advice}"
        )
    if quantum > 1e-6 * median:
        # rounded times: the mean step over the whole span is off by at most 2 quanta over
        # the span, where one step's (the median's) is off by 2 quanta over one step
        span = float(t[-1] - t[0])
        rate = (t.size - 1) / span
        # a whole rate in Hz the rounding cannot tell from the measured one is the rate
        # (float32 times of a 50 Hz episode from 0 s give 49.99999988 Hz)
        whole = round(rate)
        if whole > 0 and abs(rate - whole) <= rate * 2.0 * quantum / span:
            return float(whole)
        return rate
    return 1.0 / median


# ---------------------------------------------------------------------------
# Trajectory
# ---------------------------------------------------------------------------


@dataclass(frozen=True, eq=False, repr=False)
class Trajectory:
    """Joint-position targets at a fixed control rate.

    All arrays are stored as read-only float64 copies.

    Attributes:
        actions: (T, na) joint-position targets in the scenario's action
            convention (ALOHA: 14 values, joints [rad] and grippers normalised
            0..1). T >= 2, all finite.
        fps: control rate [Hz]; action ``i`` applies at time ``i / fps`` [s]. None (the
            default): the scenario's ``[actions] fps`` where it states one, else
            :data:`DEFAULT_FPS` (``fps_assumed`` is then True).
        start: (na,) initial joint state in the action convention (e.g. ACT's
            ``observations/qpos[0]``), or ``None`` when unknown.
        qpos0: (nq,) full MuJoCo initial ``qpos`` when known, else ``None``.
        object_pose: (7,) initial object pose, position [m] then unit
            quaternion (w, x, y, z), or ``None``. The quaternion is normalised.
        meta: JSON-serialisable metadata (format, file attributes, ...).
        source: where the trajectory came from (a path or a description).
        qvel0: (nv,) full MuJoCo initial ``qvel`` with ``qpos0`` (an action chunk cut from a
            running episode starts moving), else ``None`` (the run starts at rest).
        observed: (T, na) where the joints were (recorded) or were planned to be at each
            action's time, in the action convention (ACT's ``/observations/qpos``, LeRobot's
            ``observation.state``), or ``None``. The twin must reproduce the motion: its
            joints may trail their targets (a feed-forward target leads a soft servo's joint
            by design) as long as they follow this path (:mod:`critmoment.feasibility`).
    """

    actions: np.ndarray
    fps: float | None = None
    start: np.ndarray | None = None
    qpos0: np.ndarray | None = None
    object_pose: np.ndarray | None = None
    meta: dict = field(default_factory=dict)
    source: str = ""
    #: the file recorded no rate: ``fps`` is :data:`DEFAULT_FPS`, assumed (a scenario's
    #: ``[actions] fps`` replaces it, :meth:`with_rate_from`)
    fps_assumed: bool = field(default=False, compare=False)
    qvel0: np.ndarray | None = None
    #: the SHA-256 of the file's bytes as read (:func:`load_trajectory`), for the report's
    #: manifest; None for a trajectory built in code or read from a dataset folder
    source_sha256: str | None = field(default=None, compare=False)
    observed: np.ndarray | None = None

    def content_sha256(self) -> str:
        """SHA-256 of what an audit plays: the actions, the rate and the initial state
        (``start``, ``qpos0``, ``qvel0``, ``object_pose``); not ``meta`` or ``source``. Two
        trajectories with the same hash are audited alike (the report's manifest carries
        it beside the file's own hash: a file read with another ``--object-pose``, or a
        loaded trajectory changed in code, is another trajectory)."""
        h = hashlib.sha256()
        h.update(repr(float(self.fps)).encode())
        for name in ("actions", "start", "qpos0", "qvel0", "object_pose", "observed"):
            value = getattr(self, name)
            if name == "observed" and value is None:
                continue  # the hashes of trajectories without it stay what they were
            h.update(name.encode())
            if value is None:
                h.update(b"none")
                continue
            arr = np.ascontiguousarray(value, dtype=np.float64)
            h.update(repr(arr.shape).encode())
            h.update(arr.tobytes())
        return h.hexdigest()

    def with_rate_from(self, fps: float | None) -> Trajectory:
        """This trajectory at ``fps`` (a scenario's ``[actions] fps``) where its file
        recorded no rate, else itself (a recorded rate is authoritative)."""
        if not self.fps_assumed or fps is None or fps == self.fps:
            return self
        logger.info("%s: no recorded rate; the scenario's %g Hz", self.source, fps)
        return replace(self, fps=float(fps), fps_assumed=False)

    def __post_init__(self) -> None:
        try:
            self._check_fields()
        except TrajectoryError as exc:
            # a file's field names its file (a NaN in the start row of an ACT episode)
            if self.source and self.source not in str(exc):
                raise TrajectoryError(f"{self.source!r}: {exc}") from None
            raise

    def _check_fields(self) -> None:
        actions = _as_float_array(self.actions, what="actions", error=TrajectoryError)
        if actions.ndim != 2:
            raise TrajectoryError(
                f"actions: expected a 2-D array of shape (T, na) (T time steps, "
                f"na action channels), got {actions.ndim}-D array of shape "
                f"{actions.shape}"
            )
        n_steps, n_channels = actions.shape
        if n_steps < 2:
            raise TrajectoryError(
                f"actions: expected at least 2 time steps (T >= 2), got T = {n_steps}"
            )
        if n_channels < 1:
            raise TrajectoryError(
                f"actions: expected at least 1 action channel, got shape {actions.shape}"
            )
        _check_finite_rows(actions, what="actions")
        object.__setattr__(self, "actions", _read_only(actions))

        if self.fps is None:
            # no rate given: the scenario's [actions] fps where it states one, as for a file
            # that records none (a policy's chunk built in code had played at 50 Hz against
            # a 30 Hz scenario)
            object.__setattr__(self, "fps", DEFAULT_FPS)
            object.__setattr__(self, "fps_assumed", True)
        object.__setattr__(
            self, "fps", _as_rate(self.fps, what="fps", error=TrajectoryError)
        )

        if self.start is not None:
            start = _as_float_array(self.start, what="start", error=TrajectoryError)
            if start.shape != (n_channels,):
                raise TrajectoryError(
                    f"start: expected shape ({n_channels},) (one value per action "
                    f"channel), got shape {start.shape}; the actions and the start "
                    f"disagree on the number of channels ({n_channels} vs "
                    f"{start.shape[-1] if start.ndim else 1}): check which matches the "
                    f"scenario's action convention"
                )
            _check_finite_vector(start, what="start")
            object.__setattr__(self, "start", _read_only(start))

        if self.observed is not None:
            observed = _as_float_array(self.observed, what="observed", error=TrajectoryError)
            if observed.shape != actions.shape:
                raise TrajectoryError(
                    f"observed: expected shape {actions.shape} (the joints' recorded or "
                    f"planned positions, one row per action, in the action convention), got "
                    f"shape {observed.shape}")
            _check_finite_rows(observed, what="observed")
            object.__setattr__(self, "observed", _read_only(observed))

        if self.qvel0 is not None and self.qpos0 is None:
            raise TrajectoryError("qvel0: expected it with qpos0 (the velocities of that "
                                  "state), got qvel0 alone")
        for name, size in (("qpos0", "nq"), ("qvel0", "nv")):
            if getattr(self, name) is not None:
                vector = _as_float_array(getattr(self, name), what=name, error=TrajectoryError)
                if vector.ndim != 1 or vector.size == 0:
                    raise TrajectoryError(
                        f"{name}: expected a non-empty 1-D array of shape ({size},), got "
                        f"shape {vector.shape}"
                    )
                _check_finite_vector(vector, what=name)
                object.__setattr__(self, name, _read_only(vector))

        if self.object_pose is not None:
            pose = _as_float_array(
                self.object_pose, what="object_pose", error=TrajectoryError
            )
            if pose.shape != (7,):
                raise TrajectoryError(
                    f"object_pose: expected shape (7,) = xyz [m] + quaternion "
                    f"(w, x, y, z), got shape {pose.shape}"
                )
            _check_finite_vector(pose, what="object_pose")
            norm = float(np.linalg.norm(pose[3:]))
            # as everywhere else a pose comes in (--object-pose, ACT env_state, qpos0): a
            # quaternion far from unit length is a mistake (another convention, degrees),
            # not something to rescale silently
            if abs(norm - 1.0) > _POSE_NORM_TOL:
                raise TrajectoryError(
                    f"object_pose: expected a unit quaternion (w, x, y, z) in elements 3..6 "
                    f"(norm within {_POSE_NORM_TOL:g} of 1), got {pose[3:].tolist()} with "
                    f"norm {norm:.6g}"
                )
            if abs(norm - 1.0) > _QUAT_NORM_TOL:
                pose[3:] /= norm
            object.__setattr__(self, "object_pose", _read_only(pose))

        object.__setattr__(self, "meta", _check_json(self.meta))
        if not isinstance(self.source, str):
            object.__setattr__(self, "source", os.fspath(self.source)
                               if isinstance(self.source, os.PathLike)
                               else str(self.source))

    # -- derived quantities ------------------------------------------------

    @property
    def n_steps(self) -> int:
        """Number of actions T."""
        return int(self.actions.shape[0])

    @property
    def n_channels(self) -> int:
        """Number of action channels na."""
        return int(self.actions.shape[1])

    @property
    def duration(self) -> float:
        """Duration T / fps [s] (the last action is held for one period)."""
        return self.n_steps / self.fps

    @property
    def times(self) -> np.ndarray:
        """(T,) time of each action, ``arange(T) / fps`` [s]."""
        return np.arange(self.n_steps, dtype=np.float64) / self.fps

    def upsample(self, physics_dt: float, **kwargs: Any) -> np.ndarray:
        """Interpolates the actions to one control per physics step.

        Shorthand for ``upsample(self, physics_dt=physics_dt, **kwargs)``; see
        :func:`upsample`.

        Args:
            physics_dt: physics time step [s].
            **kwargs: ``bounded``, ``lower``, ``upper`` as in :func:`upsample`.

        Returns:
            (n, na) controls, n = round(T / fps / physics_dt).
        """
        return upsample(self, physics_dt=physics_dt, **kwargs)

    # -- dunder ------------------------------------------------------------

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Trajectory):
            return NotImplemented
        for f in fields(self):
            if not f.compare:
                continue
            a, b = getattr(self, f.name), getattr(other, f.name)
            if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
                if a is None or b is None or not np.array_equal(a, b):
                    return False
            elif a != b:
                return False
        return True

    __hash__ = None  # type: ignore[assignment]  # mutable meta, array fields

    def __repr__(self) -> str:
        extras = [
            name for name in ("start", "qpos0", "qvel0", "object_pose", "observed")
            if getattr(self, name) is not None
        ]
        return (
            f"Trajectory(n_steps={self.n_steps}, n_channels={self.n_channels}, "
            f"fps={self.fps:g}, duration={self.duration:g} s, "
            f"with={extras}, source={self.source!r})"
        )


# ---------------------------------------------------------------------------
# Readers and writer
# ---------------------------------------------------------------------------


def load_trajectory(
    path: str | os.PathLike,
    *,
    fps: float | None = None,
    episode: int | None = None,
    object_pose: Any = None,
) -> Trajectory:
    """Reads a trajectory from a file or a LeRobot dataset directory.

    The format is chosen from the suffix (case-insensitive); a directory is
    read as a LeRobot dataset.

    Frame-rate resolution: a rate recorded in the file (npz ``fps`` / ``time``,
    LeRobot ``meta/info.json`` / ``timestamp``) is authoritative, and an
    ``fps`` argument that disagrees with it by more than 1 % is an error.
    Where the file records no rate the ``fps`` argument is used, else
    :data:`DEFAULT_FPS` (50 Hz; a warning is issued for LeRobot data).

    Args:
        path: file or dataset directory.
        fps: control rate [Hz] to use or to check against the file.
        episode: LeRobot only: the ``episode_index`` to read. Required when the
            file or dataset holds more than one episode.
        object_pose: (7,) initial object pose, xyz [m] + unit quaternion
            (w, x, y, z), replacing the file's (see :func:`as_object_pose`).

    Before any array is read, the sizes the file declares (npy headers, HDF5
    dataset shapes, parquet value counts) are checked against
    :func:`critmoment.budget.active`'s ``max_input_bytes``. When neither the
    file (npz ``object_pose`` or ``qpos0``, ACT ``/observations/env_state``)
    nor ``object_pose`` gives the object's start pose, a
    :class:`~critmoment.exceptions.CritmomentWarning` says that the model's
    default pose will be used.

    Returns:
        The trajectory, with ``source`` set to ``str(path)``.

    Raises:
        InputFileError: the path does not exist, has an unsupported suffix, or
            cannot be read as the format its suffix names.
        TrajectoryError: the content is malformed (missing actions, wrong
            shapes, NaN, irregular timing, unknown episode, ...).
        ParameterError: ``fps`` is not a positive finite number, or
            ``episode`` is given for a format without episodes.
        ResourceLimitError: the file declares more data than the budget allows.
    """
    pose = None if object_pose is None else as_object_pose(object_pose)
    before = input_identity(path)["sha256"] if isinstance(path, (str, os.PathLike)) else None
    traj = _load_any(path, fps=fps, episode=episode)
    if before is not None:
        # the manifest names the bytes the audit read, not what the file holds at report
        # time: a file rewritten while it was read (a policy loop writing its next chunk)
        # is an error, not a trajectory of two versions
        if input_identity(path)["sha256"] != before:
            raise InputFileError(f"trajectory file {str(path)!r} changed while it was read; "
                                 f"expected a file that stays the same while it is loaded")
        traj = replace(traj, source_sha256=before)
    if pose is not None:
        return replace(traj, object_pose=pose)
    if traj.object_pose is None and traj.qpos0 is None:
        warnings.warn(
            f"{traj.source!r} gives no object start pose (npz 'object_pose'/'qpos0', "
            f"ACT /observations/env_state); the object starts where the scenario puts it "
            f"(its [model] keyframe's pose, else the model's default); pass object_pose= "
            f"(CLI: --object-pose X Y Z QW QX QY QZ) to set it",
            CritmomentWarning,
            stacklevel=2,
        )
    return traj


def check_trajectory(value: Any, what: str = "trajectory") -> Trajectory:
    """``value`` itself when it is a :class:`Trajectory`.

    Raises:
        ParameterError: anything else (a path, an array), with what to call instead.
    """
    if not isinstance(value, Trajectory):
        hint = (" (read a file with critmoment.load_trajectory(path))"
                if isinstance(value, (str, os.PathLike)) else "")
        raise ParameterError(f"{what}: expected a critmoment Trajectory{hint}, got "
                             f"{type(value).__name__}")
    return value


def _load_any(path: str | os.PathLike, *, fps: float | None,
              episode: int | None) -> Trajectory:
    if not isinstance(path, (str, os.PathLike)):
        raise ParameterError(f"path: expected a trajectory file or dataset folder (str or "
                             f"os.PathLike), got {type(path).__name__} {path!r}")
    p = Path(os.fspath(path))
    if fps is not None:
        fps = _as_rate(fps, what="fps argument", error=ParameterError)
    if episode is not None and (
        isinstance(episode, (bool, np.bool_)) or not isinstance(episode, (int, np.integer))
    ):
        raise ParameterError(
            f"episode: expected an int episode_index or None, got "
            f"{type(episode).__name__} {episode!r}"
        )
    try:
        exists, is_dir = p.exists(), p.is_dir()
    except (OSError, ValueError) as exc:  # a name too long, an embedded NUL byte
        raise InputFileError(
            f"trajectory path {_short(p)!r} cannot be used: "
            f"{getattr(exc, 'strerror', None) or exc}; "
            f"expected an existing file or directory: {_SUPPORTED_TEXT}"
        ) from None
    if not exists:
        raise InputFileError(
            f"trajectory path {str(p)!r} does not exist; expected an existing "
            f"file or directory: {_SUPPORTED_TEXT}"
        )
    if is_dir:
        if (p / "meta" / "info.json").is_file():
            return _load_lerobot_dir(p, fps=fps, episode=episode)
        raise InputFileError(
            f"trajectory path {str(p)!r} is a directory without meta/info.json; "
            f"expected a LeRobot dataset directory or a file: {_SUPPORTED_TEXT}"
        )
    if not p.is_file():  # reading a FIFO would wait forever, a device for ever more
        raise InputFileError(
            f"trajectory path {str(p)!r} is not a regular file (a FIFO, device or "
            f"socket); expected a file or directory: {_SUPPORTED_TEXT}"
        )
    suffix = p.suffix.lower()
    if suffix not in SUPPORTED_SUFFIXES:
        raise InputFileError(
            f"trajectory file {str(p)!r} has unsupported suffix {p.suffix!r}; "
            f"supported: {_SUPPORTED_TEXT}"
        )
    if suffix == ".parquet":
        return _load_lerobot_files([p], root=_find_lerobot_root(p), fps=fps,
                                   episode=episode, source=str(p))
    if episode is not None:
        raise ParameterError(
            f"episode: only LeRobot parquet data holds several episodes; got "
            f"episode={episode!r} for a {suffix!r} file {str(p)!r}; give no episode (CLI: "
            f"drop --episode)"
        )
    if suffix == ".npz":
        return _load_npz(p, fps=fps)
    return _load_act_hdf5(p, fps=fps)


def _short(path: Any, limit: int = 120) -> str:
    """A path for a message, its middle elided when very long."""
    text = str(path)
    return text if len(text) <= limit else f"{text[:60]}...{text[-40:]}"


#: Quaternion norms accepted (and normalised) by :func:`as_object_pose`.
_POSE_NORM_TOL = 0.01


def as_object_pose(value: Any, *, what: str = "object_pose") -> np.ndarray:
    """Validates an object pose given by a user.

    Args:
        value: 7 numbers, position [m] then quaternion (w, x, y, z).
        what: where it came from, for messages.

    Returns:
        (7,) float64 pose with a unit quaternion (a norm within 1 % of 1 is
        normalised).

    Raises:
        ParameterError: not 7 finite numbers, or a quaternion whose norm is
            not within 1 % of 1.
    """
    pose = _as_float_array(value, what=what, error=ParameterError)
    if pose.shape != (7,):
        raise ParameterError(
            f"{what}: expected 7 numbers X Y Z QW QX QY QZ (position [m], unit "
            f"quaternion), got shape {pose.shape}"
        )
    if not np.all(np.isfinite(pose)):
        raise ParameterError(f"{what}: expected 7 finite numbers, got {pose.tolist()}")
    norm = float(np.linalg.norm(pose[3:]))
    if abs(norm - 1.0) > _POSE_NORM_TOL:
        raise ParameterError(
            f"{what}: expected a unit quaternion QW QX QY QZ (norm within "
            f"{_POSE_NORM_TOL:g} of 1), got {pose[3:].tolist()} with norm {norm:.6g}"
        )
    pose[3:] /= norm
    return pose


def input_identity(source: Any) -> dict:
    """A path-independent identity of an input: its file name and content hash.

    Two spellings of one file (relative, absolute, through a symlink) give the
    same identity, so a report's manifest does not depend on how a path was
    typed.

    Args:
        source: a path (file or directory) or a description string.

    Returns:
        ``{"name": str, "sha256": str | None}``; the hash of a regular file's
        bytes, None for a directory or something that is not a file.
    """
    text = "" if source is None else os.fspath(source) if isinstance(
        source, os.PathLike) else str(source)
    p = Path(text)
    digest = None
    try:
        if text and p.is_file():
            h = hashlib.sha256()
            with open(p, "rb") as fh:
                for block in iter(lambda: fh.read(1 << 20), b""):
                    h.update(block)
            digest = h.hexdigest()
        name = p.resolve().name if text and p.exists() else (p.name or text)
    except OSError:
        name = p.name or text
    return {"name": printable_name(name), "sha256": digest}


def printable_name(name: str) -> str:
    """``name`` as text any UTF-8 writer takes: a file name that is not UTF-8 (its bytes
    kept by Python as lone surrogates, ``caf\udce9.npz``) with those bytes written as
    backslash escapes (``caf\\xe9.npz``); other text unchanged. A report's manifest
    named such a trajectory as it came, and writing the report's HTML then failed."""
    try:
        raw = name.encode("utf-8", "surrogateescape")
    except UnicodeEncodeError:  # a lone surrogate that is no escaped byte
        return name.encode("utf-8", "backslashreplace").decode("utf-8")
    return raw.decode("utf-8", "backslashreplace")


def name_head(name: str, limit: int = 80) -> str:
    """The start of a file name, at most ``limit`` bytes in the file system's encoding, for
    a temporary name beside it (80 characters of a CJK name are 240 bytes: a valid output
    name of 84 such characters had been refused as "File name too long")."""
    raw = os.fsencode(name)[:limit]
    return os.fsdecode(raw.decode("utf-8", "ignore").encode("utf-8"))


def _scalar(value: np.ndarray, *, what: str) -> Any:
    if value.shape != ():
        raise TrajectoryError(f"{what}: expected a scalar, got shape {value.shape}")
    return value.item()


_ZIP_METHODS = frozenset({zipfile.ZIP_STORED, zipfile.ZIP_DEFLATED, zipfile.ZIP_BZIP2,
                          zipfile.ZIP_LZMA})


def _npy_header(zf: zipfile.ZipFile, info: zipfile.ZipInfo, *,
                member: str) -> tuple[tuple[int, ...], np.dtype]:
    """The shape and dtype an npz member's .npy header declares (no data is read)."""
    try:
        with zf.open(info) as fh:
            version = np.lib.format.read_magic(fh)
            if version == (1, 0):
                shape, _, dtype = np.lib.format.read_array_header_1_0(fh)
            elif version == (2, 0):
                shape, _, dtype = np.lib.format.read_array_header_2_0(fh)
            else:
                raise InputFileError(
                    f"{member}: .npy format version {version}; expected 1.0 or "
                    f"2.0 as numpy.savez writes for plain arrays"
                )
    except CritmomentError:
        raise
    except Exception as exc:  # noqa: BLE001 - numpy parses the header as Python literals
        raise InputFileError(
            f"{member}: corrupt .npy header (expected a dict with 'descr', "
            f"'fortran_order' and 'shape'): {type(exc).__name__}: {exc}"
        ) from None
    return shape, dtype


def _npz_declared_bytes(path: Path) -> None:
    """Checks an npz archive's members from their headers, before numpy reads them.

    Raises:
        InputFileError: not a zip, an encrypted or unsupported member, a header
            declaring more data than its member holds, or a pickled array.
        ResourceLimitError: the arrays declared exceed ``max_input_bytes``.
    """
    try:
        is_zip = zipfile.is_zipfile(path)
    except OSError as exc:
        raise InputFileError(f"cannot open {_short(path)!r} for reading: {exc}") from None
    if not is_zip:
        with open(path, "rb") as fh:
            head = fh.read(6)
        kind = ("a single .npy array" if head == b"\x93NUMPY"
                else "not a zip archive")
        raise InputFileError(
            f"cannot read {_short(path)!r} as an .npz archive: the file is {kind}; "
            f"expected a zip of .npy arrays written by numpy.savez / save_trajectory "
            f"with at least the key 'actions'"
        )
    total = 0
    with zipfile.ZipFile(path) as zf:
        names = [info.filename for info in zf.infolist()]
        twice = sorted({n for n in names if names.count(n) > 1})
        if twice:  # numpy would read the last one silently
            raise InputFileError(
                f"{_short(path)!r} holds member(s) {twice} more than once; expected one "
                f"array per key (which one is meant is ambiguous)")
        for info in zf.infolist():
            member = f"{_short(path)!r} member {info.filename!r}"
            if info.flag_bits & 0x1:
                raise InputFileError(
                    f"{member} is encrypted; expected the plain (unencrypted) .npy "
                    f"members numpy.savez writes"
                )
            if info.compress_type not in _ZIP_METHODS:
                raise InputFileError(
                    f"{member} uses zip compression method {info.compress_type}, "
                    f"which cannot be read; expected stored (0) or deflated (8) "
                    f"members as numpy.savez writes them (or bzip2 (12), lzma (14))"
                )
            if not info.filename.endswith(".npy"):
                continue
            budget.check_bytes(info.file_size, what=f"{member} (uncompressed size)")
            shape, dtype = _npy_header(zf, info, member=member)
            if dtype.hasobject:
                raise InputFileError(
                    f"{member} holds Python objects (pickled); expected plain "
                    f"numeric or string arrays"
                )
            declared = float(math.prod(shape)) * dtype.itemsize
            budget.check_bytes(declared, what=f"{member} declares shape {shape} of "
                                              f"{dtype}")
            if declared > info.file_size:
                raise InputFileError(
                    f"{member}: its header declares shape {shape} of {dtype} "
                    f"({declared:.0f} bytes), but the member holds only "
                    f"{info.file_size} bytes; the archive is corrupt or truncated"
                )
            total += declared
    budget.check_bytes(total, what=f"{_short(path)!r} (all arrays)")


def _load_npz(path: Path, *, fps: float | None) -> Trajectory:
    # Check the archive from its headers first, then let numpy read it; open
    # the file ourselves so that it is closed even when numpy fails half-way.
    try:
        _npz_declared_bytes(path)
        with open(path, "rb") as fh:
            archive = np.load(fh, allow_pickle=False)
            if not isinstance(archive, np.lib.npyio.NpzFile):
                raise InputFileError(
                    f"{_short(path)!r} holds a single .npy array, expected an .npz "
                    f"archive with at least the key 'actions'"
                )
            with archive:
                data = {key: archive[key] for key in archive.files}
    except CritmomentError:
        raise
    except (ValueError, EOFError, KeyError, zipfile.BadZipFile, zlib.error,
            NotImplementedError, RuntimeError, OSError, MemoryError) as exc:
        raise InputFileError(
            f"cannot read the arrays of .npz archive {_short(path)!r} (corrupt, "
            f"truncated, pickled or unsupported content; expected plain numeric "
            f"arrays written by numpy.savez / save_trajectory): "
            f"{type(exc).__name__}: {exc}"
        ) from None

    unknown = sorted(set(data) - _NPZ_KEYS)
    if unknown:
        warnings.warn(
            f"{str(path)!r}: ignoring unknown key(s) {unknown}; known keys are "
            f"{sorted(_NPZ_KEYS)}",
            CritmomentWarning,
            stacklevel=3,
        )
    # a time base under another name (LeRobot's 'timestamp', a 'dt', an 'FPS'), with none
    # that critmoment reads and no rate given: the run had gone on at the scenario's rate
    # with only the unknown-key warning, at twice the recorded speed for a 25 Hz file
    timing = [k for k in unknown if _is_time_base(k)]
    if timing and fps is None and not {"fps", "time"} & set(data):
        raise TrajectoryError(
            f"{str(path)!r}: key(s) {timing} look like the trajectory's time base, but "
            f"critmoment reads it only from 'fps' (the rate [Hz]) or 'time' (each row's "
            f"time [s]); expected one of those (rename the key), or give the rate (--fps)")
    if "actions" not in data:
        raise TrajectoryError(
            f"{str(path)!r}: expected key 'actions' with shape (T, na), found keys "
            f"{sorted(data)}"
        )
    actions = data["actions"]
    n_steps = actions.shape[0] if actions.ndim >= 1 else 0

    file_fps = None
    if "fps" in data:
        file_fps = _as_rate(
            _scalar(data["fps"], what=f"{str(path)!r}: 'fps'"),
            what=f"{str(path)!r}: 'fps'",
            error=TrajectoryError,
        )
    if "time" in data:
        time_fps = _fps_from_times(data["time"], n_steps, what=f"{str(path)!r}: 'time'")
        if file_fps is not None and not _rates_agree(file_fps, time_fps):
            raise TrajectoryError(
                f"{str(path)!r}: 'fps' = {file_fps:g} Hz disagrees with the rate "
                f"{time_fps:g} Hz implied by 'time' (expected agreement within "
                f"{_RATE_RTOL:.0%})"
            )
        if file_fps is None:
            file_fps = time_fps
    rate = _given_or_recorded(fps, file_fps, repr(str(path)))
    if rate is None:
        logger.info("%s records no frame rate; assuming %g Hz", path, DEFAULT_FPS)

    meta: dict = {}
    if "meta" in data:
        raw = data["meta"]
        if raw.shape != () or raw.dtype.kind not in "US":
            raise TrajectoryError(
                f"{str(path)!r}: 'meta' expected a 0-d string array holding JSON, "
                f"got {_describe_dtype(raw)} with shape {raw.shape}"
            )
        text = raw.item()
        if isinstance(text, bytes):
            try:
                text = text.decode("utf-8")
            except UnicodeDecodeError as exc:
                raise TrajectoryError(
                    f"{str(path)!r}: 'meta' expected UTF-8 encoded JSON, got bytes "
                    f"that are not UTF-8 ({exc})"
                ) from None
        try:
            meta = json.loads(text)
        except (ValueError, RecursionError) as exc:  # also a 5000-digit number, deep nesting
            raise TrajectoryError(
                f"{str(path)!r}: 'meta' expected a JSON object string, got text "
                f"that is not valid JSON: {exc}"
            ) from None
        if not isinstance(meta, dict):
            raise TrajectoryError(
                f"{str(path)!r}: 'meta' expected a JSON object, got JSON "
                f"{type(meta).__name__}"
            )

    return Trajectory(
        actions=actions,
        fps=DEFAULT_FPS if rate is None else rate,
        start=data.get("start"),
        qpos0=data.get("qpos0"),
        qvel0=data.get("qvel0"),
        object_pose=data.get("object_pose"),
        meta=meta,
        source=str(path),
        fps_assumed=rate is None,
        observed=data.get("observed"),
    )


def save_trajectory(traj: Trajectory, path: str | os.PathLike) -> None:
    """Writes a trajectory in critmoment's ``.npz`` schema.

    Keys written: ``actions`` (T, na) float64; ``fps`` 0-d float64 [Hz] (not where the rate
    was assumed, ``fps_assumed``);
    ``start`` (na,), ``qpos0`` (nq,), ``qvel0`` (nv,), ``object_pose`` (7,), ``observed``
    (T, na) when present; and ``meta`` as a 0-d unicode array holding JSON. ``source`` is not stored (a
    loaded trajectory's source is the path it was read from). Reading the file
    back with :func:`load_trajectory` reproduces every array bit-exactly.

    Args:
        traj: the trajectory.
        path: destination; must end in ``.npz``. Overwritten if it exists.

    Raises:
        ParameterError: ``traj`` is not a Trajectory or the suffix is not
            ``.npz``.
        InputFileError: the file cannot be written (e.g. missing directory).
    """
    if not isinstance(traj, Trajectory):
        raise ParameterError(
            f"traj: expected a Trajectory, got {type(traj).__name__}"
        )
    p = Path(os.fspath(path))
    if p.suffix.lower() != ".npz":
        raise ParameterError(
            f"path: expected a file name ending in '.npz', got {str(p)!r}"
        )
    arrays: dict[str, np.ndarray] = {
        "actions": np.asarray(traj.actions),
        "meta": np.asarray(json.dumps(traj.meta, allow_nan=False)),
    }
    if not traj.fps_assumed:  # an assumed rate stays one: read back, the scenario's applies
        arrays["fps"] = np.asarray(traj.fps, dtype=np.float64)
    for name in ("start", "qpos0", "qvel0", "object_pose", "observed"):
        value = getattr(traj, name)
        if value is not None:
            arrays[name] = np.asarray(value)
    try:
        with open(p, "wb") as fh:
            np.savez_compressed(fh, **arrays)
    except OSError as exc:
        raise InputFileError(
            f"cannot write trajectory to {str(p)!r} (expected a writable path in "
            f"an existing directory): {exc}"
        ) from None


def _json_value(value: Any) -> Any:
    """Converts an HDF5 attribute to a JSON-friendly Python value."""
    if isinstance(value, bytes):
        return value.decode("utf-8", errors="replace")
    if isinstance(value, np.ndarray):
        return _json_value(value.tolist())
    if isinstance(value, (list, tuple)):
        return [_json_value(v) for v in value]
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return repr(value)
    if isinstance(value, (str, int, float, bool)) or value is None:
        return value
    return str(value)


def _h5_dataset(fh: Any, name: str, *, path: Path) -> Any:
    """The dataset ``name`` of an open HDF5 file, or None when absent.

    Raises:
        InputFileError: ``name`` is a dangling soft or external link, or not a
            dataset.
    """
    import h5py

    if name not in fh:
        return None
    link = fh.get(name, getlink=True)
    try:
        obj = fh[name]
    except (KeyError, OSError, RuntimeError, ValueError) as exc:
        target = ""
        if isinstance(link, h5py.ExternalLink):
            target = f" (external link to {link.path!r} in file {link.filename!r})"
        elif isinstance(link, h5py.SoftLink):
            target = f" (soft link to {link.path!r})"
        raise InputFileError(
            f"{_short(path)!r}: /{name} is a link that cannot be resolved{target}: "
            f"{exc}; expected a dataset stored in the file or a link to one that exists"
        ) from None
    if not isinstance(obj, h5py.Dataset):
        return None
    return obj


def _h5_read(dset: Any, *, path: Path) -> np.ndarray:
    """Reads a numeric HDF5 dataset after checking its declared size."""
    what = f"{_short(path)!r} dataset {dset.name}"
    if dset.shape is None:  # an HDF5 null dataspace: declared, holding nothing
        raise TrajectoryError(f"{what}: expected an array of numbers, got an empty (null) "
                              f"dataset with no shape")
    if dset.dtype.kind not in "iufb":
        raise TrajectoryError(
            f"{what}: expected a numeric dataset, got dtype {dset.dtype}"
        )
    budget.check_bytes(float(math.prod(dset.shape)) * dset.dtype.itemsize,
                       what=f"{what} of shape {dset.shape}")
    return np.asarray(dset[()])


def _h5_object_pose(fh: Any, *, path: Path) -> np.ndarray | None:
    """The object's start pose from an ACT episode, when it is stored.

    ACT's simulated episodes give the environment state as the object's
    pose (sim_transfer_cube: the cube's xyz + quaternion (w, x, y, z); the
    insertion task stores two poses, the first is taken). Looked up in
    ``/observations/env_state`` (first row), ``/env_state``, then the root
    attributes ``object_pose`` / ``env_state``. Anything unusable is ignored
    with a warning.
    """
    candidates: list[tuple[str, Any]] = []
    for name in ("observations/env_state", "env_state"):
        dset = _h5_dataset(fh, name, path=path)
        if dset is not None:
            candidates.append((f"/{name}", dset))
    for key in ("object_pose", "env_state"):
        if key in fh.attrs:
            candidates.append((f"attribute {key!r}", fh.attrs[key]))
    for where, raw in candidates:
        try:
            value = _h5_read(raw, path=path) if hasattr(raw, "shape") and hasattr(
                raw, "name") else np.asarray(raw, dtype=np.float64)
            value = np.asarray(value, dtype=np.float64)
            if value.ndim == 2 and value.shape[0] == 0:
                raise ValueError(f"shape {value.shape}: no rows")
            row = value[0] if value.ndim == 2 else value
            if row.ndim != 1 or row.shape[0] < 7:
                raise ValueError(f"shape {value.shape}, expected (7,) or (T, >=7)")
            pose = as_object_pose(row[:7], what=f"{_short(path)!r} {where}")
        except (ValueError, TypeError, CritmomentError) as exc:
            if isinstance(exc, ResourceLimitError):
                raise
            warnings.warn(
                f"{_short(path)!r}: {where} is not an object pose xyz + quaternion "
                f"({exc}); ignored",
                CritmomentWarning,
                stacklevel=4,
            )
            continue
        return pose
    return None


def _load_act_hdf5(path: Path, *, fps: float | None) -> Trajectory:
    import h5py  # local import: optional at module import time

    try:
        fh = h5py.File(path, "r")
    except OSError as exc:
        raise InputFileError(
            f"cannot open {str(path)!r} as HDF5 (expected an ACT episode file with "
            f"datasets /action and /observations/qpos): {exc}"
        ) from None
    try:
        with fh:
            found: list[str] = []
            fh.visititems(
                lambda name, obj: found.append("/" + name)
                if isinstance(obj, h5py.Dataset) else None
            )
            action = _h5_dataset(fh, "action", path=path)
            if action is None:
                raise TrajectoryError(
                    f"{str(path)!r}: expected dataset /action of shape (T, na) (ACT "
                    f"episode format), found datasets {sorted(found) or 'none'}"
                )
            actions = _h5_read(action, path=path)
            qpos = None
            qpos_dset = _h5_dataset(fh, "observations/qpos", path=path)
            if qpos_dset is not None:
                qpos = _h5_read(qpos_dset, path=path)
            object_pose = _h5_object_pose(fh, path=path)
            attrs = {str(k): _json_value(v) for k, v in fh.attrs.items()}
            # the rates as stored (the JSON form of meta spells a NaN as text)
            stored = {key: fh.attrs[key] for key in _ACT_RATE_KEYS if key in fh.attrs}
            # a time base under another name (a root attribute dt or FPS, an fps attribute on
            # /action, a /timestamps dataset): read from none of them, it must not be ignored
            timing = [f"attribute {k!r}" for k in fh.attrs
                      if _is_time_base(str(k)) and str(k) not in _ACT_RATE_KEYS]
            timing += [f"attribute {k!r} of /action" for k in action.attrs
                       if _is_time_base(str(k))]
            timing += [f"dataset {name}" for name in found
                       if _is_time_base(name.rsplit("/", 1)[-1])]
    except CritmomentError:
        raise
    except (OSError, KeyError, RuntimeError, ValueError, TypeError, MemoryError) as exc:
        raise InputFileError(
            f"cannot read {_short(path)!r} as an ACT episode (corrupt or truncated "
            f"HDF5 data; expected readable datasets /action and /observations/qpos): "
            f"{type(exc).__name__}: {exc}"
        ) from None

    if timing and not stored and fps is None:
        raise TrajectoryError(
            f"{str(path)!r}: {', '.join(timing)} look(s) like the episode's time base, but "
            f"critmoment reads an ACT episode's rate only from a root attribute "
            f"{' / '.join(_ACT_RATE_KEYS)} [Hz] (else ACT's {DEFAULT_FPS:g} Hz); expected one "
            f"of those, or give the rate (CLI --fps, load_trajectory(path, fps=...))")
    start = observed = None
    if qpos is None:
        warnings.warn(
            f"{str(path)!r}: no dataset /observations/qpos, so the start state is "
            f"unknown (found datasets {sorted(found)})",
            CritmomentWarning,
            stacklevel=3,
        )
    elif qpos.ndim != 2 or actions.ndim != 2 or qpos.shape[1] != actions.shape[1]:
        warnings.warn(
            f"{str(path)!r}: /observations/qpos has shape {qpos.shape}, expected "
            f"(T, {actions.shape[-1] if actions.ndim else '?'}) in the action "
            f"convention; start state left unknown",
            CritmomentWarning,
            stacklevel=3,
        )
    elif qpos.shape[0] == 0:
        warnings.warn(
            f"{str(path)!r}: /observations/qpos is empty; start state left unknown",
            CritmomentWarning,
            stacklevel=3,
        )
    elif qpos.shape[0] != actions.shape[0]:
        # ACT records one observation per action: other counts leave unsaid which row is the
        # state the first action starts from (a recorder that appends the final state, or
        # prepends a reset)
        warnings.warn(
            f"{str(path)!r}: /observations/qpos has {qpos.shape[0]} rows for "
            f"{actions.shape[0]} actions, expected one per action; which row the first "
            f"action starts from is unknown, so the start state is left unknown (the first "
            f"action's targets are used)",
            CritmomentWarning,
            stacklevel=3,
        )
    else:
        start = qpos[0]
        # the recorded joint path, which the twin's run may follow where its targets lead
        # (a gap in the recording leaves it out: only the start was ever needed)
        observed = np.asarray(qpos, dtype=np.float64) if np.isfinite(qpos).all() else None

    # a rate the file records (a root attribute ``fps``, as some exporters write it) is the
    # episode's; without one, ACT's own 50 Hz
    rates = {key: _as_rate(value, what=f"{_short(path)!r} attribute {key!r}",
                           error=TrajectoryError)
             for key, value in stored.items()}
    if len(set(rates.values())) > 1 and fps not in rates.values():
        raise TrajectoryError(
            f"{str(path)!r}: the root attributes record different rates "
            f"({', '.join(f'{k} = {v:g}' for k, v in rates.items())}); expected one rate for "
            f"the episode (remove the wrong attribute, or load it with load_trajectory(path, "
            f"fps=...))")
    recorded = fps if len(set(rates.values())) > 1 else next(iter(rates.values()), None)
    fps = _given_or_recorded(fps, recorded, repr(_short(path)))
    if fps is None:
        logger.info("%s: ACT episode without a rate; assuming %g Hz", path, DEFAULT_FPS)
    meta = {"source_format": "act_hdf5"}
    meta.update(attrs)
    return Trajectory(
        actions=actions,
        fps=DEFAULT_FPS if fps is None else fps,
        start=start,
        observed=observed,
        object_pose=object_pose,
        meta=meta,
        source=str(path),
        fps_assumed=fps is None,
    )


# -- LeRobot --------------------------------------------------------------


def _find_lerobot_root(path: Path) -> Path | None:
    """The nearest ancestor of ``path`` holding ``meta/info.json``: of the path as given
    first (the Hugging Face hub cache links ``snapshots/<rev>/data/...`` to a blob file
    elsewhere, whose own folders hold no dataset), then of the file it links to."""
    for start in (Path(os.path.abspath(path)), path.resolve()):
        for parent in start.parents:
            if (parent / "meta" / "info.json").is_file():
                return parent
    return None


def _read_info(root: Path) -> dict:
    info_path = root / "meta" / "info.json"
    try:
        info = json.loads(info_path.read_text(encoding="utf-8-sig"))  # a BOM is no error
    except (OSError, ValueError, RecursionError) as exc:  # ValueError: bad JSON or UTF-8
        raise InputFileError(
            f"cannot read LeRobot metadata {str(info_path)!r} (expected a JSON "
            f"object with at least 'fps'): {exc}"
        ) from None
    if not isinstance(info, dict):
        raise InputFileError(
            f"LeRobot metadata {str(info_path)!r}: expected a JSON object, got "
            f"JSON {type(info).__name__}"
        )
    return info


def _episode_files(root: Path) -> list[Path]:
    """A LeRobot dataset folder's episode parquet files, sorted.

    Raises:
        InputFileError: none under ``data/``: a dataset with no episode is not one.
    """
    # not macOS's AppleDouble sidecars (._file-000.parquet) or other hidden files
    files = (sorted(f for f in (root / "data").rglob("*.parquet")
                    if not any(part.startswith(".") for part in f.relative_to(root).parts))
             if (root / "data").is_dir() else [])
    if not files:
        raise InputFileError(
            f"LeRobot dataset {str(root)!r}: expected episode parquet files under "
            f"{str(root / 'data')!r} (e.g. data/chunk-000/episode_000000.parquet), "
            f"found none"
        )
    return files


def _load_lerobot_dir(root: Path, *, fps: float | None, episode: int | None) -> Trajectory:
    files = _episode_files(root)
    return _load_lerobot_files(files, root=root, fps=fps, episode=episode, source=str(root))


def _format_indices(indices: Sequence[int], limit: int = 20) -> str:
    shown = ", ".join(str(i) for i in indices[:limit])
    if len(indices) > limit:
        shown += f", ... ({len(indices)} in total)"
    return f"[{shown}]"


def _list_column_to_array(column: Any, *, what: str) -> np.ndarray:
    """(T, width) float64 from a pyarrow list / fixed-size-list / numeric column."""
    import pyarrow as pa
    import pyarrow.compute as pc

    arr = column.combine_chunks() if isinstance(column, pa.ChunkedArray) else column
    if arr.null_count:
        first = int(np.flatnonzero(np.asarray(arr.is_null()))[0])
        raise TrajectoryError(f"{what}: expected a value in every row, got null at row {first}")
    n = len(arr)
    typ = arr.type
    if pa.types.is_list(typ) or pa.types.is_large_list(typ) or pa.types.is_fixed_size_list(typ):
        lengths = np.asarray(pc.list_value_length(arr), dtype=np.int64)
        if n and np.any(lengths != lengths[0]):
            bad = int(np.flatnonzero(lengths != lengths[0])[0])
            raise TrajectoryError(
                f"{what}: expected a fixed length per row, got {lengths[0]} values in "
                f"row 0 but {lengths[bad]} in row {bad}"
            )
        width = int(lengths[0]) if n else 0
        values = arr.flatten()
        if not (pa.types.is_integer(values.type) or pa.types.is_floating(values.type)):
            raise TrajectoryError(
                f"{what}: expected lists of numbers, got element type {values.type}"
            )
        if values.null_count:
            raise TrajectoryError(f"{what}: expected numbers in every list, got nulls")
        flat = values.to_numpy(zero_copy_only=False).astype(np.float64)
        return flat.reshape(n, width)
    if pa.types.is_integer(typ) or pa.types.is_floating(typ):
        return arr.to_numpy(zero_copy_only=False).astype(np.float64).reshape(n, 1)
    raise TrajectoryError(
        f"{what}: expected a list<float> column (one fixed-length vector per row) "
        f"or a numeric column, got type {typ}"
    )


def _index_column(column: Any, *, what: str) -> np.ndarray:
    """(n,) int64 from an integer-valued parquet column (episode or frame index).

    Raises:
        TrajectoryError: nulls, strings, NaN or non-integral values.
    """
    import pyarrow as pa

    arr = column.combine_chunks() if isinstance(column, pa.ChunkedArray) else column
    if arr.null_count:
        first = int(np.flatnonzero(np.asarray(arr.is_null()))[0])
        raise TrajectoryError(f"{what}: expected an integer in every row, got null at row {first}")
    if pa.types.is_integer(arr.type):
        raw = np.asarray(arr.to_numpy(zero_copy_only=False))
        if raw.dtype.kind == "u" and raw.size and int(raw.max()) > np.iinfo(np.int64).max:
            i = int(np.argmax(raw > np.iinfo(np.int64).max))
            raise TrajectoryError(f"{what}: expected indices below 2**63, got {int(raw[i])} at "
                                  f"row {i}")
        out = raw.astype(np.int64)
    elif pa.types.is_floating(arr.type):
        values = np.asarray(arr.to_numpy(zero_copy_only=False), dtype=np.float64)
        bad = np.flatnonzero(~np.isfinite(values) | (values != np.round(values)))
        if bad.size:
            i = int(bad[0])
            raise TrajectoryError(
                f"{what}: expected integers, got {float(values[i])!r} at row {i} "
                f"({bad.size} non-integer value(s) in total)"
            )
        out = values.astype(np.int64)
    else:
        raise TrajectoryError(f"{what}: expected an integer column, got type {arr.type}")
    negative = np.flatnonzero(out < 0)
    if negative.size:  # LeRobot counts episodes and frames from 0
        i = int(negative[0])
        raise TrajectoryError(f"{what}: expected indices >= 0, got {int(out[i])} at row {i}")
    return out


_LEROBOT_COLUMNS = ("action", "episode_index", "frame_index", "timestamp", "observation.state")


def _check_parquet_size(path: Path) -> None:
    """Checks the values of the columns read, as the file's footer declares them, against
    the budget."""
    import pyarrow.parquet as pq

    meta = pq.ParquetFile(path).metadata
    values = 0
    for g in range(meta.num_row_groups):
        group = meta.row_group(g)
        for c in range(group.num_columns):
            column = group.column(c)
            top = column.path_in_schema
            if any(top == name or top.startswith(name + ".") for name in _LEROBOT_COLUMNS):
                values += max(int(column.num_values), 0)
    budget.check_bytes(8.0 * values, what=f"{_short(path)!r} ({meta.num_rows} rows, "
                                          f"{values} values as float64)")


@dataclass(frozen=True)
class Episode:
    """One episode of a trajectory file or LeRobot dataset.

    Attributes:
        index: the ``episode_index`` (None for a file holding one unindexed
            episode).
        frames: number of rows (actions).
        file: the file holding it.
    """

    index: int | None
    frames: int
    file: str


def list_episodes(path: str | os.PathLike) -> tuple[Episode, ...]:
    """The episodes of a LeRobot dataset (directory or parquet file) or a file.

    Reads only the ``episode_index`` column (or, for npz/HDF5 files, the
    declared shape of the actions), so it is cheap on large datasets.

    Args:
        path: a LeRobot dataset directory, a parquet file, or an npz/HDF5 file
            (one episode, index None).

    Returns:
        The episodes sorted by index.

    Raises:
        InputFileError: the path does not exist or cannot be read.
        TrajectoryError: malformed episode indices.
    """
    import pyarrow as pa
    import pyarrow.parquet as pq

    p = Path(os.fspath(path))
    try:
        is_dir, exists = p.is_dir(), p.exists()
    except (OSError, ValueError) as exc:
        raise InputFileError(f"path {_short(p)!r} cannot be used: "
                             f"{getattr(exc, 'strerror', None) or exc}") from None
    if not exists:
        raise InputFileError(f"path {str(p)!r} does not exist; expected {_SUPPORTED_TEXT}")
    if is_dir:
        if not (p / "meta" / "info.json").is_file():
            raise InputFileError(
                f"{str(p)!r} is a directory without meta/info.json; expected a LeRobot "
                f"dataset directory"
            )
        files = _episode_files(p)
    elif p.suffix.lower() == ".parquet":
        files = [p]
    else:
        traj = _load_any(p, fps=None, episode=None)
        return (Episode(index=None, frames=traj.n_steps, file=str(p)),)
    counts: dict[int | None, list] = {}
    for f in files:
        try:
            schema = pq.read_schema(f)
            if "action" not in schema.names:
                # LeRobot's own episode metadata (meta/episodes/...), or another table
                raise TrajectoryError(
                    f"{_short(f)!r}: expected episode data with a column 'action', found "
                    f"columns {schema.names[:12]}{' ...' if len(schema.names) > 12 else ''} "
                    f"(a dataset's meta/episodes table? give the dataset folder, or a file "
                    f"under its data/)")
            if "episode_index" not in schema.names:
                counts.setdefault(None, []).append((pq.ParquetFile(f).metadata.num_rows, f))
                continue
            col = pq.read_table(f, columns=["episode_index"]).column("episode_index")
        except (OSError, pa.ArrowException, MemoryError, UnicodeDecodeError) as exc:
            raise InputFileError(
                f"cannot read {_short(f)!r} as parquet: {type(exc).__name__}: {exc}"
            ) from None
        index, n = np.unique(_index_column(col, what=f"{_short(f)!r} column 'episode_index'"),
                             return_counts=True)
        for i, k in zip(index.tolist(), n.tolist(), strict=True):
            counts.setdefault(int(i), []).append((int(k), f))
    out = []
    for idx in sorted(counts, key=lambda i: -1 if i is None else i):
        if idx is not None and len(counts[idx]) > 1:
            # as loading it would say: an episode split over files cannot be read
            raise TrajectoryError(
                f"LeRobot data {str(p)!r}: expected episode {idx} in one parquet file, found "
                f"it in {[_short(f) for _, f in counts[idx]]}")
        for frames, f in counts[idx]:
            out.append(Episode(index=idx, frames=frames, file=str(f)))
    return tuple(out)


def _load_lerobot_files(
    files: Sequence[Path],
    *,
    root: Path | None,
    fps: float | None,
    episode: int | None,
    source: str,
) -> Trajectory:
    import pyarrow as pa
    import pyarrow.parquet as pq

    # Pass 1: which episodes live in which file (reads one column only).
    schemas = {}
    where: dict[int, list[Path]] = {}
    whole_file_episode: list[Path] = []
    for f in files:
        try:
            schema = pq.read_schema(f)
            schemas[f] = schema
            _check_parquet_size(f)
            if "episode_index" in schema.names:
                col = pq.read_table(f, columns=["episode_index"]).column("episode_index")
                for idx in np.unique(_index_column(col, what=f"{_short(f)!r} column "
                                                             f"'episode_index'")):
                    where.setdefault(int(idx), []).append(f)
            else:
                whole_file_episode.append(f)
        except (OSError, pa.ArrowException, MemoryError, UnicodeDecodeError) as exc:
            raise InputFileError(
                f"cannot read {_short(f)!r} as parquet (expected a LeRobot episode "
                f"file with an 'action' column): {type(exc).__name__}: {exc}"
            ) from None

    if whole_file_episode:
        if len(files) > 1:
            raise TrajectoryError(
                f"LeRobot data {source!r}: expected an 'episode_index' column in "
                f"every parquet file of a dataset, missing in "
                f"{[str(f) for f in whole_file_episode[:5]]}"
            )
        if episode is not None:
            raise TrajectoryError(
                f"{source!r} has no 'episode_index' column, so it holds a single "
                f"episode; got episode={episode}; give no episode (CLI: drop --episode)"
            )
        chosen_file, ep = files[0], None
    else:
        available = sorted(where)
        if not available:
            raise TrajectoryError(f"LeRobot data {source!r}: expected rows, found none")
        if episode is None:
            if len(available) > 1:
                raise TrajectoryError(
                    f"LeRobot data {source!r} holds {len(available)} episodes, "
                    f"which one is ambiguous; pass episode= (CLI: --episode N) one "
                    f"of {_format_indices(available)}"
                )
            ep = available[0]
        else:
            ep = int(episode)
            if ep not in where:
                raise TrajectoryError(
                    f"LeRobot data {source!r}: episode {ep} not found; available "
                    f"episode indices: {_format_indices(available)}"
                )
        if len(where[ep]) > 1:
            raise TrajectoryError(
                f"LeRobot data {source!r}: expected episode {ep} in one parquet "
                f"file, found it in {[str(f) for f in where[ep]]}"
            )
        chosen_file = where[ep][0]

    schema = schemas[chosen_file]
    if "action" not in schema.names:
        raise TrajectoryError(
            f"{str(chosen_file)!r}: expected a column 'action' (one fixed-length "
            f"vector per row), found columns {schema.names}"
        )
    wanted = [c for c in _LEROBOT_COLUMNS if c in schema.names]
    try:
        table = pq.read_table(chosen_file, columns=wanted)
        if ep is not None:
            index = _index_column(table.column("episode_index"),
                                  what=f"{_short(chosen_file)!r} column 'episode_index'")
            table = table.filter(pa.array(index == ep))
    except (OSError, pa.ArrowException, MemoryError, UnicodeDecodeError) as exc:
        raise InputFileError(
            f"cannot read {_short(chosen_file)!r} as parquet: {type(exc).__name__}: {exc}"
        ) from None
    if "frame_index" in table.column_names:
        frame = _index_column(table.column("frame_index"),
                              what=f"{_short(chosen_file)!r} episode {ep} column "
                                   f"'frame_index'")
        order = np.argsort(frame, kind="stable")
        sorted_frames = frame[order]
        dup = np.flatnonzero(np.diff(sorted_frames) == 0)
        if dup.size:
            raise TrajectoryError(
                f"{str(chosen_file)!r} episode {ep}: expected unique frame_index "
                f"values, got frame {int(sorted_frames[dup[0]])} more than once"
            )
        gap = np.flatnonzero(np.diff(sorted_frames) != 1)
        if gap.size:
            # frames missing from the episode: the actions around them would be played
            # back to back, faster than recorded, with or without timestamps
            raise TrajectoryError(
                f"{str(chosen_file)!r} episode {ep}: expected consecutive frame_index "
                f"values, got a jump from frame {int(sorted_frames[gap[0]])} to "
                f"{int(sorted_frames[gap[0] + 1])} ({gap.size} gap(s) in all): frames are "
                f"missing from the episode"
            )
        if not np.array_equal(order, np.arange(len(order))):
            table = table.take(pa.array(order))

    ep_text = "" if ep is None else f" episode {ep}"
    actions = _list_column_to_array(
        table.column("action"), what=f"{str(chosen_file)!r}{ep_text} column 'action'"
    )

    info = _read_info(root) if root is not None else {}
    info_fps = None
    if "fps" in info:
        info_fps = _as_rate(info["fps"], what=f"{str(root)}/meta/info.json 'fps'",
                            error=TrajectoryError)
    time_fps = None
    if "timestamp" in table.column_names:
        time_fps = _fps_from_times(
            table.column("timestamp").to_numpy(), actions.shape[0],
            what=f"{str(chosen_file)!r}{ep_text} column 'timestamp'",
        )
        if info_fps is not None and not _rates_agree(info_fps, time_fps):
            raise TrajectoryError(
                f"LeRobot data {source!r}{ep_text}: meta/info.json fps = "
                f"{info_fps:g} Hz disagrees with the rate {time_fps:g} Hz implied "
                f"by 'timestamp' (expected agreement within {_RATE_RTOL:.0%})"
            )
    recorded = info_fps if info_fps is not None else time_fps
    rate = _given_or_recorded(fps, recorded, f"LeRobot data {source!r}")
    if rate is None:
        warnings.warn(
            f"LeRobot data {source!r}: no meta/info.json 'fps' and no 'timestamp' "
            f"column found, and no fps= given; assuming {DEFAULT_FPS:g} Hz",
            CritmomentWarning,
            stacklevel=3,
        )

    width = actions.shape[1] if actions.ndim == 2 else 0
    action_names = _feature_names(info, "action", width)
    start = observed = None
    if "observation.state" in table.column_names and table.num_rows:
        state = _list_column_to_array(
            table.column("observation.state").slice(0, 1),
            what=f"{str(chosen_file)!r}{ep_text} column 'observation.state'",
        )[0]
        state_names = _feature_names(info, "observation.state", state.shape[0])
        if actions.ndim == 2 and state.shape == (actions.shape[1],):
            start = state
            columns = list(range(state.shape[0]))
            if action_names and state_names and state_names != action_names:
                # the state is the start in the action's convention only channel by channel
                a, b = map(_channel_keys, (action_names, state_names))
                if sorted(a) == sorted(b) and len(set(a)) == len(a):
                    columns = [b.index(k) for k in a]
                    start = state[columns]
                else:
                    warnings.warn(
                        f"{str(chosen_file)!r}{ep_text}: meta/info.json names "
                        f"'observation.state' {state_names[:6]}... and 'action' "
                        f"{action_names[:6]}...: not the same channels, so the state is not "
                        f"the start in the action's convention; start state left unknown",
                        CritmomentWarning, stacklevel=3)
                    start = None
            if start is not None:
                # the recorded joint path, which the twin's run may follow where its
                # targets lead (unreadable or with gaps: only the start was needed)
                try:
                    states = _list_column_to_array(
                        table.column("observation.state"),
                        what=f"{str(chosen_file)!r}{ep_text} column 'observation.state'")
                except TrajectoryError:
                    states = None
                if (states is not None and states.shape == actions.shape[:1] + state.shape
                        and np.isfinite(states).all()):
                    observed = states[:, columns]
        else:
            warnings.warn(
                f"{str(chosen_file)!r}{ep_text}: 'observation.state' has "
                f"{state.shape[0]} values, expected {actions.shape[1]} to match "
                f"'action'; start state left unknown",
                CritmomentWarning,
                stacklevel=3,
            )

    meta: dict = {"source_format": "lerobot", "file": str(chosen_file)}
    if ep is not None:
        meta["episode_index"] = ep
    if action_names:
        # what each column is: the audit maps them onto the scenario's channels by name
        # (recording.at_scenario_rate)
        meta["action_names"] = action_names
    for key in ("codebase_version", "robot_type"):
        if key in info:
            meta[key] = _json_value(info[key])
    return Trajectory(actions=actions, fps=DEFAULT_FPS if rate is None else rate, start=start,
                      meta=meta, source=source, fps_assumed=rate is None, observed=observed)


def _feature_names(info: Mapping[str, Any], key: str, width: int) -> list[str] | None:
    """The names a LeRobot ``meta/info.json`` gives the ``width`` components of feature
    ``key`` (``features.<key>.names``: a list, or v2.x's ``{"motors": [...]}``), else None."""
    features = info.get("features") if isinstance(info, Mapping) else None
    feature = features.get(key) if isinstance(features, Mapping) else None
    names = feature.get("names") if isinstance(feature, Mapping) else None
    if isinstance(names, Mapping):
        lists = [v for v in names.values() if isinstance(v, list)]
        names = lists[0] if len(lists) == 1 else None
    if (isinstance(names, list) and width and len(names) == width
            and all(isinstance(n, str) and n for n in names)):
        return [str(n) for n in names]
    return None


def _channel_keys(names: Sequence[str]) -> list[str]:
    """Channel names compared across conventions: lower case, every run of other characters
    one underscore (``left/waist`` and ``Left_Waist`` are one channel)."""
    return [re.sub(r"[^0-9a-z]+", "_", str(n).lower()).strip("_") for n in names]


# ---------------------------------------------------------------------------
# Range checking
# ---------------------------------------------------------------------------


class RangePolicy(enum.Enum):
    """What :func:`check_ranges` does with out-of-range values."""

    ERROR = "error"
    """Raise :class:`TrajectoryError` on the first offending value."""
    CLIP = "clip"
    """Clip to the bounds and warn how many values were clipped per channel."""
    WARN = "warn"
    """Warn and return the input unchanged."""


def _as_policy(policy: Any) -> RangePolicy:
    if isinstance(policy, RangePolicy):
        return policy
    if isinstance(policy, str):
        for member in RangePolicy:
            if policy.lower() in (member.value, member.name.lower()):
                return member
    raise ParameterError(
        f"policy: expected a RangePolicy, got {policy!r}; valid options are "
        f"{[m.name for m in RangePolicy]}"
    )


def _bounds(
    lower: Any, upper: Any, n_channels: int
) -> tuple[np.ndarray, np.ndarray]:
    """Validated (na,) bounds; ``None`` means unbounded on that side."""
    out = []
    for name, value, fill in (("lower", lower, -np.inf), ("upper", upper, np.inf)):
        if value is None:
            out.append(np.full(n_channels, fill))
            continue
        arr = _as_float_array(value, what=name, error=ParameterError)
        if arr.shape != (n_channels,):
            raise ParameterError(
                f"{name}: expected shape ({n_channels},) (one bound per action "
                f"channel), got shape {arr.shape}"
            )
        if np.isnan(arr).any():
            i = int(np.flatnonzero(np.isnan(arr))[0])
            raise ParameterError(
                f"{name}: expected numbers or +/-inf, got NaN for channel {i}"
            )
        out.append(arr)
    lo, hi = out
    if np.any(lo > hi):
        i = int(np.flatnonzero(lo > hi)[0])
        raise ParameterError(
            f"bounds: expected lower <= upper, got lower[{i}] = {float(lo[i])!r} > "
            f"upper[{i}] = {float(hi[i])!r}"
        )
    return lo, hi


def _channel_labels(names: Sequence[str] | None, n_channels: int) -> list[str]:
    if names is None:
        return [f"channel {i}" for i in range(n_channels)]
    if isinstance(names, str) or len(names) != n_channels:
        got = "a single str" if isinstance(names, str) else f"{len(names)} names"
        raise ParameterError(
            f"names: expected a sequence of {n_channels} channel names, got {got}"
        )
    return [f"channel {str(n)!r} (index {i})" for i, n in enumerate(names)]


def _actions_of(obj: Any) -> np.ndarray:
    if isinstance(obj, Trajectory):
        return obj.actions
    actions = _as_float_array(obj, what="actions", error=TrajectoryError)
    if actions.ndim != 2:
        raise TrajectoryError(
            f"actions: expected a Trajectory or a 2-D array of shape (T, na), got "
            f"{actions.ndim}-D array of shape {actions.shape}"
        )
    bad = _first_nonfinite(actions)
    if bad is not None:
        raise TrajectoryError(
            f"actions: expected finite values, got {actions[bad]} at row (step) "
            f"{bad[0]}, column (channel) {bad[1]}"
        )
    return actions


def check_ranges(
    traj_or_actions: Trajectory | np.ndarray,
    lower: Any,
    upper: Any,
    *,
    policy: RangePolicy | str = RangePolicy.ERROR,
    tolerance: float = 1e-6,
    names: Sequence[str] | None = None,
) -> Trajectory | np.ndarray:
    """Checks every action against per-channel bounds.

    A value violates its range when ``value < lower - tolerance`` or
    ``value > upper + tolerance``. The policy decides what happens then; it is
    never silent:

    * ``ERROR``: raise, naming the channel, the first offending step (earliest
      in time), its value and the range.
    * ``CLIP``: return a copy with every value outside ``[lower, upper]``
      clipped (values within the tolerance included, so the result is exactly
      in range) and issue one :class:`~critmoment.exceptions.CritmomentWarning` giving the number of
      clipped values per channel. When only within-tolerance values needed
      clipping, no warning is issued and the count is logged at INFO level.
    * ``WARN``: issue one warning with the same summary; return the input.

    Args:
        traj_or_actions: a Trajectory, or a (T, na) array of actions.
        lower: (na,) lower bounds (``-inf`` or ``None`` for unbounded).
        upper: (na,) upper bounds (``+inf`` or ``None`` for unbounded).
        policy: a :class:`RangePolicy` (or its name, case-insensitive).
        tolerance: slack beyond the bounds that is not a violation [same
            units as the channel]; finite and >= 0.
        names: optional (na,) channel names for messages.

    Returns:
        The same type as given. With ``CLIP`` and out-of-range values, a new
        Trajectory (other fields kept) or a new array; otherwise the input.

    Raises:
        TrajectoryError: ``ERROR`` policy and a value out of range, or the
            actions are malformed.
        ParameterError: bad bounds, policy, tolerance or names.
    """
    pol = _as_policy(policy)
    actions = _actions_of(traj_or_actions)
    n_steps, n_channels = actions.shape
    lo, hi = _bounds(lower, upper, n_channels)
    labels = _channel_labels(names, n_channels)
    try:
        tol = float(tolerance)
    except (TypeError, ValueError):
        tol = float("nan")
    if not math.isfinite(tol) or tol < 0:
        raise ParameterError(
            f"tolerance: expected a finite number >= 0, got {tolerance!r}"
        )

    violating = (actions < lo - tol) | (actions > hi + tol)
    outside = (actions < lo) | (actions > hi)

    def summary() -> str:
        counts = np.count_nonzero(violating, axis=0)
        parts = []
        for j in np.flatnonzero(counts):
            col = actions[:, j]
            excess = max(float(np.max(lo[j] - col)), float(np.max(col - hi[j])))
            parts.append(
                f"{labels[j]}: {int(counts[j])} of {n_steps} values outside "
                f"[{lo[j]:g}, {hi[j]:g}] (worst by {excess:.3g})"
            )
        return "; ".join(parts)

    if violating.any():
        if pol is RangePolicy.ERROR:
            steps, chans = np.nonzero(violating)  # row-major: earliest step first
            i, j = int(steps[0]), int(chans[0])
            raise TrajectoryError(
                f"{labels[j]} out of range at step {i}: value {float(actions[i, j])!r} "
                f"outside [{float(lo[j])!r}, {float(hi[j])!r}] (tolerance {tol:g}); "
                f"{int(np.count_nonzero(violating))} violating value(s) in total: "
                f"{summary()}; to clip them to the ranges or keep them with a warning, set "
                f"[actions] range_policy = {' or '.join(repr(m.value) for m in RangePolicy if m is not RangePolicy.ERROR)} "
                f"in the scenario"
            )
        if pol is RangePolicy.WARN:
            warnings.warn(
                f"actions out of range (tolerance {tol:g}), kept unchanged: {summary()}",
                CritmomentWarning,
                stacklevel=2,
            )
            return traj_or_actions

    if pol is RangePolicy.CLIP and outside.any():
        clipped = np.clip(actions, lo, hi)
        per_channel = np.count_nonzero(outside, axis=0)
        detail = ", ".join(
            f"{labels[j]}: {int(per_channel[j])}" for j in np.flatnonzero(per_channel)
        )
        if violating.any():
            warnings.warn(
                f"clipped {int(per_channel.sum())} action value(s) to their range "
                f"(per channel: {detail}); beyond tolerance {tol:g}: {summary()}",
                CritmomentWarning,
                stacklevel=2,
            )
        else:
            logger.info(
                "clipped %d action value(s) lying within tolerance %g of their "
                "bounds (per channel: %s)", int(per_channel.sum()), tol, detail,
            )
        if isinstance(traj_or_actions, Trajectory):
            return replace(traj_or_actions, actions=clipped)
        return clipped
    return traj_or_actions


# ---------------------------------------------------------------------------
# Upsampling
# ---------------------------------------------------------------------------


#: a spline's overshoot past a channel's bound, as a fraction of its range, under which the
#: clip is not warned of (a motion planned to a joint limit grazes it by micrometres)
CLIP_NOTICE = 1e-3


def upsample(
    actions: Trajectory | np.ndarray,
    *,
    fps: float | None = None,
    physics_dt: float,
    bounded: Any = None,
    lower: Any = None,
    upper: Any = None,
) -> np.ndarray:
    """Interpolates control-rate actions to one control per physics step.

    Action ``i`` sits at time ``i / fps``; the control for physics step ``k``
    is the interpolant at time ``k * physics_dt``. After the last action's
    time, the last action is held. Physics steps that fall on a sample time
    (within 1e-9 of a control period) get the sample exactly.

    * Unflagged channels (joints) use a cubic spline with not-a-knot ends: C2,
      reproduces cubic polynomials exactly, and imposes no end velocity or
      acceleration we do not know (a "natural" spline would force zero end
      acceleration, a clamped one needs end velocities).
    * Channels flagged in ``bounded`` (e.g. grippers) use PCHIP, a
      shape-preserving monotone cubic that never leaves the range of its
      neighbouring samples, so a 0 -> 1 step stays in [0, 1] and monotone.

    When ``lower``/``upper`` are given, any result outside them (spline
    overshoot past a joint limit, or samples already out of range) is clipped
    to the bound and one :class:`~critmoment.exceptions.CritmomentWarning` reports the count
    per channel.

    Args:
        actions: (T, na) actions, or a Trajectory (then ``fps`` defaults to
            its rate and must agree with it if given).
        fps: control rate [Hz]; required for an array.
        physics_dt: physics time step [s]; 0 < physics_dt <= 1 / fps.
        bounded: optional (na,) bool mask of channels interpolated with PCHIP.
        lower: optional (na,) lower bounds (``None``: unbounded).
        upper: optional (na,) upper bounds (``None``: unbounded).

    Returns:
        (n, na) float64 controls, n = round(T / fps / physics_dt).

    Raises:
        ParameterError: bad fps, physics_dt, mask or bounds.
        TrajectoryError: malformed actions (not 2-D, T < 2, non-finite).
    """
    if isinstance(actions, Trajectory):
        rate = actions.fps
        if fps is not None:
            given = _as_rate(fps, what="fps", error=ParameterError)
            if given != rate:
                raise ParameterError(
                    f"fps: expected None or the trajectory's rate {rate:g} Hz, "
                    f"got {given:g} Hz"
                )
        a = actions.actions
    else:
        if fps is None:
            raise ParameterError(
                "fps: expected the control rate [Hz] when actions is an array, "
                "got None (pass fps= or a Trajectory)"
            )
        rate = _as_rate(fps, what="fps", error=ParameterError)
        a = _actions_of(actions)
    n_steps, n_channels = a.shape
    if n_steps < 2:
        raise TrajectoryError(
            f"actions: expected at least 2 time steps to interpolate, got {n_steps}"
        )

    if isinstance(physics_dt, (bool, np.bool_)):
        dt = float("nan")
    else:
        try:
            dt = float(physics_dt)
        except (TypeError, ValueError):
            dt = float("nan")
    period = 1.0 / rate
    if not math.isfinite(dt) or dt <= 0.0 or dt * rate > 1.0 + 1e-9:
        raise ParameterError(
            f"physics_dt: expected a finite time step with 0 < physics_dt <= "
            f"1 / fps = {period!r} s, got {physics_dt!r}"
        )

    if bounded is None:
        mask = np.zeros(n_channels, dtype=bool)
    else:
        mask = np.asarray(bounded)
        if mask.dtype != np.bool_ or mask.shape != (n_channels,):
            raise ParameterError(
                f"bounded: expected a bool mask of shape ({n_channels},), got "
                f"{_describe_dtype(mask)} with shape {mask.shape}"
            )
    lo, hi = _bounds(lower, upper, n_channels)

    n_out = int(round(n_steps / rate / dt))
    # Physics-step times expressed in sample-index units (s = t * fps), so the
    # knots are the integers 0..T-1 and exact hits are easy to recognise.
    s = np.arange(n_out, dtype=np.float64) * (dt * rate)
    s = np.minimum(s, float(n_steps - 1))  # hold the last action
    nearest = np.rint(s)
    on_sample = np.abs(s - nearest) <= _SNAP_TOL
    s[on_sample] = nearest[on_sample]

    knots = np.arange(n_steps, dtype=np.float64)
    out = np.empty((n_out, n_channels), dtype=np.float64)
    smooth = ~mask
    if smooth.any():
        spline = CubicSpline(knots, a[:, smooth], axis=0, bc_type="not-a-knot")
        out[:, smooth] = spline(s)
    if mask.any():
        pchip = PchipInterpolator(knots, a[:, mask], axis=0, extrapolate=False)
        out[:, mask] = pchip(s)
    out[on_sample] = a[nearest[on_sample].astype(np.intp)]

    below, above = out < lo, out > hi
    outside = below | above
    if outside.any():
        per_channel = np.count_nonzero(outside, axis=0)
        samples_out = np.count_nonzero((a < lo) | (a > hi), axis=0)
        parts = []
        for j in np.flatnonzero(per_channel):
            worst = max(float(np.max(lo[j] - out[:, j])), float(np.max(out[:, j] - hi[j])))
            span = float(hi[j] - lo[j]) if np.isfinite(hi[j] - lo[j]) else 0.0
            if not samples_out[j] and worst <= CLIP_NOTICE * span:
                continue  # a spline grazing a limit it was planned to reach: clipped quietly
            kind = "PCHIP" if mask[j] else "cubic spline"
            note = (
                f", {int(samples_out[j])} input sample(s) already out of range"
                if samples_out[j] else ""
            )
            parts.append(
                f"channel {j} ({kind}): {int(per_channel[j])} step(s), worst by "
                f"{worst:.3g}{note}"
            )
        np.clip(out, lo, hi, out=out)
        if parts:
            warnings.warn(
                f"upsampled controls left [lower, upper] and were clipped to it in "
                f"{int(per_channel.sum())} of {out.size} values: " + "; ".join(parts),
                CritmomentWarning,
                stacklevel=2,
            )
    return out
