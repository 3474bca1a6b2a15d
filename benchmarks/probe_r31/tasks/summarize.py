"""validate table from val_*.json in DIR. usage: summarize.py DIR"""
import json, pathlib, sys
D = pathlib.Path(sys.argv[1]); rows = []; tot = dict(n=0, s=0, fs=0, fu=0)
for f in sorted(D.glob("val_*.json")):
    d = json.load(open(f)); c = d["confusion"]; o = {k: v for k, v in d["outcomes"].items() if v}
    n = len(d["per_sample"]); tot["n"] += 1; tot["s"] += n; tot["fs"] += c["false_safe"]; tot["fu"] += c["false_unsafe"]
    rows.append(f"| {f.stem[4:]} | {'yes' if d['nominal_completed'] else '**no**'} | {n} | {o} | {c['false_safe']} | {c['false_unsafe']} | {d['agreement']:.3f}{' (vacuous)' if d.get('vacuous') else ''} |")
print("| case | nominal completes | samples | outcomes | FS | FU | agreement |\n|---|---|---|---|---|---|---|")
print("\n".join(rows))
print(f"\n**{tot['n']} validations, {tot['s']} samples: {tot['fs']} false safes, {tot['fu']} false unsafes.**")
