"""Brute-force full rollouts at given parameter points (the ground truth validate uses).

    python bf.py DIR SCENARIO.toml TRAJ.npz  m,f  m,f ...
"""
import os, sys
import numpy as np
import critmoment as cm

os.chdir(sys.argv[1])
sc = cm.load_scenario(sys.argv[2])
tw = cm.Twin(sc)
traj = cm.load_trajectory(sys.argv[3])
pts = np.array([[float(v) for v in a.split(',')] for a in sys.argv[4:]])
bf = cm.brute_force(traj, twin=tw, samples=pts)
print('params', bf.parameter_names, 'nominal completed', bf.nominal_completed)
for p, o in zip(pts, bf.outcome):
    print(p, o)
