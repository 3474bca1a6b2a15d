"""Samples the ground truth calls SUCCESS although the object left the gripper before the nominal
release (drop_step before the nominal run's last gripper contact): python early_drop.py SCEN TRAJ [n] [seed]"""
import sys, numpy as np, critmoment as cm
from critmoment.trajectory import load_trajectory
from critmoment.groundtruth import brute_force
from critmoment import sparse as sp
twin = cm.Twin(cm.load_scenario(sys.argv[1])); traj = load_trajectory(sys.argv[2])
n = int(sys.argv[3]) if len(sys.argv) > 3 else 64; seed = int(sys.argv[4]) if len(sys.argv) > 4 else 0
x = sp.sweep_samples(twin.scenario.box, n=n, seed=seed)
bf = brute_force(traj, twin=twin, samples=x, nthread=1)
c = bf.classification; ref = bf.reference.frames
dt = float(twin.model.opt.timestep)
release = int(np.flatnonzero(ref.contact_gripper.any(axis=1))[-1])
early = [i for i in range(n) if str(c.outcome[i].value) == "success" and 0 <= c.drop_step[i] < release - int(0.2 / dt)]
print(sys.argv[2], "nominal last grip contact t=%.2f s;" % (release * dt), "successes", sum(str(o.value) == "success" for o in c.outcome),
      "of which object lost >0.2 s before the nominal release:", len(early))
for i in early:
    print("   #%d %s lost at t=%.2f s, max_slip %.1f mm" % (i, np.round(x[i], 3).tolist(), c.drop_step[i] * dt, 1e3 * c.max_slip[i]))
