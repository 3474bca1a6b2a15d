"""Ground-truth details for explicit samples: python detail.py SCEN TRAJ 'v1,v2;v1,v2;...'"""
import sys

import numpy as np

import critmoment as cm
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory

scen, tp, rows = sys.argv[1:4]
twin = cm.Twin(cm.load_scenario(scen)); traj = load_trajectory(tp)
s = np.array([[float(v) for v in r.split(",")] for r in rows.split(";")])
bf = gt.brute_force(traj, twin=twin, samples=s, nthread=1)
c = bf.classification
names = [twin.model.actuator(int(i)).name for i in np.flatnonzero(twin.motors)]
print("motors:", names)
for i in range(len(s)):
    col = c.motor_column[i]
    print(s[i], c.outcome[i].name, "completed", c.completed[i], "first_fail", c.first_failure_step[i],
          "slip", c.slip_step[i], "drop", c.drop_step[i], "motor", c.motor_step[i],
          "col", col, (names[col] if names is not None and col >= 0 else ""), "tracking", c.motor_tracking[i],
          "max_slip %.4f" % c.max_slip[i], "sat %.3f" % c.saturation_time[i])
