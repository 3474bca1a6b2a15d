"""One table row per validate run: critmoment's ground truth (real success/fail), false safes /
false unsafes / agreement (validate's own confusion), and, where truth.py was run on the same
samples, the independent truth's success/fail under the absolute and the nominal-relative slip
rule and the fail/pass disagreements with critmoment's ground truth.
usage: summarize.py VAL.json[:TRUTH.json] ...   (paths relative to the cwd)"""
import json
import sys

print("| run | samples | cm GT succ/fail | FS | FU | agreement | vacuous | own truth succ/fail abs (rel) | GT disagreements abs / rel |")
print("|---|---|---|---|---|---|---|---|---|")
for arg in sys.argv[1:]:
    val, _, tru = arg.partition(":")
    v = json.load(open(val))
    c = v["confusion"]
    ps = v["per_sample"]
    fail = sum(p["real_failed"] for p in ps)
    own = dis = "–"
    if tru:
        t = json.load(open(tru))
        rows = t["rows"]
        a_fail = sum(r["mine"] != "SUCCESS" for r in rows)
        r_fail = sum(r["info"].get("outcome_rel", r["mine"]) != "SUCCESS" for r in rows)
        own = f"{len(rows) - a_fail}/{a_fail} ({len(rows) - r_fail}/{r_fail})"
        dis = f"{sum(not r['agree_fail'] for r in rows)} / {sum(not r['agree_fail_rel'] for r in rows)}"
    print(f"| {val} | {len(ps)} | {len(ps) - fail}/{fail} | {c['false_safe']} | {c['false_unsafe']} | "
          f"{v['agreement']:.3f} | {v['vacuous']} | {own} | {dis} |")
