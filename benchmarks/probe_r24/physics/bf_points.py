"""Brute-force full rollouts at given points of a variant's box.
usage: python bf_points.py NAME TRAJ 'v1,v2;v1,v2;...'  (values in the box's parameter order)"""
import sys
import warnings

import numpy as np

import critmoment as cm
from critmoment import groundtruth

warnings.simplefilter("ignore")
n, tp, pts = sys.argv[1:4]
twin = cm.Twin(cm.load_scenario(f"v/{n}"))
S = np.array([[float(x) for x in p.split(",")] for p in pts.split(";")])
bf = groundtruth.brute_force(cm.load_trajectory(tp), twin=twin, samples=S)
c = bf.classification
print(n, twin.scenario.box.names, "nominal_completed", bf.nominal_completed)
for i, s in enumerate(S):
    print("  ", s.tolist(), c.outcome[i].value, f"max_slip {c.max_slip[i]:.4f}", "first_fail", c.first_failure_step[i])
