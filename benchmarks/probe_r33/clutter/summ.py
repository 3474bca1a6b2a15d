"""Results table for the clutter cases + collateral effects (truth.py's per-sample other free bodies / contacts).
usage: summ.py CASEDIR ...   (run from /tmp/r33/clutter)
Engineer's-judgement failure rules fixed before looking at the results:
  * collateral: another free body ends > 2 cm from its start, tilted > 30 deg, or below the table top (z < 0);
  * collision: the carried object touched a geom that is neither a support nor a gripper (steps > 0)."""
import json, sys, re
import numpy as np, mujoco
import critmoment as _c; assert _c.__file__.startswith("/tmp/r33/src2"), _c.__file__
rows = []
for d in sys.argv[1:]:
    v = json.load(open(f"{d}/val.json")); nv = json.load(open(f"{d}/valnv.json"))
    try: tr = json.load(open(f"{d}/tr.json"))
    except Exception: tr = None
    m = mujoco.MjModel.from_xml_path(f"{d}/scene.xml"); k = m.key("home").qpos
    start = {}
    for b in range(m.nbody):
        if m.body_jntnum[b] and m.jnt_type[m.body_jntadr[b]] == 0 and m.body(b).name != "cube":
            a = m.jnt_qposadr[m.body_jntadr[b]]; start[m.body(b).name] = k[a:a + 3]
    c, cn = v["confusion"], nv["confusion"]
    print(f"\n## {d}: verify FS {c['false_safe']} FU {c['false_unsafe']} agr {v['agreement']:.3f} | no-verify FS {cn['false_safe']} FU {cn['false_unsafe']} agr {nv['agreement']:.3f} | outcomes {dict((a,b) for a,b in v['outcomes'].items() if b)}")
    dis = coll = colli = 0
    if tr is None: print("  (no truth)"); continue
    rs = tr["rows"] if isinstance(tr, dict) and "rows" in tr else tr
    for r in rs:
        i = r["i"]; p = v["per_sample"][i]; pn = nv["per_sample"][i]
        mine = r["info"].get("outcome_rel", r["mine"])
        real_fail = p["real_failed"]
        d_fail = (mine != "SUCCESS") != real_fail
        dis += d_fail
        notes = []
        for name, (pos, zz) in (r.get("free_end") or {}).items():
            disp = float(np.linalg.norm(np.array(pos) - start[name])); tilt = float(np.degrees(np.arccos(np.clip(zz, -1, 1))))
            bad = disp > 0.02 or tilt > 30 or pos[2] < 0
            notes.append(f"{name} moved {100*disp:.1f} cm tilt {tilt:.0f}deg{' BAD' if bad else ''}")
            if bad and not real_fail: coll += 1
        if r.get("other_steps"):
            notes.append(f"object touched non-support {r['other_steps']} steps")
            if not real_fail: colli += 1
        flag = " <== TRUTH DISAGREES" if d_fail else ""
        if d_fail or (not real_fail and any("BAD" in x or "touched" in x for x in notes)) or (p["predicted_failed"] != real_failed if (real_failed:=real_fail) is not None else False) or pn["predicted_failed"] != real_fail:
            print(f"  {i:2d} m={r['values'].get('mass', 0):.4f} mu={r['values'].get('friction', 0):.3f} cm={p['outcome']} pred={p['predicted_failed']} predNV={pn['predicted_failed']} truth={mine} {'; '.join(notes)}{flag}")
    print(f"  truth checked {len(rs)}, pass/fail disagreements {dis}; critmoment-successes with collateral {coll}, with object collision {colli}")
