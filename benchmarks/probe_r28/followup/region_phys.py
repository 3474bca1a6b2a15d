"""Points inside a stated safe region, judged physically: object lost mid-carry (ground truth's drop_step
before T_LOSS s) or max slip (new rule) > 1 cm, though the ground truth says success.
python region_phys.py SCEN TRAJ MASS_LO MASS_HI FRIC_LO FRIC_HI T_LOSS [n]"""
import sys, itertools, numpy as np, critmoment as cm
from critmoment.trajectory import load_trajectory
from critmoment.groundtruth import brute_force
twin = cm.Twin(cm.load_scenario(sys.argv[1])); traj = load_trajectory(sys.argv[2])
mlo, mhi, flo, fhi, tl = map(float, sys.argv[3:8]); n = int(sys.argv[8]) if len(sys.argv) > 8 else 64
grid = np.array(list(itertools.product(np.linspace(mlo, mhi, 5), np.linspace(flo, fhi, 5))))
rnd = np.random.default_rng(0).uniform([mlo, flo], [mhi, fhi], size=(n, 2))
x = np.vstack([grid, rnd])
bf = brute_force(traj, twin=twin, samples=x, nthread=1); c = bf.classification
dt = float(twin.model.opt.timestep)
# the old rule's verdicts too (slip counted in the opening gripper)
orig = cm.Twin.letting_go
cm.Twin.letting_go = lambda self, c_, t: np.zeros(np.asarray(t).shape, bool)
old = brute_force(traj, twin=twin, samples=x, nthread=1).classification
cm.Twin.letting_go = orig
bad = [i for i in range(len(x)) if c.outcome[i].value == "success" and (0 <= c.drop_step[i] * dt < tl)]
print(sys.argv[2], "points", len(x), "gt success", sum(o.value == "success" for o in c.outcome),
      "| success though lost before t=%.1f s:" % tl, len(bad), "| old rule failures:", int(old.failed.sum()))
for i in bad:
    print("   %s lost at %.2f s max_slip %.1f mm; old rule: %s" % (np.round(x[i], 4).tolist(), c.drop_step[i] * dt, 1e3 * c.max_slip[i], old.outcome[i].value))
