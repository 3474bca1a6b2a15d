"""Plain-MuJoCo replay of a hand-over trajectory, for debugging the script (not the audit).

Zero-order hold of each action for 1/fps, the scenario's channel mapping; every 0.2 s prints
the cube's position, which bodies touch it (left/right fingers or palm, table), the finger
joint angles and the tips' (TCP) positions.

``--friction`` sets the cube geom's friction only: the OpenArm's finger geoms have
``priority="1"``, so in plain MuJoCo their friction (1) governs the grip whatever the cube's
(critmoment instead writes the parameter into explicit contact pairs).

Usage: python inspect_run.py SCENE.xml SCENARIO.toml TRAJ.npz [--mass M] [--friction F]
       [--every S] [--from T]
"""
from __future__ import annotations

import argparse

import mujoco
import numpy as np
import tomllib

TIP = np.array([-0.0015, 0.0, -0.164])


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scene")
    p.add_argument("scenario")
    p.add_argument("traj")
    p.add_argument("--mass", type=float)
    p.add_argument("--friction", type=float)
    p.add_argument("--every", type=float, default=0.2)
    p.add_argument("--from", dest="start", type=float, default=0.0)
    a = p.parse_args()
    m = mujoco.MjModel.from_xml_path(a.scene)
    sc = tomllib.load(open(a.scenario, "rb"))
    z = np.load(a.traj, allow_pickle=True)
    acts, fps = z["actions"], float(z["fps"])
    cube = m.body("cube").id
    if a.mass is not None:
        m.body_mass[cube] = a.mass
    if a.friction is not None:
        for g in range(m.ngeom):
            if m.geom_bodyid[g] == cube:
                m.geom_friction[g, 0] = a.friction
    d = mujoco.MjData(m)
    d.qpos[:] = z["qpos0"]
    mujoco.mj_forward(m, d)
    chans = sc["actions"]["channel"]
    per = int(round(1 / fps / m.opt.timestep))
    hands = {s: m.body(f"openarm_{s}_ee_base_link").id for s in ("left", "right")}
    fj = {s: m.jnt_qposadr[m.joint(f"openarm_{s}_finger_joint1").id] for s in ("left", "right")}
    every = max(1, int(round(a.every * fps)))

    def who(b):
        n = m.body(b).name
        return n.replace("openarm_", "")

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
        if (i % every == 0 or i == len(acts) - 1) and d.time >= a.start:
            touch = set()
            for k in range(d.ncon):
                b1, b2 = m.geom_bodyid[d.contact[k].geom1], m.geom_bodyid[d.contact[k].geom2]
                if cube in (b1, b2):
                    touch.add(who(b2 if b1 == cube else b1))
            tcp = {s: d.xpos[h] + d.xmat[h].reshape(3, 3) @ TIP for s, h in hands.items()}
            lr = sorted((who(m.geom_bodyid[d.contact[k].geom1]), who(m.geom_bodyid[d.contact[k].geom2]))
                        for k in range(d.ncon)
                        if {who(m.geom_bodyid[d.contact[k].geom1])[:4], who(m.geom_bodyid[d.contact[k].geom2])[:4]} == {"left", "righ"})
            print(f"t={d.time:5.2f} cube={np.round(d.xpos[cube], 3)} touch={sorted(touch)} "
                  f"fingers L {d.qpos[fj['left']]:.3f} R {d.qpos[fj['right']]:.3f} "
                  f"tcpL={np.round(tcp['left'], 3)} tcpR={np.round(tcp['right'], 3)}"
                  + (f" LEFT-RIGHT {sorted(set(lr))}" if lr else ""))


if __name__ == "__main__":
    main()
