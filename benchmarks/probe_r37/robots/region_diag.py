"""analyze (library, nthread=1, seed 0) with critmoment.verdict.shrink_region wrapped to print the points that failed
each region-check round (and whether sparse evaluation or an own run failed them), to find what shrank a region.
usage: region_diag.py SCENARIO TRAJ OUT.json"""
import json, sys
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r37/src"), cm.__file__
import critmoment.analysis as an
from critmoment.analysis import AnalyzeOptions
from critmoment.trajectory import load_trajectory
log = []
orig_shrink = an.vd.shrink_region
def shrink(current, failing, box, sides, **kw):
    log.append(dict(region=current, failing=np.asarray(failing).tolist(), names=list(box.names) if hasattr(box, "names") else None))
    print("shrink: region", current, "failing points", np.round(failing, 4).tolist(), flush=True)
    return orig_shrink(current, failing, box, sides, **kw)
an.vd.shrink_region = shrink
orig_sf = an._sparse_fails
def sparse_fails(res, undecided):
    f = orig_sf(res, undecided)
    print("region round: sparse-evaluation failures decided alone:", int(np.asarray(f).sum()), flush=True)
    return f
an._sparse_fails = sparse_fails
scen, traj, out = sys.argv[1:4]
twin = cm.Twin(scen)
rep = cm.analyze(load_trajectory(traj), twin=twin, options=AnalyzeOptions(seed=0, nthread=1))
print(rep.verdict, rep.p_success, rep.safe_region_text)
names = [p.name for p in twin.scenario.box.parameters] if hasattr(twin.scenario.box, "parameters") else None
json.dump(dict(log=log, names=names), open(out, "w"), indent=1, default=str)
