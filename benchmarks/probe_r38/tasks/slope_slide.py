"""Plain MuJoCo: the tilt15 scene, cube friction f, robot held at its start (ctrl = keyframe, the trajectory's
start), cube position over the first 3 s (before the grasp at ~3 s). usage: slope_slide.py SCENE.xml CASE.npz f [f ...]"""
import sys, numpy as np, mujoco
m = mujoco.MjModel.from_xml_path(sys.argv[1]); z = np.load(sys.argv[2])
for f in map(float, sys.argv[3:]):
    m.geom_friction[m.geom("cube").id, 0] = f
    d = mujoco.MjData(m); d.qpos[:] = z["qpos0"]; d.ctrl[:7] = z["qpos0"][:7]; d.ctrl[7:9] = 0.04
    mujoco.mj_forward(m, d); p0 = d.body("cube").xpos.copy(); out = []
    for k in range(1, 1501):
        mujoco.mj_step(m, d)
        if k in (100, 250, 500, 1000, 1500): out.append((k * m.opt.timestep, np.round((d.body("cube").xpos - p0) * 1000, 1).tolist()))
    print(f"friction {f}: cube displacement [mm] at t:", out)
