"""Ground-truth labels of lift-dropped samples on a hand-over whose nominal run has its own
short drop (A_drop_into) vs the plain demo: drop_step / motor_step / outcome per sample.
usage: diag_drop_label.py SCENARIO TRAJ [TRAJ ...]"""
import sys
import numpy as np
import critmoment as cm
from critmoment.groundtruth import brute_force
from critmoment.trajectory import load_trajectory

twin = cm.Twin(sys.argv[1])
pts = np.array([[0.705, 0.417], [1.352, 0.26], [1.052, 0.521], [0.438, 0.211], [0.2, 1.0]])
for f in sys.argv[2:]:
    bf = brute_force(load_trajectory(f), twin=twin, samples=pts, nthread=1)
    c = bf.classification
    ref = bf.reference
    print("==", f, "nominal completed", bf.nominal_completed)
    for i, p in enumerate(pts):
        print(f"  mass {p[0]:.3f} fric {p[1]:.3f}: {c.outcome[i].value:9s} first {c.first_failure_step[i]:5d} "
              f"drop_step {c.drop_step[i]:5d} motor_step {c.motor_step[i]:5d} motor_col {c.motor_column[i]} "
              f"tracking {c.motor_tracking[i]} completed {c.completed[i]}")
    print("  twin.motors:", getattr(twin, "motors", None))
