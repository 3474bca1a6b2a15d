"""critmoment's own ground-truth slip trace (brute_force runs the nominal as its row 0) for chosen samples (grip_slip's output, recorded
by wrapping it; nothing in critmoment changed). usage: cmslip.py SCENARIO TRAJ VAL.json I ... (probe_r35)"""
import sys, json
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r35/src"), cm.__file__
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory
scen, traj, valj, *idx = sys.argv[1:]
v = json.load(open(valj)); idx = [int(i) for i in idx]
twin = cm.Twin(scen); tr = load_trajectory(traj)
names = list(v["parameters"]) if isinstance(v["parameters"], list) else list(v["parameters"].keys())
S = np.array([[v["per_sample"][i]["values"][n] for n in names] for i in idx])
rec = {}
calls = []
orig = gt.grip_slip
def wrap(position, nominal_position, held, nominal_held, **kw):
    out = orig(position, nominal_position, held, nominal_held, **kw)
    calls.append((np.asarray(position).shape, float(np.max(out)) if out.size else 0.0, np.asarray(held).shape))
    if np.asarray(position).shape[0] == len(idx) + 1: rec.update(out=out[1:], pos=np.asarray(position)[1:], nom=np.asarray(nominal_position), held=np.asarray(held)[1:],
               nheld=np.asarray(nominal_held), formed=kw.get("formed"))
    return out
gt.grip_slip = wrap
bf = gt.brute_force(tr, twin=twin, samples=S, nthread=1)
print("grip_slip calls", calls)
print("outcomes", [str(o) for o in bf.outcome])
out = rec["out"]
f = rec["formed"]; nh = rec["nheld"]
print("nominal held from", int(np.argmax(nh[:, 0])), "formed from", int(np.argmax(f[:, 0])) if f is not None else None)
for k, i in enumerate(idx):
    s = out[k]; first = int(np.argmax(s > 0.01)) if (s > 0.01).any() else -1
    p = rec["pos"][k][:, 0]; n = rec["nom"][:, 0]
    p = p[..., 0, :] if p.ndim == 3 else p; n = n[..., 0, :] if n.ndim == 3 else n
    t0 = int(np.argmax(rec["held"][k][:, 0] & nh[:, 0] & (f[:, 0] if f is not None else True)))
    print(i, dict(zip(names, S[k].round(3))), bf.outcome[k], "max slip mm", round(float(s.max()) * 1e3, 2), "first >1cm", first, "t0", t0)
    for t in (t0, 1744, 1800, 2000, 2500, 3499):
        if t >= len(s): continue
        print("   step", t, "sample moved mm", ((p[t] - p[t0]) * 1e3).round(1), "nominal moved mm", ((n[t] - n[t0]) * 1e3).round(1), "slip mm", round(float(s[t]) * 1e3, 2), "held", bool(rec["held"][k][t, 0]))
