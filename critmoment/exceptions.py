"""Errors raised by critmoment.

Every error raised on bad input or failed physics is a :class:`CritmomentError`
subclass, and every message says what was expected, what came, and where
possible the valid options.
"""

from __future__ import annotations

__all__ = [
    "CritmomentError",
    "InputFileError",
    "TrajectoryError",
    "ScenarioError",
    "ParameterError",
    "SimulationDivergedError",
    "InfeasibleTwinError",
]


class CritmomentError(Exception):
    """Base class of every error critmoment raises on purpose."""


class InputFileError(CritmomentError, FileNotFoundError):
    """An input file is missing, unreadable or of an unknown format."""


class TrajectoryError(CritmomentError, ValueError):
    """A trajectory has the wrong shape, dtype, values or timing."""


class ScenarioError(CritmomentError, ValueError):
    """A scenario file is malformed or names things the model does not have."""


class ParameterError(CritmomentError, ValueError):
    """Uncertain parameters, ranges or options that make no sense."""


class SimulationDivergedError(CritmomentError, RuntimeError):
    """The physics diverged (NaN, MuJoCo warning) during a simulation.

    Attributes:
        step: index of the physics step at which divergence was detected, or
            ``None`` when unknown.
    """

    def __init__(self, message: str, *, step: int | None = None):
        super().__init__(message)
        self.step = step


class InfeasibleTwinError(CritmomentError, RuntimeError):
    """The twin cannot reproduce the nominal motion (see :mod:`critmoment.feasibility`).

    The message names the joint, the lag, its duration and start, and the likely cause.

    Attributes:
        report: the :class:`~critmoment.feasibility.FeasibilityReport`, or ``None``.
    """

    def __init__(self, message: str, *, report=None):
        super().__init__(message)
        self.report = report


class OutputError(CritmomentError, OSError):
    """An output path cannot be used: it is a file, lies under a file, is not writable,
    holds files that are not a critmoment output, or the disk filled while writing."""


class ResourceLimitError(CritmomentError, ValueError):
    """The work or memory an input asks for exceeds a documented limit
    (:mod:`critmoment.budget`); the message names the option that raises it."""


class CritmomentWarning(UserWarning):
    """Something critmoment had to assume (e.g. the model's default object pose)."""
