"""Non-monotone outcomes in a mass x friction validate run: failures 'easier' than some success
(lighter and grippier). python monotone.py VARIANT [valfile]"""
import json
import sys
v = sys.argv[1]; f = sys.argv[2] if len(sys.argv) > 2 else "val_64_0.json"
d = json.load(open(f"/tmp/r29/physics/v/{v}/{f}"))
P = d["per_sample"]
if not all("mass" in p["values"] and "friction" in p["values"] for p in P):
    sys.exit(0)
S = [(p["values"]["mass"], p["values"]["friction"], p["real_failed"], p["outcome"]) for p in P]
bad = []
for i, (m, mu, fl, o) in enumerate(S):
    if fl:
        dom = [j for j, (m2, mu2, f2, _) in enumerate(S) if not f2 and m2 >= m and mu2 <= mu]
        if dom:
            bad.append((i, round(m, 3), round(mu, 3), o, [(j, round(S[j][0], 3), round(S[j][1], 3)) for j in dom[:3]]))
print(v, "non-monotone failures:", len(bad))
for b in bad:
    print("  ", b)
