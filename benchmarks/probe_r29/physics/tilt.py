"""Tilted-support variants: the object rests on a fixed ramp tilted by DEG about the world x or y
axis, under the trajectory's own object position. Writes v/NAME/{scene.xml,scenario.toml,traj.npz}.
usage: python tilt.py NAME BASE(a|p) AXIS(x|y) DEG"""
import math
import shutil
import sys
from pathlib import Path

import numpy as np

V = Path("/tmp/r29/physics/v")
name, base, axis, deg = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
src = V / ("a_base" if base == "a" else "p_base")
traj = Path("/tmp/r29/physics") / ("aloha_s0.npz" if base == "a" else "panda_s0.npz")
out = V / name
if out.exists():
    shutil.rmtree(out)
shutil.copytree(src, out, ignore=shutil.ignore_patterns("*.json", "*.err", "*.log"))
d = dict(np.load(traj, allow_pickle=True))
x, y = float(d["object_pose"][0]), float(d["object_pose"][1])
th = math.radians(deg)
n = np.array([0, -math.sin(th), math.cos(th)]) if axis == "x" else np.array([math.sin(th), 0, math.cos(th)])
c = np.array([x, y, -0.005]) + 0.0302 * n
q = [math.cos(th / 2), math.sin(th / 2), 0, 0] if axis == "x" else [math.cos(th / 2), 0, math.sin(th / 2), 0]
eul = f"{th} 0 0" if axis == "x" else f"0 {th} 0"
ramp = (f'<body name="ramp" pos="{x} {y} -0.005" euler="{eul}"><geom name="ramp" type="box" size="0.05 0.05 0.01" '
        f'contype="1" conaffinity="1" friction="1 0.005 0.0001"/></body>\n    ')
s = (out / "scene.xml").read_text()
anchor = '<body name="box"' if base == "a" else '<body name="cube"'
s = s.replace(anchor, ramp + anchor, 1)
(out / "scene.xml").write_text(s)
t = (out / "scenario.toml").read_text()
t = t.replace('geoms = ["table"]', 'geoms = ["table", "ramp"]', 1)
(out / "scenario.toml").write_text(t)
d["object_pose"] = np.array([*c, *q])
if "qpos0" in d:
    d["qpos0"] = d["qpos0"].copy()
    d["qpos0"][-7:] = d["object_pose"]
np.savez(out / "traj.npz", **d)
print(name, "object_pose", d["object_pose"].round(4))
