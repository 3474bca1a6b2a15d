"""The results table from val_TAG.json (validate) and tr_TAG.json (independent truth), run in the scratch folder.
usage: table.py TAG:ROBOT:BOX ..."""
import json, sys
print("| case | robot | box (mass kg × friction) | real S / F (critmoment brute force) | false safe | false unsafe | agreement | indep. truth: pass/fail disagreements | samples passed with base tilt > 5° (truth) |")
print("|---|---|---|---|---|---|---|---|---|")
for arg in sys.argv[1:]:
    tag, robot, box = arg.split(":")
    v = json.load(open(f"val_{tag}.json")); c = v["confusion"]
    t = json.load(open(f"tr_{tag}.json"))
    rows = t["rows"]
    dis = sum(1 for r in rows if not r["agree_fail_rel"])
    tilt = [r["i"] for r in rows if r["cm_outcome"] == "success" and r["info"].get("base_max_tilt_deg", 0) > 5]
    tilts = ", ".join(f"#{r['i']}: {r['info']['base_max_tilt_deg']}°" for r in rows if r["i"] in tilt)
    succ = c["true_safe"] + c["false_unsafe"]; fail = c["true_unsafe"] + c["false_safe"]
    print(f"| {tag} | {robot} | {box} | {succ} / {fail} {v['outcomes'] and {k: n for k, n in v['outcomes'].items() if n}} | {c['false_safe']} | {c['false_unsafe']} | {v['agreement']:.3f} | {dis} of {len(rows)} | {len(tilt)}{' (' + tilts + ')' if tilt else ''} |")
