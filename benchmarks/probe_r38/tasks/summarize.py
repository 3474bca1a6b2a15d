"""Table of validate results: summarize.py GENDIR [PREFIX=val_]"""
import json, sys, pathlib, collections
g = pathlib.Path(sys.argv[1]); pre = sys.argv[2] if len(sys.argv) > 2 else "val_"
print("| case | nominal completes | samples | real succ / fail | outcomes | own runs | FS | FU | agreement |")
print("|---|---|---|---|---|---|---|---|---|")
for f in sorted(g.glob(pre + "*.json")):
    d = json.load(open(f)); c = d["confusion"]; ps = d["per_sample"]
    rs = sum(not p["real_failed"] for p in ps); rf = len(ps) - rs
    oc = {k: v for k, v in d["outcomes"].items() if v}
    own = sum(bool(p.get("verified")) for p in ps)
    ag = f'{d["agreement"]:.3f}' + (" (vacuous)" if d.get("vacuous") else "")
    print(f'| {f.stem[len(pre):]} | {"yes" if d.get("nominal_completed") else "**no**"} | {len(ps)} | {rs} / {rf} | {oc} | {own} | '
          f'{c["false_safe"]} | {c["false_unsafe"]} | {ag} |')
