"""One run's object path and contacts (critmoment's rollout with the scenario's nominal replaced
by the given values), printed every K steps, plus brute_force's classification.
usage: look.py SCENARIO TRAJ [name=value ...] [--every K] [--from A --to B]"""
import argparse, numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r33/src"), cm.__file__
from critmoment.groundtruth import brute_force
from critmoment.trajectory import load_trajectory
ap = argparse.ArgumentParser(); ap.add_argument("scen"); ap.add_argument("traj"); ap.add_argument("vals", nargs="*")
ap.add_argument("--every", type=int, default=100); ap.add_argument("--from", dest="a", type=int, default=0)
ap.add_argument("--to", type=int, default=10**9)
a = ap.parse_args()
twin = cm.Twin(a.scen); traj = load_trajectory(a.traj)
names = [p.name for p in twin.scenario.box.parameters]
vals = {p.name: p.nominal for p in twin.scenario.box.parameters}
vals.update({k: float(v) for k, v in (s.split("=") for s in a.vals)})
x = np.array([[vals[n] for n in names]])
bf = brute_force(traj, twin=twin, samples=x, nthread=1, keep_signals=True) if "keep_signals" in brute_force.__code__.co_varnames else brute_force(traj, twin=twin, samples=x, nthread=1)
c = bf.classification
print("values", vals, "outcome", bf.outcome[0].value, "completed", bool(c.completed[0]), "drop_step", int(c.drop_step[0]),
      "slip_step", int(c.slip_step[0]), "motor_step", int(c.motor_step[0]), f"max_slip {1000*float(c.max_slip[0]):.2f} mm")
