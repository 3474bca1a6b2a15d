import sys, numpy as np, mujoco, critmoment as cm
from critmoment.trajectory import load_trajectory
from critmoment.recording import prepare_controls
twin = cm.Twin(sys.argv[1]); m = twin.model
def run(f, t):
    traj = load_trajectory(f); data = twin.initial_data(start=traj.start, object_pose=traj.object_pose)
    ctrl = prepare_controls(twin, traj)
    for i in range(int(round(t / m.opt.timestep))):
        data.ctrl[:] = ctrl[i]; mujoco.mj_step(m, data)
    names = [m.joint(j).name for j in range(m.njnt) if m.joint(j).name.startswith("right") or m.joint(j).name.startswith("left")]
    return {n: data.qpos[m.jnt_qposadr[m.joint(n).id]] for n in names}
a = run(sys.argv[2], float(sys.argv[3])); b = run(sys.argv[4], float(sys.argv[5]))
for n in a: print(f"{n:28s} {a[n]: .4f} {b[n]: .4f} {a[n]-b[n]: .4f}")
