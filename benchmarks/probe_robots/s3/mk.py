import sys; from pathlib import Path; sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import numpy as np, mujoco
from common import *
xml = sys.argv[1] if len(sys.argv) > 1 else 'scene.xml'
m = mujoco.MjModel.from_xml_path(xml)
J = ['j1', 'j2', 'j3', 'j4', 'j5']
obj = np.array([0.35, 0.05, 0.725]); goal = obj
seed = np.zeros(m.nq); seed[1:4] = [0.5, 1.5, 1.1]
qs, errs = plan(m, 'tcp', J, obj, goal, seed, hold_only=True)
print('ik errs', np.round(errs, 4))
home = qs['pre'] + np.array([0, -0.3, 0, 0, 0])
rows = segments(waypoints(qs, home, hold_only=True), 50)
kp = np.array([101.8, 533.6, 181.2, 101.4, 99.23]); kv = np.array([6.483, 33.97, 11.53, 6.454, 6.317])
lim = np.array([87, 87, 50, 12, 12])
def arm(d, q):
    global tgt; tgt = q
def grip(d, g): d.ctrl[5:7] = 0.04 * g
def init(m, d):
    d.qpos[:5] = rows[0, :5]; d.qpos[5:7] = 0.04; d.act[:] = 0.04
import mujoco as mj
d = mj.MjData(m); init(m, d); mj.mj_forward(m, d)
nsub = int(round(0.02 / m.opt.timestep)); bid = m.body('ball').id; xs = []; lag = 0
for r in rows:
    grip(d, r[-1])
    for _ in range(nsub):
        q = d.qpos[:5]; qd = d.qvel[:5]
        d.ctrl[:5] = np.clip(kp * (r[:5] - q) - kv * qd, -lim, lim)
        mj.mj_step(m, d); lag = max(lag, np.abs(r[:5] - d.qpos[:5]).max())
    xs.append(d.xpos[bid].copy())
xs = np.array(xs)
print('max z', xs[:, 2].max(), 'final', xs[-1], 'max lag (incl. step target)', lag)
np.savez('traj.npz', actions=rows, fps=50.0)
