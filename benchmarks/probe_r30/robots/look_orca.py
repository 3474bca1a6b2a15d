"""ORCA diagnostics: run the nominal through truth.Setup's controls in plain MuJoCo and print
wrist angle vs target, fingertip positions relative to the ball, ball contacts (by body),
every 0.2 s between t0 and t1. usage: look_orca.py SCENARIO TRAJ [t0 t1]"""
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
import mujoco
import numpy as np
import truth

s = truth.Setup(sys.argv[1], sys.argv[2])
t0, t1 = (float(x) for x in sys.argv[3:5]) if len(sys.argv) > 4 else (2.0, 5.0)
m = s.model if hasattr(s, "model") else None
import tomllib
cfg = tomllib.loads(Path(sys.argv[1]).read_text())
m = mujoco.MjModel.from_xml_path(str(Path(sys.argv[1]).parent / cfg["model"]["mjcf"]))
d = mujoco.MjData(m)
d.qpos[:] = s.ctraj.qpos0
mujoco.mj_forward(m, d)
U = s.controls
ball = m.body("ball").id
wa = m.actuator("h_right_wrist_actuator").id; wq = m.jnt_qposadr[m.joint("h_right_wrist").id]
tips = ["h_right_thumb_dp", "h_right_index_ip", "h_right_middle_ip", "h_right_ring_ip", "h_right_pinky_ip"]
dt = m.opt.timestep
for k in range(len(U)):
    d.ctrl[:] = U[k]
    mujoco.mj_step(m, d)
    t = (k + 1) * dt
    if t0 <= t <= t1 and k % int(round(0.2 / dt)) == 0:
        bp = d.xpos[ball]
        rel = {n[8:12]: np.round(d.xpos[m.body(n).id] - bp, 3).tolist() for n in tips}
        cons = sorted({m.body(m.geom_bodyid[c.geom1 if m.geom_bodyid[c.geom2] == ball else c.geom2]).name
                       for c in d.contact[:d.ncon] if ball in (m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2])})
        print(f"t={t:.2f} wrist q={d.qpos[wq]:+.3f} tgt={U[k][wa]:+.3f} ball={np.round(bp, 3)} cons={cons}\n     tips-ball {rel}")
