"""Print the samples where critmoment's ground truth and the independent truth disagree (probe_r35, reused in probe_r36).
usage: disagree.py RES TAG"""
import json, sys, os
res, tag = sys.argv[1:3]
v = json.load(open(os.path.join(res, f"val_{tag}.json"))); t = json.load(open(os.path.join(res, f"tr_{tag}.json")))
print("nominal (indep.)", t["nominal"][0], {k: t["nominal"][1].get(k) for k in ("max_slip_mm", "max_slip_rel_mm", "events")})
for r in t["rows"]:
    ps = v["per_sample"][r["i"]]
    flag = "" if r["agree_fail_rel"] else "  <== fail/pass differs (rel)"
    print(r["i"], {k: round(x, 3) for k, x in r["values"].items()}, "cm", r["cm_outcome"], "pred_fail", r["cm_predicted_failed"],
          "indep", r["mine"], "rel", r["info"].get("outcome_rel"), "slip abs/rel mm", r["info"]["max_slip_mm"], r["info"]["max_slip_rel_mm"],
          r["info"]["events"], "cm first fail", ps["first_failure_step"], flag)
