"""Run the independent insertion truth at the stated safe region's 4 corners and centre.
usage: region_truth.py REPORT.json TRAJ OBJECT [--cone elliptic --impratio 10]"""
import json
import subprocess
import sys

import critmoment
assert critmoment.__file__.startswith("/tmp/r37/src"), critmoment.__file__

rep, traj, obj, *extra = sys.argv[1:]
d = json.load(open(rep))
r = d.get("safe_region") or {}
if not r:
    print(rep, "no safe region stated"); sys.exit(0)
m, f = r["mass"], r["friction"]
pts = [f"{a},{b}" for a in m for b in f] + [f"{sum(m) / 2},{sum(f) / 2}"]
out = subprocess.run([sys.executable, "/work/main/benchmarks/probe_r37/insertion/truth.py", traj, "--object", obj,
                      "--values", *pts, *extra], capture_output=True, text=True, check=True).stdout
fails = 0
for line in out.splitlines():
    x = json.loads(line)
    fails += not x["success"]
    print(rep, "point", x["values"], "insertion", x["success"], "reward end", x["reward_end"])
print(rep, "region", r, "points failing the insertion truth:", fails, "of", len(pts))
