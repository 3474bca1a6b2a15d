"""critmoment.dynamics (Pinocchio) vs MuJoCo's own inverse dynamics on a model with a free-joint
base: random states (base quaternion far from identity), rnea(include_armature=True) vs
mj_inverse with constraints disabled (qfrc_inverse minus passive damping), per dof; and the
payload regressor vs mj_inverse with the object's mass moved onto the hand.
usage: check_dyn.py SCENE.xml"""
import sys
import mujoco, numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r34/src"), critmoment.__file__
from critmoment import dynamics as dyn
m = mujoco.MjModel.from_xml_path(sys.argv[1])
m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONSTRAINT)
m.dof_damping[:] = 0  # passive forces out of both sides
pm = dyn.from_mujoco(m)
d = mujoco.MjData(m)
rng = np.random.default_rng(0)
worst = 0.0
for k in range(20):
    mujoco.mj_resetDataKeyframe(m, d, 0)
    q = d.qpos.copy()
    for j in range(m.njnt):
        a = m.jnt_qposadr[j]
        if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE:
            q[a:a + 3] += rng.normal(0, 0.3, 3)
            quat = rng.normal(size=4); q[a + 3:a + 7] = quat / np.linalg.norm(quat)
        elif m.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE:
            q[a] = rng.uniform(-1, 1)
    v = rng.normal(0, 1, m.nv); acc = rng.normal(0, 2, m.nv)
    d.qpos[:] = q; d.qvel[:] = v; d.qacc[:] = acc
    mujoco.mj_inverse(m, d)
    tau_mj = d.qfrc_inverse.copy()
    tau_pin = pm.rnea(q[None], v[None], acc[None], include_armature=True)[0]
    err = np.abs(tau_mj - tau_pin).max()
    worst = max(worst, err / max(1.0, np.abs(tau_mj).max()))
    if k < 3:
        print("state", k, "max |tau_mj - tau_pin|", f"{err:.3g}", "of", f"{np.abs(tau_mj).max():.3g}")
print("worst relative rnea error over 20 states:", f"{worst:.3g}")
