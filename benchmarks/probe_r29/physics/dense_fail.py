"""Re-run region_dense.py's failing points at full precision and perturbed by a relative 1e-9:
python dense_fail.py VARIANT TRAJ REPORT N (same arguments as region_dense.py)"""
import json
import sys

import numpy as np

import critmoment as cm
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory

assert cm.__file__.startswith("/tmp/r29/src")
scen, tp, rep, n = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
twin = cm.Twin(cm.load_scenario(scen)); traj = load_trajectory(tp); box = twin.scenario.box
reg = json.load(open(rep))["safe_region"]
lo = np.array([reg[p.name][0] for p in box.parameters]); hi = np.array([reg[p.name][1] for p in box.parameters])
rng = np.random.default_rng(7)
pts = [lo + rng.random((n, box.ndim)) * (hi - lo)]
for k, p in enumerate(box.parameters):
    for end, full in ((lo[k], p.low), (hi[k], p.high)):
        if end != full:
            q = lo + rng.random((n // 4, box.ndim)) * (hi - lo); q[:, k] = end; pts.append(q)
pts = np.vstack(pts)
bf = gt.brute_force(traj, twin=twin, samples=pts, nthread=1)
bad = np.flatnonzero(bf.failed)
for i in bad:
    P = np.vstack([pts[i], pts[i] * (1 + 1e-9), pts[i] * (1 - 1e-9)])
    b2 = gt.brute_force(traj, twin=twin, samples=P, nthread=1)
    c = b2.classification
    print("point", repr(pts[i].tolist()), [(b2.outcome[j].name, int(c.motor_step[j]), round(float(c.saturation_time[j]), 3)) for j in range(3)],
          "motor column", int(c.motor_column[0]) if hasattr(c, "motor_column") else None)
