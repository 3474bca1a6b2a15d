"""Object-gripper / object-support contacts over the last N steps of the nominal run, stepped
here with mj_step from the twin's initial data and critmoment's per-step controls.
usage: endcontacts.py SCENARIO TRAJ GRIPPER_BODY [N]"""
import sys
import mujoco
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r34/src"), cm.__file__
from critmoment.trajectory import load_trajectory
from critmoment.recording import prepare_controls

twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2]); gbody = sys.argv[3]
N = int(sys.argv[4]) if len(sys.argv) > 4 else 50
ctrl = np.asarray(prepare_controls(twin, traj)); m = twin.model
d = twin.initial_data(start=traj.start, object_pose=traj.object_pose)
obj = twin.object_body_id
root = m.body(gbody).id
def under(b):
    while b != 0:
        if b == root: return True
        b = m.body_parentid[b]
    return False
rows = []
zs = []
for t in range(len(ctrl)):
    d.ctrl[:] = ctrl[t]; mujoco.mj_step(m, d)
    if t % 250 == 249:
        R = d.xmat[root].reshape(3, 3); rel = R.T @ (d.xpos[obj] - d.xpos[root])
        zs.append((t + 1, round(float(d.xpos[obj][2]), 4), tuple(np.round(rel, 4))))
    if t >= len(ctrl) - N:
        g = s = 0
        for c in d.contact[:d.ncon]:
            b1, b2 = m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]
            if obj in (b1, b2):
                other = b2 if b1 == obj else b1
                if under(other): g += 1
                elif other == 0: s += 1
        rows.append((t, g, s, round(float(d.xpos[obj][2]), 4)))
print("last", N, "steps: (step, object-gripper contacts, object-world contacts, z)")
print(rows[-10:])
print("every 0.5 s (step, object z, object in the gripper body frame):", zs)
print("steps with no gripper contact:", sum(r[1] == 0 for r in rows), "of", N)
