"""critmoment: audit robot trajectories for physical safety before they run on hardware.

The pipeline, one stage per module::

    trajectory -> recording (frequent rollout) -> moments -> dynamics / search
               -> sparse (evaluation) -> analysis (evidence) -> verdict (decision) -> report
    groundtruth: full rollouts and their real outcomes (below the audit)
    validate: the audit's decisions against the ground truth

``critmoment.analyze(traj, scenario)`` chains the stages; each stage can be called alone.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

# The names below load their module on first use (PEP 562), so that ``import critmoment``,
# and the command line before it has its signal handlers, does not wait for MuJoCo, Pinocchio,
# CasADi, SciPy and Optuna to import (about 1 s): a Ctrl-C there is then handled as in a run.
_EXPORTS: dict[str, str] = {
    "AnalyzeOptions": "analysis",
    "AuditReport": "analysis",
    "Verdict": "analysis",
    "analyze": "analysis",
    "CritmomentError": "exceptions",
    "InfeasibleTwinError": "exceptions",
    "InputFileError": "exceptions",
    "ParameterError": "exceptions",
    "ScenarioError": "exceptions",
    "SimulationDivergedError": "exceptions",
    "TrajectoryError": "exceptions",
    "OutputError": "exceptions",
    "ResourceLimitError": "exceptions",
    "CritmomentWarning": "exceptions",
    "FeasibilityReport": "feasibility",
    "check_feasibility": "feasibility",
    "BruteForce": "groundtruth",
    "brute_force": "groundtruth",
    "init_scenario": "modelinfo",
    "inspect_model": "modelinfo",
    "Moment": "moments",
    "MomentDetector": "moments",
    "MomentLabel": "moments",
    "find_moments": "moments",
    "UncertaintyBox": "params",
    "Recording": "recording",
    "rollout": "recording",
    "simulate": "recording",
    "CostParams": "scenario",
    "Scenario": "scenario",
    "load_scenario": "scenario",
    "SparseEvaluator": "sparse",
    "SparseMode": "sparse",
    "SparseResult": "sparse",
    "evaluate": "sparse",
    "probability_of_success": "sparse",
    "sweep": "sparse",
    "TASK_KINDS": "task",
    "Task": "task",
    "Trajectory": "trajectory",
    "load_trajectory": "trajectory",
    "save_trajectory": "trajectory",
    "Signals": "twin",
    "Twin": "twin",
    "Outcome": "validation",
    "ValidationResult": "validation",
    "validate": "validation",
    "Decision": "verdict",
    "decide": "verdict",
}

if TYPE_CHECKING:  # the same names, eagerly, for type checkers and IDEs
    from critmoment.analysis import AnalyzeOptions, AuditReport, Verdict, analyze
    from critmoment.exceptions import (
        CritmomentError,
        CritmomentWarning,
        InfeasibleTwinError,
        InputFileError,
        OutputError,
        ParameterError,
        ResourceLimitError,
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


def __getattr__(name: str) -> Any:
    module = _EXPORTS.get(name)
    if module is not None:
        value = getattr(importlib.import_module(f"critmoment.{module}"), name)
        globals()[name] = value
        return value
    try:  # a submodule reached as an attribute (``critmoment.sparse``)
        return importlib.import_module(f"critmoment.{name}")
    except ModuleNotFoundError as exc:
        if exc.name != f"critmoment.{name}":
            raise
    raise AttributeError(f"module 'critmoment' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_EXPORTS))


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
    "OutputError",
    "ResourceLimitError",
    "CritmomentWarning",
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
