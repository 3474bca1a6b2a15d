"""compare two gt.py outputs: cmpgt.py OLD.json NEW.json"""
import sys, json
o, n = (json.load(open(f)) for f in sys.argv[1:3])
flips = 0
for a, b in zip(o["rows"], n["rows"]):
    assert a["p"] == b["p"]
    tag = ""
    if a["outcome"] != b["outcome"]:
        tag = "FLIP"; flips += 1
    elif abs(a["max_slip_mm"] - b["max_slip_mm"]) > 0.5:
        tag = "slipdiff"
    if tag:
        print(tag, a["p"], a["outcome"], a["max_slip_mm"], "->", b["outcome"], b["max_slip_mm"])
print(sys.argv[2], "points", len(o["rows"]), "flips", flips, "nominal", o["nominal_completed"], n["nominal_completed"])
