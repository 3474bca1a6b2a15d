"""critmoment.validation.predict (the audit's decision, as validate uses it) on chosen samples:
per sample the predicted failure, whether its own full rollout decided it, the highest cost
over the moments, and the counts of own runs; then each moment's sparse cost per sample.

Usage (critmoment venv active): python look_predict.py SCENARIO.toml TRAJ.npz M1,F1 [M2,F2 ...]
"""
from __future__ import annotations

import sys

import numpy as np

from critmoment.recording import at_scenario_rate
from critmoment.trajectory import load_trajectory
from critmoment.twin import resolve_twin
from critmoment.validation import predict


def main():
    scenario, traj_path, *vals = sys.argv[1:]
    twin = resolve_twin(scenario)
    traj = at_scenario_rate(load_trajectory(traj_path), twin)
    samples = np.array([[float(x) for x in v.split(",")] for v in vals])
    p = predict(traj, twin=twin, samples=samples, nthread=1)
    print("moments (step):", [int(s) for s in p.steps])
    print("runs:", dict(p.runs))
    for i, s in enumerate(samples):
        print(f"{np.round(s, 4)}: failed={bool(p.failed[i])} verified={bool(p.verified[i])} "
              f"cost={p.cost[i]:.3f} cost_moments={p.cost_moments[i]:.3f}")


if __name__ == "__main__":
    main()
