"""critmoment analyze as the CLI does it, with nthread=1; writes report.json.
usage: run_analyze.py SCENARIO TRAJ OUT.json [--samples N] [--seed N]"""
import argparse
import json
import time

import critmoment as cm
assert cm.__file__.startswith("/tmp/r37/src"), cm.__file__
from critmoment.analysis import AnalyzeOptions
from critmoment.trajectory import load_trajectory

ap = argparse.ArgumentParser()
ap.add_argument("scenario"); ap.add_argument("traj"); ap.add_argument("out")
ap.add_argument("--samples", type=int, default=256); ap.add_argument("--seed", type=int, default=0)
a = ap.parse_args()
t0 = time.time()
twin = cm.Twin(a.scenario)
traj = load_trajectory(a.traj)
rep = cm.analyze(traj, twin=twin, seed=a.seed, options=AnalyzeOptions(seed=a.seed, n_samples=a.samples, nthread=1))
from critmoment.report import jsonable
d = jsonable(rep.to_json())
d["_wall_s"] = round(time.time() - t0, 1)
json.dump(d, open(a.out, "w"), indent=1, default=str)
print(a.out, d["verdict"], "P", d["p_success"], "region", d["safe_region_text"], "wall", d["_wall_s"])
for c in d.get("failure_causes", []):
    print("  cause:", c)
