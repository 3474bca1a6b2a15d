"""Ground truth with and without Twin.letting_go, per sample: python cmp_rule.py SCEN TRAJ OUT.json [samples] [seed]
Prints samples whose outcome differs between the new rule (letting_go) and the old rule (slip counted
wherever one gripper holds alone), with max_slip under each, and whether the task completed."""
import sys, json
import numpy as np
import critmoment as cm
from critmoment.trajectory import load_trajectory
from critmoment.groundtruth import brute_force
from critmoment.validation import validate  # noqa
scen, tp, out = sys.argv[1:4]
n = int(sys.argv[4]) if len(sys.argv) > 4 else 32
seed = int(sys.argv[5]) if len(sys.argv) > 5 else 0
twin = cm.Twin(cm.load_scenario(scen)); traj = load_trajectory(tp)
from critmoment import sparse as sp
samples = sp.sweep_samples(twin.scenario.box, n=n, seed=seed)  # validate's own samples
new = brute_force(traj, twin=twin, samples=samples, nthread=1)
orig = cm.Twin.letting_go
cm.Twin.letting_go = lambda self, c, t: np.zeros(np.asarray(t).shape, bool)
old = brute_force(traj, twin=twin, samples=samples, nthread=1)
cm.Twin.letting_go = orig
rows = []
for i in range(n):
    a, b = new.classification, old.classification
    rows.append(dict(values=samples[i].tolist(), new=str(a.outcome[i]), old=str(b.outcome[i]),
                     new_slip_mm=1e3 * float(a.max_slip[i]), old_slip_mm=1e3 * float(b.max_slip[i]),
                     completed=bool(a.completed[i])))
flip = [r for r in rows if r["new"] != r["old"]]
print(tp, "new fail", int(new.failed.sum()), "old fail", int(old.failed.sum()), "flipped", len(flip))
for r in flip:
    print("  FLIP", r)
print("  max new-rule slip among successes: %.2f mm; old-rule slip among them: %.2f mm" % (
    max([r["new_slip_mm"] for r in rows if "success" in r["new"].lower()] or [0]),
    max([r["old_slip_mm"] for r in rows if "success" in r["new"].lower()] or [0])))
json.dump(rows, open(out, "w"), indent=1)
