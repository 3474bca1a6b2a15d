"""Why the audit decided one validate sample as it did: sparse evaluation of the sample at every
audited moment (as validate: audit_evaluator + audit_moments, all moments evaluated, no first-failure
stop), and critmoment's brute_force classification of its full rollout.
usage: explain.py SCENARIO TRAJ VAL.json INDEX [INDEX ...]"""
import json, sys
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r32/src"), cm.__file__
from critmoment.analysis import audit_evaluator, audit_moments, AnalyzeOptions
from critmoment.groundtruth import brute_force
from critmoment.recording import at_scenario_rate
from critmoment.trajectory import load_trajectory, check_trajectory

scen, trajf, valf = sys.argv[1:4]; idx = [int(x) for x in sys.argv[4:]]
val = json.load(open(valf))
twin = cm.Twin(scen)
traj = at_scenario_rate(check_trajectory(load_trajectory(trajf)), twin)
names = [p.name for p in twin.scenario.box.parameters]
pts = np.array([[val["per_sample"][i]["values"][n] for n in names] for i in idx])
rec = cm.rollout(traj, twin=twin)
ev, _ = audit_evaluator(rec, twin, nthread=1)
cands, steps = audit_moments(rec, twin, ev, AnalyzeOptions().max_moments)
r = ev.evaluate(steps, pts, first_failure=False)
bf = brute_force(traj, twin=twin, samples=pts, nthread=1); c = bf.classification
print("dt", rec.dt, "moments", [(int(s), m.label if hasattr(m, "label") else "") for s, m in zip(steps, cands)])
for k, i in enumerate(idx):
    p = val["per_sample"][i]
    print(f"\n== sample {i} {dict(zip(names, np.round(pts[k], 4)))} validate: outcome {p['outcome']} predicted_failed "
          f"{p['predicted_failed']} verified {p['verified']} max_cost {p['max_cost']}")
    for j, s in enumerate(steps):
        fl = [f for f in ("unlifted_failure", "sticking_failure", "saturated") if getattr(r, f, None) is not None and bool(getattr(r, f)[j, k])]
        print(f"  moment step {int(s):5d} t={s*rec.dt:.3f}s cost {r.cost[j,k]:.3f} (contact {r.cost_contact[j,k]:.3f} motor {r.cost_motor[j,k]:.3f})"
              f" fos_grasp {r.fos_grasp[j,k]:.3f} fos_motor {r.fos_motor[j,k]:.3f} limiting {r.actuator_names[int(r.motor_argmax[j,k])] if r.motor_argmax[j,k] >= 0 else '-'}"
              f" stage {int(r.stage[j,k])} {' '.join(fl)}")
    print(f"  full rollout: {bf.outcome[k].value} completed {bool(c.completed[k])} first_fail {int(c.first_failure_step[k])} "
          f"motor_step {int(c.motor_step[k])} sat_time {float(c.saturation_time[k]):.4f} drop {int(c.drop_step[k])} slip {int(c.slip_step[k])} "
          f"max_slip {1000*float(c.max_slip[k]):.1f} mm")
