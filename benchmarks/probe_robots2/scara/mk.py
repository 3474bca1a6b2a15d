"""SCARA: analytic 2-link IK for (j1, j2), the quill d3 for height, j4 keeps the fingers' yaw."""
import sys; from pathlib import Path; sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import numpy as np, mujoco
from common2 import segments, run_plain
xml = sys.argv[1] if len(sys.argv) > 1 else 'scene.xml'
out = sys.argv[2] if len(sys.argv) > 2 else 'traj.npz'
yaw = float(sys.argv[3]) if len(sys.argv) > 3 else 0.0
m = mujoco.MjModel.from_xml_path(xml)
L1, L2 = 0.3, 0.25
def ik(x, y, wrist_z, elbow=1):
    r2 = x * x + y * y
    c2 = (r2 - L1 * L1 - L2 * L2) / (2 * L1 * L2)
    q2 = elbow * np.arccos(np.clip(c2, -1, 1))
    q1 = np.arctan2(y, x) - np.arctan2(L2 * np.sin(q2), L1 + L2 * np.cos(q2))
    d3 = wrist_z - 0.59
    return np.array([q1, q2, d3, yaw - q1 - q2])
obj = np.array([0.4, -0.1]); goal = np.array([0.15, 0.35])
G = lambda q, g: np.concatenate([q, [g]])
pre, grasp, lift = ik(*obj, 0.53), ik(*obj, 0.47), ik(*obj, 0.59)
carry, place, back = ik(*goal, 0.59), ik(*goal, 0.572), ik(*goal, 0.59)
home = pre + np.array([0.2, -0.2, 0, 0])
W = [(0, G(home, 1)), (1.2, G(pre, 1)), (0.8, G(grasp, 1)), (0.3, G(grasp, 1)), (0.6, G(grasp, 0)),
     (0.3, G(grasp, 0)), (1.0, G(lift, 0)), (1.5, G(carry, 0)), (0.8, G(place, 0)), (0.3, G(place, 0)),
     (0.5, G(place, 1)), (0.6, G(back, 1)), (0.5, G(back, 1))]
rows = segments(W, 50)
def ctrl(d, r):
    d.ctrl[:4] = r[:4]; d.ctrl[4:6] = 0.04 * r[4]
def init(m, d):
    d.qpos[:4] = rows[0, :4]; d.qpos[4:6] = 0.04
xs, d = run_plain(m, ctrl, rows, 50, 'egg', qinit=init)
print('max z', xs[:, 2].max(), 'final', xs[-1], 'dist goal', np.linalg.norm(xs[-1] - [*goal, 0.52]))
np.savez(out, actions=rows, fps=50.0)
