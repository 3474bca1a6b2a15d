"""Where Twin.letting_go marks the nominal hold, and the longest stretch where slip counts:
python lg_runs.py SCEN TRAJ"""
import sys, numpy as np, critmoment as cm
from critmoment.trajectory import load_trajectory
from critmoment.groundtruth import brute_force, OutcomeCriteria
twin = cm.Twin(cm.load_scenario(sys.argv[1])); traj = load_trajectory(sys.argv[2])
bf = brute_force(traj, twin=twin, samples=np.array([twin.scenario.box.nominal]), nthread=1)
ref = bf.reference.frames
from critmoment.recording import prepare_controls
try:
    ctrl = prepare_controls(twin, traj)
except Exception as e:
    ctrl = None; print("prepare_controls", e)
held = ref.held
lg = twin.letting_go(ctrl, ref.contact_gripper)
dt = float(twin.model.opt.timestep)
for g in range(held.shape[1]):
    h = held[:, g]; c = h & ~lg[:, g]
    def runs(x):
        e = np.flatnonzero(np.diff(np.concatenate([[0], x.astype(int), [0]])))
        return list(zip(e[::2], e[1::2]))
    r = runs(c)
    print("gripper", g, "held %.2f s" % (h.sum() * dt), "letting_go within hold %.2f s" % ((h & lg[:, g]).sum() * dt),
          "counted stretches", len(r), "longest %.0f ms" % (1e3 * dt * max([b - a for a, b in r] or [0])),
          "counted stretches >= 50 ms after first letting_go:",
          sum(1 for a, b in r if (b - a) * dt >= 0.05 and lg[:a, g].any()))
print("criteria", OutcomeCriteria())
