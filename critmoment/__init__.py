"""critmoment: audit robot trajectories for physical safety before they run on hardware."""

from critmoment.exceptions import (CritmomentError, InputFileError, ParameterError,
                                   ScenarioError, SimulationDivergedError, TrajectoryError)
from critmoment.params import UncertaintyBox
from critmoment.scenario import CostParams, Scenario, load_scenario
from critmoment.twin import Signals, Twin

__version__ = "0.1.0"

__all__ = [
    "CritmomentError",
    "InputFileError",
    "ParameterError",
    "ScenarioError",
    "SimulationDivergedError",
    "TrajectoryError",
    "UncertaintyBox",
    "CostParams",
    "Scenario",
    "load_scenario",
    "Signals",
    "Twin",
    "__version__",
]
