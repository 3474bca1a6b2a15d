"""Fine sweep near the slip edge of P_regrasp_low (needs regrasp_slip.py's npz files):
samples whose second-hold slip the chunk measures > tolerance but the full run masks.
usage: regrasp_fine.py OUTDIR"""
import pathlib, sys
import numpy as np
import critmoment as cm
from critmoment import panda_demo as pd
from critmoment.groundtruth import brute_force
from critmoment.trajectory import load_trajectory
OUT = pathlib.Path(sys.argv[1])
twin = cm.Twin(str(pd.scene_path().parent / "scenario.toml"))
full = load_trajectory(OUT / "P_regrasp_low.npz"); half = load_trajectory(OUT / "P_regrasp_low_half2.npz")
pts = np.array([[m, f] for f in (0.6, 0.65, 0.7, 0.75, 0.8) for m in np.arange(1.2, 1.56, 0.05)])
a = brute_force(full, twin=twin, samples=pts, nthread=1).classification
b = brute_force(half, twin=twin, samples=pts, nthread=1).classification
for i, p in enumerate(pts):
    if a.outcome[i] != b.outcome[i] or (a.max_slip[i] > 0.003 or b.max_slip[i] > 0.003):
        print(f"mass {p[0]:.2f} fric {p[1]:.2f}: full {a.outcome[i].value:8s} {1e3*a.max_slip[i]:5.1f} mm | "
              f"half2 {b.outcome[i].value:8s} {1e3*b.max_slip[i]:5.1f} mm" + ("  <-- differs" if a.outcome[i] != b.outcome[i] else ""))
print("differ:", sum(x != y for x, y in zip(a.outcome, b.outcome)), "of", len(pts))
