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
  simulations: every sparse evaluation of :func:`critmoment.analysis.analyze`
  (the moments' ranking, the sweep, the critical values, the searches, the check
  of the safe region; each the horizon plus its persistence and settling steps)
  plus the samples' own runs through the recording, or samples × rollout steps
  for the full rollouts of ``validate``.

Besides these limits, options that set the size of the work without a physics
step count have fixed bounds (:data:`MAX_THREADS`; the audit's options in
:class:`critmoment.analysis.AnalyzeOptions`), and the sparse horizon must leave
at least half of the recording for the moments (:func:`check_horizon`).

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
import threading
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
    "check_horizon",
    "check_audit_horizon",
    "check_nthread",
    "check_step_count",
    "audit_work",
    "SEED_MAX",
    "MAX_THREADS",
]

#: Seeds are unsigned 32-bit integers (numpy's SeedSequence, Optuna's samplers).
SEED_MAX: int = 2**32 - 1

#: Most MuJoCo threads one batch may ask for (four per CPU on larger machines): MuJoCo's
#: thread pool allocates per thread, and 100,000 threads fail deep inside it.
MAX_THREADS: int = max(256, 4 * (os.cpu_count() or 1))

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


class Cancelled(BaseException):
    """Raised in an audit's physics thread once its caller has stopped (an interrupt, a
    timeout, an error): the thread stops between batches instead of finishing its stage.
    A BaseException, so that no ``except Exception`` takes it for a result."""


_CANCEL: contextvars.ContextVar[threading.Event | None] = contextvars.ContextVar(
    "critmoment_cancel", default=None)


@contextlib.contextmanager
def cancel_scope() -> Iterator[threading.Event]:
    """A block whose threads (run in copies of this context) stop at their next
    :func:`check_cancelled` once the returned event is set."""
    event = threading.Event()
    token = _CANCEL.set(event)
    try:
        yield event
    finally:
        _CANCEL.reset(token)


#: set by the command line's stop-signal handler (SIGTERM, SIGHUP, ...), which also raises
#: KeyboardInterrupt: a library that catches that interrupt (CasADi's IPOPT call, outside
#: the main thread's protected solve) cannot make the run finish and replace its output
_STOP = threading.Event()


def request_stop() -> None:
    """Marks the process as stopping (the CLI's stop-signal handler)."""
    _STOP.set()


def clear_stop() -> None:
    """Forgets a stop request (a new command starts)."""
    _STOP.clear()


def check_stop() -> None:
    """Raises KeyboardInterrupt where a stop was requested (:func:`request_stop`): checked
    before an output replaces the previous one, and after a command's work."""
    if _STOP.is_set():
        raise KeyboardInterrupt


def check_cancelled() -> None:
    """Raises :class:`Cancelled` where the enclosing :func:`cancel_scope` was cancelled."""
    event = _CANCEL.get()
    if event is not None and event.is_set():
        raise Cancelled


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


def check_nthread(value: Any, *, what: str = "nthread") -> int:
    """A MuJoCo thread count: an integer in [0, :data:`MAX_THREADS`] (0: all CPUs).

    Raises:
        ParameterError: not an integer, negative, or beyond :data:`MAX_THREADS`.
    """
    if isinstance(value, bool) or not isinstance(value, int) and not hasattr(value, "__index__"):
        raise ParameterError(f"{what}: expected an integer in [0, {MAX_THREADS}] (0: all "
                             f"CPUs), got {type(value).__name__} {value!r}")
    number = int(value.__index__())
    if number < 0:
        raise ParameterError(f"{what}: expected an integer >= 0, got "
                             f"{type(value).__name__} {value!r}")
    if number > MAX_THREADS:
        raise ParameterError(f"{what}: expected at most {MAX_THREADS} threads "
                             f"(max(256, 4 x {os.cpu_count()} CPUs); 0 uses all CPUs), got "
                             f"{number}")
    return number


def check_step_count(nstep: int, *, what: str, n: int = 1) -> None:
    """Refuses ``n`` simulations of ``nstep`` physics steps each beyond the limits: one of
    more than ``max_steps``, or more than ``max_batch_steps`` in all.

    Raises:
        ResourceLimitError: beyond a limit.
    """
    _refuse("max_steps", what=what, got=float(nstep), unit="physics steps")
    if n > 1:
        check_batch_steps(float(n) * float(nstep), what=what,
                          detail=f"{n} simulations x {nstep} physics steps")


def check_horizon(horizon: int, n_steps: int, timestep: float, *,
                  what: str = "horizon") -> None:
    """Refuses a sparse horizon that leaves less than half of the recording for moments.

    A moment at step k is evaluated over steps [k, k + horizon): moments later than
    ``n_steps − horizon`` would have to move earlier, to a time they do not happen at. An
    audit whose horizon is longer than half the recording would move most of its moments
    (with a horizon of 3990 steps in a recording of 4000, every moment to the first ten
    steps), and one longer than the recording can evaluate none.

    Args:
        horizon: physics steps per sparse evaluation.
        n_steps: physics steps of the recording.
        timestep: physics time step [s].
        what: the option, for the message.

    Raises:
        ParameterError: ``horizon`` > ``n_steps`` / 2.
    """
    if isinstance(horizon, bool) or not isinstance(horizon, int) and not hasattr(
            horizon, "__index__") or int(horizon) < 1:
        raise ParameterError(f"{what}: expected an integer >= 1 [physics steps], got "
                             f"{type(horizon).__name__} {horizon!r}")
    horizon = int(horizon.__index__())
    most = int(n_steps) // 2
    if horizon <= most:
        return
    dt = float(timestep)
    recording = f"recording of {int(n_steps):,} steps = {n_steps * dt:g} s"
    if horizon >= n_steps:
        told = (f"it must be shorter than the {recording}, and at most half of it so that "
                f"the moments are audited where they happen")
    else:
        told = (f"it would leave only steps [0, {n_steps - horizon}] of the {recording} "
                f"for the moments, and move every later moment to step {n_steps - horizon}")
    raise ParameterError(
        f"{what}: expected at most half of the recording, {most:,} physics steps "
        f"({most * dt:g} s), got {int(horizon):,} steps ({horizon * dt:g} s): {told}; "
        f"lower --horizon (or [sparse] horizon in the scenario)")


def audit_work(trajectory, twin, options) -> tuple[float, str]:
    """The physics steps an audit may take in all, and how they add up, in words.

    Every sparse evaluation steps the horizon, plus up to the persistence of a contact
    excursion (or the creep horizon) past it; the sweep's and the region check's evaluations
    may follow a contact failure for up to ``SETTLE_TIME`` more. The audit evaluates

    * the ranking of up to 32 candidate moments on the 3^k probe of the box,
    * the sweep, (samples + 1) × moments,
    * the 1-D curves and the critical values' grid, 2 × critical_grid × k × moments, and
      about 24 bisection points per parameter and moment,
    * the search, search_trials × moments (with ``search``),
    * the check of the safe region, up to 4 rounds of its corners, edges and inside
      points (336 for two parameters) × moments,

    and the samples' own runs: each may be carried through the whole recording (the chain,
    the verification rollouts), samples × rollout steps. The result is an upper estimate:
    samples that fail early stop, a region that holds at once takes one round.

    Returns:
        (physics steps, the terms in words).
    """
    from critmoment import sparse as sp

    timestep = float(twin.model.opt.timestep)
    n_steps = check_rollout(trajectory, twin)
    horizon = int(options.horizon if options.horizon is not None else twin.scenario.horizon)
    settings = sp.sparse_settings(twin.scenario)
    persistence = max(1, int(round(settings.persistence / timestep)))
    extension = max(persistence - 1, int(settings.creep_horizon) - horizon, 0)
    settle = int(math.ceil(sp.SETTLE_TIME / timestep))
    ndim = int(twin.scenario.box.ndim)
    m = int(options.max_moments)
    n = int(options.n_samples)
    length = horizon + extension
    ranking = 3.0 ** ndim * max(32, m)
    sweep = (n + 1.0) * m
    critical = 2.0 * options.critical_grid * ndim * m + 24.0 * ndim * m
    search = float(options.search_trials) * m if options.search else 0.0
    # the region check: up to 4 rounds of corners, edges (3 per edge, 4 times denser where
    # the cost comes near the threshold) and 4 × 2^(k+1) points inside, per moment
    region = 4.0 * (2 ** ndim + 12.0 * ndim * 2 ** (ndim - 1) + 4.0 * 2 ** (ndim + 1)) * m
    runs = float(n) * n_steps
    total = (ranking + critical + search) * length + (sweep + region) * (length + settle) + runs
    words = (f"{n} samples x {m} moments x horizon {horizon} (+{extension} persistence, "
             f"+{settle} settling steps) for the sweep, plus {ranking + critical + search + region:,.0f} "
             f"evaluations for the ranking, the critical values (critical_grid "
             f"{options.critical_grid}), the search (search_trials {options.search_trials}) "
             f"and the region check, plus {n} samples' own runs of {n_steps:,} steps; lower "
             f"--samples, --max-moments or --horizon")
    return total, words


def check_audit(trajectory, twin, options) -> None:
    """Checks an audit's seed, threads, horizon and size before it starts.

    Args:
        trajectory: the :class:`~critmoment.trajectory.Trajectory`.
        twin: the :class:`~critmoment.twin.Twin` (physics time step [s], the scenario's
            sparse horizon [steps]).
        options: the :class:`~critmoment.analysis.AnalyzeOptions`.

    Raises:
        ParameterError: a seed outside [0, 2³² − 1], too many threads, or a horizon
            longer than half the recording (:func:`check_horizon`).
        ResourceLimitError: the rollout, or the audit's simulations in all
            (:func:`audit_work`), beyond the active limits.
    """
    check_seed(options.seed, what="seed")
    check_nthread(options.nthread)
    check_rollout(trajectory, twin)
    check_audit_horizon(trajectory, twin, options.horizon)
    total, words = audit_work(trajectory, twin, options)
    check_batch_steps(total, what="sparse sweep and the audit's other simulations",
                      detail=words)


def check_audit_horizon(trajectory, twin, horizon: int | None = None) -> None:
    """:func:`check_horizon` of an audit's horizon (``None``: the scenario's ``[sparse]
    horizon``) against the rollout of ``trajectory`` in ``twin``, before the rollout.

    A trajectory whose rows come faster than the physics steps is left to the rollout,
    which refuses it naming both rates (its recording would be a few steps long, and a
    horizon compared with them would only hide that).

    Raises:
        ParameterError: a horizon longer than half the recording.
    """
    timestep = float(twin.model.opt.timestep)
    if float(trajectory.fps) * timestep > 1.0 + 1e-9:
        return
    n_steps = check_rollout(trajectory, twin)
    check_horizon(twin.scenario.horizon if horizon is None else horizon, n_steps, timestep,
                  what="[sparse] horizon" if horizon is None else "horizon")


def check_validation(trajectory, twin, *, n_samples: int) -> int:
    """Checks that ``n_samples`` full rollouts of ``trajectory`` are within ``max_batch_steps``.

    Returns:
        The estimated physics steps of one rollout.

    Raises:
        ResourceLimitError: beyond the limit.
    """
    steps = check_rollout(trajectory, twin)
    check_batch_steps(float(n_samples) * steps, what="brute-force full rollouts",
                      detail=f"{n_samples} samples x {steps} physics steps; lower --samples")
    return steps
