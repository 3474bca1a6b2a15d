"""ALOHA demo seed 0 at 10 s and 2 s (time_scale 1.25 / 0.25) + aloha_m15 scenario copy. usage: gen_aloha.py OUTDIR"""
import pathlib, shutil, sys
import numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r31/src"), critmoment.__file__
from critmoment import demos
OUT = pathlib.Path(sys.argv[1])
src = pathlib.Path(critmoment.__file__).parent.parent / "models" / "aloha_transfer_cube"
d = OUT / "aloha_m15"
if not d.exists():
    shutil.copytree(src, d)
    t = (d / "scenario.toml").read_text().replace("range = [0.05, 10.0]", "range = [0.05, 1.5]")
    (d / "scenario.toml").write_text(t)
with open(OUT / "cases_aloha.tsv", "w") as f:
    for nm, ts in (("A_nominal8s", 1.0), ("A_slow10s", 1.25), ("A_fast2s", 0.25)):
        tr = demos.scripted_transfer(0, options=demos.DemoOptions(time_scale=ts))
        kw = dict(qpos0=tr.qpos0) if tr.qpos0 is not None else {}
        np.savez(OUT / f"{nm}.npz", actions=tr.actions, fps=tr.fps, start=tr.start, object_pose=tr.object_pose, **kw)
        f.write(f"{nm}\taloha_m15\n"); print(nm, tr.actions.shape)
