"""budget.limits (a contextvar) is not seen by the audit's worker thread.

The environment sets max_steps below the demo's 4,000 physics steps and the
documented Python override, ``with critmoment.budget.limits(max_steps=10_000)``,
raises it above them. Expected: every call below succeeds (the innermost limits win).

    CRITMOMENT_MAX_STEPS=3000 PYTHONPATH=/tmp/r29/src python api_budget.py
"""
import os
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from common import check_src, demo_traj  # noqa: E402

import critmoment as cm  # noqa: E402
from critmoment import budget  # noqa: E402

check_src()
assert os.environ.get("CRITMOMENT_MAX_STEPS") == "3000", "run with CRITMOMENT_MAX_STEPS=3000"
traj = cm.load_trajectory(demo_traj())
with budget.limits(max_steps=10_000):
    print("active in this thread:", budget.active())
    rec = cm.rollout(traj)
    print("rollout: ok")
    for nthread in (1, 0):
        try:
            r = cm.analyze(traj, options=cm.AnalyzeOptions(n_samples=32, nthread=nthread))
            print(f"analyze nthread={nthread}: ok {r.verdict.value}")
        except cm.CritmomentError as exc:
            print(f"analyze nthread={nthread}: {type(exc).__name__}: {exc}")
    try:
        v = cm.validate(traj, n_samples=8, nthread=1)
        print("validate: ok", v.confusion)
    except cm.CritmomentError as exc:
        print(f"validate: {type(exc).__name__}: {exc}")
