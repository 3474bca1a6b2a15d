"""analyze with the region check's rounds traced (each shrink: the region, failing points, their sparse cost):
python region_trace.py VARIANT [samples]"""
import sys, numpy as np, critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src")
from critmoment import analysis as an
from critmoment.analysis import AnalyzeOptions, analyze
from critmoment.trajectory import load_trajectory
v = sys.argv[1]; n = int(sys.argv[2]) if len(sys.argv) > 2 else 128
vd = f"/tmp/r31/contact/v/{v}"
twin = cm.Twin(cm.load_scenario(vd)); traj = load_trajectory("/tmp/r31/contact/" + ("aloha_s0.npz" if v.startswith("a_") else "panda_s0.npz"))
orig = an.vd.shrink_region
def traced(current, failing, box, sides, **kw):
    new = orig(current, failing, box, sides, **kw)
    print("ROUND region", {k: tuple(round(x, 4) for x in r) for k, r in current.items()}, "failing pts", np.round(failing, 4).tolist()[:6], "->", new and {k: tuple(round(x, 4) for x in r) for k, r in new.items()}, flush=True)
    return new
an.vd.shrink_region = traced
orig_sf = an._sparse_fails
def sf(res, undecided):
    out = orig_sf(res, undecided)
    if out.any():
        print("  sparse-decided failures:", int(out.sum()), "costs", np.round(np.asarray(res.worst_cost())[out], 3).tolist()[:8], flush=True)
    return out
an._sparse_fails = sf
res = analyze(traj, twin.scenario, twin=twin, options=AnalyzeOptions(seed=0, nthread=1, n_samples=n))
j = res.to_json(); print(j["verdict"], j["safe_region_text"])
