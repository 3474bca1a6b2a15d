"""Independent-truth table: truth_summary.py GENDIR (reads tr_<case>.json)"""
import json, sys, pathlib
g = pathlib.Path(sys.argv[1])
print("| case | nominal (truth) | samples | pass/fail disagreements, relative rule (absolute) | truth fails, critmoment predicts pass | truth passes, critmoment predicts fail |")
print("|---|---|---|---|---|---|")
for f in sorted(g.glob("tr_*.json")):
    d = json.load(open(f)); rows = d["rows"]
    fa = sum(not r["agree_fail"] for r in rows); fr = sum(not r["agree_fail_rel"] for r in rows)
    ts_cf = sum((r["info"]["outcome_rel"] == "SUCCESS") and r["cm_predicted_failed"] for r in rows)
    tf_cp = sum((r["info"]["outcome_rel"] != "SUCCESS") and not r["cm_predicted_failed"] for r in rows)
    print(f"| {f.stem[3:]} | {d['nominal'][0]} | {len(rows)} | {fr} ({fa}) | {tf_cp} | {ts_cf} |")
