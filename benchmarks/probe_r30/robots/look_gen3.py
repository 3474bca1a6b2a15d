"""Plain-MuJoCo replay of a Gen3 + 2F-85 trajectory: cube position, gripper command, contacts,
max arm tracking error every 0.4 s. usage: look_gen3.py SCENE.xml TRAJ.npz [mass friction]"""
import sys
import mujoco
import numpy as np

m = mujoco.MjModel.from_xml_path(sys.argv[1])
t = np.load(sys.argv[2], allow_pickle=True)
A = t["actions"]; fps = float(t["fps"])
cb = m.body("cube").id; cg = m.geom("cube_geom").id
if len(sys.argv) > 3:
    m.body_mass[cb] = float(sys.argv[3]); m.geom_friction[cg, 0] = float(sys.argv[4]); m.geom_priority[cg] = 10
d = mujoco.MjData(m); d.qpos[:] = t["qpos0"]; mujoco.mj_forward(m, d)
n = int(round(1 / fps / m.opt.timestep))
for k in range(len(A)):
    d.ctrl[:7] = A[k, :7]; d.ctrl[7] = 255 * (1 - A[k, 7])
    err = 0
    for _ in range(n):
        mujoco.mj_step(m, d)
    err = np.abs(d.qpos[:7] - A[k, :7]).max()
    if k % 20 == 0:
        nc = sum(1 for c in d.contact[:d.ncon] if cb in (m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]))
        x = d.xpos[cb]
        print(f"t={k/fps:5.2f} g={A[k,7]:.2f} cube=({x[0]:+.3f},{x[1]:+.3f},{x[2]:+.3f}) ncon={nc} armerr={err:.3f} frc={np.round(d.actuator_force[:4],0)}")
