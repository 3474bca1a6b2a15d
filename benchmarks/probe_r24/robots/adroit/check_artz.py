"""Finding 4's check: replays traj_hand_ctrl30.npy (the 30 controls of traj_hand.npz, held
per 50 Hz sample) in plain MuJoCo with the ball's mass and friction set (the ball given
priority, as critmoment does), and prints A_ARTz's largest force and its joint's largest
lag behind the servo's target (2.5 x ctrl: gain 500, bias -200).

Usage: python check_artz.py MASS FRICTION [SCENE.xml [CTRL.npy]]
SCENE defaults to assets/critmoment_r24_adroit_shipped.xml and CTRL to
traj_hand_ctrl30.npy, both next to this file (run fetch.sh first: it makes the link).
"""
import sys
from pathlib import Path

import mujoco
import numpy as np

HERE = Path(__file__).absolute().parent
scene = sys.argv[3] if len(sys.argv) > 3 else HERE / "assets" / "critmoment_r24_adroit_shipped.xml"
m = mujoco.MjModel.from_xml_path(str(scene))
mass, fric = float(sys.argv[1]), float(sys.argv[2])
b, g = m.body("Object").id, m.geom("sphere").id
m.body_inertia[b] *= mass / m.body_mass[b]
m.body_mass[b] = mass
m.geom_friction[g, 0] = fric
m.geom_priority[g] = 10
ctrl = np.load(sys.argv[4] if len(sys.argv) > 4 else HERE / "traj_hand_ctrl30.npy")
d = mujoco.MjData(m)
fj = m.jnt_qposadr[m.joint("object_free").id]
d.qpos[fj:fj + 7] = [0, 0, 0.035, 1, 0, 0, 0]
a = m.actuator("A_ARTz").id
j = m.jnt_qposadr[m.joint("ARTz").id]
fmax, lag = 0.0, []
for i in range(len(ctrl)):
    d.ctrl[:] = ctrl[i]
    for _ in range(10):
        mujoco.mj_step(m, d)
        fmax = max(fmax, abs(d.actuator_force[a]))
        lag.append(2.5 * d.ctrl[a] - d.qpos[j])
lag = np.array(lag)
k = int(np.argmax(np.abs(lag)))
print(f"mass {mass} friction {fric}: |A_ARTz force| max {fmax:.1f} N; lag max {lag[k]*1000:.1f} mm "
      f"at t = {k * m.opt.timestep:.2f} s; lag > 10 mm for {np.sum(np.abs(lag) > 0.01) * m.opt.timestep:.2f} s; "
      f"ball z end {d.qpos[fj + 2]:.3f}")
