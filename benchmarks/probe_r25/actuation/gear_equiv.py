"""Is the gear-50 Panda (kp/g^2, kv/g^2, forcerange/g, ctrl*g) the same physics as the bundled
one? Steps both from the home keyframe with the same joint targets (a 0.4 rad step on joint2
and joint4) and a 2.2 kg cube welded nowhere (cube mass raised), and prints the joint2 torque
(qfrc_actuator) and the difference of the arm's qpos.   usage: python gear_equiv.py"""
from pathlib import Path

import mujoco
import numpy as np

here = Path(__file__).resolve().parent
runs = {}
for name, g in (("base_panda", 1.0), ("p_gear50_nolimits", 50.0)):
    m = mujoco.MjModel.from_xml_path(str(here / "v" / name / "scene.xml"))
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, 0)
    m.body_mass[m.body("hand").id] += 2.2  # a heavy payload in the hand
    target = d.qpos[:7].copy()
    target[1] += 0.4
    target[3] += 0.4
    qs, taus = [], []
    for _ in range(1000):
        d.ctrl[:7] = target * g
        mujoco.mj_step(m, d)
        qs.append(d.qpos[:7].copy())
        taus.append(d.qfrc_actuator[:7].copy())
    runs[name] = (np.array(qs), np.array(taus))
    print(name, "max |tau| per joint", np.abs(runs[name][1]).max(0).round(2),
          "actuator_force max", np.abs(d.actuator_force[:7]).round(3))
(qa, ta), (qb, tb) = runs.values()
print("max |dq| over the run", np.abs(qa - qb).max(), "max |dtau|", np.abs(ta - tb).max())
