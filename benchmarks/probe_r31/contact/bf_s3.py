import sys, numpy as np, critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src")
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory
twin = cm.Twin(cm.load_scenario("/tmp/r31/contact/v/p_it3")); traj = load_trajectory("/tmp/r31/contact/panda_s3.npz")
bf = gt.brute_force(traj, twin=twin, samples=np.array([[1.0, 1.0], [1.0, 0.6], [1.3, 1.0]]), nthread=1)
c = bf.classification
for i in range(3): print(c.outcome[i], round(float(c.max_slip[i]) * 1e3, 2), "mm")
