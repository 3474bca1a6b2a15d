"""Plain MuJoCo: step the scenario's nominal run (critmoment's controls) and print, at given steps,
the object's contacts: partner geom, dist, included in the solver (efc_address >= 0), normal force.
usage: contacts_at.py SCEN_DIR CASE.npz STEP [STEP ...]"""
import sys, numpy as np, mujoco
import critmoment as cm
assert cm.__file__.startswith("/tmp/r38/tasks/src"), cm.__file__
from critmoment.trajectory import load_trajectory
twin = cm.Twin(sys.argv[1] + "/scenario.toml")
traj = load_trajectory(sys.argv[2])
steps = sorted(int(s) for s in sys.argv[3:])
rec = cm.rollout(traj, twin=twin)
m = twin.model; d = mujoco.MjData(m)
st = rec.states
for k in steps:
    mujoco.mj_setState(m, d, st[k], mujoco.mjtState.mjSTATE_INTEGRATION)
    mujoco.mj_forward(m, d)
    ob = m.body("cube").id
    print("step", k)
    for i in range(d.ncon):
        c = d.contact[i]
        b1, b2 = m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]
        if ob not in (b1, b2): continue
        f = np.zeros(6); mujoco.mj_contactForce(m, d, i, f)
        print(f"  {m.geom(c.geom1).name:>10s} {m.geom(c.geom2).name:>10s} dist {c.dist*1e3:7.3f} mm efc {c.efc_address:5d} "
              f"exclude {c.exclude} fn {f[0]:8.3f}")
