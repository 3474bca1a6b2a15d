"""1-D ground-truth sweeps per parameter (others nominal) for a scenario: where does the real outcome change?"""
import sys
import time

import numpy as np

import critmoment as cm
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory

scen, traj_path = sys.argv[1], sys.argv[2]
npts = int(sys.argv[3]) if len(sys.argv) > 3 else 7
twin = cm.Twin(cm.load_scenario(scen))
traj = load_trajectory(traj_path)
box = twin.scenario.box
print(scen, [(p.name, type(p).__name__, p.target, p.low, p.high, p.nominal, p.unit) for p in box.parameters])
t = time.time()
for j, p in enumerate(box.parameters):
    vals = np.linspace(p.low, p.high, npts)
    s = np.tile(box.nominal, (npts, 1)); s[:, j] = vals
    bf = gt.brute_force(traj, twin=twin, samples=s, nthread=1)
    print(f"  {p.name}: " + ", ".join(f"{v:.4g}:{o.name}" for v, o in zip(vals, bf.outcome)))
print(f"  {time.time()-t:.1f}s")
