"""Region study: does the audit's stated safe region hold under brute-force full rollouts?

    PYTHONPATH=. python benchmarks/region_study.py [--quick] [--per-edge 5] [--out results.json]

For each case the audit (``critmoment.analysis.analyze``, Sobol seed = the trajectory's
seed) states a safe sub-box of the uncertainty box, or none. Where it states one, the
region's corners, ``--per-edge`` points per edge (``verdict.region_points``) and
``--inside`` points inside it (a scrambled Sobol set, seed 7, not the audit's own inside
points) are run in full (``groundtruth.brute_force``), and every point whose real run fails
is listed with its parameter values and outcome. Cases:

* ``aloha``: the bundled ALOHA scenario, ``demos.scripted_transfer(seed)`` for seeds 0-9,
  128 samples;
* ``aloha m<=1.5``: the same with the box's mass range cut to 0.05-1.5 kg, seeds 0-4;
* ``panda``: the bundled Panda, ``panda_demo.make_pick_place(seed)`` for seeds 0-2;
* ``xarm``: only when ``--xarm DIR`` holds them, an xArm7 scene's ``scenario.toml`` with
  ``traj0.npz`` and ``traj1.npz`` and its ``scen_region.toml`` with ``traj0.npz``, 64 samples.

``--quick`` runs seed 0 of each case. Prints one line per case (verdict, region, the audit's
own runs over the points it checked, the full-rollout points, the failing points, seconds)
and the totals. About 3 minutes on 2 cores (2026-12-04; ``--quick``: under a minute).
"""

from __future__ import annotations

import argparse
import json
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.stats import qmc

import critmoment as cm
from critmoment import demos, panda_demo
from critmoment import verdict as vd
from critmoment.analysis import AnalyzeOptions, analyze
from critmoment.groundtruth import brute_force


@dataclass(frozen=True)
class Case:
    name: str
    twin: cm.Twin
    make_trajectory: Callable[[], cm.Trajectory]
    sobol_seed: int
    n_samples: int


def describe_region(region: dict[str, tuple[float, float]] | None) -> str:
    """The region in a few characters: ``mass 0.05-0.82, friction 0.4-1.5``."""
    if region is None:
        return "none"
    return ", ".join(f"{name} {lo:.3g}-{hi:.3g}" for name, (lo, hi) in region.items())


def build_cases(quick: bool, xarm_dir: Path | None) -> list[Case]:
    cases: list[Case] = []
    aloha_scenario = cm.load_scenario()
    aloha = cm.Twin(aloha_scenario)
    for seed in (0,) if quick else range(10):
        cases.append(Case(f"aloha seed {seed}", aloha,
                          lambda s=seed: demos.scripted_transfer(s, twin=aloha), seed, 128))
    light = cm.Twin(aloha_scenario.replace(
        box=aloha_scenario.box.with_range("mass", 0.05, 1.5)))
    for seed in (0,) if quick else range(5):
        cases.append(Case(f"aloha m<=1.5 seed {seed}", light,
                          lambda s=seed: demos.scripted_transfer(s, twin=light), seed, 128))
    panda = cm.Twin(cm.load_scenario("panda_pick_place"))
    for seed in (0,) if quick else range(3):
        cases.append(Case(f"panda seed {seed}", panda,
                          lambda s=seed: panda_demo.make_pick_place(s), seed, 128))
    if xarm_dir is not None and not quick:
        scenes = (("scenario.toml", ("traj0.npz", "traj1.npz")),
                  ("scen_region.toml", ("traj0.npz",)))
        for scenario_file, trajectory_files in scenes:
            if not (xarm_dir / scenario_file).is_file():
                continue
            twin = cm.Twin(cm.load_scenario(str(xarm_dir / scenario_file)))
            for trajectory_file in trajectory_files:
                path = xarm_dir / trajectory_file
                if path.is_file():
                    cases.append(Case(f"xarm {Path(scenario_file).stem}/{path.stem}", twin,
                                      lambda p=path: cm.load_trajectory(str(p)), 0, 64))
    return cases


def study(case: Case, per_edge: int, inside: int = 16) -> dict:
    t_start = time.perf_counter()
    trajectory = case.make_trajectory()
    report = analyze(trajectory, twin=case.twin,
                     options=AnalyzeOptions(seed=case.sobol_seed, n_samples=case.n_samples))
    analyze_seconds = time.perf_counter() - t_start
    check = report.region_check
    result = {
        "verdict": report.verdict.name,
        "safe_region": (None if report.safe_region is None
                        else {k: list(v) for k, v in report.safe_region.items()}),
        "safe_region_text": report.safe_region_text,
        "check_holds": None if check is None else bool(check.holds),
        "check_own_runs": None if check is None else check.own_runs,
        "check_points": None if check is None else int(check.points.shape[0]),
        "check_chained": None if check is None else check.n_chained,
        "check_rollouts": None if check is None else check.n_rollouts,
        "rollout_points": 0,
        "failing": [],
        "analyze_seconds": analyze_seconds,
    }
    if report.safe_region is not None:
        box = case.twin.scenario.box
        points, _ = vd.region_points(report.safe_region, box, per_edge=per_edge)
        lo = np.array([report.safe_region[n][0] for n in box.names])
        hi = np.array([report.safe_region[n][1] for n in box.names])
        u = qmc.Sobol(d=box.ndim, scramble=True, seed=7).random(inside) if inside else None
        if u is not None:
            points = np.vstack([points, lo + u * (hi - lo)])
        truth = brute_force(trajectory, twin=case.twin, samples=points, nthread=0)
        result["rollout_points"] = int(points.shape[0])
        result["nominal_completed"] = bool(truth.nominal_completed)
        result["failing"] = [
            {"params": dict(zip(box.names, map(float, points[i]), strict=True)),
             "outcome": truth.outcome[i].name}
            for i in np.flatnonzero(truth.failed)]
    result["seconds"] = time.perf_counter() - t_start
    return result


def format_line(name: str, r: dict) -> str:
    if r["check_points"] is None:
        check = "check -"
    else:
        check = (f"check {r['check_own_runs']}/{r['check_points']} own"
                 f"{'' if r['check_holds'] else ' (not holding)'}")
    failing = "; ".join(
        ", ".join(f"{k}={v:.4g}" for k, v in f["params"].items()) + f" {f['outcome']}"
        for f in r["failing"]) or "-"
    return (f"{name:24s} {r['verdict']:11s} region [{describe_region(r['safe_region'])}] "
            f"{check}, full rollouts {r['rollout_points']}, failing {len(r['failing'])}: "
            f"{failing} ({r['seconds']:.0f} s)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="seed 0 of each case, no xarm")
    parser.add_argument("--inside", type=int, default=16,
                        help="points inside each stated region, run in full (default 16)")
    parser.add_argument("--per-edge", type=int, default=5,
                        help="points per edge of the region, corners included")
    parser.add_argument("--xarm", type=Path, default=Path("/tmp/probeA/xarm"),
                        help="the xArm7 scene's directory (skipped when absent)")
    parser.add_argument("--out", default=None, help="write the results as JSON here")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    xarm_dir = args.xarm if args.xarm.is_dir() else None
    results = {}
    for case in build_cases(args.quick, xarm_dir):
        results[case.name] = study(case, args.per_edge, args.inside)
        print(format_line(case.name, results[case.name]), flush=True)
    with_region = [r for r in results.values() if r["safe_region"] is not None]
    print(f"cases {len(results)}, with a stated region {len(with_region)}, points rolled out "
          f"{sum(r['rollout_points'] for r in with_region)}, failing points "
          f"{sum(len(r['failing']) for r in with_region)} "
          f"(in {sum(bool(r['failing']) for r in with_region)} cases)")
    if args.out:
        with open(args.out, "w") as f:
            json.dump({"per_edge": args.per_edge, "cases": results}, f, indent=1)


if __name__ == "__main__":
    main()
