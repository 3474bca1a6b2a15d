"""Compare critmoment's own run of a sample (recording.simulate) with truth.py's plain-MuJoCo run
and print critmoment's ground-truth classification: python cmp_traj.py VARIANT 'v1,v2'"""
import sys
from pathlib import Path

import mujoco
import numpy as np

import critmoment as cm
import truth
from critmoment import groundtruth as gt
from critmoment.recording import initial_state, prepare_controls, simulate
from critmoment.trajectory import load_trajectory

R = Path("/tmp/r29/physics")
v = sys.argv[1]
vd = R / "v" / v
tp = vd / "traj.npz" if (vd / "traj.npz").exists() else R / ("aloha_s0.npz" if v.startswith("a_") else "panda_s0.npz")
vals = np.array([[float(x) for x in sys.argv[2].split(",")]])  # extra flag: --zero-vel
twin = cm.Twin(cm.load_scenario(str(vd)))
traj = load_trajectory(str(tp))
ctrl = prepare_controls(twin, traj)
s0 = initial_state(twin, traj)
out = simulate(twin, s0, ctrl, samples=vals, record_state=True, nthread=1)
nq = twin.model.nq
qpos_cm = out["state"][0][:, 1:1 + nq]
S = truth.Setup(str(vd), str(tp))
m = S.model
S.apply(vals[0])
d = mujoco.MjData(m)
mujoco.mj_setConst(m, d)
S.initial(d)
if "--zero-vel" in sys.argv:  # truth.py keeps the settle's residual object velocity; critmoment zeroes it
    d.qvel[:] = 0
    mujoco.mj_forward(m, d)
print("initial qpos diff", np.abs(d.qpos - s0[1:1 + nq]).max())
T = ctrl.shape[0]
qpos_t = np.zeros((T, nq))
for t in range(T):
    d.ctrl[:] = S.controls[t]
    mujoco.mj_step(m, d)
    qpos_t[t] = d.qpos
diff = np.abs(qpos_cm - qpos_t).max(axis=1)
first = int(np.argmax(diff > 1e-9)) if (diff > 1e-9).any() else -1
print("max |qpos diff|", diff.max(), "first step > 1e-9:", first, "diff at end", diff[-1])
print("diff growth", {k: float(diff[k]) for k in (0, 1, 10, 100, 500, 1000, 1500, 2000, 3000, T - 1) if k < T})
print("object end cm", qpos_cm[-1, -7:-4].round(4), "truth", qpos_t[-1, -7:-4].round(4))
bf = gt.brute_force(traj, twin=twin, samples=vals, nthread=1)
c = bf.classification
print("critmoment GT", bf.outcome[0].name, "completed", bool(c.completed[0]), "slip_step", int(c.slip_step[0]), "drop_step",
      int(c.drop_step[0]), "max_slip %.2f mm" % (1e3 * float(c.max_slip[0])))
