"""Nominal run (critmoment rollout) of a scenario: per arm actuator, the longest run of steps at >= 99 % and
>= 99.9 % of its force limit. usage: satruns.py SCEN_DIR CASE.npz"""
import sys, numpy as np, mujoco
import critmoment as cm
assert cm.__file__.startswith("/tmp/r38/tasks/src"), cm.__file__
from critmoment.trajectory import load_trajectory
twin = cm.Twin(sys.argv[1] + "/scenario.toml"); m = twin.model; d = mujoco.MjData(m)
rec = cm.rollout(load_trajectory(sys.argv[2]), twin=twin)
print("completed", rec.summary()["completed"])
F = []
for k in range(len(rec.states) - 1):
    mujoco.mj_setState(m, d, rec.states[k + 1], mujoco.mjtState.mjSTATE_INTEGRATION)
    d.ctrl[:] = rec.controls[k]; mujoco.mj_forward(m, d); F.append(d.actuator_force.copy())
F = np.abs(np.array(F)); dt = m.opt.timestep
def longest(mask):
    best = cur = 0; start = bs = -1
    for i, v in enumerate(mask):
        if v: cur += 1; start = i if cur == 1 else start
        else: cur = 0
        if cur > best: best, bs = cur, start
    return best, bs
for a in range(m.nu):
    lim = m.actuator_forcerange[a, 1]
    for fr in (0.99, 0.999):
        n, s = longest(F[:, a] >= fr * lim)
        if n: print(f"{m.actuator(a).name}: >= {fr} of {lim}: longest {n*dt*1000:.0f} ms from t = {s*dt:.3f} s (max {F[:, a].max()/lim:.4f})")
