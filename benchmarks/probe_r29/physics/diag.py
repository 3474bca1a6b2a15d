"""Sparse details of chosen samples: python diag.py VARIANT 'm1,f1;m2,f2' (values in the box's order)
or python diag.py VARIANT --val val_64_0.json IDX[,IDX..] (samples of a validate run)."""
import json
import sys
from pathlib import Path

import numpy as np

import critmoment as cm
from critmoment import groundtruth as gt
from critmoment.analysis import AnalyzeOptions, audit_evaluator, audit_moments
from critmoment.recording import rollout
from critmoment.trajectory import load_trajectory

assert cm.__file__.startswith("/tmp/r29/src")
R = Path("/tmp/r29/physics")
v = sys.argv[1]
vd = R / "v" / v
tp = vd / "traj.npz" if (vd / "traj.npz").exists() else R / ("aloha_s0.npz" if v.startswith("a_") else "panda_s0.npz")
twin = cm.Twin(cm.load_scenario(str(vd)))
traj = load_trajectory(str(tp))
names = [p.name for p in twin.scenario.box.parameters]
if sys.argv[2] == "--val":
    d = json.load(open(vd / sys.argv[3]))
    idx = [int(i) for i in sys.argv[4].split(",")]
    S = np.array([[d["per_sample"][i]["values"][n] for n in names] for i in idx])
else:
    S = np.array([[float(x) for x in s.split(",")] for s in sys.argv[2].split(";")])
rec = rollout(traj, twin=twin)
ev, _ = audit_evaluator(rec, twin, nthread=1)
cands, steps = audit_moments(rec, twin, ev, AnalyzeOptions().max_moments)
print("moments", [(int(s), c.label.name if hasattr(c.label, "name") else c.label) for s, c in zip(steps, cands)])
res = ev.evaluate(steps, S)


def flags(res, k, j):
    out = []
    for a in ("sticking_failure", "short_slip", "margin_failure", "unlifted_failure", "settled", "stopped"):
        x = getattr(res, a, None)
        if callable(x):
            try:
                x = x()
            except TypeError:
                continue
        if isinstance(x, np.ndarray) and x.ndim == 2 and bool(x[k, j]):
            out.append(a)
    return ",".join(out)


for j in range(S.shape[0]):
    print("sample", dict(zip(names, S[j].round(4))))
    for k, s in enumerate(steps):
        f = int(res.failure[k, j])
        print(f"  step {int(s):5d} fail={f} cost={res.cost[k, j]:.3f} fos_grasp={np.nanmin(res.fos_grasp[k, j]) if res.fos_grasp is not None else None:.3f}"
              f" slip={getattr(res, 'slip')[k, j]*1e3 if res.slip is not None else float('nan'):.2f}mm"
              f" exc={res.excursion[k, j] if res.excursion is not None else None}"
              f" {flags(res, k, j)}")
bf = gt.brute_force(traj, twin=twin, samples=S, nthread=1)
c = bf.classification
for j in range(S.shape[0]):
    print("real", bf.outcome[j].name, "max_slip %.2f mm" % (1e3 * float(c.max_slip[j])), "slip_step", int(c.slip_step[j]),
          "drop_step", int(c.drop_step[j]), "motor_step", int(c.motor_step[j]), "completed", bool(c.completed[j]))
