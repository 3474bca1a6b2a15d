"""critmoment brute_force at points, with its classification details. usage: bfinfo.py SCENARIO TRAJ v1,v2[,v3] ..."""
import sys, numpy as np, critmoment as cm
assert cm.__file__.startswith("/tmp/r32/src")
from critmoment.groundtruth import brute_force
from critmoment.trajectory import load_trajectory
twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2])
pts = np.array([[float(v) for v in a.split(",")] for a in sys.argv[3:]])
bf = brute_force(traj, twin=twin, samples=pts, nthread=1); c = bf.classification
print("motor-checked limits", getattr(twin, "limits", None).ravel()[:12] if getattr(twin, "limits", None) is not None else None)
for i, p in enumerate(pts):
    print(p.tolist(), bf.outcome[i].value, "completed", bool(c.completed[i]), "first_fail", int(c.first_failure_step[i]),
          "motor_step", int(c.motor_step[i]), "motor_col", int(c.motor_column[i]), "sat_time", round(float(c.saturation_time[i]), 4),
          "drop", int(c.drop_step[i]), "slip", int(c.slip_step[i]), f"max_slip {1000*float(c.max_slip[i]):.1f} mm")
