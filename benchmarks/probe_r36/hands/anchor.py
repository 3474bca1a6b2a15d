"""critmoment's own slip measure (groundtruth.grip_slip's positions and beyond_nominal), re-anchored:
counts how many samples exceed the 1 cm / 50 ms slip rule when the hold is measured from step A
instead of critmoment's `formed` step. Nothing in critmoment is changed. (probe_r35, reused in probe_r36)
usage: anchor.py SCENARIO TRAJ VAL.json A [A ...]"""
import sys, json
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r36/src"), cm.__file__
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory
scen, traj, valj, *anchors = sys.argv[1:]
v = json.load(open(valj)); n = len(v["per_sample"])
twin = cm.Twin(scen); tr = load_trajectory(traj)
names = list(v["per_sample"][0]["values"].keys())
S = np.array([[p["values"][k] for k in names] for p in v["per_sample"]])
rec = {}
orig = gt.grip_slip
def wrap(position, nominal_position, held, nominal_held, **kw):
    out = orig(position, nominal_position, held, nominal_held, **kw)
    if np.asarray(position).shape[0] == n + 1:
        rec.update(out=out[1:], pos=np.asarray(position)[1:, :, 0], nom=np.asarray(nominal_position)[:, 0],
                   held=np.asarray(held)[1:, :, 0], nheld=np.asarray(nominal_held)[:, 0], formed=kw["formed"][:, 0])
    return out
gt.grip_slip = wrap
bf = gt.brute_force(tr, twin=twin, samples=S, nthread=1, chunk=64)
dt = twin.model.opt.timestep; w = int(round(0.05 / dt))
f0 = int(np.argmax(rec["formed"] & rec["nheld"]))
print("critmoment's anchor (formed & held):", f0, "| outcomes", {o: sum(str(x) == o for x in bf.outcome) for o in set(map(str, bf.outcome))})
def runs(flags):
    best = cur = 0
    for x in flags:
        cur = cur + 1 if x else 0; best = max(best, cur)
    return best
for A in [f0] + [int(a) for a in anchors]:
    bad = []
    for i in range(n):
        p, q = rec["pos"][i], rec["nom"]
        mask = rec["held"][i] & rec["nheld"] & (np.arange(len(q)) >= A)
        moved = p - p[A]; nm = q - q[A]
        s = np.where(mask, gt.beyond_nominal(moved, nm).max(-1), 0.0)
        if runs(s > 0.01) >= w: bad.append(i)
    print(f"anchor {A}: {len(bad)} of {n} samples slip > 1 cm beyond the nominal for 50 ms:", bad)
