"""Round 38 third batch: the stick / bottle carried along x (across the closing axis: swings about it),
at 1x and 0.5x time. usage: gen3.py OUTDIR"""
import sys, pathlib, runpy, shutil, numpy as np
sys.argv = [sys.argv[0], sys.argv[1]]
g = runpy.run_path(str(pathlib.Path(__file__).parent / "gen.py"))
traj, pose, pd, OUT = g["traj"], g["pose"], g["pd"], g["OUT"]
g["cases"].clear(); cases = g["cases"]
X, Y = g["X"], g["Y"]
for obj, z in (("stick", 0.125), ("bottle", 0.11)):
    for ts in (1.0, 0.5):
        scen = f"{obj}_x{'' if ts == 1.0 else '_fast'}"
        d = OUT / scen; shutil.copytree(OUT / obj, d, dirs_exist_ok=True)
        goal = (0.66, Y + 0.02, z)
        t = (d / "scenario.toml").read_text().replace(f"goal = [0.5, 0.15, {z}]", f"goal = [{goal[0]}, {goal[1]}, {goal[2]}]")
        assert str(goal[0]) in t; (d / "scenario.toml").write_text(t)
        traj(f"X_{scen}", scen, pose(z), pd.PickPlaceOptions(goal=goal, grasp_offset=0.0, place_clearance=0.003, time_scale=ts))
(OUT / "cases3.tsv").write_text("".join(f"{c}\t{s}\n" for c, s in cases))
