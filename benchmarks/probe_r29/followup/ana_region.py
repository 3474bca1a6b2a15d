"""analyze (nthread=1, seed 0, N samples) + the stated safe region checked by critmoment's own
full rollouts (groundtruth.brute_force): its 3^k grid (corners, edge/face midpoints, centre),
64 random points inside, and 8 random points on each face of the region (where a face moved
inward, the failure it cut off lies just outside).
usage: PYTHONPATH=/tmp/r29b/src python ana_region.py SCEN TRAJ OUTDIR [samples]"""
import itertools, json, sys, time, warnings
from pathlib import Path
import numpy as np
import critmoment as cm
from critmoment import groundtruth as gt
from critmoment.analysis import AnalyzeOptions, analyze
from critmoment.trajectory import load_trajectory
warnings.simplefilter("ignore")
print("critmoment", cm.__file__)
scen, tp, out = sys.argv[1:4]
n = int(sys.argv[4]) if len(sys.argv) > 4 else 256
out = Path(out); out.mkdir(parents=True, exist_ok=True)
twin = cm.Twin(cm.load_scenario(scen)); traj = load_trajectory(tp); box = twin.scenario.box
t = time.time()
res = analyze(traj, twin.scenario, twin=twin, options=AnalyzeOptions(seed=0, nthread=1, n_samples=n))
j = res.to_json()
(out / "report.json").write_text(json.dumps(j, indent=1, default=str))
print(f"== {scen}: {j['verdict']} p={j['p_success']:.3f} wall {time.time()-t:.0f}s")
print("region:", j["safe_region"]); print("text:", j["safe_region_text"])
for k in ("fail_sides", "sides", "region_check"):
    if k in j: print(k, json.dumps(j[k], default=str)[:600])
for c in j["failure_causes"]: print("cause:", c)
reg = j["safe_region"]
if reg:
    lo = np.array([reg.get(p.name, (p.low, p.high))[0] for p in box.parameters])
    hi = np.array([reg.get(p.name, (p.low, p.high))[1] for p in box.parameters])
    grid = np.array(list(itertools.product(*[np.linspace(lo[k], hi[k], 3) for k in range(box.ndim)])))
    rng = np.random.default_rng(1)
    inside = lo + rng.random((64, box.ndim)) * (hi - lo)
    faces = []
    for k in range(box.ndim):
        for v in (lo[k], hi[k]):
            q = lo + rng.random((8, box.ndim)) * (hi - lo); q[:, k] = v; faces.append(q)
    pts = np.vstack([grid, inside] + faces)
    kind = ["grid"] * len(grid) + ["inside"] * 64 + ["face"] * (8 * 2 * box.ndim)
    bf = gt.brute_force(traj, twin=twin, samples=pts, nthread=1)
    bad = [{"point": dict(zip(box.names, pts[i].round(5).tolist())), "where": kind[i],
            "outcome": bf.outcome[i].name} for i in np.flatnonzero(bf.failed)]
    print(f"region check: {len(pts)} points, {len(bad)} failures")
    for b in bad[:12]: print("  FAIL in region:", b)
    (out / "region_check.json").write_text(json.dumps({"region": reg, "points": len(pts), "failures": bad}, indent=1))
