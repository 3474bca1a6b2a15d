"""table of ana_*.json in DIR. usage: ana_summary.py DIR [--long]"""
import json, pathlib, sys
D = pathlib.Path(sys.argv[1]); long = "--long" in sys.argv
print("| case | verdict | P(success) | stated safe region | points checked | failing inside |\n|---|---|---|---|---|---|")
for f in sorted(D.glob("ana_*.json")):
    d = json.load(open(f))
    if d.get("skipped"): continue
    rc = d.get("region_check") or []
    print(f"| {f.stem[4:]} | {d['verdict']} | {d['p_success']:.3f} | {d['safe_region_text']} | {len(rc)} | {len(d.get('region_failures') or [])} |")
    if long:
        for c in d["causes"]: print("    cause:", c[:400])
        for m in d["moments"]: print("    moment", m["step"], m["time"], m["label"], "crit", m["critical"], m["critical_side"], "ff", m["fail_fraction"], "overturned", m["overturned"], "worst_fails", m["worst_fails"], m["dominant"], m["limiting_actuator"])
        for r in d.get("region_failures") or []: print("    REGION FAIL", r)
        print("    warnings:", [w[:200] for w in d.get("warnings") or []])
