"""Plain-MuJoCo trace of one run (truth.py's Setup): object pos, gripper touches, support contact.
usage: trace.py SCENARIO TRAJ [name=value ...] [--every K] [--from A] [--to B]"""
import argparse, sys
sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import truth
ap = argparse.ArgumentParser(); ap.add_argument("scen"); ap.add_argument("traj"); ap.add_argument("vals", nargs="*")
ap.add_argument("--every", type=int, default=100); ap.add_argument("--from", dest="a", type=int, default=0)
ap.add_argument("--to", type=int, default=10**9)
a = ap.parse_args()
s = truth.Setup(a.scen, a.traj)
import critmoment as cm; assert cm.__file__.startswith("/tmp/r33/src"), cm.__file__
vals = {n: s.unc[n]["nominal"] for n in s.names}
vals.update({k: float(v) for k, v in (x.split("=") for x in a.vals)})
nom = s.rollout([s.unc[n]["nominal"] for n in s.names])
rec = s.rollout([vals[n] for n in s.names])
G = list(s.grippers)
for t in range(a.a, min(a.to, len(rec["pos"])), a.every):
    print(t, np.round(rec["pos"][t], 4), "touch", rec["touch"][t].astype(int), "both", rec["both"][t].astype(int),
          "sup", int(rec["sup"][t]), "other", int(rec["other"][t]), "| nom z", round(float(nom["pos"][t, 2]), 4),
          "nom touch", nom["touch"][t].astype(int), "nsup", int(nom["sup"][t]))
out, info = truth.classify(s, rec, nom)
print("values", vals, "->", out, info)
