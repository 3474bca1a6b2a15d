"""Collect the results table from /tmp/r28/params (validate JSONs, analyze reports, region checks)."""
import glob
import json
import os

import tomllib

R = "/tmp/r28/params"
rows = []
for v in sorted(glob.glob(f"{R}/val_*.json")):
    b = os.path.basename(v)[4:-5]
    d = json.load(open(v)); c = d["confusion"]
    real_s = c["true_safe"] + c["false_safe"]; real_f = c["true_unsafe"] + c["false_unsafe"]
    a = f"{R}/ana_{b}/report.json"; reg = chk = "-"; verdict = "-"
    if os.path.exists(a):
        r = json.load(open(a)); verdict = f"{r['verdict']} p={r['p_success']:.3f}"
        reg = "none" if r["safe_region"] is None else r["safe_region_text"].split(" (checked")[0].replace("safe for ", "")
        rc = f"{R}/ana_{b}/region_check.json"
        if os.path.exists(rc):
            q = json.load(open(rc)); chk = f"{q['points']} pts, {len(q['failures'])} fail"
    f = next(x for x in (f"scen/{b}.toml", f"scen2/{b}.toml") if os.path.exists(x))
    u = tomllib.load(open(f, "rb"))["uncertainty"]
    params = " × ".join(f"{q.get('kind', k)}({q.get('body') or q.get('geom') or q.get('actuator')}) [{q['range'][0]:g}, {q['range'][1]:g}] nom {q['nominal']:g}" for k, q in u.items())
    rows.append(f"| {b} | {params} | {real_s}/{real_f} | {c['false_safe']} | {c['false_unsafe']} | {d['agreement']:.3f}{' (vacuous)' if d['vacuous'] else ''} | {verdict} | {reg} | {chk} |")
print("| twin_box | box | real success/fail (of 64) | false safe | false unsafe | agreement | analyze verdict | stated region | region brute-force check |")
print("|---|---|---|---|---|---|---|---|---|")
print("\n".join(rows))
