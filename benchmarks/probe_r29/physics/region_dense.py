"""Denser brute-force check of a stated region: python region_dense.py SCEN TRAJ REPORT.json N"""
import json
import sys

import numpy as np

import critmoment as cm
assert cm.__file__.startswith("/tmp/r29/src"), cm.__file__
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory

scen, tp, rep, n = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
twin = cm.Twin(cm.load_scenario(scen)); traj = load_trajectory(tp); box = twin.scenario.box
reg = json.load(open(rep))["safe_region"]
lo = np.array([reg[p.name][0] for p in box.parameters]); hi = np.array([reg[p.name][1] for p in box.parameters])
rng = np.random.default_rng(7)
pts = [lo + rng.random((n, box.ndim)) * (hi - lo)]
# points on the cut faces (where the region is narrower than the box)
for k, p in enumerate(box.parameters):
    for end, full in ((lo[k], p.low), (hi[k], p.high)):
        if end != full:
            q = lo + rng.random((n // 4, box.ndim)) * (hi - lo); q[:, k] = end; pts.append(q)
pts = np.vstack(pts)
bf = gt.brute_force(traj, twin=twin, samples=pts, nthread=1)
bad = [(pts[i].round(5).tolist(), bf.outcome[i].name) for i in np.flatnonzero(bf.failed)]
print(f"{scen}: region {reg}: {len(pts)} points, {len(bad)} failures", bad[:8])
