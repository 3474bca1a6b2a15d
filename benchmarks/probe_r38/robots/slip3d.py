"""probe_r38: plain-MuJoCo replay (linear interpolation of the 50 Hz rows, every actuator after the arm's = the
gripper's normalised channel) at one (mass, friction) with the friction written on the cube (priority 10): prints
the cube's displacement in the gripper body's frame (3-D and per axis) from the formed grasp (t_grasp) through
the carry (until t_release), its max rise, and the final distance to the goal.
usage: slip3d.py SCENE TRAJ CLOSED OPEN GRIPPER_BODY T_GRASP T_RELEASE [--mass M] [--friction MU]"""
import argparse, mujoco, numpy as np
import critmoment; assert critmoment.__file__.startswith("/tmp/r38/robots/src")
ap = argparse.ArgumentParser()
for n in ("scene", "traj"): ap.add_argument(n)
for n in ("closed", "open"): ap.add_argument(n, type=float)
ap.add_argument("body"); ap.add_argument("tg", type=float); ap.add_argument("tr", type=float)
ap.add_argument("--mass", type=float); ap.add_argument("--friction", type=float)
a = ap.parse_args()
m = mujoco.MjModel.from_xml_path(a.scene); d = mujoco.MjData(m)
cb = m.body("cube").id; cg = m.geom("cube").id; gb = m.body(a.body).id
if a.mass:
    s = a.mass / m.body_mass[cb]; m.body_mass[cb] *= s; m.body_inertia[cb] *= s
    mujoco.mj_setConst(m, mujoco.MjData(m))
if a.friction:
    m.geom_friction[cg, 0] = a.friction; m.geom_priority[cg] = 10
t = np.load(a.traj, allow_pickle=True); act = t["actions"]; fps = float(t["fps"])
(mujoco.mj_resetDataKeyframe(m, d, 0) if m.nkey else mujoco.mj_resetData(m, d))
d.qpos[:] = t["qpos0"]; mujoco.mj_forward(m, d)
n_arm = act.shape[1] - 1; spr = int(round(1 / fps / m.opt.timestep)); N = len(act) * spr
z0 = d.xpos[cb][2]; zmax = z0; ref = None; dmax = np.zeros(3); dn = 0; Rref = None; amax = 0.0; amax_t = None
for k in range(N):
    i = k // spr; f = (k % spr) / spr
    r = act[min(i, len(act) - 1)] * (1 - f) + act[min(i + 1, len(act) - 1)] * f
    d.ctrl[:n_arm] = r[:n_arm]; d.ctrl[n_arm:] = a.closed + r[n_arm] * (a.open - a.closed)
    mujoco.mj_step(m, d); zmax = max(zmax, d.xpos[cb][2])
    R = d.xmat[gb].reshape(3, 3); rel = R.T @ (d.xpos[cb] - d.xpos[gb])
    if a.tg <= d.time <= a.tr:
        Rrel = R.T @ d.xmat[cb].reshape(3, 3)
        if ref is None: ref = rel.copy(); Rref = Rrel.copy()
        ang = np.arccos(np.clip((np.trace(Rref.T @ Rrel) - 1) / 2, -1, 1))
        if ang > amax: amax = ang; amax_t = d.time
        dd = rel - ref
        if np.linalg.norm(dd) > dn: dn = np.linalg.norm(dd); dmax = dd
goal = d.site_xpos[m.site("goal").id]
print(f"max turn in the grip {np.degrees(amax):.1f} deg (t = {amax_t}); max rise {1000*(zmax-z0):.1f} mm; max displacement in the grip {1000*dn:.2f} mm (gripper-frame xyz {np.round(1000*dmax,2)} mm); final goal dist {1000*np.linalg.norm(d.xpos[cb]-goal):.1f} mm")
