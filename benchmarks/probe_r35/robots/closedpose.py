"""What init's 'closed' (gripper channel 0) does to the Allegro hand vs a real flexion grasp (probe_r35)."""
import mujoco, numpy as np
import critmoment; assert critmoment.__file__.startswith("/tmp/r35/src"), critmoment.__file__
from critmoment import actuators as A
m = mujoco.MjModel.from_xml_path('allegro_ball.xml'); d = mujoco.MjData(m)
m.geom_contype[m.geom('ball').id]=0; m.geom_conaffinity[m.geom('ball').id]=0
names = ["ffa1","ffa2","ffa3","mfa1","mfa2","mfa3","rfa1","rfa2","rfa3","tha0","tha2","tha3"]
closed = [-0.196, 1.709, 1.618, -0.196, 1.709, 1.618, -0.196, 1.709, 1.618, 1.396, 1.644, 1.719]
opened = [1.61, -0.174, -0.227, 1.61, -0.174, -0.227, 1.61, -0.174, -0.227, 0.263, -0.189, -0.162]
def pose(vals, tha1=1.163):
    d.qpos[:] = 0; d.qvel[:] = 0; d.ctrl[:] = 0
    for n, v in zip(names, vals): d.ctrl[m.actuator(n).id] = v
    d.ctrl[m.actuator('tha1').id] = tha1
    for _ in range(1500): mujoco.mj_step(m, d)
    p = d.body('palm').xpos
    return {b: (d.body(b).xpos - p).round(3).tolist() for b in ['ff_tip', 'mf_tip', 'th_tip']}
print("init 'closed' (channel 0):", pose(closed))
print("init 'open'   (channel 1):", pose(opened))
flex = list(closed); flex[0] = flex[3] = flex[6] = 1.61
print("closed with proximal flexed 1.61:", pose(flex))
# the per-actuator measurement init ran for ffa1
gids = [g for g in range(m.ngeom) if m.geom_contype[g] or m.geom_conaffinity[g]]
