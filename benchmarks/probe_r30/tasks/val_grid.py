"""validate on an explicit grid (predictions by the audit's decision function vs full rollouts).
usage: val_grid.py SCENARIO TRAJ OUT.json m_lo m_hi nm f_lo f_hi nf"""
import sys, json, numpy as np, critmoment as cm
assert cm.__file__.startswith("/tmp/r30/src")
from critmoment.trajectory import load_trajectory
from critmoment.validation import validate
sc, tr, out = sys.argv[1:4]; mlo, mhi, nm, flo, fhi, nf = map(float, sys.argv[4:10])
pts = np.array([[m, f] for m in np.linspace(mlo, mhi, int(nm)) for f in np.linspace(flo, fhi, int(nf))])
res = validate(load_trajectory(tr), twin=cm.Twin(sc), samples=pts, nthread=1)
d = res.to_json(); json.dump(d, open(out, "w"), indent=1, default=str)
print(out, d["confusion"], "agreement", d["agreement"], d["outcomes"])
for s in d["per_sample"]:
    if s["real_failed"] != s["predicted_failed"]:
        print("  DISAGREE", {k: round(v, 3) for k, v in s["values"].items()}, s["outcome"], "pred_failed", s["predicted_failed"], "verified", s["verified"], "cost", round(s["max_cost"], 3), "step", s["first_failure_step"])
