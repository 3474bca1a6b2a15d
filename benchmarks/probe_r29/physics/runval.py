"""validate (as the CLI does, nthread=1) -> JSON: python runval.py VARIANT [samples] [seed] [tag]
VARIANT is a folder under /tmp/r29/physics/v (trajectory: its traj.npz, else aloha_s0/panda_s0).
Appends a row to /tmp/r29/physics/val.tsv."""
import json
import sys
import time
from pathlib import Path

import critmoment as cm
from critmoment.analysis import AnalyzeOptions
from critmoment.trajectory import load_trajectory
from critmoment.validation import validate

assert cm.__file__.startswith("/tmp/r29/src"), cm.__file__
R = Path("/tmp/r29/physics")
v = sys.argv[1]
n = int(sys.argv[2]) if len(sys.argv) > 2 else 64
seed = int(sys.argv[3]) if len(sys.argv) > 3 else 0
tag = sys.argv[4] if len(sys.argv) > 4 else ""
vd = R / "v" / v
tp = vd / "traj.npz"
if not tp.exists():
    tp = R / ("aloha_s0.npz" if v.startswith("a_") else "panda_s0.npz")
twin = cm.Twin(cm.load_scenario(str(vd)))
traj = load_trajectory(str(tp))
d = AnalyzeOptions()
t = time.time()
r = validate(traj, twin=twin, n_samples=n, seed=seed, max_moments=d.max_moments, verify=d.verify, nthread=1)
j = r.to_json()
j["_wall_s"] = time.time() - t
(vd / f"val{tag}_{n}_{seed}.json").write_text(json.dumps(j, indent=1, default=str))
c = j["confusion"]
rs = c["true_safe"] + c["false_unsafe"]
rf = c["true_unsafe"] + c["false_safe"]
row = [v + tag, n, seed, rs, rf, c["false_safe"], c["false_unsafe"], f"{j['agreement']:.3f}", j["vacuous"],
       f"{j['timings']['compute_ratio']:.3f}", f"{j['_wall_s']:.0f}", json.dumps(j["outcomes"])]
with open(R / "val.tsv", "a") as f:
    f.write("\t".join(map(str, row)) + "\n")
print(*row, sep="\t")
for m in j["missed"]:
    print("  MISSED", m)
