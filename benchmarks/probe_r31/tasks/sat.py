import sys, numpy as np, mujoco, critmoment as cm
from critmoment.trajectory import load_trajectory
from critmoment.recording import prepare_controls
twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2]); mass, fr = float(sys.argv[3]), float(sys.argv[4])
m = twin.model; act = m.actuator(sys.argv[5]).id
m2 = m.__copy__(); b = m2.body(twin.scenario.object_body).id
s = mass / m2.body_mass[b]; m2.body_mass[b] = mass; m2.body_inertia[b] *= s
for g in range(m2.ngeom):
    if m2.geom_bodyid[g] == b: m2.geom_friction[g, 0] = fr
data = twin.initial_data(start=traj.start, qpos0=traj.qpos0, object_pose=traj.object_pose, model=m2)
ctrl = prepare_controls(twin, traj)
lim = m2.actuator_forcerange[act, 1]
t0, t1 = float(sys.argv[6]), float(sys.argv[7])
run = 0; frac = []
for i in range(len(ctrl)):
    data.ctrl[:] = ctrl[i]; mujoco.mj_step(m2, data)
    if t0 <= data.time <= t1:
        f = abs(data.actuator_force[act]) / lim; frac.append((round(data.time, 3), round(f, 4)))
fr_ = np.array([x[1] for x in frac])
print("limit", lim, "steps >=0.999:", int((fr_ >= 0.999).sum()), "steps >= 1/1.05:", int((fr_ >= 1/1.05).sum()), "of", len(fr_))
# longest runs
def longest(mask):
    best = cur = 0
    for v in mask:
        cur = cur + 1 if v else 0; best = max(best, cur)
    return best
print("longest run >=0.999:", longest(fr_ >= 0.999), "steps; longest run >= 1/1.05:", longest(fr_ >= 1/1.05), "steps (2 ms each)")
