"""Per-joint tracking lag (target - q) of the nominal run, stepped here with mj_step on the
twin's own initial data and critmoment's per-step controls.
usage: lag.py SCENARIO TRAJ [ACTUATOR ...]"""
import sys
import mujoco
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r34/src"), cm.__file__
from critmoment.trajectory import load_trajectory
from critmoment.recording import prepare_controls

scen, trajp = sys.argv[1], sys.argv[2]
twin = cm.Twin(scen)
traj = load_trajectory(trajp)
ctrl = np.asarray(prepare_controls(twin, traj))
m = twin.model
d = twin.initial_data(start=traj.start, object_pose=traj.object_pose)
names = sys.argv[3:] or [m.actuator(i).name for i in range(m.nu)]
T = len(ctrl)
lag = {n: np.zeros(T) for n in names}
for t in range(T):
    d.ctrl[:] = ctrl[t]
    mujoco.mj_step(m, d)
    for n in names:
        a = m.actuator(n).id
        j = m.actuator_trnid[a, 0]
        lag[n][t] = d.ctrl[a] - d.qpos[m.jnt_qposadr[j]]
dt = m.opt.timestep
for n in names:
    x = np.abs(lag[n]); k = int(x.argmax())
    over = np.flatnonzero(x > 0.1)
    print(f"{n:22s} max |lag| {x.max():.3f} at t={k*dt:.3f}s; >0.1 for {len(over)*dt:.3f}s"
          + (f" (first {over[0]*dt:.3f}s last {over[-1]*dt:.3f}s)" if len(over) else ""))
