"""validate table from PREFIX_*.json (default val) in DIR. usage: summarize.py DIR [PREFIX]"""
import json, pathlib, sys
D = pathlib.Path(sys.argv[1]); P = sys.argv[2] if len(sys.argv) > 2 else "val"; rows = []; tot = dict(n=0, s=0, fs=0, fu=0)
for f in sorted(D.glob(f"{P}_*.json")):
    d = json.load(open(f)); c = d["confusion"]; o = {k: v for k, v in d["outcomes"].items() if v}
    n = len(d["per_sample"]); tot["n"] += 1; tot["s"] += n; tot["fs"] += c["false_safe"]; tot["fu"] += c["false_unsafe"]
    rows.append(f"| {f.stem[len(P) + 1:]} | {'yes' if d['nominal_completed'] else '**no**'} | {n} | {d['verified']} | {o} | {c['false_safe']} | {c['false_unsafe']} | {d['agreement']:.3f}{' (vacuous)' if d.get('vacuous') else ''} |")
print("| case | nominal completes | samples | own full rollouts | outcomes | FS | FU | agreement |\n|---|---|---|---|---|---|---|---|")
print("\n".join(rows))
print(f"\n**{tot['n']} validations, {tot['s']} samples: {tot['fs']} false safes, {tot['fu']} false unsafes.**")
