"""(probe_r37: probe_r31/robots/run_analyze.py, snapshot path -> /tmp/r37/src) critmoment analyze via the library (nthread=1; the CLI has no --nthread), default options
otherwise (the CLI's --samples default 256), seed 0. Writes the verdict, P(success), the
safe region and a region check point list (corners, mid-edges, centre, 4 inside points)
for truth.py --points.  usage: run_analyze.py SCENARIO TRAJ OUT_PREFIX"""
import itertools
import json
import sys
import time

import numpy as np

import critmoment as cm
assert cm.__file__.startswith("/tmp/r37/src"), cm.__file__
from critmoment.analysis import AnalyzeOptions
from critmoment.trajectory import load_trajectory

scen, traj_path, out = sys.argv[1:4]
t0 = time.time()
twin = cm.Twin(scen)
rep = cm.analyze(load_trajectory(traj_path), twin=twin, options=AnalyzeOptions(seed=0, nthread=1))
doc = dict(verdict=str(rep.verdict.value), p_success=rep.p_success, safe_region_text=rep.safe_region_text,
           safe_region=None if rep.safe_region is None else {k: [float(a), float(b)] for k, (a, b) in rep.safe_region.items()},
           wall_s=round(time.time() - t0, 1))
from critmoment.report import summary_text

doc["summary_text"] = summary_text(rep)
print(json.dumps({k: v for k, v in doc.items() if k != "summary_text"}, indent=1))
print(doc["summary_text"])
json.dump(doc, open(out + "_analyze.json", "w"), indent=1)
if rep.safe_region:
    names = list(rep.safe_region)
    lo = np.array([rep.safe_region[n][0] for n in names]); hi = np.array([rep.safe_region[n][1] for n in names])
    pts = [np.array(c) for c in itertools.product(*[(0, 1)] * len(names))]       # corners
    for i in range(len(names)):                                                 # mid-edges
        for c in itertools.product(*[(0, 1)] * (len(names) - 1)):
            p = list(c); p.insert(i, 0.5); pts.append(np.array(p, float))
    pts.append(np.full(len(names), 0.5))
    rng = np.random.default_rng(0)
    pts += [rng.uniform(0.05, 0.95, len(names)) for _ in range(16)]  # 16 inside points
    vals = [dict(zip(names, (lo + p * (hi - lo)).tolist())) for p in pts]
    json.dump(vals, open(out + "_points.json", "w"), indent=1)
    print(len(vals), "region points written")
