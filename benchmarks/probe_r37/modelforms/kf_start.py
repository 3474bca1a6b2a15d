"""Where does a run start on a model with keyframes, for each trajectory form?

Model: models/keyframe (keyframes 'away' first: joint1 = 0.5, cube at (0.6, 0.1); then 'home':
cube at (0.5, -0.15), the body's own pos). Scenario: init's (keyframe = "away").
Run from /tmp/r37/modelforms/kf: PYTHONPATH=/tmp/r37/src /work/venv/bin/python kf_start.py
"""
import warnings

import numpy as np

import common  # noqa: F401
from critmoment import load_scenario, load_trajectory
from critmoment.twin import Twin

z = np.load("/tmp/r37/modelforms/panda.npz")
np.savez("acts_only.npz", actions=z["actions"], fps=z["fps"])
np.savez("acts_start.npz", actions=z["actions"], fps=z["fps"], start=z["start"])
for toml in ("init.toml",):
    sc = load_scenario(toml)
    tw = Twin(sc)
    for f in ("acts_only.npz", "acts_start.npz", "/tmp/r37/modelforms/panda.npz"):
        with warnings.catch_warnings(record=True) as w:
            warnings.simplefilter("always")
            tr = load_trajectory(f)
            d = tw.initial_data(start=tr.start if tr.start is not None else tr.actions[0],
                                qpos0=tr.qpos0, object_pose=tr.object_pose, settle=False)
        adr = tw.object_qposadr
        print(f"{toml} {f}: joint1 {d.qpos[0]:.3f} cube {np.round(d.qpos[adr:adr+3], 3)}; "
              f"warnings: {[str(x.message)[:160] for x in w]}")
