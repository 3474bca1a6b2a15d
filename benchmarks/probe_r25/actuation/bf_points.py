"""Full rollouts (critmoment's ground truth) of one trajectory at given parameter points on
several variants, printing each run's outcome and its joints' largest lag.
usage: python bf_points.py TRAJ 'm1,f1;m2,f2' VARIANT...   (variants: folders under v/)"""
import sys
from pathlib import Path

import numpy as np

import critmoment as cm
from critmoment.groundtruth import brute_force

here = Path(__file__).resolve().parent
traj_path, pts, *names = sys.argv[1:]
samples = np.array([[float(x) for x in p.split(",")] for p in pts.split(";")])
traj = cm.load_trajectory(traj_path)
for name in names:
    twin = cm.Twin(here / "v" / name / "scenario.toml")
    if samples.shape[1] < len(twin.scenario.box.parameters):  # extra parameters at their nominal values
        nom = np.array([p.nominal for p in twin.scenario.box.parameters])
        samples_v = np.hstack([samples, np.tile(nom[samples.shape[1]:], (len(samples), 1))])
    else:
        samples_v = samples
    bf = brute_force(traj, twin=twin, samples=samples_v, nthread=2)
    for s, o in zip(samples_v, bf.outcome, strict=True):
        print(f"{name:32s} {np.round(s, 3)} -> {o.value}")
