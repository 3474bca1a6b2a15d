"""Old vs new: validate JSON (critmoment GT + audit) against one independent-truth JSON
(plain MuJoCo; its pass/fail does not depend on the critmoment version).
usage: compare.py TAG OLD_VAL NEW_VAL [TRUTH]   ('-' for a missing file)"""
import json, os, sys
tag, ov, nv = sys.argv[1:4]
trp = sys.argv[4] if len(sys.argv) > 4 else '-'
def ld(p): return json.load(open(p)) if p != '-' and os.path.exists(p) else None
tr = ld(trp)
def vsum(v):
    if v is None: return '–'
    c = v['confusion']; o = v['outcomes']; s = o.get('success', 0)
    fl = ' '.join(f"{k} {n}" for k, n in o.items() if k != 'success' and n)
    out = f"{s}/{v['samples']-s} ({fl}); FS {c['false_safe']} FU {c['false_unsafe']} agr {v['agreement']:.3f}"
    if tr:
        rows = tr['rows']; assert len(rows) == len(v['per_sample'])
        ind = [r['info'].get('outcome_rel', r.get('mine')) != 'SUCCESS' for r in rows]
        cmf = [p['real_failed'] for p in v['per_sample']]
        unsafe = [i for i in range(len(rows)) if ind[i] and not cmf[i]]
        cons = [i for i in range(len(rows)) if cmf[i] and not ind[i]]
        out += f"; indep rel {len(rows)-sum(ind)}/{sum(ind)}: dis {len(unsafe)+len(cons)} (cm pass/indep fail {unsafe}; cm fail/indep pass {cons})"
    return out
print(f"{tag}\n  old: {vsum(ld(ov))}\n  new: {vsum(ld(nv))}")
a, b = ld(ov), ld(nv)
if a and b:
    for i, (x, y) in enumerate(zip(a['per_sample'], b['per_sample'])):
        if x['outcome'] != y['outcome'] or x['predicted_failed'] != y['predicted_failed']:
            print(f"   sample {i} {dict((k, round(v, 4)) for k, v in x['values'].items())}: old {x['outcome']} pred_fail {x['predicted_failed']} step {x['first_failure_step']} -> new {y['outcome']} pred_fail {y['predicted_failed']} step {y['first_failure_step']}")
