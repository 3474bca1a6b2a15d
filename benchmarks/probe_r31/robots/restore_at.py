"""What sparse evaluation does, by hand: critmoment's nominal rollout, its state at STEP restored into
a copy of the twin's model with the sample's (mass, friction) written by the twin, then the recorded
controls stepped for N steps; prints object height, gripper contact count and the twin's grasp FOS.
Compared with the same sample's own full run (from t=0) at the same steps.
usage: restore_at.py SCEN TRAJ STEP MASS FRICTION [N]"""
import sys
import mujoco
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src")
from critmoment.trajectory import load_trajectory
scen, trajp, step, mass, fric = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
N = int(sys.argv[6]) if len(sys.argv) > 6 else 40
twin = cm.Twin(scen); traj = load_trajectory(trajp)
rec = cm.rollout(traj, twin=twin)
m = twin.copy_model()
twin.write_parameters(m, np.array([[mass, fric]]))
d = mujoco.MjData(m)
twin.set_state(m, d, np.asarray(rec.states)[step])
mujoco.mj_forward(m, d)
ctrl = np.asarray(rec.controls)
ob = twin.object_body_id
def ncon(d):
    return sum(1 for c in d.contact[:d.ncon] if ob in (m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2])
               and m.body_rootid[m.geom_bodyid[c.geom2 if m.geom_bodyid[c.geom1] == ob else c.geom1]] != 0)
print("restored at step", step, "z", round(d.xpos[ob][2], 4), "gripper contacts", ncon(d))
for k in range(N):
    d.ctrl[:] = ctrl[step + k]
    mujoco.mj_step(m, d)
    if k % 4 == 0 or k == N - 1:
        sig = twin.signals(np.asarray(d.sensordata)[None, :twin.nsensordata], mu=fric)
        print(f"  +{k+1:3d} z={d.xpos[ob][2]:.4f} vz={d.qvel[twin.object_qposadr - 0 if False else 0]:.3f} grip_contacts={ncon(d)} fos={float(np.ravel(sig.fos_contact)[0]):.3f}")
