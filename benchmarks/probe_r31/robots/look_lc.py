"""Plain-MuJoCo replay (zero-order hold) of the low-cost-arm trajectory at (mass, friction); prints,
between T0 and T1, every object contact: partner geom, normal force, tangential/(mu*normal).
usage: look_lc.py SCENE.xml TRAJ.npz MASS FRICTION T0 T1"""
import sys
import mujoco
import numpy as np
m = mujoco.MjModel.from_xml_path(sys.argv[1])
t = np.load(sys.argv[2], allow_pickle=True)
A = t["actions"]; fps = float(t["fps"])
cb = m.body("cube").id; cg = m.geom("cube_geom").id
m.body_mass[cb] = float(sys.argv[3]); m.geom_friction[cg, 0] = float(sys.argv[4]); m.geom_priority[cg] = 10
t0, t1 = float(sys.argv[5]), float(sys.argv[6])
d = mujoco.MjData(m); d.qpos[:] = t["qpos0"]; mujoco.mj_forward(m, d)
n = int(round(1 / fps / m.opt.timestep))
f = np.zeros(6)
for k in range(len(A)):
    d.ctrl[:5] = A[k, :5]; d.ctrl[5] = 0.032 + A[k, 5] * (-1.6 - 0.032)
    for i in range(n):
        mujoco.mj_step(m, d)
        tt = d.time
        if t0 <= tt <= t1 and i % 2 == 0:
            rows = []
            for j, c in enumerate(d.contact[:d.ncon]):
                if cb not in (m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]):
                    continue
                other = c.geom2 if m.geom_bodyid[c.geom1] == cb else c.geom1
                mujoco.mj_contactForce(m, d, j, f)
                mu = c.friction[0]
                ratio = np.linalg.norm(f[1:3]) / (mu * f[0]) if f[0] > 1e-9 else np.inf
                rows.append(f"{m.geom(other).name or other}:N={f[0]:.2f},r={ratio:.2f},dist={c.dist*1000:.2f}mm")
            print(f"t={tt:.3f} z={d.xpos[cb][2]:.4f} grip_q={d.qpos[5]:.3f} " + " | ".join(rows))
    if d.time > t1:
        break
