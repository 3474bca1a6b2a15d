"""Run critmoment's ground truth (critmoment.groundtruth.brute_force) on chosen samples and
print each one's classification: outcome, first failure step, slip/drop/motor steps, largest
slip, saturation time, and the motor column of the first motor event.

Usage (critmoment venv active): python look_sample.py SCENARIO.toml TRAJ.npz M1,F1 [M2,F2 ...]
(values in the box's column order, here mass [kg], friction).
"""
from __future__ import annotations

import sys

import numpy as np

from critmoment.groundtruth import brute_force
from critmoment.recording import at_scenario_rate
from critmoment.trajectory import load_trajectory
from critmoment.twin import resolve_twin


def main():
    scenario, traj_path, *vals = sys.argv[1:]
    twin = resolve_twin(scenario)
    traj = at_scenario_rate(load_trajectory(traj_path), twin)
    samples = np.array([[float(x) for x in v.split(",")] for v in vals])
    bf = brute_force(traj, twin=twin, samples=samples, nthread=1)
    c = bf.classification
    print("parameters", bf.parameter_names, "nominal completed", bf.nominal_completed,
          f"dt {bf.dt}, {bf.seconds:.1f} s")
    for i, s in enumerate(samples):
        print(f"{np.round(s, 4)}: {c.outcome[i]} completed={bool(c.completed[i])} "
              f"first_failure_step={c.first_failure_step[i]} slip_step={c.slip_step[i]} "
              f"drop_step={c.drop_step[i]} motor_step={c.motor_step[i]} "
              f"max_slip={c.max_slip[i]:.4f} m saturation_time={c.saturation_time[i]:.3f} s "
              f"motor_column={c.motor_column[i]} tracking={bool(c.motor_tracking[i])}")


if __name__ == "__main__":
    main()
