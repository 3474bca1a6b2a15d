"""Replay a scenario's trajectory in plain MuJoCo through truth.Setup (same controls, servos,
parameter edits and initial state as truth.py) and print, between T0 and T1 [s], every EVERY-th
step: object height, each object contact's partner geom (name or id, its body), normal force,
tangential/(mu N), penetration; and the gripper actuators' ctrl/force.
usage: look_contacts.py SCENARIO TRAJ MASS FRICTION T0 T1 [EVERY]"""
import sys
import mujoco
import numpy as np
sys.path.insert(0, "/work/main/benchmarks/probe_r32/robots")
import truth  # noqa: E402

scen, traj, mass, fr, t0, t1 = sys.argv[1:7]
every = int(sys.argv[7]) if len(sys.argv) > 7 else 25
s = truth.Setup(scen, traj)
s.apply([float(mass), float(fr)])
m = s.model; d = mujoco.MjData(m); mujoco.mj_setConst(m, d); s.initial(d)
ob = s.obj_body; f = np.zeros(6)
for t in range(s.controls.shape[0]):
    d.ctrl[:] = s.controls[t]
    mujoco.mj_step(m, d)
    if float(t0) <= d.time <= float(t1) and t % every == 0:
        rows = []
        for j in range(d.ncon):
            c = d.contact[j]
            if ob not in (m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]):
                continue
            o = c.geom2 if m.geom_bodyid[c.geom1] == ob else c.geom1
            mujoco.mj_contactForce(m, d, j, f)
            r = np.linalg.norm(f[1:3]) / (c.friction[0] * f[0]) if f[0] > 1e-9 else np.inf
            rows.append(f"{m.geom(o).name or o}@{m.body(m.geom_bodyid[o]).name}:N={f[0]:.2f},r={r:.2f},d={c.dist*1e3:.1f}mm")
        hb = s.grippers[list(s.grippers)[0]]["base"]
        rel = d.xmat[hb].reshape(3, 3).T @ (d.xpos[ob] - d.xpos[hb])
        lag = [round(float(d.qpos[m.jnt_qposadr[m.actuator_trnid[a, 0]]] - s.joint_target(a, d.ctrl[a])), 3)
               for a in s.servo_acts] if getattr(s, "servo_acts", None) else []
        print(f"t={d.time:.3f} z={d.xpos[ob][2]:.4f} rel={np.round(rel, 4).tolist()} lag={lag} ctrl_g={np.round(d.ctrl[6:], 3).tolist()} qfing={np.round([d.qpos[m.jnt_qposadr[m.actuator_trnid[a, 0]]] for a in range(6, m.nu)], 4).tolist()} quat={np.round(d.xquat[ob], 3).tolist()} " + " | ".join(rows))
    if d.time > float(t1):
        break
