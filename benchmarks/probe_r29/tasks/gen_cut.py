"""Panda demo (seed 0) cut while the arm still moves: after the release (retreating up) and mid-descent
(before the release: must FAIL). usage: gen_cut.py OUTDIR"""
import pathlib, sys
import numpy as np
from critmoment import panda_demo as pd
OUT = pathlib.Path(sys.argv[1])
tr = pd.make_pick_place(0)
for n in (400, 420, 360):
    np.savez(OUT / f"P_cut{n}.npz", actions=tr.actions[:n], fps=tr.fps, start=tr.start, qpos0=tr.qpos0,
             object_pose=tr.object_pose)
    print("wrote", n)
