"""brute force (critmoment.groundtruth) of given points with the classification's details:
python bf1.py VARIANT '[[v1, v2, ...], ...]'"""
import json, sys
from pathlib import Path
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r32/src")
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory
R = Path("/tmp/r32/contact"); v = sys.argv[1]; vd = R / "v" / v
tp = vd / "traj.npz"
if not tp.exists():
    tp = R / ("aloha_s0.npz" if v.startswith("a_") else "panda_s0.npz")
twin = cm.Twin(cm.load_scenario(str(vd))); traj = load_trajectory(str(tp))
pts = np.array(json.loads(sys.argv[2]), float)
bf = gt.brute_force(traj, twin=twin, samples=pts, nthread=1)
c = bf.classification
for i in range(len(pts)):
    d = {f: getattr(c, f)[i] for f in ("outcome", "completed", "first_failure_step", "slip_step", "drop_step", "motor_step", "max_slip", "saturation_time", "motor_tracking") if hasattr(c, f)}
    print(pts[i].tolist(), {k: (x.name if hasattr(x, "name") else (round(float(x), 4) if np.ndim(x) == 0 else x)) for k, x in d.items()})
    for f in dir(c):
        if "actuator" in f or "joint" in f:
            print("   ", f, getattr(c, f)[i] if hasattr(getattr(c, f), "__getitem__") else getattr(c, f))
