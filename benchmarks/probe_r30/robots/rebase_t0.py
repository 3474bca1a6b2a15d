"""Finding 1, with critmoment's own `groundtruth.grip_slip`: the object's position in the hand's
base frame (truth.Setup's plain-MuJoCo runs), `held` = touch and off the support (critmoment's
definition), slip counted from the first common hold (as shipped) vs from the end of the closing
command + 50 ms (the grasp settled). No closing-axis projector (a hand has none; this can only
overstate slip). usage: rebase_t0.py SCENARIO TRAJ VAL.json T_SETTLED"""
import json
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
import numpy as np
import critmoment
from critmoment.groundtruth import grip_slip
import truth

assert critmoment.__file__.startswith("/tmp/r30/src"), critmoment.__file__
s = truth.Setup(sys.argv[1], sys.argv[2])
val = json.load(open(sys.argv[3]))
t_set = float(sys.argv[4])
dt = s.model.opt.timestep
n50 = int(round(0.05 / dt))
nom = s.rollout([s.unc[n]["nominal"] for n in s.names])


def held(rec):
    return (rec["touch"].any(axis=1) & ~rec["sup"])[:, None]


def slipped(d):
    over = d > 0.01
    run = 0
    for k, o in enumerate(over):
        run = run + 1 if o else 0
        if run >= n50:
            return k
    return -1


rows = []
for i, p in enumerate(val["per_sample"]):
    if p["outcome"] != "slipped":
        continue
    rec = s.rollout([p["values"][n] for n in s.names])
    pos = rec["rel"][None, :, :1, :]
    npos = nom["rel"][:, :1, :]
    h, nh = held(rec)[None], held(nom)
    d0 = grip_slip(pos, npos, h, nh)[0]
    late = np.zeros_like(nh); late[int(round(t_set / dt)):] = True
    d1 = grip_slip(pos, npos, h & late[None], nh & late)[0]
    k0, k1 = slipped(d0), slipped(d1)
    rows.append((i, round(1000 * d0.max(), 1), round(k0 * dt, 3) if k0 >= 0 else None,
                 round(1000 * d1.max(), 1), round(k1 * dt, 3) if k1 >= 0 else None))
    print(f"sample {i:2d} {p['values']}: from first hold max {rows[-1][1]} mm, slipped at {rows[-1][2]} s; "
          f"from t={t_set} s max {rows[-1][3]} mm, slipped at {rows[-1][4]}", flush=True)
print(f"{len(rows)} samples critmoment calls SLIPPED: {sum(r[2] is not None for r in rows)} slip from the first hold, "
      f"{sum(r[4] is not None for r in rows)} from the settled grasp (t >= {t_set} s)")
