"""full rollouts (critmoment brute_force) at given points. usage: points.py SCENARIO TRAJ m,f m,f ..."""
import sys, numpy as np, critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src")
from critmoment.groundtruth import brute_force
from critmoment.trajectory import load_trajectory
twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2])
pts = np.array([[float(v) for v in a.split(",")] for a in sys.argv[3:]])
bf = brute_force(traj, twin=twin, samples=pts, nthread=1)
c = bf.classification
for p, o, s in zip(pts, bf.outcome, c.max_slip):
    print(p.tolist(), o.value, f"max_slip {s*1000:.1f} mm")
