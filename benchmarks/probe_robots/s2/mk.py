import sys; from pathlib import Path; sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import numpy as np, mujoco
from common import *
xml = sys.argv[1] if len(sys.argv) > 1 else 'scene.xml'
m = mujoco.MjModel.from_xml_path(xml)
J = ['j1', 'j2', 'j3', 'j4', 'j5']
obj = np.array([0.35, 0.05, 0.73]); goal = np.array([0.3, -0.2, 0.73])
seed = np.zeros(m.nq); seed[1:4] = [0.5, 1.5, 1.1]
qs, errs = plan(m, 'tcp', J, obj, goal, seed)
print('ik errs', np.round(errs, 4)); print({k: np.round(v, 3) for k, v in qs.items()})
home = qs['pre'] + np.array([0, -0.3, 0, 0, 0])
rows = segments(waypoints(qs, home), 50)
def arm(d, q): d.ctrl[:5] = q
def grip(d, g): d.ctrl[5] = 0.04 * g
def init(m, d):
    d.qpos[:5] = rows[0, :5]; d.qpos[5:7] = 0.04
xs, d = run_plain(m, arm, grip, rows, 50, 'can', qinit=init)
print('max z', xs[:, 2].max(), 'final', xs[-1], 'dist goal', np.linalg.norm(xs[-1] - goal))
np.savez('traj.npz', actions=rows, fps=50.0)
