"""analyze (nthread=1, seed 0) + full-rollout check of the stated safe region: 4 corners,
4 edge midpoints, 16 uniform random points inside (rng seed 0), by critmoment's brute_force.
usage: ana_region.py SCENARIO TRAJ OUT.json"""
import itertools, json, sys, time
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src"), cm.__file__
from critmoment.analysis import analyze, AnalyzeOptions
from critmoment.groundtruth import brute_force
from critmoment.trajectory import load_trajectory

scen, trajf, out = sys.argv[1:4]
t0 = time.time()
twin = cm.Twin(scen)
traj = load_trajectory(trajf)
rep = analyze(traj, twin=twin, options=AnalyzeOptions(seed=0, nthread=1))
res = {"verdict": rep.verdict, "p_success": rep.p_success, "safe_region": rep.safe_region,
       "safe_region_text": rep.safe_region_text, "causes": list(rep.failure_causes),
       }
from critmoment.report import report_json
j = json.loads(json.dumps(report_json(rep, timings=False), default=str))
res["moments"] = [{k: m.get(k) for k in ("step", "time", "label", "critical", "critical_side", "dominant", "limiting_actuator", "fail_fraction", "overturned", "reached", "worst_case", "worst_fails", "worst_note", "min_fos_motor", "min_fos_contact", "max_cost")} for m in j["moments"]]
res["report"] = j
res["verification"] = j.get("verification")
res["contact_model_summary"] = (j.get("contact_model") or {}).get("summary")
res["warnings"] = j.get("warnings")
box_names = [p.name for p in twin.scenario.box.parameters]
if rep.safe_region:
    lohi = np.array([rep.safe_region.get(n, None) for n in box_names], float)
    corners = [list(c) for c in itertools.product(*lohi)]
    mids = []
    for i in range(len(box_names)):
        for side in (0, 1):
            p = lohi.mean(1).copy(); p[i] = lohi[i, side]; mids.append(list(p))
    rng = np.random.default_rng(0)
    inside = list(lohi[:, 0] + rng.random((16, len(box_names))) * (lohi[:, 1] - lohi[:, 0]))
    pts = np.array(corners + mids + [list(x) for x in inside])
    kinds = ["corner"] * len(corners) + ["edge_mid"] * len(mids) + ["inside"] * 16
    bf = brute_force(traj, twin=twin, samples=pts, nthread=1)
    res["region_check"] = [{"kind": k, "point": dict(zip(box_names, map(float, p))), "outcome": o.value}
                           for k, p, o in zip(kinds, pts, bf.outcome)]
    res["region_failures"] = [r for r in res["region_check"] if r["outcome"] != "success"]
res["wall"] = round(time.time() - t0, 1)
json.dump(res, open(out, "w"), indent=1, default=str)
print(json.dumps({k: res.get(k) for k in ("verdict", "p_success", "safe_region_text", "causes", "region_failures", "wall")}, indent=1, default=str))
