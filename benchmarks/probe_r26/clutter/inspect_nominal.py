"""What the nominal run of a variant does with the extra bodies: the object's highest and
final position, each free body's largest displacement, and which geoms ever touch it.

usage: python inspect_nominal.py NAME [mass friction ...]   (parameter values optional)
"""
import os
import sys
import warnings
from pathlib import Path

import mujoco
import numpy as np

import critmoment as cm

warnings.simplefilter("ignore")
OUT = Path(os.environ.get("R26_OUT", "/tmp/r26/clutter"))
name = sys.argv[1]
v = OUT / "v" / name
traj = cm.load_trajectory(str(v / "traj.npz" if (v / "traj.npz").exists() else OUT / "aloha_s0.npz"))
sc = cm.load_scenario(str(v))
twin = cm.Twin(sc)
rec = cm.rollout(traj, sc)
m = twin.model
d = mujoco.MjData(m)
free = [j for j in range(m.njnt) if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
pos = {}
touch = {}
for k in range(0, rec.states.shape[0], 5):
    mujoco.mj_setState(m, d, rec.states[k], mujoco.mjtState.mjSTATE_INTEGRATION)
    mujoco.mj_forward(m, d)
    for j in free:
        pos.setdefault(j, []).append(d.qpos[m.jnt_qposadr[j]:m.jnt_qposadr[j] + 3].copy())
    for c in d.contact[:d.ncon]:
        b1, b2 = m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]
        for b, g in ((b1, c.geom2), (b2, c.geom1)):
            jn = m.body_jntadr[b]
            if jn >= 0 and m.jnt_type[jn] == mujoco.mjtJoint.mjJNT_FREE:
                touch.setdefault(m.body(b).name, set()).add(m.geom(g).name)
print(name, "nominal completed:", rec.summary().get("completed"), "stages first step:", rec.summary().get("stage_first_step"))
for j in free:
    p = np.array(pos[j])
    b = m.body(m.jnt_bodyid[j]).name
    print(f"  {b}: start {p[0].round(3).tolist()} max z {p[:, 2].max():.3f} end {p[-1].round(3).tolist()} "
          f"max displacement {np.linalg.norm(p - p[0], axis=1).max():.3f} m; touched by {sorted(touch.get(b, []))}")
