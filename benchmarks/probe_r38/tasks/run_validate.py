"""critmoment validate as the CLI does it (Twin + load_trajectory + validate + to_json), but
with nthread=1 (the CLI has no --nthread). usage: run_validate.py SCENARIO TRAJ OUT.json [--samples N | --points P.json]"""
import argparse
import json
import time

import critmoment as cm
assert cm.__file__.startswith("/tmp/r38/tasks/src"), cm.__file__
from critmoment.trajectory import load_trajectory
from critmoment.validation import validate

ap = argparse.ArgumentParser()
ap.add_argument("scenario"); ap.add_argument("traj"); ap.add_argument("out")
ap.add_argument("--samples", type=int, default=32); ap.add_argument("--seed", type=int, default=0)
ap.add_argument("--points", help="JSON list of {param: value} dicts: explicit samples instead of Sobol")
a = ap.parse_args()
t0 = time.time()
twin = cm.Twin(a.scenario)
traj = load_trajectory(a.traj)
if a.points:
    import numpy as np
    names = [p.name for p in twin.scenario.box.parameters]
    pts = np.array([[d[n] for n in names] for d in json.load(open(a.points))])
    res = validate(traj, twin=twin, samples=pts, nthread=1)
else:
    res = validate(traj, twin=twin, n_samples=a.samples, seed=a.seed, nthread=1)
payload = res.to_json()
payload["_wall_s"] = round(time.time() - t0, 1)
json.dump(payload, open(a.out, "w"), indent=1, default=str)
print(a.out, payload["confusion"], "agreement", payload["agreement"], "outcomes", payload.get("outcomes"),
      "vacuous", payload.get("vacuous"), "wall", payload["_wall_s"])
