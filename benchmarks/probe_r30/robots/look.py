"""Nominal (or given-parameter) plain-MuJoCo run through truth.Setup (critmoment's per-step
controls): object position, gripper touch, every 0.4 s. usage: look.py SCENARIO TRAJ [v1 v2 ...]"""
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
import numpy as np
import truth

s = truth.Setup(sys.argv[1], sys.argv[2])
vals = [float(v) for v in sys.argv[3:]] or [s.unc[n]["nominal"] for n in s.names]
rec = s.rollout(vals)
out, info = truth.classify(s, rec)
step = int(round(0.4 / s.model.opt.timestep))
for t in range(0, len(rec["pos"]), step):
    print(f"t={t * s.model.opt.timestep:5.2f} obj={np.round(rec['pos'][t], 3)} touch={rec['touch'][t].astype(int)} both={rec['both'][t].astype(int)}")
print(out, info)
