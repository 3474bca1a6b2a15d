"""F4 follow-up: one pick-and-place whose hand opens slowly (2 s instead of 0.5 s). usage: gen3.py OUTDIR"""
import sys
src = open(__file__.replace("gen3.py", "gen.py")).read()
exec(src.split("# --- objects")[0])
import os
T_OPEN = int(os.environ.get("T_OPEN", "470"))
segs = (75, 125, 140, 165, 180, 230, 305, 355, 370, T_OPEN, T_OPEN + 50, T_OPEN + 105)
traj(f"P_slowopen{T_OPEN}", "panda", pose(0.02), segs=segs)
(OUT / "cases5.tsv").write_text("".join(f"{c}\t{s}\n" for c, s in cases))
