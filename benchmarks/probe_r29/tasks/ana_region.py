"""analyze (nthread=1, seed 0) + full-rollout check of the stated safe region's 4 corners and
centre, + brute-force details of chosen samples.
usage: ana_region.py SCENARIO TRAJ OUT.json"""
import itertools, json, sys, time
import numpy as np
import critmoment as cm
from critmoment.analysis import analyze, AnalyzeOptions
from critmoment.groundtruth import brute_force, OutcomeCriteria
from critmoment.trajectory import load_trajectory

scen, trajf, out = sys.argv[1:4]
t0 = time.time()
twin = cm.Twin(scen)
traj = load_trajectory(trajf)
rep = analyze(traj, twin=twin, options=AnalyzeOptions(seed=0, nthread=1))
res = {"verdict": rep.verdict, "p_success": rep.p_success, "safe_region": rep.safe_region,
       "safe_region_text": rep.safe_region_text,
       "causes": list(getattr(rep, "failure_causes", []))}
names = [p.name for p in twin.box.parameters] if hasattr(twin, "box") else None
res["names"] = names
if rep.safe_region:
    names = list(rep.safe_region.keys())
    lohi = [rep.safe_region[n] for n in names]
    pts = np.array([list(c) for c in itertools.product(*lohi)] + [[(a + b) / 2 for a, b in lohi]])
    bf = brute_force(traj, twin=twin, samples=pts, nthread=1)
    res["region_check"] = [{"point": dict(zip(names, map(float, p))), "outcome": o.value,
                            "max_slip": float(s), "completed": bool(c)}
                           for p, o, s, c in zip(pts, bf.outcome, bf.classification.max_slip,
                                                bf.classification.completed)]
res["wall"] = round(time.time() - t0, 1)
json.dump(res, open(out, "w"), indent=1, default=str)
print(json.dumps(res, indent=1, default=str))
