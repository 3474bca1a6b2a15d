"""Diffs analyze --json reports (timings excluded): diff_reports.py BASE.json OTHER.json ..."""
import json, sys

def flat(d, pre=""):
    if isinstance(d, dict):
        for k, v in d.items():
            yield from flat(v, f"{pre}.{k}" if pre else k)
    elif isinstance(d, list):
        for i, v in enumerate(d):
            yield from flat(v, f"{pre}[{i}]")
    else:
        yield pre, d

base = dict(flat(json.load(open(sys.argv[1]))))
for other in sys.argv[2:]:
    o = dict(flat(json.load(open(other))))
    diffs = [(k, base.get(k), o.get(k)) for k in sorted(set(base) | set(o))
             if not k.startswith("timings") and base.get(k) != o.get(k)]
    print(f"== {other}: {len(diffs)} differing fields")
    for k, a, b in diffs[:40]:
        print(f"   {k}: {str(a)[:150]!s} | {str(b)[:150]!s}")
