"""How far the object moves before any gripper first touches it, in critmoment's nominal recording:
python pretouch.py VARIANT..."""
import sys
from pathlib import Path

import numpy as np

import critmoment as cm
from critmoment.recording import rollout
from critmoment.trajectory import load_trajectory

R = Path("/tmp/r29/physics")
for v in sys.argv[1:]:
    vd = R / "v" / v
    tp = vd / "traj.npz" if (vd / "traj.npz").exists() else R / ("aloha_s0.npz" if v.startswith("a_") else "panda_s0.npz")
    twin = cm.Twin(cm.load_scenario(str(vd)))
    rec = rollout(load_trajectory(str(tp)), twin=twin)
    sig = rec.signals
    cg = np.asarray(sig.contact_gripper, bool).any(axis=-1)
    first = int(np.argmax(cg)) if cg.any() else len(cg) - 1
    nq = twin.model.nq
    adr = twin.object_qposadr
    q = rec.states[:, 1 + adr:1 + adr + 7]
    d = np.linalg.norm(q[:first + 1, :3] - q[0, :3], axis=1)
    ang = np.degrees(2 * np.arccos(np.clip(np.abs((q[:first + 1, 3:] * q[0, 3:]).sum(axis=1)), 0, 1)))
    print(f"{v}: first gripper touch at step {first} (t = {first * rec.dt:.2f} s); before it the object moved up to "
          f"{1e3 * d.max():.1f} mm (rose {1e3 * (q[:first + 1, 2].max() - q[0, 2]):.1f} mm) and turned up to {ang.max():.1f}°")
