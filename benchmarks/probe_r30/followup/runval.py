"""validate (CLI-equivalent, nthread=1) -> JSON file: python runval.py SCEN TRAJ OUT.json [samples] [seed]"""
import json
import sys
import time

import critmoment as cm, os
assert cm.__file__.startswith(os.environ["PYTHONPATH"]), cm.__file__
from critmoment.analysis import AnalyzeOptions
from critmoment.trajectory import load_trajectory
from critmoment.validation import validate

scen, tp, out = sys.argv[1:4]
n = int(sys.argv[4]) if len(sys.argv) > 4 else 64
seed = int(sys.argv[5]) if len(sys.argv) > 5 else 0
twin = cm.Twin(cm.load_scenario(scen)); traj = load_trajectory(tp)
d = AnalyzeOptions()
t = time.time()
r = validate(traj, twin=twin, n_samples=n, seed=seed, max_moments=d.max_moments, verify=d.verify, nthread=1)
j = r.to_json(); j["_wall_s"] = time.time() - t
open(out, "w").write(json.dumps(j, indent=1, default=str))
print(scen, "confusion", r.confusion, "agreement %.3f" % r.agreement, "vacuous", r.vacuous, "%.0fs" % j["_wall_s"])
