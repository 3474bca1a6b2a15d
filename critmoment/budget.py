"""Resource bounds: estimate the work an input asks for before allocating it.

A trajectory file can declare arrays far larger than itself (a 312-byte ``.npz``
whose header claims 72 TiB), a scenario can ask for a 1 µs physics step, and a
command line can ask for 10⁹ samples. Each of these would end in a
``MemoryError`` or hours of stepping. The checks here estimate the size of the
work from headers and options alone and refuse, with a
:class:`~critmoment.exceptions.ResourceLimitError` naming the option that raises
the limit, what lies beyond :class:`Budget`'s limits.

The limits (defaults in brackets) are

* ``max_input_bytes`` [1 GiB]: bytes of the arrays a trajectory file declares
  (npz/npy headers, HDF5 dataset shapes, parquet value counts), read before any
  array is;
* ``max_steps`` [500,000]: physics steps of one full rollout, trajectory
  duration / physics time step (1000 s at 500 Hz);
* ``max_batch_steps`` [50,000,000]: physics steps of an audit's batched
  simulations, samples × moments × horizon for the sweep plus samples × rollout
  steps for the full rollouts of ``validate``.

Each is raised by an environment variable (``CRITMOMENT_MAX_INPUT_BYTES``,
``CRITMOMENT_MAX_STEPS``, ``CRITMOMENT_MAX_BATCH_STEPS``), by the CLI options
``--max-input-bytes``, ``--max-steps``, ``--max-batch-steps``, or in Python by
``with budget.limits(max_steps=...)``.
"""

from __future__ import annotations

import contextlib
import contextvars
import dataclasses
import math
import os
from collections.abc import Iterator
from typing import Any

from critmoment.exceptions import ParameterError, ResourceLimitError

__all__ = [
    "Budget",
    "limits",
    "active",
    "check_bytes",
    "check_steps",
    "check_batch_steps",
    "check_seed",
    "check_rollout",
    "check_audit",
    "check_validation",
    "SEED_MAX",
]

#: Seeds are unsigned 32-bit integers (numpy's SeedSequence, Optuna's samplers).
SEED_MAX: int = 2**32 - 1

# (field, environment variable, CLI option, default)
_LIMITS = (
    ("max_input_bytes", "CRITMOMENT_MAX_INPUT_BYTES", "--max-input-bytes", 2**30),
    ("max_steps", "CRITMOMENT_MAX_STEPS", "--max-steps", 500_000),
    ("max_batch_steps", "CRITMOMENT_MAX_BATCH_STEPS", "--max-batch-steps", 50_000_000),
)
_ENV = {name: env for name, env, _, _ in _LIMITS}
_OPTION = {name: opt for name, _, opt, _ in _LIMITS}


def _positive_int(value: Any, *, what: str) -> int:
    if isinstance(value, bool):
        raise ParameterError(f"{what}: expected an integer >= 1, got bool {value!r}")
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ParameterError(
            f"{what}: expected an integer >= 1, got {type(value).__name__} {value!r}") from None
    if not math.isfinite(number) or number < 1 or number != int(number):
        raise ParameterError(f"{what}: expected an integer >= 1, got {value!r}")
    return int(number)


@dataclasses.dataclass(frozen=True)
class Budget:
    """Limits on the work and memory one command may ask for.

    Attributes:
        max_input_bytes: bytes of array data a trajectory file may declare [B].
        max_steps: physics steps of one full rollout.
        max_batch_steps: physics steps of an audit's batched simulations in total.
    """

    max_input_bytes: int = _LIMITS[0][3]
    max_steps: int = _LIMITS[1][3]
    max_batch_steps: int = _LIMITS[2][3]

    def __post_init__(self) -> None:
        for f in dataclasses.fields(self):
            object.__setattr__(self, f.name,
                               _positive_int(getattr(self, f.name), what=f.name))

    @classmethod
    def from_env(cls, environ: os._Environ | dict | None = None) -> Budget:
        """The defaults, overridden by ``CRITMOMENT_MAX_*`` environment variables.

        Raises:
            ParameterError: a variable that is not an integer >= 1.
        """
        env = os.environ if environ is None else environ
        values = {}
        for name, var, _, _ in _LIMITS:
            if env.get(var, "").strip():
                values[name] = _positive_int(env[var].strip(), what=f"environment {var}")
        return cls(**values)


_ACTIVE: contextvars.ContextVar[Budget | None] = contextvars.ContextVar(
    "critmoment_budget", default=None)


def active() -> Budget:
    """The budget in force: the innermost :func:`limits`, else :meth:`Budget.from_env`."""
    budget = _ACTIVE.get()
    return Budget.from_env() if budget is None else budget


@contextlib.contextmanager
def limits(budget: Budget | None = None, **overrides: int | None) -> Iterator[Budget]:
    """Runs a block under other limits.

    Args:
        budget: the limits to use (default: the active ones).
        **overrides: single limits to replace (``None`` keeps the value), e.g.
            ``max_steps=2_000_000``.

    Yields:
        The budget in force inside the block.
    """
    base = active() if budget is None else budget
    new = dataclasses.replace(base, **{k: v for k, v in overrides.items() if v is not None})
    token = _ACTIVE.set(new)
    try:
        yield new
    finally:
        _ACTIVE.reset(token)


def _refuse(limit: str, *, what: str, got: float, unit: str, hint: str = "") -> None:
    budget = active()
    cap = getattr(budget, limit)
    if got <= cap:
        return
    raise ResourceLimitError(
        f"{what}: expected at most {cap:,} {unit} ({limit}), got {_count(got)} {unit}"
        f"{'; ' + hint if hint else ''}; raise the limit with {_OPTION[limit]} or the "
        f"environment variable {_ENV[limit]} if this is intended")


def _count(x: float) -> str:
    return f"{int(x):,}" if x < 1e18 else f"{x:.3g}"


def check_bytes(nbytes: float, *, what: str) -> None:
    """Refuses an input that declares more than ``max_input_bytes`` of array data.

    Args:
        nbytes: declared size [B] (may be astronomically large; a float is fine).
        what: the file and array, for the message.

    Raises:
        ResourceLimitError: beyond the limit.
    """
    _refuse("max_input_bytes", what=what, got=float(nbytes), unit="bytes")


def check_steps(duration: float, timestep: float, *, what: str) -> int:
    """Refuses a rollout of more than ``max_steps`` physics steps.

    Args:
        duration: trajectory duration [s].
        timestep: physics time step [s], > 0.
        what: the trajectory, for the message.

    Returns:
        The estimated number of physics steps.

    Raises:
        ResourceLimitError: beyond the limit.
        ParameterError: a time step that is not finite and > 0.
    """
    if not (isinstance(timestep, (int, float)) and math.isfinite(timestep) and timestep > 0):
        raise ParameterError(f"physics time step: expected a finite number > 0 [s], "
                             f"got {timestep!r}")
    steps = float(duration) / float(timestep)
    _refuse("max_steps", what=what, got=steps, unit="physics steps",
            hint=f"{duration:g} s of trajectory at a {timestep:g} s physics step")
    return int(round(steps))


def check_batch_steps(steps: float, *, what: str, detail: str = "") -> None:
    """Refuses batched simulations of more than ``max_batch_steps`` physics steps in total.

    Raises:
        ResourceLimitError: beyond the limit.
    """
    _refuse("max_batch_steps", what=what, got=float(steps), unit="physics steps",
            hint=detail)


def check_seed(seed: Any, *, what: str = "seed") -> int:
    """A seed as an int in [0, 2³² − 1] (numpy's and Optuna's domain).

    Raises:
        ParameterError: not an integer, or out of range.
    """
    if isinstance(seed, bool) or not isinstance(seed, int) and not hasattr(seed, "__index__"):
        raise ParameterError(f"{what}: expected an integer in [0, {SEED_MAX}], got "
                             f"{type(seed).__name__} {seed!r}")
    value = int(seed.__index__())
    if not 0 <= value <= SEED_MAX:
        raise ParameterError(f"{what}: expected an integer in [0, 2**32 - 1 = {SEED_MAX}], "
                             f"got {value}")
    return value


def check_rollout(trajectory, twin) -> int:
    """Checks that one full rollout of ``trajectory`` in ``twin`` is within ``max_steps``.

    Args:
        trajectory: the :class:`~critmoment.trajectory.Trajectory`.
        twin: the :class:`~critmoment.twin.Twin` (its model's physics time step [s]).

    Returns:
        The estimated number of physics steps.

    Raises:
        ResourceLimitError: beyond the limit.
    """
    return check_steps(trajectory.duration, float(twin.model.opt.timestep),
                       what=f"rollout of {trajectory.source or 'the trajectory'}")


def check_audit(trajectory, twin, options) -> None:
    """Checks an audit's seed and size before it starts.

    Args:
        trajectory: the :class:`~critmoment.trajectory.Trajectory`.
        twin: the :class:`~critmoment.twin.Twin` (physics time step [s], the scenario's
            sparse horizon [steps]).
        options: the :class:`~critmoment.analysis.AnalyzeOptions`.

    Raises:
        ParameterError: a seed outside [0, 2³² − 1].
        ResourceLimitError: the rollout or the sweep is beyond the active limits.
    """
    check_seed(options.seed, what="seed")
    check_rollout(trajectory, twin)
    horizon = options.horizon if options.horizon is not None else twin.scenario.horizon
    sweep = float(options.n_samples) * float(options.max_moments) * float(horizon)
    check_batch_steps(sweep, what="sparse sweep",
                      detail=f"{options.n_samples} samples x {options.max_moments} moments x "
                             f"horizon {horizon}; lower --samples, --max-moments or --horizon")


def check_validation(trajectory, twin, *, n_samples: int) -> None:
    """Checks that ``n_samples`` full rollouts of ``trajectory`` are within ``max_batch_steps``.

    Raises:
        ResourceLimitError: beyond the limit.
    """
    steps = check_rollout(trajectory, twin)
    check_batch_steps(float(n_samples) * steps, what="brute-force full rollouts",
                      detail=f"{n_samples} samples x {steps} physics steps; lower --samples")
