"""critmoment validate as the CLI does it (Twin + load_trajectory + validate + to_json), with nthread=1
(the CLI has no thread option). Adapted from benchmarks/probe_r32/robots/run_validate.py.
usage: run_validate.py SCENARIO TRAJ OUT.json [--samples N] [--seed N]"""
import argparse
import json
import time

import critmoment as cm
assert cm.__file__.startswith("/tmp/r37/src"), cm.__file__
from critmoment.trajectory import load_trajectory
from critmoment.validation import validate

ap = argparse.ArgumentParser()
ap.add_argument("scenario"); ap.add_argument("traj"); ap.add_argument("out")
ap.add_argument("--samples", type=int, default=64); ap.add_argument("--seed", type=int, default=0)
a = ap.parse_args()
t0 = time.time()
twin = cm.Twin(a.scenario)
traj = load_trajectory(a.traj)
res = validate(traj, twin=twin, n_samples=a.samples, seed=a.seed, nthread=1)
payload = res.to_json()
payload["_wall_s"] = round(time.time() - t0, 1)
json.dump(payload, open(a.out, "w"), indent=1, default=str)
print(a.out, payload["confusion"], "agreement", payload["agreement"], "outcomes", payload.get("outcomes"),
      "vacuous", payload.get("vacuous"), "wall", payload["_wall_s"])
