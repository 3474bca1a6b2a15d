"""fine 1-D ground-truth sweep of parameter j: python sweep1.py SCEN TRAJ j lo hi n"""
import sys

import numpy as np

import critmoment as cm
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory

scen, tp = sys.argv[1:3]; j = int(sys.argv[3]); lo, hi = float(sys.argv[4]), float(sys.argv[5]); n = int(sys.argv[6])
twin = cm.Twin(cm.load_scenario(scen)); traj = load_trajectory(tp); box = twin.scenario.box
s = np.tile(box.nominal, (n, 1)); v = np.linspace(lo, hi, n); s[:, j] = v
bf = gt.brute_force(traj, twin=twin, samples=s, nthread=1); c = bf.classification
fails = [(round(v[i], 4), bf.outcome[i].name, int(c.first_failure_step[i])) for i in np.flatnonzero(bf.failed)]
print(f"{scen} {box.parameters[j].name} in [{lo}, {hi}] x{n}: {len(fails)} fail:", fails[:40])
