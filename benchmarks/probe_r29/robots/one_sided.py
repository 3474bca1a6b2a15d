"""Two-sided vs one-sided slip relative to the nominal run (finding 1).

For each validate sample (truth.Setup's plain-MuJoCo rollout), the object's displacement in the
gripper base frame since the first step both runs hold it: d_s(t) for the sample, d_n(t) for the
nominal. critmoment's measure (groundtruth.py:446-450, sparse.py:1720) is |d_s(t) - d_n(t)|
(two-sided); the one-sided excess is |d_s(t)| - |d_n(t)| (how much FURTHER the sample has moved
than the nominal). Prints both maxima [mm] and critmoment's ground-truth outcome.
usage: one_sided.py SCENARIO TRAJ VALIDATE.json"""
import json
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import truth  # noqa: E402

scen, traj, valp = sys.argv[1:4]
s = truth.Setup(scen, traj)
v = json.load(open(valp))
nomv = [s.unc[n]["nominal"] for n in s.names]
nom = s.rollout(nomv)
rows = []
for i, p in enumerate(v["per_sample"]):
    r = s.rollout([p["values"][n] for n in s.names])
    both = r["both"][:, 0] & nom["both"][:, 0]
    if not both.any():
        print(i, "never held by both"); continue
    t0 = int(np.argmax(both))
    ds = r["rel"][:, 0] - r["rel"][t0, 0]
    dn = nom["rel"][:, 0] - nom["rel"][t0, 0]
    two = np.linalg.norm(ds - dn, axis=1)[both].max() * 1000
    one = (np.linalg.norm(ds, axis=1) - np.linalg.norm(dn, axis=1))[both].max() * 1000
    absd = np.linalg.norm(ds, axis=1)[both].max() * 1000
    rows.append((i, p["values"], p["outcome"], two, one, absd))
    print(f"{i:2d} " + " ".join(f"{n}={p['values'][n]:.3f}" for n in s.names)
          + f"  cm={p['outcome']:8s} two-sided={two:6.2f} one-sided={one:6.2f} abs={absd:6.2f} mm")
nb = nom["both"][:, 0]
nd = np.linalg.norm(nom["rel"][:, 0] - nom["rel"][int(np.argmax(nb)), 0], axis=1)[nb].max() * 1000
flag = [r for r in rows if r[2] == "slipped" and r[4] < 10.0]
print(f"nominal's own displacement {nd:.2f} mm; samples cm calls slipped whose one-sided excess "
      f"stays under 10 mm: {len(flag)} of {sum(r[2] == 'slipped' for r in rows)} slipped")
