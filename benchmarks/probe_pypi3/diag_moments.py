"""Per-moment sparse evaluation of chosen samples (the audit's own evaluator and moments),
to see which moment and criterion makes a sample predicted to fail.

Usage: python diag_moments.py SCENARIO.toml TRAJ.npz MASS,FRICTION [MASS,FRICTION ...]
"""
import sys

import numpy as np

import critmoment as cm
from critmoment.analysis import audit_evaluator, audit_moments
from critmoment.recording import rollout
from critmoment.trajectory import load_trajectory

sc = cm.load_scenario(sys.argv[1])
twin = cm.Twin(sc)
traj = load_trajectory(sys.argv[2])
samples = np.array([[float(v) for v in s.split(",")] for s in sys.argv[3:]])
rec = rollout(traj, twin=twin)
ev, _ = audit_evaluator(rec, twin, horizon=None, mode=cm.sparse.SparseMode.STEP
                        if hasattr(cm, "sparse") else None, nthread=0, chain=True)
cands, steps = audit_moments(rec, twin, ev, 8)
res = ev.evaluate(steps, samples, first_failure=False)
for j, s in enumerate(samples):
    print("sample", s)
    for i, st in enumerate(steps):
        fail = res.failure[i, j] if res.failure is not None else None
        print(f"  step {st:5d} {cands[i].label.value:12s} cost {res.cost[i, j]:.3f} "
              f"(contact {res.cost_contact[i, j]:.3f}, motor {res.cost_motor[i, j]:.3f}) "
              f"fos_c {np.min(res.fos_contact[i, j]):.3f} fos_m {res.fos_motor[i, j]:.3f} "
              f"failure {fail} sticking {res.sticking_failure[i, j]} "
              f"unlifted {res.unlifted_failure[i, j]} slip {res.slip[i, j] if res.slip is not None else None}")
