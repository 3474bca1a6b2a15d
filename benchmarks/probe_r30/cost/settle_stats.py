"""The settle follow-ups of one audit (nthread=1): per followed pair, the blocks it was stepped
and whether it came out settled (a sticking failure, for its own run) or not (the failure
stands).   python settle_stats.py SRC CASE"""
import sys, collections, warnings
import numpy as np
src, case = sys.argv[1], sys.argv[2]
sys.path.insert(0, src)
import critmoment as cm
assert cm.__file__.startswith(src)
from critmoment import analysis, suite, sparse
warnings.simplefilter("ignore")
scen = {"aloha": "aloha_transfer_cube", "panda": "panda_pick_place"}[case[:5]]
twin = cm.Twin(cm.load_scenario(scen))
traj = suite.make("nominal", seed=int(case[5:]), scenario=scen)
rows = []
orig = sparse.SparseEvaluator._settled
def settled(self, batch, k, run, decided, slip, length):
    blocks = collections.Counter()
    roll = self._roll
    def counting(b, kk, n, ids, raised, *a, **kw):
        for i in np.atleast_1d(ids): blocks[int(i)] += 1
        return roll(b, kk, n, ids, raised, *a, **kw)
    self._roll = counting
    try:
        out = orig(self, batch, k, run, decided, slip, length)
    finally:
        del self._roll
    for i, nb in blocks.items():
        rows.append((nb, bool(out[i]), float(np.where(np.arange(slip.shape[1]) < length[i], slip[i], 0).max())))
    return out
sparse.SparseEvaluator._settled = settled
opts = analysis.AnalyzeOptions(seed=0, n_samples=256, nthread=1)
analysis.analyze(traj, twin=twin, options=opts)
p = 10
c = collections.Counter((nb, s) for nb, s, _ in rows)
print(case, "followed pairs", len(rows), "settled", sum(s for _, s, _ in rows),
      "block-steps", p * sum(nb for nb, _, _ in rows),
      "of which on pairs not settled", p * sum(nb for nb, s, _ in rows if not s))
print(" (blocks, settled): pairs", sorted(c.items()))
