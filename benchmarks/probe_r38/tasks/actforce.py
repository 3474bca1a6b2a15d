"""Nominal run (critmoment rollout): per arm actuator, the time at >= 99 % of its force limit, and when.
usage: actforce.py SCEN_DIR CASE.npz"""
import sys, numpy as np, mujoco
import critmoment as cm
assert cm.__file__.startswith("/tmp/r38/tasks/src"), cm.__file__
from critmoment.trajectory import load_trajectory
twin = cm.Twin(sys.argv[1] + "/scenario.toml"); m = twin.model; d = mujoco.MjData(m)
rec = cm.rollout(load_trajectory(sys.argv[2]), twin=twin)
F = []
for k in range(len(rec.states) - 1):
    mujoco.mj_setState(m, d, rec.states[k + 1], mujoco.mjtState.mjSTATE_INTEGRATION)
    d.ctrl[:] = rec.controls[k]; mujoco.mj_forward(m, d); F.append(d.actuator_force.copy())
F = np.array(F); dt = m.opt.timestep
for a in range(m.nu):
    lim = m.actuator_forcerange[a, 1]
    sat = np.abs(F[:, a]) >= 0.99 * lim
    if sat.any():
        i = np.flatnonzero(sat)
        print(f"{m.actuator(a).name}: limit {lim}, {sat.sum()*dt:.3f} s at >=99 %, first {i[0]*dt:.3f} s, last {i[-1]*dt:.3f} s, max |f| {np.abs(F[:,a]).max():.2f}")
