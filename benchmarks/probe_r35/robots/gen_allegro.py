"""Scripted palm-down power grasp and lift of a ball: Menagerie's Allegro hand on a slide (probe_r35).

usage: gen_allegro.py SCENE.xml OUT.npz [--low Z] [--up Z] [--extra N] [--check]

Writes init's 6-channel layout [lift, ffa0, palm/gripper (0 closed..1 open), mfa0, rfa0, tha1];
the scenario's gripper channel is edited to closed = CLOSED, open = OPEN below (the only edit).
50 Hz: descend 0-100, close 100-150, lift 160-230, hold to 350. --check replays the raw
controls in plain MuJoCo and prints the ball's path.
"""
import argparse
import mujoco, numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r35/src"), critmoment.__file__
from critmoment.trajectory import Trajectory, save_trajectory

GRIP = ["ffa1", "ffa2", "ffa3", "mfa1", "mfa2", "mfa3", "rfa1", "rfa2", "rfa3", "tha0", "tha2", "tha3"]
CLOSED = [1.3, 1.2, 1.0, 1.3, 1.2, 1.0, 1.3, 1.2, 1.0, 1.396, 1.2, 1.2]
OPEN = [0, 0, 0, 0, 0, 0, 0, 0, 0, 1.39, 0.2, 0.2]
ap = argparse.ArgumentParser()
ap.add_argument("scene"); ap.add_argument("out")
ap.add_argument("--low", type=float, default=-0.175)
ap.add_argument("--up", type=float, default=-0.06)
ap.add_argument("--check", action="store_true")
ap.add_argument("--extra", type=int, default=0)
a = ap.parse_args()
def smooth(t): t = np.clip(t, 0, 1); return t * t * t * (10 - 15 * t + 6 * t * t)
n, fps = 350, 50.0
act = np.zeros((n, 6))
for i in range(n):
    act[i, 0] = a.low * smooth(i / 100) + (a.up - a.low) * smooth((i - 160) / 70)
    act[i, 2] = 1 - smooth((i - 100) / 50)
    act[i, 5] = 1.163
act = np.vstack([act, np.repeat(act[-1:], a.extra, axis=0)])
ball = np.array([-0.011, 0.0, 0.08, 1, 0, 0, 0])
if a.check:
    m = mujoco.MjModel.from_xml_path(a.scene); d = mujoco.MjData(m)
    ids = [m.actuator(x).id for x in GRIP]
    steps = int(round(1 / fps / m.opt.timestep))
    for i in range(len(act)):
        for k, nm in ((0, "lift"), (1, "ffa0"), (3, "mfa0"), (4, "rfa0"), (5, "tha1")):
            d.ctrl[m.actuator(nm).id] = act[i, k]
        g = act[i, 2]
        d.ctrl[ids] = np.array(CLOSED) + g * (np.array(OPEN) - np.array(CLOSED))
        for _ in range(steps): mujoco.mj_step(m, d)
        if i % 50 == 0 or i == len(act) - 1:
            print(i, "lift", round(d.qpos[0], 3), "ball", d.body("ball").xpos.round(3), "ncon", d.ncon)
save_trajectory(Trajectory(actions=act, fps=fps, start=act[0], object_pose=ball,
                           meta={"generator": "probe_r35 gen_allegro"}, source="gen_allegro"), a.out)
print("wrote", a.out, act.shape)
