"""Plain-MuJoCo replay of a trajectory (linear interpolation of the 50 Hz actions to the physics
rate, scenario's channel mapping: arm channels = ctrl, gripper channel 0..1 -> 0..0.04 m, base
channels = ctrl) at a given cube mass/friction; prints base pose, cube pose, TCP every 0.5 s.
usage: look.py SCENE.xml TRAJ.npz [--mass M] [--friction MU] [--every S]"""
import argparse, sys
import mujoco, numpy as np
ap = argparse.ArgumentParser(); ap.add_argument("scene"); ap.add_argument("traj")
ap.add_argument("--mass", type=float); ap.add_argument("--friction", type=float); ap.add_argument("--every", type=float, default=0.5)
a = ap.parse_args()
m = mujoco.MjModel.from_xml_path(a.scene); d = mujoco.MjData(m)
z = np.load(a.traj); act = z["actions"]; fps = float(z["fps"]); d.qpos[:] = z["qpos0"]
cb = m.body("cube").id; cg = m.geom("cube_geom").id
if a.mass:
    r = a.mass / m.body_mass[cb]; m.body_mass[cb] = a.mass; m.body_inertia[cb] *= r
if a.friction:
    m.geom_friction[cg, 0] = a.friction; m.geom_priority[cg] = 10
mujoco.mj_setConst(m, d)
names = [m.actuator(i).name for i in range(m.nu)]
def ctrl(row):
    u = np.zeros(m.nu); u[:6] = row[:6]; u[names.index("grip_l")] = u[names.index("grip_r")] = 0.04 * row[6]
    for k, n in enumerate(("bx", "by", "byaw")):
        if n in names: u[names.index(n)] = row[7 + k]
    return u
n = int(round(len(act) / fps / m.opt.timestep)); every = int(a.every / m.opt.timestep)
hand = m.body("hand").id; base = m.body("base").id
for i in range(n):
    t = i * m.opt.timestep; x = min(t * fps, len(act) - 1); k = int(x); f = x - k
    row = act[k] if k + 1 >= len(act) else (1 - f) * act[k] + f * act[k + 1]
    d.ctrl[:] = ctrl(row)
    mujoco.mj_step(m, d)
    if i % every == 0 or i == n - 1:
        tcp = d.xpos[hand] + d.xmat[hand].reshape(3, 3) @ [0.06, 0, 0]
        R = d.xmat[base].reshape(3, 3); tilt = np.degrees(np.arccos(np.clip(R[2, 2], -1, 1)))
        print(f"t={t:5.2f} base={np.round(d.xpos[base], 4)} tilt={tilt:5.2f}deg cube={np.round(d.xpos[cb], 4)} tcp={np.round(tcp, 4)} ncon={d.ncon}")
