"""Scripted palm-down grasp, lift and hold of a ball with Menagerie's Shadow Hand E3M5 on a slide (probe_r36).

usage: gen_shadow.py SCENARIO.toml OUT.npz [--low Z] [--up Z] [--close-end N] [--extra N] [--check SCENE.xml]

Writes the channel layout of SCENARIO.toml's [[actions.channel]] tables (init's guess for the hand):
the lift channel descends to LOW (0-100), the gripper channel goes 1 -> 0 over steps 100..CLOSE_END,
the lift rises to UP (160-230), hold to 350 (50 Hz, 7 s). Other channels hold JOINT values below
(RFJ3 is a joint channel in init's layout: it follows the gripper command to 1.3 rad).
--check replays the controls in plain MuJoCo (the scene given) and prints the ball's path.
"""
import argparse, tomllib
import mujoco, numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r36/src"), critmoment.__file__
from critmoment.trajectory import Trajectory, save_trajectory

ap = argparse.ArgumentParser()
ap.add_argument("scenario"); ap.add_argument("out")
ap.add_argument("--low", type=float, default=-0.215)
ap.add_argument("--up", type=float, default=-0.10)
ap.add_argument("--close-end", type=int, default=150)
ap.add_argument("--extra", type=int, default=0)
ap.add_argument("--ball", type=float, nargs=3, default=[0.0, 0.0, 0.113])
ap.add_argument("--check")
ap.add_argument("--set", nargs="*", default=[], help="ACT=VALUE for single-actuator channels (held)")
ap.add_argument("--follow", nargs="*", default=["rh_A_RFJ3=1.3"], help="ACT=CLOSED: channel follows the grip command from 0 (open) to CLOSED")
a = ap.parse_args()
t = tomllib.load(open(a.scenario, "rb")); ch = t["actions"]["channel"]
hold = {k: float(v) for k, v in (s.split("=") for s in a.set)}
follow = {k: float(v) for k, v in (s.split("=") for s in a.follow)}
def smooth(x): x = np.clip(x, 0, 1); return x * x * x * (10 - 15 * x + 6 * x * x)
n, fps = 350, 50.0
act = np.zeros((n, len(ch)))
for i in range(n):
    g = 1 - smooth((i - 100) / (a.close_end - 100))
    for j, c in enumerate(ch):
        nm = c["actuators"][0]
        if c.get("normalised"):
            act[i, j] = g
        elif nm == "lift":
            act[i, j] = a.low * smooth(i / 100) + (a.up - a.low) * smooth((i - 160) / 70)
        elif nm in follow:
            act[i, j] = (1 - g) * follow[nm]
        else:
            act[i, j] = hold.get(nm, 0.0)
act = np.vstack([act, np.repeat(act[-1:], a.extra, axis=0)])
ball = np.array(list(a.ball) + [1, 0, 0, 0])
if a.check:
    m = mujoco.MjModel.from_xml_path(a.check); d = mujoco.MjData(m)
    d.qpos[m.jnt_qposadr[m.joint("ball_joint").id]:][:3] = a.ball; mujoco.mj_forward(m, d)
    steps = int(round(1 / fps / m.opt.timestep)); z0 = d.body("ball").xpos[2]
    def ctrl(row):
        for j, c in enumerate(ch):
            ids = [m.actuator(x).id for x in c["actuators"]]
            if c.get("normalised"):
                C, O = np.array(c["closed"]), np.array(c["open"]); d.ctrl[ids] = C + row[j] * (O - C)
            else:
                d.ctrl[ids] = row[j]
    for i in range(len(act)):
        ctrl(act[i])
        for _ in range(steps): mujoco.mj_step(m, d)
        if i % 25 == 0 or i == len(act) - 1:
            bid = m.body("ball").id
            tc = sum(1 for k in range(d.ncon) if bid in (m.geom_bodyid[d.contact[k].geom1], m.geom_bodyid[d.contact[k].geom2]))
            print(i, "lift", round(d.qpos[0], 3), "ball", d.body("ball").xpos.round(3), "rise", round(d.body("ball").xpos[2] - z0, 3), "ball contacts", tc)
save_trajectory(Trajectory(actions=act, fps=fps, start=act[0], object_pose=ball,
                           meta={"generator": "probe_r36 gen_shadow"}, source="gen_shadow"), a.out)
print("wrote", a.out, act.shape)
