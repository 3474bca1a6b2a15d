"""The report's table: old vs new per case (validate JSONs + the probe's recorded independent truth)."""
import json, os
F = "/tmp/r36f/followup"; B = "/work/main/benchmarks"
U = f"{B}/probe_r34/unseen/results"; R32 = f"{B}/probe_r32/robots/results"; R30 = f"{B}/probe_r30/robots/results"; R31 = f"{B}/probe_r31/robots/results"
def pick(*ps):
    for p in ps:
        if p and os.path.exists(p): return p
    return None
C = []  # (robot, contact, box, old_val (805c813 run if any, else the probe's), new_val, truth, old_src)
for tag, rob, con, box in [("piper_pyr_light", "PiPER", "pyr 1", "light 0.02-0.05 x 1.0-1.5"), ("piper_pyr_init", "PiPER", "pyr 1", "init"),
                           ("piper_pyr_narrow", "PiPER", "pyr 1", "narrow"), ("piper_ell_init", "PiPER", "ell 10", "init"),
                           ("piper_ell_narrow", "PiPER", "ell 10", "narrow"), ("piper_ell_edge", "PiPER", "ell 10", "edge"), ("piper_pyr_edge", "PiPER", "pyr 1", "edge"),
                           ("ell_init", "ALOHA 2 (ACT 2x)", "ell 10", "init"), ("ell_narrow", "ALOHA 2 (ACT 2x)", "ell 10", "narrow"),
                           ("pyr_init", "ALOHA 2 (ACT 2x)", "pyr 1", "init"), ("pyr_narrow", "ALOHA 2 (ACT 2x)", "pyr 1", "narrow"),
                           ("prop_ell_init", "ALOHA 2 proper", "ell 10", "init"), ("prop_ell_heavy", "ALOHA 2 proper", "ell 10", "heavy"), ("prop_pyr_heavy", "ALOHA 2 proper", "pyr 1", "heavy")]:
    C.append((rob, con, box, f"{F}/res_old/val_{tag}.json", f"{U}/val_{tag}.json", f"{F}/res/val_{tag}.json", f"{U}/tr_{tag}.json"))
for tag, rob, con, box, tr in [("scen_hold", "Jaco pick_hold", "pyr 1", "init", "truth_scen_hold"), ("scen_hold_narrow", "Jaco pick_hold", "pyr 1", "narrow", "truth_scen_hold_narrow"),
                               ("motor_dz_init", "Jaco pick_place dz", "pyr 1", "init", "truth_motor_dz_init"), ("motor_init", "Jaco pick_place s3", "pyr 1", "init", "truth_motor_init"),
                               ("scen_ell", "Jaco pick_place dz", "ell 10", "init", "truth_scen_ell"), ("motor_dz_narrow", "Jaco pick_place dz", "pyr 1", "narrow", None),
                               ("motor_narrow", "Jaco pick_place s3", "pyr 1", "narrow", None), ("scen_ell_narrow", "Jaco pick_place dz", "ell 10", "narrow", None),
                               ("motor_heavy", "Jaco pick_place dz", "pyr 1", "heavy", None)]:
    C.append((rob, con, box, f"{F}/res_old/val_r32_{tag}.json", f"{R32}/val_{tag}.json", f"{F}/res/val_r32_{tag}.json", tr and f"{R32}/{tr}.json"))
for d, tag, rob, con, box in [("orca", "e_init", "Gen3+ORCA", "ell 10", "init"), ("orca", "s_init", "Gen3+ORCA", "pyr 1 (shipped)", "init"),
                              ("orca", "e_narrow", "Gen3+ORCA", "ell 10", "narrow"), ("orca", "s_narrow", "Gen3+ORCA", "pyr 1 (shipped)", "narrow"),
                              ("gen3", "s_init", "Gen3+2F-85", "pyr 1 (shipped)", "init"), ("gen3", "s_narrow", "Gen3+2F-85", "pyr 1", "narrow"),
                              ("gen3", "e_init", "Gen3+2F-85", "ell 10", "init"), ("gen3", "e_narrow", "Gen3+2F-85", "ell 10", "narrow")]:
    C.append((rob, con, box, f"{F}/res_old/val_r30_{d}_{tag}.json", f"{R30}/{d}/val_{tag}.json", pick(f"{F}/res3/val_r30_{d}_{tag}.json", f"{F}/res/val_r30_{d}_{tag}.json"), f"{R30}/{d}/truth_{tag}.json"))
for d, dd, tag, ot, rob, con, box in [("trossen_wx250s", "wx", "hold", "hold", "WX250s pick_hold", "ell 10", "0.02-0.2 x 0.2-1.2"), ("trossen_wx250s", "wx", "hold_p", "hold_p", "WX250s pick_hold", "pyr 1", "same"),
                                 ("trossen_wx250s", "wx", "s_init", "s_init", "WX250s", "ell 10", "init"), ("trossen_wx250s", "wx", "pyr1", "pyr1", "WX250s", "pyr 1", "init"),
                                 ("trossen_wx250s", "wx", "shipped_n", "shipped_n", "WX250s", "ell 10", "narrow"), ("trossen_wx250s", "wx", "pyr1_n", "pyr1_n", "WX250s", "pyr 1", "narrow"),
                                 ("low_cost_robot_arm", "lc", "shipped", "shipped", "low-cost arm", "ell 10", "init"), ("low_cost_robot_arm", "lc", "pyr1", "pyr1", "low-cost arm", "pyr 1", "init"),
                                 ("low_cost_robot_arm", "lc", "shipped_m", "shipped_m", "low-cost arm", "ell 10", "mid"), ("low_cost_robot_arm", "lc", "shipped_n", "shipped_n", "low-cost arm", "ell 10", "narrow"),
                                 ("low_cost_robot_arm", "lc", "pyr1_n", "pyr1_n", "low-cost arm", "pyr 1", "narrow"), ("low_cost_robot_arm", "lc", "pyr1_n2", "pyr1_n2", "low-cost arm", "pyr 1", "narrow2")]:
    C.append((rob, con, box, f"{F}/res_old/val_r31_{d}_{tag}.json", f"{R31}/{dd}/val_{ot}.json", f"{F}/res/val_r31_{d}_{tag}.json", f"{R31}/{dd}/t_{ot}.json"))
def ld(p): return json.load(open(p)) if p and os.path.exists(p) else None
def cell(v, tr):
    if v is None: return "not run", "", ""
    c = v["confusion"]; o = v["outcomes"]; s = o.get("success", 0)
    fl = ", ".join(f"{n} {k}" for k, n in o.items() if k != "success" and n)
    t = "–"
    if tr and len(tr["rows"]) == len(v["per_sample"]):
        ind = [r["info"].get("outcome_rel", r.get("mine")) != "SUCCESS" for r in tr["rows"]]
        cmf = [p["real_failed"] for p in v["per_sample"]]
        a = sum(i and not f for i, f in zip(ind, cmf)); b = sum(f and not i for i, f in zip(ind, cmf))
        t = f"{a} / {b}"
    return f"{s}/{v['samples']-s} ({fl})", f"{c['false_safe']} / {c['false_unsafe']} / {v['agreement']:.3f}", t
print("| robot | contact | box | old: S/F (failures) | old FS/FU/agr | old indep dis (cm pass & indep fail / cm fail & indep pass) | new: S/F | new FS/FU/agr | new indep dis | changed |")
print("|---|---|---|---|---|---|---|---|---|---|")
for rob, con, box, o805, oprobe, nv, trp in C:
    tr = ld(trp); o = ld(o805); src = "805c813"
    if o is None: o = ld(oprobe); src = "probe"
    n = ld(nv)
    if n is None: continue
    a = cell(o, tr); b = cell(n, tr)
    ch = "" if o is None else ("no" if [p["outcome"] for p in o["per_sample"]] == [p["outcome"] for p in n["per_sample"]] and [p["predicted_failed"] for p in o["per_sample"]] == [p["predicted_failed"] for p in n["per_sample"]] else "**yes**")
    print(f"| {rob} | {con} | {box} | {a[0]} [{src}] | {a[1]} | {a[2]} | {b[0]} | {b[1]} | {b[2]} | {ch} |")
