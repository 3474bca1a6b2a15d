"""Feasibility (check_feasibility on the nominal rollout, raise_on_failure=False) per trajectory:
python feas.py SCEN TRAJ... ; prints problems (exit-2 causes) and warnings (held back by contacts)"""
import sys, critmoment as cm
from critmoment.trajectory import load_trajectory
from critmoment.recording import rollout
from critmoment.feasibility import check_feasibility
import inspect
twin = cm.Twin(cm.load_scenario(sys.argv[1]))
for tp in sys.argv[2:]:
    traj = load_trajectory(tp)
    rec = rollout(twin, traj) if "twin" in list(inspect.signature(rollout).parameters)[:1] else rollout(traj, twin=twin)
    rep = check_feasibility(rec, twin, raise_on_failure=False)
    print("==", tp, "completed", getattr(rec, "completed", None))
    for p in rep.problems: print("  PROBLEM (exit 2):", str(p)[:400])
    for w in rep.warnings: print("  held:", str(w)[:300])
    for j in rep.joints:
        if j.saturation_duration > 0.05 or j.blocked_by:
            print("   joint", j.joint, "sat %.3f s" % j.saturation_duration, "limit", j.force_limit, "blocked_by", j.blocked_by)
