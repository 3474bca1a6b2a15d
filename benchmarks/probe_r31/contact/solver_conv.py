"""How often the solver stops at its iteration cap in the nominal run (critmoment's controls, plain mj_step):
python solver_conv.py VARIANT"""
import sys, numpy as np, mujoco, critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src")
from critmoment.trajectory import load_trajectory
from critmoment.recording import prepare_controls
v = sys.argv[1]; vd = f"/tmp/r31/contact/v/{v}"
twin = cm.Twin(cm.load_scenario(vd)); traj = load_trajectory("/tmp/r31/contact/" + ("aloha_s0.npz" if v.startswith("a_") else "panda_s0.npz"))
rec = cm.rollout(traj, twin=twin) if "twin" in cm.rollout.__code__.co_varnames else cm.rollout(traj, twin.scenario)
m = twin.model if hasattr(twin, "model") else None
print("opt iterations", m.opt.iterations, "tolerance", m.opt.tolerance)
d = mujoco.MjData(m)
states = np.asarray(rec.states); ctrls = np.asarray(rec.controls)
spec = mujoco.mjtState.mjSTATE_INTEGRATION
capped = 0; nits = []; improv = []
for k in range(0, len(ctrls)):
    mujoco.mj_setState(m, d, states[k], spec); d.ctrl[:] = ctrls[k]
    mujoco.mj_step(m, d)
    it = int(d.solver_niter[0]); nits.append(it); capped += it >= m.opt.iterations
    if it: improv.append(d.solver[min(it, m.opt.iterations) - 1].improvement)
print("steps", len(ctrls), "capped", capped, "median niter", np.median(nits), "max", max(nits), "median final improvement", np.median(improv) if improv else None)
