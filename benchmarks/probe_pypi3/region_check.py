"""Brute-force check of a stated safe region: its 4 corners, 4 mid-edges and 12 random points
inside, each a full rollout judged by validate's default ground truth.

Usage: python region_check.py SCENARIO.toml TRAJ.npz MASS_LO MASS_HI MU_LO MU_HI
"""
import sys

import numpy as np

import critmoment as cm
from critmoment.groundtruth import brute_force
from critmoment.trajectory import load_trajectory

sc = cm.load_scenario(sys.argv[1])
traj = load_trajectory(sys.argv[2])
m0, m1, f0, f1 = map(float, sys.argv[3:7])
rng = np.random.default_rng(0)
pts = [(m, f) for m in (m0, m1) for f in (f0, f1)]
pts += [((m0 + m1) / 2, f0), ((m0 + m1) / 2, f1), (m0, (f0 + f1) / 2), (m1, (f0 + f1) / 2)]
pts += [(rng.uniform(m0, m1), rng.uniform(f0, f1)) for _ in range(12)]
names = sc.box.names
samples = np.array([[p[0] if n == "mass" else p[1] for n in names] for p in pts])
bf = brute_force(traj, twin=cm.Twin(sc), samples=samples)
bad = [(tuple(np.round(s, 4)), o.value) for s, o, f in zip(samples, bf.outcome, bf.failed, strict=True) if f]
print(f"{len(pts)} points, {len(bad)} fail:", bad)
