import sys, numpy as np, mujoco
sys.path.insert(0,'/tmp/r31/src')
import critmoment as cm
from critmoment.trajectory import load_trajectory
from critmoment.recording import prepare_controls
scen, tf = sys.argv[1], sys.argv[2]
tw = cm.Twin(scen); tr = load_trajectory(tf)
m = mujoco.MjModel.from_xml_path(str(tw.scenario.mjcf_path) if hasattr(tw.scenario,'mjcf_path') else scen+'/scene.xml')
d = mujoco.MjData(m); d.qpos[:] = tr.qpos0; ctrl = np.asarray(prepare_controls(tw, tr))
d.ctrl[:] = ctrl[0]; mujoco.mj_forward(m, d)
ob = m.body('cube').id; seen=set()
for t in range(min(len(ctrl), int(sys.argv[3]) if len(sys.argv)>3 else 2000)):
    d.ctrl[:] = ctrl[t]; mujoco.mj_step(m, d)
    for c in d.contact[:d.ncon]:
        b1, b2 = m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]
        if ob in (b1, b2):
            other = c.geom2 if b1 == ob else c.geom1
            n = m.geom(other).name or f'g{other}'
            if n not in seen: seen.add(n); print(t, t*m.opt.timestep, n, m.body(m.geom_bodyid[other]).name)
