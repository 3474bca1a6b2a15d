"""Per-moment sparse results (all moments, no first-failure skipping) for given points:
cost, failure kind, sticking/unlifted flags, slip, the nominal stage.
usage: python diag_moments.py NAME 'v1,v2;...'"""
import os
import sys
import warnings
from pathlib import Path

import numpy as np

import critmoment as cm
from critmoment import analysis

warnings.simplefilter("ignore")
OUT = Path(os.environ.get("R26_OUT", "/tmp/r26/clutter"))
name = sys.argv[1]
S = np.array([[float(x) for x in p.split(",")] for p in sys.argv[2].split(";")])
v = OUT / "v" / name
traj = cm.load_trajectory(str(v / "traj.npz" if (v / "traj.npz").exists() else OUT / "aloha_s0.npz"))
twin = cm.Twin(cm.load_scenario(str(v)))
rec = cm.rollout(traj, twin=twin)
ev, _ = analysis.audit_evaluator(rec, twin, chain=True)
cands, steps = analysis.audit_moments(rec, twin, ev, 8)
res = ev.evaluate(steps, S, first_failure=False)
for j in range(len(S)):
    print("sample", S[j].tolist())
    for i, k in enumerate(steps):
        print(f"  step {k:5d} {cands[i].label.value:12s} cost {res.cost[i, j]:.3f} fos_c {res.fos_contact[i, j].round(3).tolist()} "
              f"fos_m {res.fos_motor[i, j]:.2f} failure {res.failure[i, j]} sticking {res.sticking_failure[i, j]} "
              f"unlifted {res.unlifted_failure[i, j]} slip {res.slip[i, j]:.2e} stage {res.stage[i, j]} "
              f"support {res.contact_support[i, j]} grip {res.contact_gripper[i, j].tolist()}")
