"""Compare the reports of two audit.py outputs (timings stripped already): prints SAME or the
differing keys.   python same.py A.json B.json"""
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
ra, rb = a["report"], b["report"]
def diff(x, y, path=""):
    if type(x) != type(y): return [path]
    if isinstance(x, dict):
        out = []
        for k in sorted(set(x) | set(y)):
            if k not in x or k not in y: out.append(path + "/" + k)
            else: out += diff(x[k], y[k], path + "/" + k)
        return out
    if isinstance(x, list):
        if len(x) != len(y): return [path + f"[len {len(x)}!={len(y)}]"]
        out = []
        for i, (u, v) in enumerate(zip(x, y)): out += diff(u, v, f"{path}[{i}]")
        return out
    return [] if x == y else [path]
d = diff(ra, rb)
print("SAME" if not d else f"DIFF {len(d)}: {d[:20]}",
      f"| steps {a.get('total_steps')} -> {b.get('total_steps')}",
      "| cpu", [round(c, 2) for _, c in a["times"]], "->", [round(c, 2) for _, c in b["times"]])
