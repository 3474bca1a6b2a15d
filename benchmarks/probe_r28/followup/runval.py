"""validate (CLI-equivalent, nthread=1) -> JSON: python runval.py SCEN TRAJ OUT.json [samples] [seed]"""
import sys, json, time
import critmoment as cm
from critmoment.validation import validate
from critmoment.trajectory import load_trajectory
from critmoment.analysis import AnalyzeOptions
scen, tp, out = sys.argv[1:4]
n = int(sys.argv[4]) if len(sys.argv) > 4 else 32
seed = int(sys.argv[5]) if len(sys.argv) > 5 else 0
twin = cm.Twin(cm.load_scenario(scen)); traj = load_trajectory(tp)
d = AnalyzeOptions(); t = time.time()
r = validate(traj, twin=twin, n_samples=n, seed=seed, max_moments=d.max_moments, verify=d.verify, nthread=1)
j = r.to_json(); j["_wall_s"] = time.time() - t
open(out, "w").write(json.dumps(j, indent=1, default=str))
print(tp, scen, "confusion", r.confusion, "agreement %.3f" % r.agreement, "vacuous", r.vacuous, "%.0fs" % j["_wall_s"])
