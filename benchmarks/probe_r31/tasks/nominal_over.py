"""where the nominal's contact term crosses the threshold at lifted steps (sparse.SparseEvaluator._nominal_over). usage: nominal_over.py SCEN TRAJ"""
import sys, numpy as np, critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src")
from critmoment import sparse as sp
from critmoment.trajectory import load_trajectory
twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2])
rec = cm.rollout(traj, twin=twin); ev = sp.SparseEvaluator(rec, twin)
o = ev._nominal_over(); idx = np.flatnonzero(o)
print("persistence_steps", ev.persistence_steps, "over steps", idx.size, "chatter", ev._nominal_chatter())
if idx.size:
    runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
    print("runs (start, end, len):", [(int(r[0]), int(r[-1]), len(r)) for r in runs][:20])
