"""Slip timeline (old rule, all alone frames counted) of one sample: python slip_timeline.py SCEN TRAJ MASS FRIC"""
import sys, numpy as np, critmoment as cm
from critmoment.trajectory import load_trajectory
from critmoment import groundtruth as gt
twin = cm.Twin(cm.load_scenario(sys.argv[1])); traj = load_trajectory(sys.argv[2])
x = np.array([[float(sys.argv[3]), float(sys.argv[4])]])
cap = {}
orig = gt.grip_slip
def spy(*a, **k):
    r = orig(*a, **k); cap.setdefault("s", []).append((r, k.get("counted"))); return r
gt.grip_slip = spy
bf = gt.brute_force(traj, twin=twin, samples=x, nthread=1)
c = bf.classification
print("outcome", c.outcome, "completed", c.completed, "max_slip %.1f mm" % (1e3 * c.max_slip[0]), "slip_step", c.slip_step, "drop_step", c.drop_step)
r, counted = cap["s"][-1]
s = r[-1]; dt = float(twin.model.opt.timestep)
for t in range(0, s.size, 100):
    print("t=%.1fs slip %.1f mm counted %s" % (t * dt, 1e3 * s[t], None if counted is None else bool(counted[t].any())), end=" | ")
print()
over = s > 0.01
print("time over 1 cm (counted): %.3f s" % (over.sum() * dt))
# uncounted displacement: rerun with counted=None
cm.Twin.letting_go = lambda self, c, t: np.zeros(np.asarray(t).shape, bool)
cap.clear(); bf2 = gt.brute_force(traj, twin=twin, samples=x, nthread=1)
r2, _ = cap["s"][-1]; s2 = r2[-1]
print("old rule: outcome", bf2.classification.outcome, "max %.1f mm; time over 1 cm %.3f s; longest run over 1 cm %.3f s" % (
    1e3 * s2.max(), (s2 > 0.01).sum() * dt, max([len(g) for g in np.split(np.arange(s2.size), np.flatnonzero(np.diff((s2 > 0.01).astype(int))) + 1) if (s2[g] > 0.01).all()] or [0]) * dt))
