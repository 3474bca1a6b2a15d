"""Full rollouts (validate's ground truth) at given points of a variant's box.
usage: python bf_points.py NAME 'v1,v2,...;v1,v2,...'   (values in the box's parameter order)"""
import os
import sys
import warnings
from pathlib import Path

import numpy as np

import critmoment as cm
from critmoment import groundtruth

warnings.simplefilter("ignore")
OUT = Path(os.environ.get("R26_OUT", "/tmp/r26/clutter"))
name = sys.argv[1]
S = np.array([[float(x) for x in p.split(",")] for p in sys.argv[2].split(";")])
v = OUT / "v" / name
traj = cm.load_trajectory(str(v / "traj.npz" if (v / "traj.npz").exists() else OUT / "aloha_s0.npz"))
twin = cm.Twin(cm.load_scenario(str(v)))
bf = groundtruth.brute_force(traj, twin=twin, samples=S)
print(name, list(twin.scenario.box.names))
for i in range(len(S)):
    print("  ", S[i].tolist(), bf.classification.outcome[i].value)
