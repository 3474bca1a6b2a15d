"""A "magic grasp": the cube welded to the hand (an active <equality weld>) in a chunk audited from
mid-carry, against the same chunk without the weld. Writes /tmp/r37/modelforms/weldhold/.

Run: PYTHONPATH=/tmp/r37/src /work/venv/bin/python make_weld.py [OUT BASE TRAJ]
(BASE: a folder with the bundled Panda scene.xml/panda.xml and init's init.toml; TRAJ: its demo npz)
"""
import sys
import re
import shutil
from pathlib import Path

import mujoco
import numpy as np

import common  # noqa: F401
from critmoment import load_scenario, load_trajectory, rollout
from critmoment.twin import Twin, state_slice

args = sys.argv[1:] or ["/tmp/r37/modelforms/weldhold", "/tmp/r37/modelforms/base", "/tmp/r37/modelforms/panda.npz"]
W = Path(args[0])
shutil.rmtree(W, ignore_errors=True)
W.mkdir(parents=True)
base = Path(args[1])
shutil.copy(base / "panda.xml", W / "panda.xml")
sc = load_scenario(base / "init.toml")
tw = Twin(sc)
traj = load_trajectory(args[2])
rec = rollout(traj, twin=tw)
spp = int(round(1 / (traj.fps * tw.model.opt.timestep)))      # physics steps per action
k = 2400 // spp * spp                                          # t = 4.8 s: carried (stage 2)
q = tw.qpos(rec.states)[k].copy()
qv = rec.states[k, state_slice(tw.model, mujoco.mjtState.mjSTATE_QVEL)].copy()
m = tw.model
d = mujoco.MjData(m)
d.qpos[:] = q
mujoco.mj_forward(m, d)
hb, cb = m.body("hand").id, m.body("cube").id
# the cube's pose in the hand's frame
rel_pos = d.xmat[hb].reshape(3, 3).T @ (d.xpos[cb] - d.xpos[hb])
qinv = np.zeros(4); mujoco.mju_negQuat(qinv, d.xquat[hb])
rel_q = np.zeros(4); mujoco.mju_mulQuat(rel_q, qinv, d.xquat[cb])
a0 = k // spp
np.savez(W / "chunk.npz", actions=traj.actions[a0:370], fps=traj.fps, qpos0=q, qvel0=qv)   # ends while carried
scene = (base / "scene.xml").read_text()
scene = re.sub(r"  <keyframe>.*?</keyframe>\n", "", scene, flags=re.S)
(W / "scene_noweld.xml").write_text(scene)
weld = (f'\n  <equality>\n    <weld name="magic_grasp" body1="hand" body2="cube" relpose="'
        f'{" ".join(f"{v:.6f}" for v in rel_pos)} {" ".join(f"{v:.6f}" for v in rel_q)}"/>\n  </equality>\n')
(W / "scene_weld.xml").write_text(scene.replace("</mujoco>", weld + "</mujoco>"))
print("chunk from action", a0, "stage at k:", "cube z", q[11], "rel", rel_pos, rel_q)
