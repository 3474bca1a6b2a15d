"""critmoment's own SparseEvaluator at one moment for a few samples: failure, cost, grasp FOS,
gripper contact at the horizon's end. usage: sparse_at.py SCEN TRAJ STEP "m,f" ["m,f" ...]"""
import sys
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src")
from critmoment.sparse import SparseEvaluator
from critmoment.trajectory import load_trajectory
twin = cm.Twin(sys.argv[1]); rec = cm.rollout(load_trajectory(sys.argv[2]), twin=twin)
step = int(sys.argv[3]); S = np.array([[float(x) for x in a.split(",")] for a in sys.argv[4:]])
ev = SparseEvaluator(rec, twin, nthread=1)
r = ev.evaluate(np.array([step]), S, keep_raw=True)
fail = r.failure if hasattr(r, "failure") else None
for j, s in enumerate(S):
    f = None if fail is None else (fail[0, j] if np.ndim(fail) else fail)
    print(s, "cost", round(float(r.cost[0, j]), 3), "fos_grasp", round(float(np.ravel(r.fos_grasp[0, j])[0]), 3),
          "gripper contact at end", bool(np.ravel(r.contact_gripper[0, j]).any()), "failure", f)
