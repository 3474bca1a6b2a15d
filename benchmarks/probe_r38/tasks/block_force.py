"""F4: the nominal run of a scenario copy (e.g. hold_block with nominal mass 0.358, friction 1.478: scenes
hb_s10 = hold_block with those nominals), the object's active contact normal forces per partner geom at
some steps. usage: block_force.py SCEN_DIR CASE.npz MASS"""
import sys, numpy as np, mujoco, critmoment as cm
assert cm.__file__.startswith("/tmp/r38/tasks/src"), cm.__file__
from critmoment.trajectory import load_trajectory
twin = cm.Twin(sys.argv[1] + "/scenario.toml"); m = twin.model; d = mujoco.MjData(m)
rec = cm.rollout(load_trajectory(sys.argv[2]), twin=twin)
print("completed", rec.summary()["completed"])
for k in (2500, 3000, 3100, 4000, len(rec.states) - 2):
    mujoco.mj_setState(m, d, rec.states[k], mujoco.mjtState.mjSTATE_INTEGRATION); mujoco.mj_forward(m, d)
    ob = m.body("cube").id; fs = {}
    for i in range(d.ncon):
        c = d.contact[i]
        if ob not in (m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]) or c.efc_address < 0: continue
        f = np.zeros(6); mujoco.mj_contactForce(m, d, i, f); o = c.geom2 if m.geom_bodyid[c.geom1] == ob else c.geom1
        fs[m.geom(o).name] = round(fs.get(m.geom(o).name, 0) + f[0], 2)
    print(k, "cube z", round(d.body("cube").xpos[2], 4), fs, "weight", round(float(sys.argv[3]) * 9.81, 2))
