"""print the object's position/tilt and gripper contacts along the nominal rollout.
usage: objpath.py SCENARIO TRAJ [every_s]"""
import sys
import numpy as np, mujoco
import critmoment as cm
from critmoment.trajectory import load_trajectory
from critmoment.recording import prepare_controls
twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2]); every = float(sys.argv[3]) if len(sys.argv) > 3 else 0.5
m = twin.model
data = twin.initial_data(start=traj.start, qpos0=traj.qpos0, object_pose=traj.object_pose)
ctrl = prepare_controls(twin, traj)
bid = m.body(twin.scenario.object_body).id
k = int(round(every / m.opt.timestep))
for i in range(len(ctrl)):
    data.ctrl[:] = ctrl[i]; mujoco.mj_step(m, data)
    if i % k == 0 or i == len(ctrl) - 1:
        R = data.xmat[bid].reshape(3, 3)
        tilt = np.degrees(np.arccos(np.clip(R[2, 2], -1, 1))); yaw = np.degrees(np.arctan2(R[1, 0], R[0, 0]))
        touch = set()
        for c in data.contact[:data.ncon]:
            b1, b2 = m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]
            if bid in (b1, b2):
                o = b2 if b1 == bid else b1
                touch.add(m.body(o).name)
        print(f"t={data.time:5.2f} pos={np.round(data.xpos[bid],3)} tilt={tilt:5.1f} yaw={yaw:6.1f} touch={sorted(touch)}")
