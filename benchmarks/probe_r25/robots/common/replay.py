"""Replay a critmoment trajectory in plain MuJoCo (no critmoment twin) and print the object.

Maps each channel to its actuators as the scenario's [[actions.channel]] say (normalised
channels: closed + v * (open - closed)), holds each action for 1/fps (zero-order hold),
and prints the object body's position, the gripper actuators' ctrl and forces every 0.5 s.

Usage: python replay.py SCENE.xml SCENARIO.toml TRAJ.npz OBJECT [--mass M] [--friction F]
"""
from __future__ import annotations

import argparse

import mujoco
import numpy as np
import tomllib


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("scenario")
    p.add_argument("traj")
    p.add_argument("obj")
    p.add_argument("--mass", type=float)
    p.add_argument("--friction", type=float)
    a = p.parse_args()
    m = mujoco.MjModel.from_xml_path(a.scene)
    sc = tomllib.load(open(a.scenario, "rb"))
    z = np.load(a.traj, allow_pickle=True)
    acts, fps = z["actions"], float(z["fps"]) if "fps" in z else 50.0
    body = m.body(a.obj).id
    if a.mass is not None:
        m.body_mass[body] = a.mass
    if a.friction is not None:
        for g in range(m.ngeom):
            if m.geom_bodyid[g] == body:
                m.geom_friction[g, 0] = a.friction
    d = mujoco.MjData(m)
    if "qpos0" in z:
        d.qpos[:] = z["qpos0"]
    mujoco.mj_forward(m, d)
    chans = sc["actions"]["channel"]
    per = int(round(1 / fps / m.opt.timestep))
    for i, row in enumerate(acts):
        for c, v in zip(chans, row, strict=False):
            ids = [m.actuator(n).id for n in c["actuators"]]
            if c.get("normalised"):
                cl, op = np.array(c["closed"]), np.array(c["open"])
                d.ctrl[ids] = cl + v * (op - cl)
            else:
                d.ctrl[ids] = v
        for _ in range(per):
            mujoco.mj_step(m, d)
        if i % 25 == 0 or i == len(acts) - 1:
            g = [m.actuator(n).id for c in chans if c.get("normalised") for n in c["actuators"]]
            print(f"t={d.time:5.2f} obj={np.round(d.xpos[body], 3)} grip ctrl="
                  f"{np.round(d.ctrl[g], 3)} force={np.round(d.actuator_force[g], 2)} "
                  f"ncon={d.ncon}")


if __name__ == "__main__":
    main()
