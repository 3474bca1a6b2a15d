"""Panda pick_hold variants + trajectories that end while moving.
usage: gen_hold.py OUTDIR (needs gen_panda.py's helpers: imports it with OUTDIR)"""
import pathlib, re, shutil, sys
import numpy as np
sys.argv = [sys.argv[0], sys.argv[1]]
import importlib.util
spec = importlib.util.spec_from_file_location("gp", pathlib.Path(__file__).with_name("gen_panda.py"))
# re-use the helpers without re-running gen_panda's cases: exec only its defs
src = pathlib.Path(__file__).with_name("gen_panda.py").read_text().split("# 1a regrasp")[0]
g = {"__name__": "gp"}; exec(compile(src, "gen_panda.py", "exec"), g)
OUT, build, pick, pd, model, cube, H = g["OUT"], g["build"], g["pick"], g["pd"], g["model"], g["cube"], g["H"]
# pick_hold scenario copy
d = OUT / "hold"; d.mkdir(exist_ok=True)
for f in ("panda.xml", "scene.xml"): shutil.copy(g["SRC"] / f, d / f)
t = (g["SRC"] / "scenario.toml").read_text()
t = re.sub(r"\[task\].*?(?=\n# Force limits)", '[task]\nkind = "pick_hold"\ngripper = "hand"\nlift_height = 0.02\n', t, flags=re.S)
(d / "scenario.toml").write_text(t)
above = np.array([cube[0], cube[1], H])
# long hold, still: pick, lift to 15 cm, hold 8 s
pts = pick(0, cube[:3]) + [(230, above, 0.0), (630, above, 0.0)]
build(model, cube, pts, "P_hold_long")
# long slow sag: after the lift the TCP sinks 10 cm over 8 s (ends 5 cm above the table... cube bottom at ~3.9 cm)
pts = pick(0, cube[:3]) + [(230, above, 0.0), (630, above - [0, 0, 0.10], 0.0)]
build(model, cube, pts, "P_hold_sag")
# sag all the way: cube set back onto the table at the end (should FAIL: on the support)
pts = pick(0, cube[:3]) + [(230, above, 0.0), (630, np.array([cube[0], cube[1], 0.02 + 0.01 - 0.004]), 0.0)]
build(model, cube, pts, "P_hold_sag_to_table")
# ends while moving: still carrying fast sideways at the last step (pick_hold)
pts = pick(0, cube[:3]) + [(230, above, 0.0), (300, above + [0, 0.3, 0], 0.0)]
q = build(model, cube, pts, "P_hold_moving_full")
a = np.load(OUT / "P_hold_moving_full.npz"); dd = dict(a)
dd["actions"] = a["actions"][:265]; np.savez(OUT / "P_hold_end_moving.npz", **dd)
