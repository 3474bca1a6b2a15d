"""validate on explicit parameter points (library, nthread=1): the audit's per-sample prediction vs each
point's own full rollout. usage: run_samples.py SCENARIO TRAJ OUT.json --mass M1 M2 .. --friction F1 F2 ..
(the grid of the two lists) [--no-verify]"""
import argparse, itertools, json, time
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r33/src"), cm.__file__
from critmoment.trajectory import load_trajectory
from critmoment.validation import validate

ap = argparse.ArgumentParser()
ap.add_argument("scenario"); ap.add_argument("traj"); ap.add_argument("out")
ap.add_argument("--mass", type=float, nargs="+"); ap.add_argument("--friction", type=float, nargs="+")
ap.add_argument("--no-verify", action="store_true")
a = ap.parse_args()
twin = cm.Twin(a.scenario)
pts = np.array(list(itertools.product(a.mass, a.friction)))
t0 = time.time()
res = validate(load_trajectory(a.traj), twin=twin, samples=pts, nthread=1, **({"verify": None} if a.no_verify else {}))
p = res.to_json(); p["_wall_s"] = round(time.time() - t0, 1)
json.dump(p, open(a.out, "w"), indent=1, default=str)
print(a.out, p["confusion"], p["outcomes"], "wall", p["_wall_s"])
