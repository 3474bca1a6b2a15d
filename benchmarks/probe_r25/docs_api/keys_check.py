"""Compare the report.json keys docs/formats.md describes with an actual report.json.

    python keys_check.py REPORT_JSON
"""
import json
import sys

DOC_TOP = ["schema", "verdict", "p_success", "p_success_interval", "confidence", "n_samples",
           "nominal_cost", "threshold", "safe_region", "safe_region_text", "failure_causes",
           "moments", "candidates", "uncertainty", "cost", "horizon", "rollout", "verification",
           "feasibility", "contact_model", "load_bound", "timings", "manifest"]
DOC_MOMENT = ["step", "time", "label", "reason", "sensitivity", "audited_step", "worst_case",
              "max_cost", "min_fos_contact", "min_fos_motor", "critical", "critical_side",
              "dominant", "limiting_actuator", "fail_fraction", "overturned", "reached",
              "squeeze", "analytic", "search"]
DOC_ANALYTIC = ["critical_mass", "limiting_joint", "min_fos_motor", "min_fos_contact",
                "contact_critical_mass", "assumptions_hold", "notes"]
DOC_SEARCH = ["method", "evaluations", "worst_case", "worst_cost", "stop_reason"]
DOC_CAND = ["step", "time", "label", "reason", "score"]
DOC_UNC = ["kind", "target", "range", "nominal", "prior", "unit"]
DOC_VER = ["fraction", "cost_from", "rollouts", "failed", "near", "near_failed", "unlifted",
           "unlifted_failed", "sticking", "sticking_failed", "slipping", "slipping_failed",
           "chained", "chained_failed", "chained_rolled_out", "chained_confirmed",
           "chained_near", "chained_near_failed", "region"]
DOC_REGION = ["holds", "rounds", "sparse", "chained", "rollouts", "points",
              "rollouts_last_round", "own_runs_last_round"]
DOC_CM = ["cone", "impratio", "noslip_iterations", "probe_mass", "creep_rate", "carry_time",
          "soft", "creep_horizon", "findings", "force_ratio_untrusted_at"]
DOC_LB = ["min_critical_payload"]
DOC_MAN = ["critmoment", "mujoco", "numpy", "python", "platform", "scenario", "scenario_file",
           "scenario_sha256", "trajectory", "trajectory_sha256", "model_sha256", "seed",
           "options", "task", "limits", "unlimited_actuators"]


def cmp(name, doc, actual):
    actual = set(actual)
    missing = [k for k in doc if k not in actual]
    extra = sorted(actual - set(doc))
    print(f"{name}: documented but absent {missing}; present but undocumented {extra}")


r = json.load(open(sys.argv[1]))
cmp("top", DOC_TOP, r)
cmp("moments[0]", DOC_MOMENT, r["moments"][0])
cmp("moments[0].analytic", DOC_ANALYTIC, r["moments"][0]["analytic"] or {})
cmp("moments[0].search", DOC_SEARCH, r["moments"][0]["search"] or {})
cmp("candidates[0]", DOC_CAND, r["candidates"][0])
cmp("uncertainty[*]", DOC_UNC, next(iter(r["uncertainty"].values())) if isinstance(r["uncertainty"], dict) else r["uncertainty"][0])
cmp("verification", DOC_VER, r["verification"] or {})
cmp("verification.region", DOC_REGION, (r["verification"] or {}).get("region") or {})
cmp("contact_model", DOC_CM, r["contact_model"])
cmp("load_bound", DOC_LB, r["load_bound"] or {})
cmp("manifest", DOC_MAN, r["manifest"])
print("uncertainty is", type(r["uncertainty"]).__name__, "; load_bound keys", list(r["load_bound"] or {})[:8])
print("failure_causes[0]", r["failure_causes"][0] if r["failure_causes"] else None)
print("feasibility keys", list(r["feasibility"]))
