"""tr_*.json in DIR: nominal outcome, pass/fail disagreements with critmoment's ground truth. usage: truth_summary.py DIR"""
import json, pathlib, sys, collections
for f in sorted(pathlib.Path(sys.argv[1]).glob("tr_*.json")):
    d = json.load(open(f)); rows = d["rows"]
    dis = [r for r in rows if not r["agree_fail"]]; dis_rel = [r for r in rows if not r["agree_fail_rel"]]
    print(f"{f.stem[3:]}: nominal {d['nominal'][0]}; mine {dict(collections.Counter(r['mine'] for r in rows))}; "
          f"pass/fail disagreements {len(dis)} (rel rule {len(dis_rel)}) of {len(rows)}")
    for r in dis:
        print("   ", {k: round(v, 4) for k, v in r["values"].items()}, "mine", r["mine"], "cm", r["cm_outcome"], "pred_fail", r["cm_predicted_failed"],
              {k: r["info"].get(k) for k in ("goal_dist", "max_slip_mm", "max_slip_rel_mm", "events", "end_pos", "outcome_rel")})
