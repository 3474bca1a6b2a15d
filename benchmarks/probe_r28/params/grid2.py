"""2-D ground-truth grid: python grid2.py SCEN TRAJ j1 n1 j2 n2 (other params nominal)"""
import sys

import numpy as np

import critmoment as cm
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory

scen, tp = sys.argv[1:3]; j1, n1, j2, n2 = map(int, sys.argv[3:7])
lo1 = float(sys.argv[7]) if len(sys.argv) > 7 else None; hi1 = float(sys.argv[8]) if len(sys.argv) > 8 else None
twin = cm.Twin(cm.load_scenario(scen)); traj = load_trajectory(tp); box = twin.scenario.box
p1, p2 = box.parameters[j1], box.parameters[j2]
a = np.linspace(lo1 if lo1 is not None else p1.low, hi1 if hi1 is not None else p1.high, n1); b = np.linspace(p2.low, p2.high, n2)
s = np.tile(box.nominal, (n1 * n2, 1)); A, B = np.meshgrid(a, b, indexing="ij"); s[:, j1] = A.ravel(); s[:, j2] = B.ravel()
bf = gt.brute_force(traj, twin=twin, samples=s, nthread=1)
o = np.array([x.name[0] for x in bf.outcome]).reshape(n1, n2)
print(f"rows {p1.name} [{p1.unit}], cols {p2.name} [{p2.unit}]: " + " ".join(f"{v:.4g}" for v in b))
for i in range(n1): print(f"{a[i]:8.4g} " + " ".join(o[i]))
