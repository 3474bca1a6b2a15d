"""Which hand bodies touch the ball, and where the ball is, at given steps of the nominal run (plain MuJoCo; probe_r36).
usage: contacts.py SCENE.xml TRAJ SCENARIO.toml STEP [STEP ...]"""
import sys, mujoco, numpy as np, tomllib
import critmoment; assert critmoment.__file__.startswith("/tmp/r36/src"), critmoment.__file__
from critmoment.trajectory import load_trajectory
scene, traj, toml, *at = sys.argv[1:]; at = {int(x) for x in at}
tr = load_trajectory(traj); ch = tomllib.load(open(toml, 'rb'))['actions']['channel']
m = mujoco.MjModel.from_xml_path(scene); d = mujoco.MjData(m)
qa = m.jnt_qposadr[m.joint("ball_joint").id]; d.qpos[qa:qa + 7] = tr.object_pose; mujoco.mj_forward(m, d)
bid = m.body("ball").id; palm = m.body("rh_palm").id; p0 = None
steps = int(round(1 / tr.fps / m.opt.timestep)); k = 0
for a in tr.actions:
    for j, c in enumerate(ch):
        ids = [m.actuator(x).id for x in c["actuators"]]
        d.ctrl[ids] = (np.array(c["closed"]) + a[j] * (np.array(c["open"]) - np.array(c["closed"]))) if c.get("normalised") else a[j]
    for _ in range(steps):
        mujoco.mj_step(m, d); k += 1
        if k in at:
            R, p = d.xmat[palm].reshape(3, 3), d.xpos[palm]; rel = R.T @ (d.xpos[bid] - p)
            if p0 is None: p0 = rel
            who = sorted({m.body(m.geom_bodyid[c.geom2 if m.geom_bodyid[c.geom1] == bid else c.geom1]).name
                          for c in d.contact[:d.ncon] if bid in (m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2])})
            print(k, "ball z", round(float(d.xpos[bid][2]), 4), "ball in palm frame [mm]", (rel * 1e3).round(1),
                  "moved from first listed step [mm]", round(float(np.linalg.norm(rel - p0)) * 1e3, 1), who)
