"""Table of analyze + region-check results: ana_summary.py GENDIR"""
import json, sys, pathlib
g = pathlib.Path(sys.argv[1])
print("| case | verdict | P(success) | stated safe region | region points run (critmoment brute force) | failing |")
print("|---|---|---|---|---|---|")
for f in sorted(g.glob("ana_*.json")):
    d = json.load(open(f)); rc = d.get("region_check") or []
    txt = d["safe_region_text"].split(" (checked")[0]
    print(f'| {f.stem[4:]} | {d["verdict"]} | {d["p_success"]:.3f} | {txt} | {len(rc)} | {len(d.get("region_failures") or [])} |')
