"""Why does a lower right/right_finger force limit fail the ALOHA hand-over? Plain MuJoCo replay."""
import mujoco
import numpy as np

import critmoment as cm
from critmoment.recording import initial_state, prepare_controls
from critmoment.trajectory import load_trajectory

twin = cm.Twin(cm.load_scenario("scen/aloha_grip_lim.toml")); traj = load_trajectory("/tmp/r28/params/aloha0.npz")
from critmoment.recording import at_scenario_rate

traj = at_scenario_rate(traj, twin)
ctrl = prepare_controls(twin, traj); s0 = initial_state(twin, traj)
m = twin.model
a = m.actuator("right/right_finger").id
jf = {n: m.joint(n).qposadr[0] for n in ["right/left_finger", "right/right_finger", "right/wrist_angle"]}
gl = m.body("right/gripper_link").id; box = m.body("box").id
wa = m.actuator("right/wrist_angle").id
for lim in (5.0, 4.5):
    mm = m
    mm.actuator_forcerange[a] = [-lim, lim]
    d = mujoco.MjData(mm); mujoco.mj_setState(mm, d, s0, mujoco.mjtState.mjSTATE_INTEGRATION)
    print(f"--- right/right_finger limit {lim} N")
    for k in range(ctrl.shape[0]):
        d.ctrl[:] = ctrl[k]; mujoco.mj_step(mm, d)
        if k in (1500, 1700, 2000, 2400, 2600, 2650, 2770, 3000, 3300):
            R = d.xmat[gl].reshape(3, 3); rel = R.T @ (d.xpos[box] - d.xpos[gl])
            cons = set()
            for c in d.contact[:d.ncon]:
                b1, b2 = mm.geom_bodyid[c.geom1], mm.geom_bodyid[c.geom2]
                cons.add(tuple(sorted((mm.body(b1).name, mm.body(b2).name))))
            print(f"step {k}: box in right gripper frame {np.round(rel*1000,1)} mm; fingers {d.qpos[jf['right/left_finger']]:.4f} {d.qpos[jf['right/right_finger']]:.4f}; "
                  f"wrist_angle err {d.qpos[jf['right/wrist_angle']]-d.ctrl[wa]:+.3f} frc {d.actuator_force[wa]:+.2f}; finger frc {d.actuator_force[a]:+.2f} {d.actuator_force[a-1]:+.2f}; contacts {sorted(c for c in cons if 'box' in c or ('left/' in c[0]+c[1] and 'right/' in c[0]+c[1]))}")
    mm.actuator_forcerange[a] = [-5, 5]
