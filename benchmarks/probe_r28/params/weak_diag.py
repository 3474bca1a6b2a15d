"""Panda with joint2 clamped to 10 N·m at nominal: what does the arm do? (plain MuJoCo replay)"""
import mujoco

import critmoment as cm
from critmoment.recording import at_scenario_rate, initial_state, prepare_controls
from critmoment.trajectory import load_trajectory

twin = cm.Twin(cm.load_scenario("bad/panda_shoulder_nominal_weak_nolim.toml")); traj = at_scenario_rate(load_trajectory("/tmp/r28/params/panda0.npz"), twin)
ctrl = prepare_controls(twin, traj); s0 = initial_state(twin, traj); m = twin.model
a = m.actuator("joint2").id; q = m.joint("joint2").qposadr[0]; print("forcerange joint2", m.actuator_forcerange[a])
d = mujoco.MjData(m); mujoco.mj_setState(m, d, s0, mujoco.mjtState.mjSTATE_INTEGRATION)
sat = 0
for k in range(ctrl.shape[0]):
    d.ctrl[:] = ctrl[k]; mujoco.mj_step(m, d)
    sat += abs(d.actuator_force[a]) >= 0.99 * 10
    if k % 250 == 0 or k in (10, 50, 100):
        cons = sorted({tuple(sorted((m.body(m.geom_bodyid[c.geom1]).name, m.body(m.geom_bodyid[c.geom2]).name))) for c in d.contact[:d.ncon]})
        print(f"t={d.time:.2f} joint2 err {d.qpos[q]-d.ctrl[a]:+.3f} rad force {d.actuator_force[a]:+.2f} N·m  contacts {[c for c in cons if 'table' in c and 'cube' not in c]}")
print("steps at >=99% of 10 N·m:", sat)
