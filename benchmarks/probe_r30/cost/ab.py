"""Alternating A/B/C of the demo audit under several checkouts, fresh subprocess per checkout
per round (warm-up audit, then --per-round timed audits, 1 s rest before each).
    python ab.py --case aloha0 --nthread 1 --rounds 3 CHECKOUT...
Prints medians and minima of wall and CPU per checkout."""
import argparse, json, statistics, subprocess, sys
CHILD = r'''
import json, sys, time, warnings
src, case, per, nthread = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
sys.path.insert(0, src)
import critmoment as cm
assert cm.__file__.startswith(src)
from critmoment import analysis, suite
warnings.simplefilter("ignore")
scen = {"aloha": "aloha_transfer_cube", "panda": "panda_pick_place"}[case[:5]]
twin = cm.Twin(cm.load_scenario(scen))
try:
    traj = suite.make("nominal", seed=int(case[5:]), scenario=scen)
except TypeError:
    traj = suite.make("nominal", seed=int(case[5:]), twin=twin)
opts = analysis.AnalyzeOptions(seed=0, n_samples=256, nthread=nthread)
analysis.analyze(traj, twin=twin, options=opts)
out = []
for _ in range(per):
    time.sleep(1.0)
    t0, c0 = time.perf_counter(), time.process_time()
    analysis.analyze(traj, twin=twin, options=opts)
    out.append((time.perf_counter() - t0, time.process_time() - c0))
print(json.dumps(out))
'''
ap = argparse.ArgumentParser(); ap.add_argument("paths", nargs="+")
ap.add_argument("--case", default="aloha0"); ap.add_argument("--nthread", type=int, default=1)
ap.add_argument("--rounds", type=int, default=3); ap.add_argument("--per-round", type=int, default=2)
a = ap.parse_args()
times = {p: [] for p in a.paths}
for _ in range(a.rounds):
    for p in a.paths:
        r = subprocess.run([sys.executable, "-c", CHILD, p, a.case, str(a.per_round), str(a.nthread)],
                           capture_output=True, text=True, check=True)
        times[p] += json.loads(r.stdout.strip().splitlines()[-1])
base = None
for p, runs in times.items():
    w = statistics.median(x for x, _ in runs); c = statistics.median(y for _, y in runs)
    cmin = min(y for _, y in runs)
    base = base or (w, c, cmin)
    print(f"{p}: wall median {w:.3f} (min {min(x for x, _ in runs):.3f}), CPU median {c:.3f} "
          f"(min {cmin:.3f}); vs first: wall {w / base[0]:.2f}x CPU {c / base[1]:.2f}x "
          f"(min CPU {cmin / base[2]:.2f}x); runs {[(round(x, 2), round(y, 2)) for x, y in runs]}")
