"""Plain-MuJoCo replay of a Z1 trajectory (scene XML, traj.npz): cube position, jaw angle and
jaw command, pad contacts every 0.2 s. usage: look_z1.py SCENE.xml TRAJ.npz [mass friction]"""
import sys
import mujoco
import numpy as np

scene, traj = sys.argv[1:3]
m = mujoco.MjModel.from_xml_path(scene)
t = np.load(traj, allow_pickle=True)
A = t["actions"]; fps = float(t["fps"])
if len(sys.argv) > 3:
    m.body_mass[m.body("cube").id] *= float(sys.argv[3]) / m.body_mass[m.body("cube").id]
    m.geom_friction[m.geom("cube_geom").id, 0] = float(sys.argv[4]); m.geom_priority[m.geom("cube_geom").id] = 10
d = mujoco.MjData(m)
d.qpos[:] = t["qpos0"]
mujoco.mj_forward(m, d)
n = int(round(1 / fps / m.opt.timestep))
lo, hi = 0.0, -1.51844
for k in range(len(A)):
    u = A[k].copy(); g = u[6]
    d.ctrl[:6] = u[:6]; d.ctrl[6] = lo + g * (hi - lo)
    for _ in range(n):
        mujoco.mj_step(m, d)
    if k % 10 == 0:
        cube = d.body("cube").xpos
        nc = sum(1 for c in d.contact[:d.ncon] if m.geom_bodyid[c.geom1] == m.body("cube").id or m.geom_bodyid[c.geom2] == m.body("cube").id)
        print(f"t={k/fps:5.2f} g={g:.2f} ctrl={d.ctrl[6]:+.3f} q={d.qpos[6]:+.3f} jawF={d.actuator_force[6]:+6.1f} cube=({cube[0]:+.3f},{cube[1]:+.3f},{cube[2]:+.3f}) ncontacts={nc}")
