"""sparse evaluation of given samples at one moment: failure kind, min motor FOS, margin flag.
usage: sparse_at.py SCENARIO TRAJ STEP m,f ..."""
import sys, numpy as np, critmoment as cm
assert cm.__file__.startswith("/tmp/r32/src")
from critmoment import sparse as sp
from critmoment.trajectory import load_trajectory
twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2]); step = int(sys.argv[3])
pts = np.array([[float(v) for v in a.split(",")] for a in sys.argv[4:]])
rec = cm.rollout(traj, twin=twin)
ev = sp.SparseEvaluator(rec, twin)
r = ev.evaluate(np.array([step]), pts)
print("motor_steps", ev.motor_steps, "MOTOR_MARGIN", sp.MOTOR_MARGIN)
for i, p in enumerate(pts):
    print(p.tolist(), "failure", r.failure[0, i] if r.failure is not None else None, "cost", round(float(r.cost[0, i]), 4),
          "fos_motor", round(float(r.fos_motor[0, i]), 5), "margin", bool(r.margin_failure[0, i]),
          "margin_only", bool(r.failed_margin_only()[i]))
