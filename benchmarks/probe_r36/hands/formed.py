"""critmoment's own slip anchors on the nominal run (probe_r36): Twin.slip_masks' `formed` (the grasp judged
formed from the gripper command) and `counted` (held alone), and the nominal gripper command there.
Nothing in critmoment is changed. usage: formed.py SCENARIO TRAJ"""
import sys
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r36/src"), cm.__file__
from critmoment.trajectory import load_trajectory
scen, traj = sys.argv[1:3]
twin = cm.Twin(scen); rec = cm.rollout(load_trajectory(traj), twin=twin)
c = np.asarray(rec.controls); cg = np.asarray(rec.signals.contact_gripper); cs = np.asarray(rec.signals.contact_support)
mk = twin.slip_masks(c, cg, cs); op = twin.gripper_opening(c)
for g in range(cg.shape[1]):
    f = int(np.argmax(mk.formed[:, g])); h = int(np.argmax(mk.counted[:, g])); both = int(np.argmax(mk.formed[:, g] & mk.counted[:, g]))
    print(f"gripper {g}: first touch {int(np.argmax(cg[:, g]))}, formed (from the command) {f} (command opening there {op[f, g]:.4f}),"
          f" held alone (off the support) {h}, slip counted from {both}")
