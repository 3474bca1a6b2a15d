"""Markdown results table. usage: table.py CASEDIR ...  (run from /tmp/r33/clutter)
collateral / collision: critmoment-successes (brute force) in which another free body ends > 2 cm from its start,
tilted > 30 deg or below the table top / in which the object touched a non-support, non-gripper geom (truth.py)."""
import json, sys
import numpy as np, mujoco
import critmoment as _c; assert _c.__file__.startswith("/tmp/r33/src2"), _c.__file__
print("| case | samples | verify: FS / FU / agreement | no-verify: FS / FU / agreement | outcomes (critmoment brute force) | indep. truth: checked / pass-fail disagreements (cm permissive, cm stricter) | successes with collateral | successes with object collision |")
print("|---|---|---|---|---|---|---|---|")
for d in sys.argv[1:]:
    v = json.load(open(f"{d}/val.json")); nv = json.load(open(f"{d}/valnv.json"))
    t = json.load(open(f"{d}/tr.json")); rs = t["rows"] if isinstance(t, dict) else t
    m = mujoco.MjModel.from_xml_path(f"{d}/scene.xml"); k = m.key("home").qpos; start = {}
    for b in range(m.nbody):
        if m.body_jntnum[b] and m.jnt_type[m.body_jntadr[b]] == 0 and m.body(b).name != "cube":
            a = m.jnt_qposadr[m.body_jntadr[b]]; start[m.body(b).name] = k[a:a + 3]
    perm = strict = coll = colli = 0
    for r in rs:
        real = v["per_sample"][r["i"]]["real_failed"]; mine = r["info"].get("outcome_rel", r["mine"]) != "SUCCESS"
        perm += (mine and not real); strict += (real and not mine)
        if not real:
            bad = any(np.linalg.norm(np.array(p) - start[n]) > 0.02 or np.degrees(np.arccos(np.clip(zz, -1, 1))) > 30 or p[2] < 0
                      for n, (p, zz) in (r.get("free_end") or {}).items())
            coll += bad; colli += bool(r.get("other_steps"))
    c, cn = v["confusion"], nv["confusion"]
    out = {a: b for a, b in v["outcomes"].items() if b}
    print(f"| {d} | {len(v['per_sample'])} | {c['false_safe']} / {c['false_unsafe']} / {v['agreement']:.3f} | {cn['false_safe']} / {cn['false_unsafe']} / {nv['agreement']:.3f} | {out} | {len(rs)} / {perm+strict} ({perm}, {strict}) | {coll} | {colli} |")
