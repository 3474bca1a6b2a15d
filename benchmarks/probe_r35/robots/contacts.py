"""Contacts and finger geometry at a step of the OMX nominal (plain MuJoCo; probe_r35)."""
import sys, mujoco, numpy as np
from critmoment.trajectory import load_trajectory
import critmoment; assert critmoment.__file__.startswith("/tmp/r35/src"), critmoment.__file__
scene, traj, stop = sys.argv[1], sys.argv[2], int(sys.argv[3])
tr = load_trajectory(traj); m = mujoco.MjModel.from_xml_path(scene); d = mujoco.MjData(m)
mujoco.mj_resetDataKeyframe(m, d, m.key("home").id)
for i in range(stop):
    d.ctrl[:4] = tr.actions[i, :4]; d.ctrl[4] = -0.01 + tr.actions[i, 4] * 0.029
    for _ in range(10): mujoco.mj_step(m, d)
for c in d.contact[:d.ncon]:
    print("contact", m.body(m.geom_bodyid[c.geom1]).name, m.body(m.geom_bodyid[c.geom2]).name, c.pos.round(4), round(c.dist, 4))
for b in ("gripper_left", "gripper_right"):
    g = np.flatnonzero((m.geom_bodyid == m.body(b).id) & (m.geom_contype > 0))[0]
    mid = m.geom_dataid[g]; va = m.mesh_vertadr[mid]; vn = m.mesh_vertnum[mid]
    v = m.mesh_vert[va:va + vn] @ d.geom_xmat[g].reshape(3, 3).T + d.geom_xpos[g]
    print(b, "world min", v.min(0).round(4), "max", v.max(0).round(4))
