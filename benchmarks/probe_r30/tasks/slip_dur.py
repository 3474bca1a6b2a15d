"""how long critmoment's ground-truth slip stays above the tolerance: brute_force with shorter slip_time.
usage: slip_dur.py SCENARIO TRAJ mass friction"""
import sys, numpy as np, critmoment as cm
assert cm.__file__.startswith("/tmp/r30/src")
from critmoment.groundtruth import brute_force, OutcomeCriteria
from critmoment.trajectory import load_trajectory
twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2]); p = np.array([[float(sys.argv[3]), float(sys.argv[4])]])
ref = None
for st in (0.002, 0.01, 0.02, 0.03, 0.04, 0.05):
    for tol in (0.01, 0.008, 0.005):
        bf = brute_force(traj, twin=twin, samples=p, nthread=1, criteria=OutcomeCriteria(slip_time=st, slip_tolerance=tol), reference=ref)
        ref = bf.reference; c = bf.classification
        print(f"slip_time {st*1000:4.0f} ms tol {tol*1000:.0f} mm: outcome {c.outcome[0].value}, slip_step {int(c.slip_step[0])}, max_slip {c.max_slip[0]*1000:.1f} mm")
