"""Full rollouts (brute force, the validate ground truth) at the corners of a variant's stated
safe region, its centre and N_INSIDE uniform random points inside it (seed 1).

usage: python region_bf.py NAME [N_INSIDE] [--first | --region=...]   (needs OUT/v/NAME/report/report.json)
--region='name=lo:hi,...': a sub-box of your own instead (e.g. one the audit did not state).
--first: the region first claimed (report.json verification.region.first_claim), before the
audit's own check shrank it: were its failing points real?
Prints each point that fails, and appends one line to region.tsv (this folder).
"""
import itertools
import json
import os
import sys
import warnings
from pathlib import Path

import numpy as np

import critmoment as cm
from critmoment import groundtruth

warnings.simplefilter("ignore")
OUT = Path(os.environ.get("R26_OUT", "/tmp/r26/clutter"))
HERE = Path(__file__).resolve().parent
first = "--first" in sys.argv
own = next((a.split("=", 1)[1] for a in sys.argv if a.startswith("--region=")), None)
argv = [a for a in sys.argv if a != "--first" and not a.startswith("--region=")]
name = argv[1]
n_in = int(argv[2]) if len(argv) > 2 else 8
v = OUT / "v" / name
r = json.load(open(v / "report" / "report.json"))
reg = r["verification"]["region"]["first_claim"] if first else r["safe_region"]
if own:
    reg = {kv.split("=")[0]: [float(x) for x in kv.split("=")[1].split(":")] for kv in own.split(",")}
if not reg:
    print(name, "no safe region stated")
    sys.exit(0)
twin = cm.Twin(cm.load_scenario(str(v)))
names = list(twin.scenario.box.names)
lo = np.array([reg[k][0] for k in names])
hi = np.array([reg[k][1] for k in names])
pts = [lo + (hi - lo) * np.array(c) for c in itertools.product([0.0, 1.0], repeat=len(names))]
pts.append((lo + hi) / 2)
rng = np.random.default_rng(1)
pts += list(lo + (hi - lo) * rng.random((n_in, len(names))))
S = np.array(pts)
traj = cm.load_trajectory(str(v / "traj.npz" if (v / "traj.npz").exists() else OUT / "aloha_s0.npz"))
bf = groundtruth.brute_force(traj, twin=twin, samples=S)
out = [o.value for o in bf.classification.outcome]
bad = [(dict(zip(names, S[i].round(4).tolist(), strict=True)), out[i]) for i in range(len(S)) if out[i] != "success"]
line = f"{name}{' (first claim)' if first else ''}{' (own sub-box)' if own else ''}\t{reg}\t{len(S)}\t{len(bad)}\t{bad}"
print(line)
with open(HERE / "region.tsv", "a") as f:
    f.write(line + "\n")
