"""critmoment analyze as the CLI does it, with nthread=1 (library). usage: run_analyze.py SCENARIO TRAJ OUT.json [--samples N]"""
import argparse, json, time
import critmoment as cm
assert cm.__file__.startswith("/tmp/r34/src"), cm.__file__
from critmoment.analysis import AnalyzeOptions, analyze
from critmoment.report import summary_text
from critmoment.trajectory import load_trajectory
ap = argparse.ArgumentParser(); ap.add_argument("scenario"); ap.add_argument("traj"); ap.add_argument("out")
ap.add_argument("--samples", type=int, default=32); ap.add_argument("--seed", type=int, default=0)
a = ap.parse_args()
t0 = time.time(); twin = cm.Twin(a.scenario)
res = analyze(load_trajectory(a.traj), twin.scenario, twin=twin, options=AnalyzeOptions(seed=a.seed, n_samples=a.samples, nthread=1))
p = res.to_json(); p["_wall_s"] = round(time.time() - t0, 1)
json.dump(p, open(a.out, "w"), indent=1, default=str)
print(summary_text(res)); print("wall", p["_wall_s"])
