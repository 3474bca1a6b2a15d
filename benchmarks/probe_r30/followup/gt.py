"""Ground truth (critmoment brute_force) at points: usage
  PYTHONPATH=SRC gt.py SRC SCENARIO TRAJ OUT.json [--n N] [--seed S] [--pts m,f;m,f]
Points: box corners + N uniform random points (seeded) + explicit points. Prints per point outcome/max_slip."""
import sys, json, argparse, time, numpy as np, critmoment as cm
ap = argparse.ArgumentParser(); ap.add_argument("src"); ap.add_argument("scen"); ap.add_argument("traj"); ap.add_argument("out")
ap.add_argument("--n", type=int, default=12); ap.add_argument("--seed", type=int, default=0); ap.add_argument("--pts", default="")
a = ap.parse_args()
assert cm.__file__.startswith(a.src), cm.__file__
from critmoment.groundtruth import brute_force
from critmoment.trajectory import load_trajectory
twin = cm.Twin(a.scen); traj = load_trajectory(a.traj)
box = twin.scenario.box
lo, hi = box.low, box.high
rng = np.random.default_rng(a.seed)
pts = [box.nominal]
if box.ndim <= 3:
    import itertools
    pts += [np.where(np.array(c), hi, lo) for c in itertools.product([0, 1], repeat=box.ndim)]
pts += list(lo + (hi - lo) * rng.random((a.n, box.ndim)))
if a.pts:
    pts += [np.array([float(v) for v in p.split(",")]) for p in a.pts.split(";")]
pts = np.array(pts)
t = time.time()
bf = brute_force(traj, twin=twin, samples=pts, nthread=1)
c = bf.classification
rows = []
for i, p in enumerate(pts):
    rows.append(dict(p=[round(float(x), 6) for x in p], outcome=bf.outcome[i].value,
                     max_slip_mm=round(float(c.max_slip[i]) * 1000, 3),
                     first=int(c.first_failure_step[i])))
json.dump(dict(names=list(box.names), nominal_completed=bool(bf.nominal_completed), rows=rows,
               seconds=time.time() - t), open(a.out, "w"), indent=1)
print(a.traj, "names", box.names, "nominal_completed", bf.nominal_completed, f"{time.time()-t:.0f}s")
for r in rows:
    print(r["p"], r["outcome"], r["max_slip_mm"], r["first"])
