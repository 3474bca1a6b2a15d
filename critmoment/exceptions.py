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
