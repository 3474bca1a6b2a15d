"""docs/search.md's block, with the names it assumes (recording, twin, step) defined first.

step: the demo's lift-off (the doc's JSON example shows step 1807 of some trajectory).
"""
import json

import critmoment as cm
from critmoment import demos

twin = cm.Twin(cm.load_scenario())
traj = demos.scripted_transfer(seed=0, twin=twin)
recording = cm.rollout(traj, twin=twin)
step = 1707

# --- verbatim ---
from critmoment import search, sparse  # noqa: E402

engine = sparse.SparseEvaluator(recording, twin, horizon=25)
bounds = search.analytic_bounds(recording, twin, step)        # AnalyticBounds
worst = search.analytic_worst_case(bounds)                    # AnalyticWorstCase
found = search.search_worst_case(engine, [step], seed=0)      # SearchResult
check = search.verify(engine, step, worst, found)             # Verification
report = search.audit_moment(engine, step)                    # JSON-able dict
# --- end ---

print(type(bounds).__name__, type(worst).__name__, type(found).__name__, type(check).__name__)
s = json.dumps(report, allow_nan=False, default=str)
print("keys", sorted(report))
print("analytic keys", sorted(report["analytic"]))
print("search keys", sorted(report["search"]))
print("verification keys", sorted(report["verification"]))
doc_analytic = ["critical_mass", "limiting_joint", "motor_critical_mass", "motor_critical_mass_threshold",
                "step_load_critical_mass", "min_fos_motor", "min_fos_contact", "contact_critical_mass",
                "contact_critical_mass_threshold", "holding", "on_support", "grasps", "assumptions_hold",
                "notes", "worst_case"]
doc_search = ["method", "evaluations", "worst_case", "worst_cost", "evaluations_to_worst", "stopped_early", "seed"]
print("doc analytic keys absent:", [k for k in doc_analytic if k not in report["analytic"]])
print("doc search keys absent:", [k for k in doc_search if k not in report["search"]])
print("analytic.worst_case keys", sorted(report["analytic"]["worst_case"]))
