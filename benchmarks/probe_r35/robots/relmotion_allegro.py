"""The ball's position in the palm frame over the nominal run, plain MuJoCo (probe_r35)."""
import sys, mujoco, numpy as np
import critmoment; assert critmoment.__file__.startswith("/tmp/r35/src"), critmoment.__file__
from critmoment.trajectory import load_trajectory
import critmoment as cm
scene, traj, toml = sys.argv[1:4]
sc = cm.load_scenario(toml); tr = load_trajectory(traj)
m = mujoco.MjModel.from_xml_path(scene); d = mujoco.MjData(m)
GRIP = ["ffa1","ffa2","ffa3","mfa1","mfa2","mfa3","rfa1","rfa2","rfa3","tha0","tha2","tha3"]
import tomllib; t = tomllib.load(open(toml, 'rb'))
ch = t['actions']['channel'][2]; C = np.array(ch['closed']); O = np.array(ch['open'])
ids = [m.actuator(x).id for x in GRIP]
steps = int(round(1 / tr.fps / m.opt.timestep)); k = 0
pal = m.body('palm').id; ball = m.body('ball').id
ref = None
for i, a in enumerate(tr.actions):
    for j, nm in ((0, "lift"), (1, "ffa0"), (3, "mfa0"), (4, "rfa0"), (5, "tha1")):
        d.ctrl[m.actuator(nm).id] = a[j]
    d.ctrl[ids] = C + a[2] * (O - C)
    for _ in range(steps):
        mujoco.mj_step(m, d); k += 1
        rel = d.xmat[pal].reshape(3, 3).T @ (d.xpos[ball] - d.xpos[pal])
        if k in (1418, 1450, 1500, 1600, 1800, 2000, 2300, 2500, 3000, 3500):
            ref = rel if ref is None else ref
            print(k, "rel [mm]", (rel * 1e3).round(1), "moved since 1418 [mm]", round(float(np.linalg.norm(rel - ref)) * 1e3, 1))
