"""analyze (nthread=1, seed 0, 128 samples) + its stated safe region by brute force at the
corners, edge mid-points and centre (3^k grid) and 8 random points inside.
python runana.py VARIANT [samples]  -> /tmp/r32/contact/v/VARIANT/ana/"""
import itertools, json, sys, time
from pathlib import Path
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r32/src"), cm.__file__
from critmoment import groundtruth as gt
from critmoment.analysis import AnalyzeOptions, analyze
from critmoment.trajectory import load_trajectory

R = Path("/tmp/r32/contact"); v = sys.argv[1]; n = int(sys.argv[2]) if len(sys.argv) > 2 else 128
import os
vd = R / "v" / v; tp = Path(os.environ["TRAJ"]) if os.environ.get("TRAJ") else vd / "traj.npz"
if not tp.exists():
    tp = R / ("aloha_s0.npz" if v.startswith("a_") else "panda_s0.npz")
out = vd / ("ana" + os.environ.get("TAG", "")); out.mkdir(exist_ok=True)
twin = cm.Twin(cm.load_scenario(str(vd))); traj = load_trajectory(str(tp)); box = twin.scenario.box
t = time.time()
res = analyze(traj, twin.scenario, twin=twin, options=AnalyzeOptions(seed=0, nthread=1, n_samples=n))
j = res.to_json(); wall = time.time() - t
(out / "report.json").write_text(json.dumps(j, indent=1, default=str))
print(f"== {v}: {j['verdict']} p={j['p_success']:.3f} wall {wall:.0f}s region {j['safe_region']} | {j['safe_region_text']}")
for c in j["failure_causes"]: print("  cause:", c[:250])
reg = j["safe_region"]
if reg:
    levels = [np.linspace(reg[p.name][0], reg[p.name][1], 3) if p.name in reg else np.array([p.low, p.high]) for p in box.parameters]
    pts = np.array(list(itertools.product(*levels)))
    rng = np.random.default_rng(1)
    lo = np.array([reg.get(p.name, (p.low, p.high))[0] for p in box.parameters])
    hi = np.array([reg.get(p.name, (p.low, p.high))[1] for p in box.parameters])
    pts = np.vstack([pts, lo + rng.random((8, box.ndim)) * (hi - lo)])
    bf = gt.brute_force(traj, twin=twin, samples=pts, nthread=1)
    bad = [(dict(zip([p.name for p in box.parameters], pts[i].round(5).tolist())), bf.outcome[i].name) for i in np.flatnonzero(bf.failed)]
    print(f"  region check: {len(pts)} points, {len(bad)} failures")
    for b in bad: print("   FAIL inside:", b)
    (out / "region_check.json").write_text(json.dumps({"points": pts.tolist(), "failed": bf.failed.tolist(), "failures": bad}, indent=1))
