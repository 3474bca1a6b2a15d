"""7-DoF arm: damped-least-squares IK on the full tcp pose (jaws closing along world y),
redundancy left to the DLS; scripted pick_place of the item on the tilted ramp to the tray.

    python mk.py [scene.xml] [traj.npz] [pick_hold]
"""
import sys; from pathlib import Path; sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
import numpy as np, mujoco
from common2 import segments, run_plain
xml = sys.argv[1] if len(sys.argv) > 1 else 'scene.xml'
out = sys.argv[2] if len(sys.argv) > 2 else 'traj.npz'
hold = len(sys.argv) > 3 and sys.argv[3] == 'pick_hold'
m = mujoco.MjModel.from_xml_path(xml)
J = [f'j{i}' for i in range(1, 8)]
Rt = np.array([[-1, 0, 0], [0, 1, 0], [0, 0, -1]], float).T  # columns x, y, z of the target frame
def ik(target, q0, iters=600):
    d = mujoco.MjData(m); d.qpos[:7] = q0
    sid = m.site('tcp').id
    for _ in range(iters):
        mujoco.mj_forward(m, d)
        R = d.site_xmat[sid].reshape(3, 3)
        ep = target - d.site_xpos[sid]
        eo = 0.5 * sum(np.cross(R[:, i], Rt[:, i]) for i in range(3))
        jp = np.zeros((3, m.nv)); jr = np.zeros((3, m.nv)); mujoco.mj_jacSite(m, d, jp, jr, sid)
        Jm = np.vstack([jp[:, :7], 0.5 * jr[:, :7]]); e = np.concatenate([ep, 0.5 * eo])
        dq = Jm.T @ np.linalg.solve(Jm @ Jm.T + 1e-4 * np.eye(6), e)
        d.qpos[:7] += 0.5 * dq
        # nullspace pull toward the seed (keeps the elbow up)
        d.qpos[:7] += 0.02 * (np.eye(7) - np.linalg.pinv(Jm) @ Jm) @ (q0 - d.qpos[:7])
    mujoco.mj_forward(m, d)
    return d.qpos[:7].copy(), float(np.linalg.norm(ep)), float(np.linalg.norm(eo))
obj = m.body('item').pos.copy()
goal = np.array([0.2, -0.35, 0.42 + (obj[2] - 0.55) + 0.002])
seed = np.array([0.3, 0.5, 0.0, 1.5, 0.0, 1.1, 0.0])
up = np.array([0, 0, 1.0])
qs = {}
for k, p in [('pre', obj + 0.09 * up), ('grasp', obj + 0.016 * up), ('lift', obj + 0.14 * up),
             ('carry', goal + 0.14 * up), ('place', goal + 0.018 * up), ('retreat', goal + 0.09 * up)]:
    qs[k], ep, eo = ik(p, seed if k in ('pre', 'carry') else qs['pre'] if k in ('grasp', 'lift') else qs['carry'])
    print(k, 'pos err %.4f ori err %.4f' % (ep, eo))
home = qs['pre'] + np.array([0, -0.3, 0, -0.2, 0, 0, 0])
G = lambda q, g: np.concatenate([q, [g]])
W = [(0, G(home, 1)), (1.2, G(qs['pre'], 1)), (1.0, G(qs['grasp'], 1)), (0.3, G(qs['grasp'], 1)),
     (0.6, G(qs['grasp'], 0)), (0.3, G(qs['grasp'], 0)), (1.2, G(qs['lift'], 0))]
if hold:
    W += [(1.0, G(qs['lift'], 0))]
else:
    W += [(1.5, G(qs['carry'], 0)), (1.2, G(qs['place'], 0)), (0.3, G(qs['place'], 0)),
          (0.5, G(qs['place'], 1)), (0.6, G(qs['retreat'], 1)), (0.5, G(qs['retreat'], 1))]
rows = segments(W, 50)
# channel -> ctrl: arm targets in radians; offset scene: ctrl_j2 = (q - 0.3) / 2
offset = 'offset' in xml
def ctrl(d, r):
    d.ctrl[:7] = r[:7]
    if offset:
        d.ctrl[1] = (r[1] - 0.3) / 2
    d.ctrl[7:9] = 0.6 + (-0.1 - 0.6) * r[7]
def init(m, d):
    d.qpos[:7] = rows[0, :7]; d.qpos[7:9] = -0.1
xs, d = run_plain(m, ctrl, rows, 50, 'item', qinit=init)
print('start', obj, 'max z', xs[:, 2].max(), 'final', xs[-1], 'dist goal', np.linalg.norm(xs[-1] - goal))
np.savez(out, actions=rows, fps=50.0)
