import sys, numpy as np, critmoment as cm
from critmoment import sparse as sp
from critmoment.trajectory import load_trajectory
twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2]); step = int(sys.argv[3])
pts = np.array([[float(v) for v in a.split(",")] for a in sys.argv[4:]])
rec = cm.rollout(traj, twin=twin); ev = sp.SparseEvaluator(rec, twin)
r = ev.evaluate(np.array([step]), pts)
for i, p in enumerate(pts):
    print(p.tolist(), "failure", r.failure[0, i], "limiting", r.actuator_names[int(r.motor_argmax[0, i])], "norm", np.round(r.actuator_norm[0, i], 3).tolist())
