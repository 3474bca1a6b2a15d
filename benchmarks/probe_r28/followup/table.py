"""Markdown table of every validate JSON in /tmp/r28b/w: python table.py"""
import json, glob, os
rows = []
for f in sorted(glob.glob("/tmp/r28b/w/val*.json")):
    j = json.load(open(f)); c = j["confusion"]
    real_s = c["true_safe"] + c["false_unsafe"]; real_f = c["true_unsafe"] + c["false_safe"]
    rows.append((os.path.basename(f)[:-5], j["samples"], f"{real_s}/{real_f}", c["false_safe"], c["false_unsafe"],
                 f'{j["agreement"]:.3f}' + (" (vacuous)" if j["vacuous"] else "")))
print("| run (val*_<case>.<scenario>[.traj][.seed]) | samples | real success/fail | false safe | false unsafe | agreement |")
print("|---|---|---|---|---|---|")
for r in rows:
    print("| " + " | ".join(str(x) for x in r) + " |")
print(f"\n{len(rows)} runs; false safes in all: {sum(r[3] for r in rows)}; agreement < 0.95: {sum(float(r[5][:5]) < 0.95 for r in rows)}")
