"""critmoment brute force at given points: python bf_points.py VARIANT 'v1,v2;v1,v2;...' | --line K LO HI N 'v1,v2'
(--line: N points with parameter K from LO to HI, the others from the given point)"""
import sys
from pathlib import Path

import numpy as np

import critmoment as cm
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory

assert cm.__file__.startswith("/tmp/r29/src")
R = Path("/tmp/r29/physics")
v = sys.argv[1]
vd = R / "v" / v
tp = vd / "traj.npz" if (vd / "traj.npz").exists() else R / ("aloha_s0.npz" if v.startswith("a_") else "panda_s0.npz")
twin = cm.Twin(cm.load_scenario(str(vd)))
traj = load_trajectory(str(tp))
if sys.argv[2] == "--line":
    k, lo, hi, n = int(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5]), int(sys.argv[6])
    base = np.array([float(x) for x in sys.argv[7].split(",")])
    S = np.tile(base, (n, 1))
    S[:, k] = np.linspace(lo, hi, n)
else:
    S = np.array([[float(x) for x in s.split(",")] for s in sys.argv[2].split(";")])
bf = gt.brute_force(traj, twin=twin, samples=S, nthread=1)
c = bf.classification
for i in range(len(S)):
    print(S[i].round(5).tolist(), bf.outcome[i].name, "max_slip %.2f mm" % (1e3 * float(c.max_slip[i])), "slip_step", int(c.slip_step[i]),
          "drop_step", int(c.drop_step[i]), "completed", bool(c.completed[i]))
print("failures", int(bf.failed.sum()), "of", len(S))
