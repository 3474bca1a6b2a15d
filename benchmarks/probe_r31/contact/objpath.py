"""Object path of the nominal rollout of a variant: python objpath.py VARIANT_DIR TRAJ"""
import sys, numpy as np, critmoment as cm
from critmoment.trajectory import load_trajectory
assert cm.__file__.startswith("/tmp/r31/src")
twin = cm.Twin(cm.load_scenario(sys.argv[1])); traj = load_trajectory(sys.argv[2])
rec = cm.rollout(traj, twin=twin) if "twin" in cm.rollout.__code__.co_varnames else cm.rollout(traj, twin.scenario)
s = rec.signals; p = np.asarray(s.object_pos); st = np.asarray(s.stage)
dt = rec.dt if hasattr(rec, "dt") else 0.002
v = np.linalg.norm(np.diff(p, axis=0), axis=1) / dt
print("steps", len(p), "max speed", v.max(), "at t", np.argmax(v) * dt, "max z", p[:, 2].max(), "at t", np.argmax(p[:, 2]) * dt)
for k in range(0, len(p), max(1, len(p) // 25)):
    print(f"t={k*dt:6.2f} pos={np.round(p[k],3)} stage={st[k]} speed={v[min(k,len(v)-1)]:.3g}")
