"""The object's position in the gripper base frame (truth.Setup's `rel`, own code), nominal vs
given samples, at listed times; and the displacement since a reference time.
usage: look_rel.py SCENARIO TRAJ "m1 f1" ["m2 f2" ...] --times 3.0 3.4 ... --ref 3.0"""
import argparse
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
import numpy as np
import truth

ap = argparse.ArgumentParser()
ap.add_argument("scenario"); ap.add_argument("traj"); ap.add_argument("points", nargs="*")
ap.add_argument("--times", type=float, nargs="+", default=[3.0, 3.4, 3.6, 3.8, 4.5, 6.0, 8.0, 9.9])
ap.add_argument("--ref", type=float, default=3.0)
a = ap.parse_args()
s = truth.Setup(a.scenario, a.traj)
dt = s.model.opt.timestep
runs = [("nominal", [s.unc[n]["nominal"] for n in s.names])] + [(p, [float(x) for x in p.split()]) for p in a.points]
ref = int(round(a.ref / dt))
for name, vals in runs:
    rec = s.rollout(vals)
    rel = rec["rel"][:, 0]
    print(f"{name}: object in the gripper base frame [mm], and moved since t={a.ref}:")
    for t in a.times:
        k = min(int(round(t / dt)), len(rel) - 1)
        print(f"   t={t:5.2f} rel={np.round(1000 * rel[k], 1)} moved={1000 * np.linalg.norm(rel[k] - rel[ref]):6.1f} "
              f"touch={int(rec['touch'][k].any())} z={rec['pos'][k][2]:.3f}")
