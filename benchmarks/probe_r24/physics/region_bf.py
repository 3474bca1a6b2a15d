"""Brute-force full rollouts at the corners, mid-edges, centre and 16 Sobol points of a
variant's stated safe region (box of the ORIGINAL variant; points inside its safe_region).
usage: python region_bf.py NAME TRAJ"""
import itertools
import json
import sys
import warnings

import numpy as np

import critmoment as cm
from critmoment import groundtruth
from critmoment import sparse as sp

n, tp = sys.argv[1], sys.argv[2]
r = json.load(open(f"v/{n}/report/report.json"))
reg = r["safe_region"]
warnings.simplefilter("ignore")
sc = cm.load_scenario(f"v/{n}")
twin = cm.Twin(sc)
names = list(twin.scenario.box.names)
lo = np.array([reg[k][0] for k in names])
hi = np.array([reg[k][1] for k in names])
pts = [lo + (hi - lo) * np.array(c) for c in itertools.product([0, 0.5, 1], repeat=len(names))]
sob = sp.sweep_samples(twin.scenario.box, n=16, seed=1)
blo = np.array([r["uncertainty"][k]["range"][0] for k in names])
bhi = np.array([r["uncertainty"][k]["range"][1] for k in names])
u = (sob - blo) / (bhi - blo)
pts += list(lo + (hi - lo) * u)
S = np.array(pts)
traj = cm.load_trajectory(tp)
bf = groundtruth.brute_force(traj, twin=twin, samples=S)
out = [o.value for o in bf.classification.outcome]
bad = [(S[i].round(4).tolist(), out[i]) for i in range(len(S)) if out[i] != "success"]
print(f"{n}: region {reg}: {len(S)} points, {len(bad)} real failures inside; nominal_completed {bf.nominal_completed}")
for b in bad:
    print("   FAIL", b)
