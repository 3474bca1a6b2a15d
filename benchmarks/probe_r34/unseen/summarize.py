"""Results table rows from RES/val_TAG.json (validate) and RES/tr_TAG.json (independent truth).
usage: summarize.py RES TAG ..."""
import json
import os
import sys

res = sys.argv[1]
print("| tag | success / fail (critmoment's truth) | FS | FU | agreement | indep. truth pass/fail (relative rule) | disagreements rel / absolute |")
print("|---|---|---|---|---|---|---|")
for tag in sys.argv[2:]:
    v = json.load(open(os.path.join(res, f"val_{tag}.json")))
    c = v["confusion"]; o = v["outcomes"]
    succ = o.get("success", 0); fail = v["samples"] - succ
    tr = os.path.join(res, f"tr_{tag}.json")
    ind = dis = "–"
    if os.path.exists(tr):
        rows = json.load(open(tr))["rows"]
        okr = sum(r["info"].get("outcome_rel") == "SUCCESS" for r in rows)
        ind = f"{okr} / {len(rows) - okr}"
        dis = f"{sum(not r['agree_fail_rel'] for r in rows)} / {sum(not r['agree_fail'] for r in rows)}"
    print(f"| {tag} | {succ} / {fail} | {c['false_safe']} | {c['false_unsafe']} | {v['agreement']:.3f} | {ind} | {dis} |")
