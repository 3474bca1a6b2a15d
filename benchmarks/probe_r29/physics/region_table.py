"""Markdown table of analyze verdicts and region checks: python region_table.py"""
import json
import re
from pathlib import Path

R = Path("/tmp/r29/physics/v")
print("| variant | verdict | P(success) | stated region | grid + inside check (brute force) | dense check (brute force) |")
print("|---|---|---|---|---|---|")
for d in sorted(R.iterdir()):
    rep = d / "ana" / "report.json"
    if not rep.exists():
        continue
    j = json.loads(rep.read_text())
    rc = d / "ana" / "region_check.json"
    grid = ""
    if rc.exists():
        r = json.loads(rc.read_text())
        grid = f"{len(r['failures'])} of {r['points']} fail"
    dense = ""
    if (d / "region_dense.txt").exists():
        m = re.search(r"(\d+) points, (\d+) failures", (d / "region_dense.txt").read_text())
        if m:
            dense = f"{m.group(2)} of {m.group(1)} fail"
    text = j["safe_region_text"].split(" (checked")[0]
    print(f"| {d.name} | {j['verdict']} | {j['p_success']:.3f} | {text} | {grid} | {dense} |")
