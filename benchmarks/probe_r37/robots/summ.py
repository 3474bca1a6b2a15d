"""Summarise one probe case: validate's confusion, the independent truth (truth.py) sample by sample against
validate's real outcome (cm GT) and prediction, and the analyze verdict/region with truth.py on its points.
usage: summ.py TAG [TAG ...]   (files /tmp/r37/robots/res/{val,truth,an,region}_TAG*)"""
import json, os, sys
O = "/tmp/r37/robots/res"
for tag in sys.argv[1:]:
    out = {"case": tag}
    v = json.load(open(f"{O}/val_{tag}.json")) if os.path.exists(f"{O}/val_{tag}.json") else None
    if v:
        c = v["confusion"]; oc = v["outcomes"]
        out.update(cm_succ=oc["success"], cm_fail=v["samples"] - oc["success"], FS=c["false_safe"], FU=c["false_unsafe"],
                   agreement=v["agreement"], vacuous=v["vacuous"], nominal_completed=v["nominal_completed"],
                   outcomes={k: n for k, n in oc.items() if n}, own_rollouts=v["own_runs"]["rollouts"], wall=v.get("_wall_s"))
    if os.path.exists(f"{O}/truth_{tag}.json"):
        t = json.load(open(f"{O}/truth_{tag}.json"))
        rows = t["rows"]
        mine_fail = [r["mine"] != "SUCCESS" for r in rows]
        out["truth_nominal"] = t["nominal"][0]
        out["truth_succ"] = sum(not f for f in mine_fail); out["truth_fail"] = sum(mine_fail)
        out["truth_vs_cmGT_differ"] = [r["i"] for r in rows if not r["agree_fail"]]
        pred = [r["cm_predicted_failed"] for r in rows]
        out["truth_false_safe"] = [r["i"] for r, f, p in zip(rows, mine_fail, pred) if f and not p]
        out["truth_false_unsafe"] = [r["i"] for r, f, p in zip(rows, mine_fail, pred) if (not f) and p]
        out["label_differ"] = sum(not r["agree_label"] for r in rows)
        rel_fail = [r["info"].get("outcome_rel", r["mine"]) != "SUCCESS" for r in rows]
        out["truth_rel_succ"] = sum(not f for f in rel_fail)
        out["truth_rel_vs_cmGT_differ"] = [r["i"] for r in rows if not r["agree_fail_rel"]]
        out["truth_rel_false_safe"] = [r["i"] for r, f, p in zip(rows, rel_fail, pred) if f and not p]
        out["truth_rel_false_unsafe"] = [r["i"] for r, f, p in zip(rows, rel_fail, pred) if (not f) and p]
    if os.path.exists(f"{O}/an_{tag}_analyze.json"):
        a = json.load(open(f"{O}/an_{tag}_analyze.json"))
        out.update(verdict=a["verdict"], p_success=round(a["p_success"], 3), region=a["safe_region_text"], an_wall=a["wall_s"])
    if os.path.exists(f"{O}/region_{tag}.json"):
        r = json.load(open(f"{O}/region_{tag}.json"))["rows"]
        bad = [(x["i"], {k: round(val, 4) for k, val in x["values"].items()}, x["mine"], x["info"].get("outcome_rel")) for x in r if x["mine"] != "SUCCESS"]
        out["region_points"] = len(r); out["region_fail_truth"] = bad
    print(json.dumps(out))
