"""The sparse evaluation (critmoment.sparse.evaluate) of chosen samples at chosen moments of
the nominal recording: per (moment, sample) the failure kind, cost and its terms, contact FOS
per gripper and of the grasp, motor FOS, measured slip, the contact excursion, the sticking
and unlifted flags and the stage.

Usage (critmoment venv active):
    python look_sparse.py SCENARIO.toml TRAJ.npz STEP[,STEP...] M1,F1 [M2,F2 ...]
"""
from __future__ import annotations

import sys

import numpy as np

from critmoment.recording import at_scenario_rate, rollout
from critmoment.sparse import Failure, evaluate
from critmoment.trajectory import load_trajectory
from critmoment.twin import resolve_twin


def main():
    scenario, traj_path, steps, *vals = sys.argv[1:]
    twin = resolve_twin(scenario)
    traj = at_scenario_rate(load_trajectory(traj_path), twin)
    rec = rollout(traj, twin.scenario)
    steps = [int(s) for s in steps.split(",")]
    samples = np.array([[float(x) for x in v.split(",")] for v in vals])
    r = evaluate(rec, twin, steps, samples, nthread=1)
    print("grippers", r.gripper_names, "settings", r.settings)
    for i, st in enumerate(r.steps):
        for j, s in enumerate(samples):
            print(f"step {st} {np.round(s, 4)}: {Failure(int(r.failure[i, j])).name} "
                  f"cost {r.cost[i, j]:.3f} (contact {r.cost_contact[i, j]:.3f}, motor "
                  f"{r.cost_motor[i, j]:.3f}) fos_contact {np.round(r.fos_contact[i, j], 3)} "
                  f"fos_grasp {r.fos_grasp[i, j]:.3f} fos_motor {r.fos_motor[i, j]:.2f} "
                  f"slip {r.slip[i, j] * 1000:.2f} mm excursion {r.excursion[i, j] * 1000:.0f} ms "
                  f"sticking {bool(r.sticking_failure[i, j])} unlifted "
                  f"{bool(r.unlifted_failure[i, j])} stage {int(r.stage[i, j])} "
                  f"touch {r.contact_gripper[i, j].astype(int)} support "
                  f"{int(r.contact_support[i, j])}")


if __name__ == "__main__":
    main()
