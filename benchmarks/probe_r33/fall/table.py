"""Markdown rows: case | samples | FS/FU/agreement (verify) | FS/FU/agreement (no verify) | real outcomes |
truth: pass/fail disagreements, samples truth-checked, completed runs with a raw fall, FALL failures.
usage: table.py TAG ...   (run in /tmp/r33/fall)"""
import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r33/src"), _cm_check.__file__  # r33 snapshot
import json, os, sys
print("| case | samples | verify: FS / FU / agreement | no-verify: FS / FU / agreement | real outcomes (critmoment brute force) | indep. truth: checked / pass-fail disagreements | completed runs with a >3 cm fall (truth) | of them failed by critmoment |")
print("|---|---|---|---|---|---|---|---|")
for tag in sys.argv[1:]:
    if not os.path.exists(f"val_{tag}.json"):
        continue
    v = json.load(open(f"val_{tag}.json"))
    nv = json.load(open(f"valnv_{tag}.json")) if os.path.exists(f"valnv_{tag}.json") else None
    tr = json.load(open(f"tr_{tag}.json")) if os.path.exists(f"tr_{tag}.json") else None
    c = v["confusion"]; o = {k: n for k, n in v["outcomes"].items() if n}
    nvs = f"{nv['confusion']['false_safe']} / {nv['confusion']['false_unsafe']} / {nv['agreement']:.3f}" if nv else "–"
    if tr:
        rows = tr["rows"]; dis = sum(not r["agree_fail_rel"] for r in rows)
        fc = [r for r in rows if r["info"].get("completed") and r["info"].get("fall_raw_at")]
        fcf = sum(v["per_sample"][r["i"]]["real_failed"] for r in fc)
        trs, fcs, fcfs = f"{len(rows)} / {dis}", str(len(fc)), str(fcf)
    else:
        trs = fcs = fcfs = "–"
    print(f"| {tag} | {len(v['per_sample'])} | {c['false_safe']} / {c['false_unsafe']} / {v['agreement']:.3f} | {nvs} | {o} | {trs} | {fcs} | {fcfs} |")
