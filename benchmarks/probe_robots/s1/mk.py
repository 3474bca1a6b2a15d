import sys; from pathlib import Path; sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import numpy as np, mujoco
from common import *
m = mujoco.MjModel.from_xml_path('scene.xml')
J = ['yaw', 'shoulder', 'elbow', 'wrist']
obj = np.array([0.3, 0, 0.415]); goal = np.array([0.25, 0.2, 0.415])
seed = np.zeros(m.nq); seed[1:4] = [0.5, 1.5, 1.1]; seed[6:9] = obj; seed[9] = 1
qs, errs = plan(m, 'grip', J, obj, goal, seed)
print('ik errs', np.round(errs, 4)); print({k: np.round(v, 3) for k, v in qs.items()})
home = qs['pre'] + np.array([0, -0.3, 0, 0])
rows = segments(waypoints(qs, home), 50)
def arm(d, q): d.ctrl[:4] = 2 * q
def grip(d, g): d.ctrl[4] = -80 * (1 - g)
def init(m, d):
    d.qpos[:4] = rows[0, :4]
xs, d = run_plain(m, arm, grip, rows, 50, 'cube', qinit=init)
print('max z', xs[:, 2].max(), 'final', xs[-1], 'dist goal', np.linalg.norm(xs[-1] - goal))
np.savez('traj.npz', actions=rows, fps=50.0)
