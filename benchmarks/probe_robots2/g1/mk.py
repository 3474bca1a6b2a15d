"""Gantry + suction: joint targets are the carriage positions directly (no IK)."""
import sys; from pathlib import Path; sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import numpy as np, mujoco
from common2 import segments, run_plain
xml = sys.argv[1] if len(sys.argv) > 1 else 'scene.xml'
out = sys.argv[2] if len(sys.argv) > 2 else 'traj.npz'
m = mujoco.MjModel.from_xml_path(xml)
# tcp z = 0.9 - 0.04 - 0.05 - 0.1 - 0.01 - 0.012 + z = 0.688 + z; part top at 0.43
ztop = 0.43 - 0.688
obj = [0.3, 0.3]; goal = [0.8, 0.6]
W = [(0, [0.3, 0.3, -0.1, 0.0, 1]),
     (1.0, [obj[0], obj[1], ztop + 0.05, 0.0, 1]),
     (0.8, [obj[0], obj[1], ztop - 0.002, 0.0, 1]),
     (0.4, [obj[0], obj[1], ztop - 0.002, 0.0, 0]),
     (0.2, [obj[0], obj[1], ztop - 0.002, 0.0, 0]),
     (0.8, [obj[0], obj[1], ztop + 0.12, 0.0, 0]),
     (1.5, [goal[0], goal[1], ztop + 0.12, 0.8, 0]),
     (0.8, [goal[0], goal[1], ztop + 0.005, 0.8, 0]),
     (0.3, [goal[0], goal[1], ztop + 0.005, 0.8, 1]),
     (0.6, [goal[0], goal[1], ztop + 0.1, 0.8, 1]),
     (0.5, [goal[0], goal[1], ztop + 0.1, 0.8, 1])]
rows = segments(W, 50)
def ctrl(d, r):
    d.ctrl[:4] = r[:4]; d.ctrl[4] = 1 - r[4]
def init(m, d):
    d.qpos[:4] = rows[0, :4]
xs, d = run_plain(m, ctrl, rows, 50, 'part', qinit=init)
print('max z', xs[:, 2].max(), 'final', xs[-1], 'dist goal xy', np.linalg.norm(xs[-1, :2] - goal))
np.savez(out, actions=rows, fps=50.0)
