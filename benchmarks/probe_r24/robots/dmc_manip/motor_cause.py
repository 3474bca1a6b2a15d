"""Which actuator the ground truth's 'motor' failures are of, and whether they are a
saturation or a tracking loss: brute force over a few (mass, friction) samples.

Usage (the critmoment venv active): python motor_cause.py SCENARIO TRAJ MASS,FRICTION ...
e.g. from this folder: python motor_cause.py scenario_shipped_gains.toml traj.npz 0.6,1.12
"""
import sys

import numpy as np

import critmoment
from critmoment import groundtruth
from critmoment.trajectory import load_trajectory
from critmoment.twin import Twin

twin = Twin(critmoment.load_scenario(sys.argv[1]))
traj = load_trajectory(sys.argv[2])
samples = np.array([[float(v) for v in s.split(",")] for s in sys.argv[3:]])
bf = groundtruth.brute_force(traj, twin=twin, samples=samples, nthread=1)
c = bf.classification if hasattr(bf, "classification") else bf
motors = getattr(twin, "motors", None)
for i, s in enumerate(samples):
    col = int(c.motor_column[i])
    print(s, c.outcome[i].value, "motor_step", int(c.motor_step[i]), "actuator",
          ([twin.model.actuator(int(a)).name for a in np.flatnonzero(motors)][col] if col >= 0 else None),
          f"saturation_time {c.saturation_time[i]:.3f} s", f"max_slip {c.max_slip[i]:.4f} m")
