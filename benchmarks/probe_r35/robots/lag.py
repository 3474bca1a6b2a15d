"""The Allegro fingers' lag behind their closing command (plain MuJoCo, nominal run; probe_r35)."""
import sys, mujoco, numpy as np, tomllib
import critmoment; assert critmoment.__file__.startswith("/tmp/r35/src"), critmoment.__file__
from critmoment.trajectory import load_trajectory
scene, traj, toml = sys.argv[1:4]
tr = load_trajectory(traj); t = tomllib.load(open(toml, 'rb'))
m = mujoco.MjModel.from_xml_path(scene); d = mujoco.MjData(m)
GRIP = t['actions']['channel'][2]['actuators']; C = np.array(t['actions']['channel'][2]['closed']); O = np.array(t['actions']['channel'][2]['open'])
ids = [m.actuator(x).id for x in GRIP]; jq = [m.jnt_qposadr[m.actuator_trnid[i, 0]] for i in ids]
steps = int(round(1 / tr.fps / m.opt.timestep)); k = 0
for a in tr.actions:
    for j, nm in ((0, "lift"), (1, "ffa0"), (3, "mfa0"), (4, "rfa0"), (5, "tha1")):
        d.ctrl[m.actuator(nm).id] = a[j]
    d.ctrl[ids] = C + a[2] * (O - C)
    for _ in range(steps):
        mujoco.mj_step(m, d); k += 1
        if k in (1300, 1422, 1444, 1500, 1550, 1600, 1700, 1800, 2000):
            lagv = d.ctrl[ids] - d.qpos[jq]
            print(k, "command g", round(float(a[2]), 4), "max finger lag [rad]", round(float(np.abs(lagv).max()), 3), GRIP[int(np.abs(lagv).argmax())], "ball z", round(float(d.body('ball').xpos[2]), 4))
