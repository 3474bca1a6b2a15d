"""Plain-MuJoCo replay of a probe trajectory (no critmoment decision): joint targets -> the arm
actuators' ctrl, the normalised grip channel -> ctrl = closed + g (open - closed), linear interpolation
between the 50 Hz rows. Prints the cube's max rise, its final distance to the goal site, gripper contact
at the end, final speed. usage: plain_check.py SCENE.xml TRAJ.npz CLOSED OPEN [--mass M] [--friction MU]"""
import argparse
import mujoco
import numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r38/robots/src"), critmoment.__file__

ap = argparse.ArgumentParser()
ap.add_argument("scene"); ap.add_argument("traj"); ap.add_argument("closed", type=float); ap.add_argument("open", type=float)
ap.add_argument("--mass", type=float); ap.add_argument("--friction", type=float)
ap.add_argument("--gripper-body", default=None)
a = ap.parse_args()
m = mujoco.MjModel.from_xml_path(a.scene); d = mujoco.MjData(m)
cb = m.body("cube").id; cg = m.geom("cube").id
if a.mass:
    s = a.mass / m.body_mass[cb]; m.body_mass[cb] *= s; m.body_inertia[cb] *= s
    d0 = mujoco.MjData(m); mujoco.mj_setConst(m, d0)  # invweight for the new mass
if a.friction:
    m.geom_friction[cg, 0] = a.friction; m.geom_priority[cg] = 10
t = np.load(a.traj, allow_pickle=True)
act = t["actions"]; fps = float(t["fps"])
(mujoco.mj_resetDataKeyframe(m, d, 0) if m.nkey else mujoco.mj_resetData(m, d))
d.qpos[:] = t["qpos0"]; mujoco.mj_forward(m, d)
n_arm = act.shape[1] - 1
def ctrl_at(row):   # probe_r38: every actuator after the arm's is the gripper's (Google Robot: two fingers)
    c = np.zeros(m.nu); c[:n_arm] = row[:n_arm]; c[n_arm:] = a.closed + row[n_arm] * (a.open - a.closed); return c
steps_per = int(round(1 / fps / m.opt.timestep))
z0 = d.xpos[cb][2]; zmax = z0
gb = m.body(a.gripper_body).id if a.gripper_body else None
def in_grip(b):
    while b:
        if b == gb: return True
        b = m.body_parentid[b]
    return False
touch_end = 0
N = len(act) * steps_per
for k in range(N):
    i = k // steps_per; f = (k % steps_per) / steps_per
    r = act[min(i, len(act) - 1)] * (1 - f) + act[min(i + 1, len(act) - 1)] * f
    d.ctrl[:] = ctrl_at(r)
    mujoco.mj_step(m, d)
    zmax = max(zmax, d.xpos[cb][2])
    if k > N - 25 and gb is not None:
        for c in d.contact[:d.ncon]:
            g1, g2 = c.geom1, c.geom2
            if cg in (g1, g2) and in_grip(m.geom_bodyid[g2 if g1 == cg else g1]):
                touch_end += 1; break
goal = d.site_xpos[m.site("goal").id]
dist = np.linalg.norm(d.xpos[cb] - goal)
v = np.linalg.norm(d.qvel[m.jnt_dofadr[m.joint("cube_joint").id]:][:3])
print(f"rise {zmax - z0:.4f} m, final dist to goal {dist:.4f} m, final pos {np.round(d.xpos[cb], 4)}, speed {v:.4f}, gripper-touch steps in last 25: {touch_end}")
