"""Per-sample: critmoment's ground truth new vs old (validate JSONs of this probe) vs r29's
independent plain-MuJoCo truth (robots/truth.py: absolute slip rule, and its two-sided
relative rule), matched by parameter values.  usage: cmp_truth.py VAL_NEW VAL_OLD TRUTH.json"""
import json, sys
vn, vo, tr = (json.load(open(p)) for p in sys.argv[1:4])
key = lambda d: tuple(round(v, 9) for v in d.values())
truth = {key(r["values"]): r for r in tr["rows"]}
def gt(p): return p.get("actual") or p.get("outcome") or p.get("ground_truth")

rows = []
cnt = {"new_vs_old": 0, "new_vs_abs": 0, "new_vs_rel": 0, "old_vs_abs": 0, "old_vs_rel": 0, "n": 0, "new_pass_abs_fail": 0, "old_pass_abs_fail": 0}
for pn, po in zip(vn["per_sample"], vo["per_sample"]):
    assert key(pn["values"]) == key(po["values"])
    t = truth.get(key(pn["values"]))
    fn = pn["real_failed"]
    fo = po["real_failed"]
    cnt["n"] += 1; cnt["new_vs_old"] += fn != fo
    if t is None: continue
    ta = t["mine"] != "SUCCESS"; trl = t["info"].get("outcome_rel", t["mine"]) != "SUCCESS"
    cnt["new_vs_abs"] += fn != ta; cnt["new_vs_rel"] += fn != trl
    cnt["old_vs_abs"] += fo != ta; cnt["old_vs_rel"] += fo != trl
    cnt["new_pass_abs_fail"] += (not fn) and ta; cnt["old_pass_abs_fail"] += (not fo) and ta
    if fn != fo or fn != ta:
        print(f"  #{pn.get('index', '?')} {pn['values']} cm new {pn['outcome']} old {po['outcome']} | truth abs {t['mine']} "
              f"(abs slip {t['info'].get('max_slip_mm')} mm, rel {t['info'].get('max_slip_rel_mm')} mm) rel-rule {t['info'].get('outcome_rel')}")
print(cnt)
