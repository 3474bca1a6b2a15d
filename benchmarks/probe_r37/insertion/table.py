"""Markdown results table from /tmp/r37/insertion/res (validate, truth, analyze, region files)."""
import json
import os

R = "/tmp/r37/insertion/res"
CASES = [  # name, audited object / gripper, trajectory, contact model, box
    ("peg_ship", "peg / right", "v0", "shipped (pyramidal 1)", "init: mass 0.025–1 kg, friction 0.2–1.5"),
    ("peg1_ship", "peg / right", "v1", "shipped (pyramidal 1)", "init"),
    ("peg_ship_narrow", "peg / right", "v1", "shipped (pyramidal 1)", "narrow: mass 0.025–0.2, friction 0.5–1.5"),
    ("peg_ell", "peg / right", "v1", "elliptic 10", "init"),
    ("peg_ell_narrow", "peg / right", "v1", "elliptic 10", "narrow: mass 0.025–0.2, friction 0.5–1.5"),
    ("peg1_sockmissed", "peg / right", "v1, socket moved 6 cm (left arm misses it)", "shipped (pyramidal 1)", "init"),
    ("sock_ship", "socket / left", "v1", "shipped (pyramidal 1)", "init"),
    ("sock_ship_narrow", "socket / left", "v1", "shipped (pyramidal 1)", "narrow: mass 0.3–0.8 (nominal 0.4), friction 0.5–1.2"),
    ("sock_ell", "socket / left", "v1", "elliptic 10", "init"),
    ("sock_ell_narrow", "socket / left", "v1", "elliptic 10", "narrow: mass 0.3–0.8 (nominal 0.4), friction 0.5–1.2"),
    ("sock_ell_v0", "socket / left", "v0 (peg never lifted)", "elliptic 10", "init"),
]
print("| case | object / gripper | traj | contact | box | critmoment brute force: success / fail (how) | validate FS / FU, agreement | insertion truth: success / fail | vs truth: FS / FU (pred) | analyze (256): verdict, P, stated region | region corners+centre failing the truth |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for n, obj, tr, cm_, box in CASES:
    vp, tp, ap, rp = (f"{R}/val_{n}.json", f"{R}/truth_{n}.json", f"{R}/an_{n}.json", f"{R}/region_{n}.txt")
    mode = "prio"
    if os.path.exists(f"{R}/truthpairs_{n}.json"):
        tp, mode = f"{R}/truthpairs_{n}.json", "pairs"
    if not os.path.exists(vp):
        continue
    v = json.load(open(vp))
    o = v["outcomes"]
    how = ", ".join(f"{k} {c}" for k, c in o.items() if c and k != "success")
    c = v["confusion"]
    row = [n, obj, tr, cm_, box, f"{o['success']} / {64 - o['success']} ({how})",
           f"{c['false_safe']} / {c['false_unsafe']}, {v['agreement']:.3f}"]
    if os.path.exists(tp):
        t = json.load(open(tp))
        ts = sum(x["success"] for x in t)
        fs = sum(x["cm_pred_ok"] and not x["success"] for x in t)
        fu = sum((not x["cm_pred_ok"]) and x["success"] for x in t)
        row += [f"{ts} / {len(t) - ts} ({mode})", f"**{fs}** / {fu}" if fs else f"{fs} / {fu}"]
    else:
        row += ["–", "–"]
    if os.path.exists(ap):
        a = json.load(open(ap))
        row.append(f"{a['verdict']}, {a['p_success']:.3f}, {a['safe_region_text'].split(' (checked')[0]}")
    else:
        row.append("not run (time)")
    if os.path.exists(rp):
        last = open(rp).read().strip().splitlines()[-1]
        row.append(last.split("failing the insertion truth: ")[-1])
    else:
        row.append("–")
    print("| " + " | ".join(row) + " |")
