"""Do analysis._curves and sparse.critical_values evaluate the same 1-D curves (bit-equal
samples, same moments, same options)?  Counts the steps of each and compares the results.
    python curves_dup.py SRC CASE"""
import sys, warnings, time
import numpy as np
src, case = sys.argv[1], sys.argv[2]
sys.path.insert(0, src)
import critmoment as cm
assert cm.__file__.startswith(src)
from critmoment import analysis, suite, sparse
import mujoco.batch
warnings.simplefilter("ignore")
scen = {"aloha": "aloha_transfer_cube", "panda": "panda_pick_place"}[case[:5]]
twin = cm.Twin(cm.load_scenario(scen))
traj = suite.make("nominal", seed=int(case[5:]), scenario=scen)
opts = analysis.AnalyzeOptions(seed=0, n_samples=256, nthread=1)
rec = cm.rollout(traj, twin=twin)
ev, _ = analysis.audit_evaluator(rec, twin, horizon=opts.horizon, chain=opts.chain, nthread=1)
cands, steps = analysis.audit_moments(rec, twin, ev, opts.max_moments)
box = twin.scenario.box
n = opts.critical_grid
count = [0]
orig = mujoco.batch.Batch.rollout
def wrapped(self, nstep, *a, **kw):
    ids = kw.get("ids"); count[0] += int(nstep) * (self.nsim if ids is None else len(ids))
    return orig(self, nstep, *a, **kw)
mujoco.batch.Batch.rollout = wrapped
calls = []
orig_eval = sparse.SparseEvaluator.evaluate
def ev_wrap(self, st, samples, **kw):
    calls.append((np.asarray(st).copy(), np.asarray(samples).copy(), kw))
    return orig_eval(self, st, samples, **kw)
sparse.SparseEvaluator.evaluate = ev_wrap
c0 = time.process_time(); count[0] = 0
curves = analysis._curves(ev, steps, box, n)
s1, t1 = count[0], time.process_time() - c0
c0 = time.process_time(); count[0] = 0
crit = analysis._critical_values(rec, twin, ev, steps, n)
s2, t2 = count[0], time.process_time() - c0
print(case, "n_grid", n, "moments", steps.size, "| _curves:", s1, "steps", round(t1, 3), "s | critical values:", s2, "steps", round(t2, 3), "s")
# the critical values' grid calls (first len(box.names) calls: one per parameter, all moments)
for st, samples, kw in calls[:box.ndim]:
    j = [i for i in range(box.ndim) if np.unique(samples[:, i]).size > 1][0]
    mine = curves[int(steps[0])][box.names[j]].samples
    print(" param", box.names[j], "steps equal", np.array_equal(np.sort(st), np.sort(steps)), "samples bit-equal", np.array_equal(mine, samples), kw)
    res = orig_eval(ev, st, samples, **kw)
    for r, s in enumerate(st):
        a = curves[int(s)][box.names[j]]
        row = list(st).index(s)
        same = all(np.array_equal(np.asarray(getattr(a, f))[0], np.asarray(getattr(res, f))[row], equal_nan=True)
                   for f in ("cost", "failed", "fos_grasp", "fos_motor", "failure"))
        if not same: print("  moment", s, "DIFFERENT")
    print("  results equal at all moments checked")
