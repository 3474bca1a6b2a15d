"""The cube's position in link5's frame (the gripper's base) over the OMX nominal, plain MuJoCo (probe_r35)."""
import sys, mujoco, numpy as np
import critmoment; assert critmoment.__file__.startswith("/tmp/r35/src"), critmoment.__file__
from critmoment.trajectory import load_trajectory
scene, traj = sys.argv[1:3]; steps_at = [int(x) for x in sys.argv[3:]]
tr = load_trajectory(traj); m = mujoco.MjModel.from_xml_path(scene); d = mujoco.MjData(m)
mujoco.mj_resetDataKeyframe(m, d, m.key("home").id)
L5 = m.body('link5').id; cb = m.body('cube').id; fl = m.body('gripper_left').id; fr = m.body('gripper_right').id
k = 0; ref = None
for a in tr.actions:
    d.ctrl[:4] = a[:4]; d.ctrl[4] = -0.01 + a[4] * 0.029
    for _ in range(10):
        mujoco.mj_step(m, d); k += 1
        if k in steps_at:
            rel = d.xmat[L5].reshape(3, 3).T @ (d.xpos[cb] - d.xpos[L5])
            ref = rel if ref is None else ref
            touch = sorted({m.body(m.geom_bodyid[g]).name for c in d.contact[:d.ncon] for g in (c.geom1, c.geom2)} - {'cube', 'world'})
            up = d.xmat[cb].reshape(3, 3)[2, 2]
            print(k, "cube in link5 [mm]", (rel * 1e3).round(1), "moved [mm]", round(float(np.linalg.norm(rel - ref)) * 1e3, 1), "cube z-axis . world z", round(float(up), 3), "touching", touch)
