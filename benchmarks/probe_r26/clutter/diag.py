"""Why a sample is predicted to fail: validate's own prediction (critmoment.validation.predict)
for given points, with per-moment sparse cost and failure flags, and the point's full rollout.

usage: python diag.py NAME 'v1,v2,...;v1,v2,...'
"""
import os
import sys
import warnings
from pathlib import Path

import numpy as np

import critmoment as cm
from critmoment import groundtruth, validation

warnings.simplefilter("ignore")
OUT = Path(os.environ.get("R26_OUT", "/tmp/r26/clutter"))
name = sys.argv[1]
S = np.array([[float(x) for x in p.split(",")] for p in sys.argv[2].split(";")])
v = OUT / "v" / name
traj = cm.load_trajectory(str(v / "traj.npz" if (v / "traj.npz").exists() else OUT / "aloha_s0.npz"))
twin = cm.Twin(cm.load_scenario(str(v)))
pr = validation.predict(traj, twin=twin, samples=S)
print("moments", pr.steps.tolist(), [m.label for m in pr.moments])
print("runs", pr.runs)
bf = groundtruth.brute_force(traj, twin=twin, samples=S)
for i in range(len(S)):
    print(S[i].tolist(), "predicted_failed", bool(pr.failed[i]), "verified", bool(pr.verified[i]),
          "cost", round(float(pr.cost[i]), 3), "real", bf.classification.outcome[i].value)
