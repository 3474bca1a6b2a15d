"""What init's measured closed/open poses do on the Shadow hand (probe_r36; plain MuJoCo + critmoment's own
gripper_gap, nothing changed). usage: closedpose.py SCENE.xml INIT_SCENARIO.toml
1) for each actuator below rh_palm: critmoment's mean pairwise geom distance (actuators.gripper_gap) at the two
   ends of its range, driven alone, as gripper_at's "does it open or close at all" test does;
2) fingertip and thumb-tip positions in the palm frame (x across, y palm normal (-y = palm side), z along the
   fingers) at init's closed and open poses (all its gripper actuators, the rest of the hand at 0)."""
import sys, tomllib, mujoco, numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r36/src"), critmoment.__file__
from critmoment import actuators as A, modelinfo
scene, toml = sys.argv[1:3]
m = mujoco.MjModel.from_xml_path(scene)
b = m.body("rh_palm").id
below = modelinfo._subtree(m, b); geoms = modelinfo._collision_geoms(m, below)
print(f"{len(geoms)} collision geoms below rh_palm")
for a in range(m.nu):
    nm = m.actuator(a).name
    if not nm.startswith("rh_A_") or nm in ("rh_A_WRJ1", "rh_A_WRJ2"): continue
    lo, hi = A.control_span(m, a)
    g = [A.gripper_gap(m, [a], [c], geoms) for c in (lo, hi)]
    print(f"  {nm:10s} ends {lo:+.3f} {hi:+.3f}: mean pair distance {g[0]*1e3:.3f} / {g[1]*1e3:.3f} mm (diff {abs(g[1]-g[0])*1e3:.3f} mm)",
          "-> left out (< 0.1 mm)" if abs(g[1]-g[0]) < 1e-4 else "")
t = tomllib.load(open(toml, "rb")); ch = [c for c in t["actions"]["channel"] if c.get("normalised")][0]
d = mujoco.MjData(m)
def tips(vals):
    mujoco.mj_resetData(m, d)
    for nm, v in vals.items():
        a = m.actuator(nm).id
        if m.actuator_trntype[a] == mujoco.mjtTrn.mjTRN_TENDON:  # tendon target split evenly over its two joints
            for j in ("J1", "J2"): d.qpos[m.jnt_qposadr[m.joint(nm.replace("rh_A_", "rh_").replace("J0", j)).id]] = v / 2
        else:
            d.qpos[m.jnt_qposadr[m.actuator_trnid[a, 0]]] = v
    mujoco.mj_kinematics(m, d)
    R, p = d.xmat[b].reshape(3, 3), d.xpos[b]
    out = {}
    for f in ("ff", "mf", "rf", "lf", "th"):
        bid = m.body(f"rh_{f}distal").id
        tip = d.xpos[bid] + d.xmat[bid].reshape(3, 3) @ np.array([0, 0, 0.026])
        out[f] = (R.T @ (tip - p)).round(3)
    return out
for lab, key in (("init closed", "closed"), ("init open", "open")):
    print(lab, dict(zip(ch["actuators"], ch[key])))
    for f, v in tips(dict(zip(ch["actuators"], ch[key]))).items(): print(f"   {f} tip in palm frame {v}")
