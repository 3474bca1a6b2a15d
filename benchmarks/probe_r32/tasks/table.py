"""README table: per case, the validate results at each sample count (val_ = 32, val128_, val256_,
valpts_ = explicit points). usage: table.py DIR"""
import json, pathlib, re, sys
D = pathlib.Path(sys.argv[1]); res = {}
for f in D.glob("val*_*.json"):
    m = re.match(r"(val\d*|valpts)_(.*)", f.stem)
    res.setdefault(m.group(2), {})[m.group(1)] = json.load(open(f))
cols = ["val", "val128", "val256", "valpts"]
print("| case | nominal completes | run | samples | own full rollouts | false safes | false unsafes | agreement | vacuous | real outcomes |")
print("|---|---|---|---|---|---|---|---|---|---|")
tot = {}
for case in sorted(res):
    for c in cols:
        d = res[case].get(c)
        if d is None: continue
        k = d["confusion"]; o = {a: b for a, b in d["outcomes"].items() if b}
        t = tot.setdefault(c, [0, 0, 0, 0]); t[0] += 1; t[1] += d["samples"]; t[2] += k["false_safe"]; t[3] += k["false_unsafe"]
        run = {"val": "Sobol 32", "val128": "Sobol 128", "val256": "Sobol 256", "valpts": "grid"}[c]
        print(f"| {case} | {'yes' if d['nominal_completed'] else 'no'} | {run} | {d['samples']} | {d['verified']} | "
              f"{k['false_safe']} | {k['false_unsafe']} | {d['agreement']:.3f} | {'yes' if d['vacuous'] else 'no'} | {o} |")
print()
for c, t in tot.items():
    print(f"- {c}: {t[0]} validations, {t[1]} samples, {t[2]} false safes, {t[3]} false unsafes")

if "--compact" in sys.argv:   # one row per case: samples / own full rollouts / FS / FU / agreement (V = vacuous)
    print("\n| case | nominal completes | " + " | ".join(f"{c}: n / own runs / FS / FU / agreement" for c in cols) + " |")
    print("|---|---|" + "---|" * len(cols))
    for case in sorted(res):
        cells = []
        for c in cols:
            d = res[case].get(c)
            if d is None: cells.append(""); continue
            k = d["confusion"]
            cells.append(f"{d['samples']} / {d['verified']} / {k['false_safe']} / {k['false_unsafe']} / {d['agreement']:.3f}{' V' if d['vacuous'] else ''}")
        nc = next(iter(res[case].values()))["nominal_completed"]
        print(f"| {case} | {'yes' if nc else 'no'} | " + " | ".join(cells) + " |")
