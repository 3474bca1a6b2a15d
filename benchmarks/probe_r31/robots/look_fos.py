"""critmoment's own rollout at the scenario's nominal; prints the contact FOS per gripper and of
the grasp, the carried flag and the object height between T0 and T1. usage: look_fos.py SCEN TRAJ T0 T1"""
import sys
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src")
from critmoment.trajectory import load_trajectory
twin = cm.Twin(sys.argv[1]); rec = cm.rollout(load_trajectory(sys.argv[2]), twin=twin)
s = rec.signals; dt = rec.dt if hasattr(rec, "dt") else twin.model.opt.timestep
t0, t1 = float(sys.argv[3]), float(sys.argv[4])
for name in ("fos_contact", "fos_grasp", "contact_gripper", "contact_support", "object_pos"):
    print(name, np.shape(getattr(s, name, None)))
fg = np.asarray(s.fos_grasp) if hasattr(s, "fos_grasp") else None
for k in range(int(t0 / dt), int(t1 / dt), 5):
    print(f"t={k*dt:.3f} z={s.object_pos[k][2]:.4f} fos_c={np.round(np.asarray(s.fos_contact)[k],3)} "
          + (f"grasp={fg[k]:.3f} " if fg is not None else "")
          + f"grip={np.asarray(s.contact_gripper)[k]} sup={np.asarray(s.contact_support)[k]}")
