"""Table of the probe: per case, the own truth's real success/fail (primary: absolute slip;
secondary: slip relative to the nominal run, critmoment's documented reference), validate's
predictions against it (false safes / false unsafes), agreement of the two ground truths,
and the region check. Reads /tmp/r28/truth_real/{val,res,reg,an}_*.json."""
import json
from pathlib import Path

W = Path("/tmp/r28/truth_real")
CASES = [("act_shipped", "ACT gym-aloha", "shipped (pyramidal, impratio 1)", "init 0.025–1 kg × μ 0.2–1.5"),
         ("act_ell10", "ACT gym-aloha", "elliptic, impratio 10", "init 0.025–1 kg × μ 0.2–1.5"),
         ("act_light_shipped", "ACT gym-aloha", "shipped (pyramidal, impratio 1)", "light 0.025–0.5 kg × μ 0.2–1.0, 64 samples"),
         ("act_light_ell10", "ACT gym-aloha", "elliptic, impratio 10", "light 0.025–0.5 kg × μ 0.2–1.0, 64 samples"),
         ("wxai_shipped", "WidowX AI", "shipped (pyramidal, impratio 1)", "0.1–0.6 kg × μ 0.5–1.0"),
         ("wxai_ell10", "WidowX AI", "elliptic, impratio 10", "0.3–1.5 kg × μ 0.3–0.9"),
         ("oa_shipped", "OpenArm", "shipped (elliptic, impratio 10)", "1.0–2.0 kg × μ 0.2–0.6"),
         ("oa_pyr1", "OpenArm", "pyramidal, impratio 1", "1.0–2.0 kg × μ 0.2–0.6"),
         ("ho_shipped", "OpenArm hand-over (r27)", "shipped (elliptic, impratio 10)", "0.7–1.1 kg × μ 0.2–0.8")]
print("| model | contact | box | own truth succ/fail (abs slip) | (rel slip) | validate (cm GT) succ/fail, FS/FU | "
      "vs own truth abs: FS / FU | vs own truth rel: FS / FU | GT pass/fail disagreements abs / rel | analyze | region: points, own-truth failures (abs/rel), cm GT failures |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for key, model, contact, box in CASES:
    try:
        val = json.load(open(W / f"val_{key}.json")); res = json.load(open(W / f"res_{key}.json"))
    except FileNotFoundError:
        print(f"| {model} | {contact} | {box} | not run |"); continue
    rows = res["rows"]
    pred = {r["i"]: r["cm_predicted_failed"] for r in rows}
    cmf = {r["i"]: r["cm_outcome"] != "success" for r in rows}
    mine = {r["i"]: r["mine"] != "SUCCESS" for r in rows}
    rel = {r["i"]: r["info"].get("outcome_rel", r["mine"]) != "SUCCESS" for r in rows}
    def fsfu(truth):
        fs = [i for i in truth if truth[i] and not pred[i]]; fu = [i for i in truth if pred[i] and not truth[i]]
        return fs, fu
    fs_a, fu_a = fsfu(mine); fs_r, fu_r = fsfu(rel)
    d_a = [i for i in mine if mine[i] != cmf[i]]; d_r = [i for i in rel if rel[i] != cmf[i]]
    c = val["confusion"]
    an = W / f"an_{key}_analyze.json"
    an_txt = "-"
    if an.exists():
        a = json.load(open(an)); an_txt = f"{a['verdict']} P={a['p_success']:.3f}; " + (
            ", ".join(f"{k} {v[0]:.3g}–{v[1]:.3g}" for k, v in a["safe_region"].items()) if a["safe_region"] else "no region")
    reg = W / f"reg_{key}.json"
    reg_txt = "-"
    if reg.exists():
        rr = json.load(open(reg))["rows"]
        fa = [r["i"] for r in rr if r["mine"] != "SUCCESS"]
        fr = [r["i"] for r in rr if r["info"].get("outcome_rel", r["mine"]) != "SUCCESS"]
        fc = [r["i"] for r in rr if r.get("bf", {}).get("outcome", "SUCCESS") != "SUCCESS"]
        reg_txt = f"{len(rr)} points; abs {len(fa)} {fa or ''}, rel {len(fr)} {fr or ''}; cm GT {len(fc)} {fc or ''}"
    n = len(rows)
    print(f"| {model} | {contact} | {box} | {n - sum(mine.values())}/{sum(mine.values())} | {n - sum(rel.values())}/{sum(rel.values())} | "
          f"{n - sum(cmf.values())}/{sum(cmf.values())}, {c['false_safe']}/{c['false_unsafe']} | "
          f"{len(fs_a)} {fs_a or ''} / {len(fu_a)} {fu_a or ''} | {len(fs_r)} {fs_r or ''} / {len(fu_r)} {fu_r or ''} | "
          f"{len(d_a)} {d_a or ''} / {len(d_r)} {d_r or ''} | {an_txt} | {reg_txt} |")
