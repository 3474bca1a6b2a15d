"""Carried cube's lowest point (centre z - 0.02) where it crosses the post's y (|y| < 0.03), per sample of a validate json.
usage: sag.py CASEDIR"""
import sys, json, numpy as np
sys.path.insert(0, __file__.rsplit("/", 1)[0]); import truth
d = sys.argv[1]; s = truth.Setup(f"{d}/scenario.toml", f"{d}/traj.npz")
v = json.load(open(f"{d}/val.json"))
def low(rec):
    p = rec["pos"]; k = np.abs(p[:, 1]) < 0.03
    return float(p[k, 2].min() - 0.02) if k.any() else None
nom = s.rollout([s.unc[n]["nominal"] for n in s.names]); print("nominal bottom z at y~0:", low(nom))
for i, p in enumerate(v["per_sample"]):
    if p["outcome"] == "success":
        r = s.rollout([p["values"][n] for n in s.names]); print(i, p["values"], round(low(r), 4))
