"""List every own run of one audit (nthread=1): the verification/region rollouts with their
outcome and first failure step, the chains with failed/first failure, and exact duplicate
points between all runs.   python own_runs.py SRC CASE"""
import sys, collections, warnings, json
import numpy as np
src, case = sys.argv[1], sys.argv[2]
sys.path.insert(0, src)
import critmoment as cm
assert cm.__file__.startswith(src)
from critmoment import analysis, suite, history
warnings.simplefilter("ignore")
scen = {"aloha": "aloha_transfer_cube", "panda": "panda_pick_place"}[case[:5]]
seed = int(case[5:])
twin = cm.Twin(cm.load_scenario(scen))
traj = suite.make("nominal", seed=seed, scenario=scen)
log = []
orig_call = analysis._Rollouts.__call__
def call(self, points, nthread=None):
    stack = set()
    f = sys._getframe(1)
    while f: stack.add(f.f_code.co_name); f = f.f_back
    who = "region" if "check_region" in stack else ("worst" if "analyze" in stack and "sample_runs" not in stack else "sweep")
    failed = orig_call(self, points, nthread)
    for p, fl in zip(points, failed):
        o = self.outcomes[np.asarray(p, float).tobytes()]
        log.append(dict(who=who, kind="rollout", point=[float(x) for x in p], failed=bool(fl), outcome=o[0], t=o[1]))
    return failed
analysis._Rollouts.__call__ = call
orig_chain = history.chained_failures
def chained(ev, steps, samples, **kw):
    stack = set()
    f = sys._getframe(1)
    while f: stack.add(f.f_code.co_name); f = f.f_back
    who = "region" if "check_region" in stack else "sweep"
    r = orig_chain(ev, steps, samples, **kw)
    fs = getattr(r, "first_failure", None)
    for i, p in enumerate(np.asarray(samples)):
        log.append(dict(who=who, kind="chain", point=[float(x) for x in p], failed=bool(r.failed[i]),
                        kinds=r.kinds()[i], near=bool(r.near(0.8)[i]), confirm=bool(r.to_confirm[i])))
    return r
history.chained_failures = chained
analysis.history.chained_failures = chained
opts = analysis.AnalyzeOptions(seed=0, n_samples=256, nthread=1)
rep = analysis.analyze(traj, twin=twin, options=opts)
for e in log: print(e)
pts = collections.Counter(tuple(e["point"]) for e in log)
print("own runs", len(log), "distinct points", len(pts), "duplicates", {k: v for k, v in pts.items() if v > 1})
print("failed", sum(e["failed"] for e in log))
print("verification", json.dumps(rep.to_json(timings=False)["verification"]))
