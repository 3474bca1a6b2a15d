"""critmoment: audit robot trajectories for physical safety before they run on hardware.

The pipeline, one stage per module::

    trajectory -> recording (frequent rollout) -> moments -> dynamics / search
               -> sparse (evaluation) -> analysis (evidence) -> verdict (decision) -> report
    groundtruth: full rollouts and their real outcomes (below the audit)
    validate: the audit's decisions against the ground truth

``critmoment.analyze(traj, scenario)`` chains the stages; each stage can be called alone.
"""

from critmoment.analysis import AnalyzeOptions, AuditReport, Verdict, analyze
from critmoment.exceptions import (
                                   CritmomentError,
                                   InfeasibleTwinError,
                                   InputFileError,
                                   ParameterError,
                                   ScenarioError,
                                   SimulationDivergedError,
                                   TrajectoryError,
)
from critmoment.feasibility import FeasibilityReport, check_feasibility
from critmoment.groundtruth import BruteForce, brute_force
from critmoment.modelinfo import init_scenario, inspect_model
from critmoment.moments import Moment, MomentDetector, MomentLabel, find_moments
from critmoment.params import UncertaintyBox
from critmoment.recording import Recording, rollout, simulate
from critmoment.scenario import CostParams, Scenario, load_scenario
from critmoment.sparse import (
                                   SparseEvaluator,
                                   SparseMode,
                                   SparseResult,
                                   evaluate,
                                   probability_of_success,
                                   sweep,
)
from critmoment.task import TASK_KINDS, Task
from critmoment.trajectory import Trajectory, load_trajectory, save_trajectory
from critmoment.twin import Signals, Twin
from critmoment.validation import Outcome, ValidationResult, validate
from critmoment.verdict import Decision, decide

__version__ = "0.1.0"

__all__ = [
    "AnalyzeOptions",
    "AuditReport",
    "Verdict",
    "analyze",
    "CritmomentError",
    "InputFileError",
    "ParameterError",
    "ScenarioError",
    "SimulationDivergedError",
    "TrajectoryError",
    "InfeasibleTwinError",
    "FeasibilityReport",
    "check_feasibility",
    "init_scenario",
    "inspect_model",
    "Task",
    "TASK_KINDS",
    "Moment",
    "MomentDetector",
    "MomentLabel",
    "find_moments",
    "UncertaintyBox",
    "Recording",
    "rollout",
    "simulate",
    "CostParams",
    "Scenario",
    "load_scenario",
    "SparseEvaluator",
    "SparseMode",
    "SparseResult",
    "evaluate",
    "probability_of_success",
    "sweep",
    "Trajectory",
    "load_trajectory",
    "save_trajectory",
    "Signals",
    "Twin",
    "BruteForce",
    "brute_force",
    "Outcome",
    "ValidationResult",
    "validate",
    "Decision",
    "decide",
    "__version__",
]
