"""npz variants used by F5 and the motion checks (writes into /tmp/r33/inputs/npz/)."""
import os
import numpy as np
from common import SCRATCH
os.makedirs(os.path.join(SCRATCH, "npz"), exist_ok=True)
z = np.load(os.path.join(SCRATCH, "traj.npz")); base = {k: z[k] for k in z.files}
a = base["actions"][::2]   # the demo at 25 Hz
for name, extra in [("dt", {"dt": np.float64(0.04)}), ("FPS", {"FPS": np.float64(25)}),
                    ("hz", {"hz": np.float64(25)}), ("frequency", {"frequency": np.float64(25)}),
                    ("control_freq", {"control_freq": np.int64(25)}),
                    ("timestamps", {"timestamps": np.arange(len(a)) / 25.0}),
                    ("timestamp", {"timestamp": np.arange(len(a)) / 25.0}),
                    ("times", {"times": np.arange(len(a)) / 25.0}), ("t", {"t": np.arange(len(a)) / 25.0}),
                    ("time", {"time": np.arange(len(a)) / 25.0}), ("none", {})]:
    d = {k: v for k, v in base.items() if k != "fps"}; d["actions"] = a; d.update(extra)
    np.savez(os.path.join(SCRATCH, f"npz/rate_{name}.npz"), **d)
for name in ("action", "qpos_targets", "ctrl", "controls", "joint_targets", "act"):
    d = {k: v for k, v in base.items() if k != "actions"}; d[name] = base["actions"]
    np.savez(os.path.join(SCRATCH, f"npz/key_{name}.npz"), **d)
d = dict(base); d["actions"] = np.repeat(base["start"][None], 400, 0); np.savez(os.path.join(SCRATCH, "npz/still.npz"), **d)
d = dict(base); d["actions"] = base["actions"][::-1].copy(); np.savez(os.path.join(SCRATCH, "npz/reversed.npz"), **d)
d = dict(base); d["actions"] = base["actions"][:150].copy(); np.savez(os.path.join(SCRATCH, "npz/prefix150.npz"), **d)
d = {k: v for k, v in base.items() if k not in ("object_pose", "qpos0")}; np.savez(os.path.join(SCRATCH, "nopose.npz"), **d)
