"""full rollout at (mass, friction): per arm actuator, longest run at >= 0.999 of its limit and >= 1/1.05, in [t0, t1].
usage: sat_all.py SCENARIO TRAJ mass friction t0 t1"""
import sys, numpy as np, mujoco, critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src")
from critmoment.trajectory import load_trajectory
from critmoment.recording import prepare_controls
twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2]); mass, fr = float(sys.argv[3]), float(sys.argv[4])
m2 = twin.model.__copy__(); b = m2.body(twin.scenario.object_body).id
s = mass / m2.body_mass[b]; m2.body_mass[b] = mass; m2.body_inertia[b] *= s
for g in range(m2.ngeom):
    if m2.geom_bodyid[g] == b: m2.geom_friction[g, 0] = fr
data = twin.initial_data(start=traj.start, qpos0=traj.qpos0, object_pose=traj.object_pose, model=m2)
ctrl = prepare_controls(twin, traj); t0, t1 = float(sys.argv[5]), float(sys.argv[6])
F = []; T = []
for i in range(len(ctrl)):
    data.ctrl[:] = ctrl[i]; mujoco.mj_step(m2, data)
    if t0 <= data.time <= t1: F.append(np.abs(data.actuator_force) / np.maximum(m2.actuator_forcerange[:, 1], 1e-9)); T.append(data.time)
F = np.array(F)
def longest(mask):
    best = cur = 0; st = -1; bs = -1
    for k, v in enumerate(mask):
        cur = cur + 1 if v else 0
        if cur > best: best = cur; bs = k - cur + 1
    return best, bs
for a in range(m2.nu):
    l1, s1 = longest(F[:, a] >= 0.999); l2, s2 = longest(F[:, a] >= 1 / 1.05)
    if l2: print(m2.actuator(a).name, "max frac", round(F[:, a].max(), 4), "longest >=0.999:", l1, "steps from t", round(T[s1], 3) if l1 else None, "; >=1/1.05:", l2, "steps from t", round(T[s2], 3))
