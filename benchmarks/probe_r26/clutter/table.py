"""results.tsv -> a markdown table (last row per variant and sample count), with region.tsv's
brute-force check of each stated safe region. usage: python table.py"""
import csv
from pathlib import Path

HERE = Path(__file__).resolve().parent
rows = {}
with open(HERE / "results.tsv") as f:
    for r in csv.DictReader(f, delimiter="\t"):
        rows[(r["variant"], r["samples"])] = r
reg = {}
if (HERE / "region.tsv").exists():
    for line in open(HERE / "region.tsv"):
        p = line.rstrip("\n").split("\t")
        if len(p) >= 4:
            reg[p[0]] = f"{p[3]}/{p[2]}"


def fmt(x, nd=3):
    try:
        return f"{float(x):.{nd}f}"
    except ValueError:
        return x


print("| variant | n | verdict (rc) | P(success) | analyze s | real succ / fail | FS | FU | agreement | stated safe region | region points failing / run |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for (v, n), r in rows.items():
    real_s = int(r["TS"]) + int(r["FS"]) if r["TS"] not in ("None", "") else "-"
    real_f = int(r["TU"]) + int(r["FU"]) if r["TU"] not in ("None", "") else "-"
    vac = " (vacuous)" if r["vacuous"] == "True" else ""
    print(f"| {v} | {n} | {r['verdict']} ({r['analyze_rc']}) | {fmt(r['p_success'])} | {r['analyze_s']} | "
          f"{real_s} / {real_f} | {r['FS']} | {r['FU']} | {fmt(r['agreement'])}{vac} | {r['safe_region']} | {reg.get(v, '-')} |")
