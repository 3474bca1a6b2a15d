"""analyze (nthread=1, seed 0, 256 samples) + check the stated safe region by brute force.
python runana.py SCEN TRAJ OUTDIR [nthread]"""
import itertools
import json
import sys
import time
from pathlib import Path

import numpy as np

import critmoment as cm
assert cm.__file__.startswith("/tmp/r29/src"), cm.__file__
from critmoment import groundtruth as gt
from critmoment import report
from critmoment.analysis import AnalyzeOptions, analyze
from critmoment.trajectory import load_trajectory

scen, tp, out = sys.argv[1:4]
nth = int(sys.argv[4]) if len(sys.argv) > 4 else 1
out = Path(out); out.mkdir(parents=True, exist_ok=True)
twin = cm.Twin(cm.load_scenario(scen)); traj = load_trajectory(tp); box = twin.scenario.box
t = time.time()
res = analyze(traj, twin.scenario, twin=twin, options=AnalyzeOptions(seed=0, nthread=nth))
wall = time.time() - t
j = res.to_json()
(out / "report.json").write_text(json.dumps(j, indent=1, default=str))
(out / "summary.txt").write_text(report.summary_text(res))
print(f"== {scen}: {res.verdict} p={j['p_success']:.3f} wall {wall:.0f}s")
print("region:", j["safe_region"]); print("text:", j["safe_region_text"])
for c in j["failure_causes"]: print("cause:", c)
for m in j["moments"][:3]:
    print(f"moment step {m['step']} {m['label']} worst {m['worst_case']} cost {m['max_cost']:.3g} dominant {m['dominant']} "
          f"lim {m['limiting_actuator']} crit {m['critical']} side {m['critical_side']} fail_frac {m['fail_fraction']}")
reg = j["safe_region"]
if reg:
    # corners, mid-edges/faces (3-level grid) and random points inside
    levels = [np.linspace(reg[p.name][0], reg[p.name][1], 3) if p.name in reg else np.array([p.nominal]) for p in box.parameters]
    pts = np.array(list(itertools.product(*levels)))
    rng = np.random.default_rng(1)
    lo = np.array([reg.get(p.name, (p.nominal, p.nominal))[0] for p in box.parameters])
    hi = np.array([reg.get(p.name, (p.nominal, p.nominal))[1] for p in box.parameters])
    pts = np.vstack([pts, lo + rng.random((32, box.ndim)) * (hi - lo)])
    # params not in the region: the region statement spans their whole range? test their ends too
    missing = [k for k, p in enumerate(box.parameters) if p.name not in reg]
    if missing:
        extra = []
        for k in missing:
            for v in (box.parameters[k].low, box.parameters[k].high):
                q = pts.copy(); q[:, k] = v; extra.append(q)
        pts = np.vstack([pts] + extra)
    bf = gt.brute_force(traj, twin=twin, samples=pts, nthread=1)
    bad = [(pts[i].round(5).tolist(), bf.outcome[i].name) for i in np.flatnonzero(bf.failed)]
    print(f"region check: {len(pts)} points, {len(bad)} failures (params not in region: {[box.parameters[k].name for k in missing]})")
    for b in bad[:10]: print("  FAIL inside:", b)
    (out / "region_check.json").write_text(json.dumps({"points": len(pts), "failures": bad}, indent=1))
