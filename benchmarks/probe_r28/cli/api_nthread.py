"""nthread=1 vs default (all CPUs) vs 2: report.json identical apart from timings?"""
import json
import time

import critmoment as cm
from critmoment import analysis

tw = cm.Twin(cm.load_scenario()); traj = cm.load_trajectory("/tmp/r28/cli/readme/traj.npz")
docs = {}
for n in (1, 0, 2):
    t = time.time(); r = analysis.analyze(traj, twin=tw, options=analysis.AnalyzeOptions(seed=0, nthread=n))
    d = r.to_json(); d.pop("timings", None); d["manifest"]["options"].pop("nthread", None)
    docs[n] = json.dumps(d, sort_keys=True, default=str); print(n, r.verdict, r.p_success, round(time.time() - t, 1), "s", flush=True)
print("1 vs 0 identical:", docs[1] == docs[0], "| 1 vs 2 identical:", docs[1] == docs[2])
