import time, json, sys
from common import *
from critmoment.analysis import AnalyzeOptions
traj = cm.load_trajectory(TRAJ)
sc = cm.load_scenario()
safe = sc.replace(box=sc.box.with_range("mass", 0.05, 0.2).with_range("friction", 0.5, 1.5))
for name, s in (("bundled", sc), ("safe", safe)):
    t0 = time.time()
    r = cm.analyze(traj, s, options=AnalyzeOptions(n_samples=32, nthread=1))
    print(name, r.verdict, r.p_success, r.safe_region_text, f"{time.time()-t0:.1f}s", flush=True)
