"""Markdown results table from /tmp/r29/physics/val.tsv (+ truth.tsv): python table.py"""
import json
from pathlib import Path

R = Path("/tmp/r29/physics")
DESC = {}
for line in (Path(__file__).parent / "variants.tsv").read_text().splitlines():
    if line.strip() and not line.startswith("#"):
        k, box, d = line.split("\t")
        DESC[k] = (box, d)
truth = {}
if (R / "truth.tsv").exists():
    for line in (R / "truth.tsv").read_text().splitlines():
        p = line.split("\t")
        truth[p[0]] = p[-1].replace("fail/pass disagreements ", "").split(" label")[0]
print("| variant | what | box | samples | real success / fail | false safes | false unsafes | agreement | compute / brute force | validate wall [s] | independent truth: pass/fail disagreements (of 32) |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for line in (R / "val.tsv").read_text().splitlines():
    v, n, seed, rs, rf, fs, fu, ag, vac, ratio, wall, outc = line.split("\t")
    box, d = DESC.get(v, ("", ""))
    vac = " (vacuous)" if vac == "True" else ""
    print(f"| {v} | {d} | {box} | {n} | {rs} / {rf}{vac} | {fs} | {fu} | {ag} | {ratio} | {wall} | {truth.get(v, '')} |")
