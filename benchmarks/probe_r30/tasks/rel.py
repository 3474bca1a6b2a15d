import sys, numpy as np, mujoco, critmoment as cm
from critmoment.trajectory import load_trajectory
from critmoment.recording import prepare_controls
twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2]); ts = [float(x) for x in sys.argv[3:]]
m = twin.model; data = twin.initial_data(start=traj.start, qpos0=traj.qpos0, object_pose=traj.object_pose)
ctrl = prepare_controls(twin, traj); bid = m.body(twin.scenario.object_body).id
sr = m.site("right/tcp").id; sl = m.site("left/tcp").id
for i in range(len(ctrl)):
    data.ctrl[:] = ctrl[i]; mujoco.mj_step(m, data)
    if any(abs(data.time - t) < 1e-4 for t in ts):
        Rr = data.site_xmat[sr].reshape(3, 3)
        rel = Rr.T @ (data.xpos[bid] - data.site_xpos[sr])
        Rrel = Rr.T @ data.xmat[bid].reshape(3, 3)
        print(f"t={data.time:.2f} cube_in_right_tcp={np.round(rel*1000,1)} mm  rel_rot_deg={np.round(np.degrees(np.arccos(np.clip((np.trace(Rrel)-1)/2,-1,1))),1)} left_tcp={np.round(data.site_xpos[sl],3)} cube={np.round(data.xpos[bid],3)}")
