"""Per case: validate (verify / no-verify) confusion + independent truth comparison, with the fall info.
usage: summ.py TAG [TAG ...]   (run in /tmp/r33/fall)"""
import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r33/src"), _cm_check.__file__  # r33 snapshot
import json, sys, os
for tag in sys.argv[1:]:
    try:
        v = json.load(open(f"val_{tag}.json")); nv = json.load(open(f"valnv_{tag}.json"))
    except FileNotFoundError:
        print(tag, "missing"); continue
    tr = json.load(open(f"tr_{tag}.json")) if os.path.exists(f"tr_{tag}.json") else None
    c, cn = v["confusion"], nv["confusion"]
    line = (f"{tag}: n={len(v['per_sample'])} verify FS={c['false_safe']} FU={c['false_unsafe']} agr={v['agreement']} "
            f"own_runs={v.get('own_runs')} | noverify FS={cn['false_safe']} FU={cn['false_unsafe']} agr={nv['agreement']} | outcomes {v['outcomes']}")
    print(line)
    if tr:
        rows = tr["rows"]
        dis = [r for r in rows if not r["agree_fail_rel"]]
        falls = [r for r in rows if "FALL" in r["info"]["events"]]
        fc = [r for r in rows if r["info"].get("completed") and r["info"].get("fall_raw_at")]
        print(f"   truth on {len(rows)}: pass/fail disagreements (rel rule) {len(dis)}; FALL events {len(falls)}; "
              f"completed runs with a raw fall {len(fc)}; nominal {tr['nominal'][0]}")
        for r in dis + [r for r in fc if r not in dis]:
            i = r["i"]
            print(f"   #{i} {r['values']} truth={r['info'].get('outcome_rel')} cm={r['cm_outcome']} pred(verify)={v['per_sample'][i]['predicted_failed']}"
                  f" pred(noverify)={nv['per_sample'][i]['predicted_failed']} completed={r['info'].get('completed')} fall={r['info'].get('fall_raw_at')} "
                  f"fall_any={r['info'].get('fall_any_at')} events={r['info']['events']}")
