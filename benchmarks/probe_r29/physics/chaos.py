"""How many validate samples flip pass/fail when the object's start x moves by EPS [m]:
python chaos.py VARIANT EPS   (critmoment's own brute_force, nthread=1, on the val_64_0.json samples)"""
import dataclasses
import json
import sys
from pathlib import Path

import numpy as np

import critmoment as cm
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory

assert cm.__file__.startswith("/tmp/r29/src")
R = Path("/tmp/r29/physics")
v, eps = sys.argv[1], float(sys.argv[2])
vd = R / "v" / v
tp = vd / "traj.npz" if (vd / "traj.npz").exists() else R / ("aloha_s0.npz" if v.startswith("a_") else "panda_s0.npz")
twin = cm.Twin(cm.load_scenario(str(vd)))
traj = load_trajectory(str(tp))
names = [p.name for p in twin.scenario.box.parameters]
d = json.load(open(vd / "val_64_0.json"))
S = np.array([[p["values"][n] for n in names] for p in d["per_sample"]])
real = np.array([p["real_failed"] for p in d["per_sample"]])
pose = np.array(traj.object_pose, float)
pose[0] += eps
kw = {}
if traj.qpos0 is not None:
    q = np.array(traj.qpos0, float)
    q[-7] += eps
    kw["qpos0"] = q
t2 = dataclasses.replace(traj, object_pose=pose, **kw)
bf = gt.brute_force(t2, twin=twin, samples=S, nthread=1)
flip = np.flatnonzero(bf.failed != real)
print(f"{v} eps={eps:g}: {flip.size} of {len(S)} samples flip (real failures {real.sum()} -> {int(bf.failed.sum())})")
for i in flip:
    print("  ", i, dict(zip(names, S[i].round(4))), "was", d["per_sample"][i]["outcome"], "now", bf.outcome[i].name)
