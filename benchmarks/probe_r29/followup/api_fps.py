"""Trajectory(actions) without fps: what rate is used, and what save/load round-trips.
usage: PYTHONPATH=/tmp/r29b/src python api_fps.py SCENARIO"""
import sys, tempfile, warnings, os
import numpy as np
import critmoment as cm
from critmoment.trajectory import Trajectory, load_trajectory, save_trajectory
from critmoment.recording import at_scenario_rate
twin = cm.Twin(sys.argv[1])
sc = twin.scenario
print("scenario actions fps:", getattr(sc, "actions", None) and getattr(sc.actions, "fps", None))
width = len(sc.channels) if hasattr(sc, "channels") else twin.model.nu
t = Trajectory(np.zeros((10, width)))
print("Trajectory fps:", t.fps, "fps_assumed:", getattr(t, "fps_assumed", "n/a"))
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    r = at_scenario_rate(t, twin)
    print("at_scenario_rate fps:", r.fps, [str(x.message)[:160] for x in w])
p = os.path.join(tempfile.mkdtemp(), "t.npz")
save_trajectory(t, p)
print("saved keys:", sorted(np.load(p).files))
t2 = load_trajectory(p)
print("loaded fps:", t2.fps, "fps_assumed:", getattr(t2, "fps_assumed", "n/a"))
t3 = Trajectory(np.zeros((10, width)), fps=30.0)
save_trajectory(t3, p); print("explicit 30 saved keys:", sorted(np.load(p).files), "loaded fps", load_trajectory(p).fps)
