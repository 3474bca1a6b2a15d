"""One demo audit (nthread=1) under a given critmoment checkout, with sample-steps counted per
stage (every mujoco.batch.Batch.rollout call classified by its caller stack) and the report
(timings stripped) written as JSON.

    python audit.py SRC CASE OUT.json [--count] [--profile PROF] [--repeat N]
CASE: aloha0 | aloha3 | panda0 (suite.make('nominal', seed, scenario)); 256 samples.
"""
import json, sys, time, collections, argparse, warnings
ap = argparse.ArgumentParser()
ap.add_argument("src"); ap.add_argument("case"); ap.add_argument("out")
ap.add_argument("--count", action="store_true"); ap.add_argument("--profile")
ap.add_argument("--repeat", type=int, default=1); ap.add_argument("--nthread", type=int, default=1); ap.add_argument("--samples", type=int, default=256)
a = ap.parse_args()
sys.path.insert(0, a.src)
import critmoment as cm
assert cm.__file__.startswith(a.src), cm.__file__
from critmoment import analysis, suite
import mujoco.batch
warnings.simplefilter("ignore")
scen = {"aloha": "aloha_transfer_cube", "panda": "panda_pick_place"}[a.case[:5]]
seed = int(a.case[5:])
twin = cm.Twin(cm.load_scenario(scen))
try:
    traj = suite.make("nominal", seed=seed, scenario=scen)
except TypeError:  # the filing-day code: one scenario
    traj = suite.make("nominal", seed=seed, twin=twin)
opts = analysis.AnalyzeOptions(seed=0, n_samples=a.samples, nthread=a.nthread)

steps = collections.Counter(); cpu = collections.Counter(); calls = collections.Counter()
if a.count:
    orig = mujoco.batch.Batch.rollout
    def classify():
        names = []
        f = sys._getframe(2)
        while f is not None:
            names.append(f.f_code.co_name); f = f.f_back
        s = set(names)
        if "_critical_values" in s or "_curves" in s: top = "critical"
        elif "_search_all" in s or "_load_bound" in s: top = "search"
        elif "check_region" in s: top = "region"
        elif "sample_runs" in s: top = "own"
        elif "_critical_values" in s or "_curves" in s: top = "critical"
        elif "_search_all" in s: top = "search"
        elif "evaluate_many" in s: top = "worst"
        elif "rollout" in names[1:] and "evaluate" not in s: top = "nominal"
        elif "evaluate" in s: top = "sweep"
        else: top = "other:" + "/".join(names[:4])
        if "_brute_force" in s or "brute_force" in s: sub = "rollout"
        elif "chained_failures" in s: sub = "chain"
        elif "_settled" in s: sub = "settle"
        elif "evaluate" in s: sub = "sparse"
        else: sub = "-"
        return f"{top}/{sub}"
    def wrapped(self, nstep, *args, **kw):
        ids = kw.get("ids")
        n = self.nsim if ids is None else len(ids)
        key = classify()
        c0 = time.process_time()
        out = orig(self, nstep, *args, **kw)
        cpu[key] += time.process_time() - c0
        steps[key] += int(nstep) * n; calls[key] += 1
        return out
    mujoco.batch.Batch.rollout = wrapped

res = []
prof = None
if a.profile:
    import cProfile; prof = cProfile.Profile(time.process_time)
for r in range(a.repeat):
    steps.clear(); cpu.clear(); calls.clear()
    t0, c0 = time.perf_counter(), time.process_time()
    if prof and r == a.repeat - 1: prof.enable()
    rep = analysis.analyze(traj, twin=twin, options=opts)
    if prof and r == a.repeat - 1: prof.disable()
    res.append((time.perf_counter() - t0, time.process_time() - c0))
if prof: prof.dump_stats(a.profile)
try:
    j = rep.to_json(timings=False)
except TypeError:
    j = rep.to_json(); j.pop("timings", None)
out = {"report": j, "times": res, "timings": rep.timings,
       "steps": dict(sorted(steps.items())), "cpu": {k: round(v, 3) for k, v in sorted(cpu.items())},
       "calls": dict(sorted(calls.items())), "total_steps": sum(steps.values())}
json.dump(out, open(a.out, "w"), indent=1, sort_keys=True, default=str)
print(a.case, "wall/cpu", [(round(w, 2), round(c, 2)) for w, c in res], "steps", sum(steps.values()))
for k in sorted(steps): print(f"  {k:24s} {steps[k]:8d} steps {calls[k]:5d} calls {cpu[k]:.3f} s")
