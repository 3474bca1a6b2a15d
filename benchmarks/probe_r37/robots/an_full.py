"""critmoment analyze via the library (nthread=1, seed 0, 256 samples) writing the whole report.json
(report_json), for the region check's details. usage: an_full.py SCENARIO TRAJ OUT.json"""
import json, sys, time
import critmoment as cm
assert cm.__file__.startswith("/tmp/r37/src"), cm.__file__
from critmoment.analysis import AnalyzeOptions
from critmoment.report import report_json
from critmoment.trajectory import load_trajectory
scen, traj, out = sys.argv[1:4]
t0 = time.time()
rep = cm.analyze(load_trajectory(traj), twin=cm.Twin(scen), options=AnalyzeOptions(seed=0, nthread=1))
doc = report_json(rep); doc["_wall_s"] = round(time.time() - t0, 1)
json.dump(doc, open(out, "w"), indent=1, default=str)
print(doc["verdict"], doc["p_success"], doc["safe_region_text"])
print(json.dumps(doc["verification"].get("region"), default=str)[:3000])
