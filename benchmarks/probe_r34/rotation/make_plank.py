"""A 12 x 2.5 x 4 cm plank on the bundled Panda, gripped at its middle; box mass x friction x
com_offset.  usage: PYTHONPATH=. python make_plank.py OUTDIR"""
import re, shutil, pathlib, sys
import numpy as np, mujoco
from critmoment import panda_demo as pd
SRC = pathlib.Path(pd.scene_path()).parent
d = pathlib.Path(sys.argv[1]); d.mkdir(parents=True, exist_ok=True)
shutil.copy(SRC / "panda.xml", d / "panda.xml")
xml = (SRC / "scene.xml").read_text()
xml = xml.replace('size="0.02 0.02 0.02" mass="0.1"', 'size="0.06 0.0125 0.02" mass="0.1"')
(d / "scene.xml").write_text(xml)
t = (SRC / "scenario.toml").read_text()
t = re.sub(r"\[uncertainty.*", "", t, flags=re.S)
t += """[uncertainty.mass]
body = "cube"
range = [0.05, 1.5]
nominal = 0.1

[uncertainty.friction]
geom = "cube"
range = [0.3, 1.2]
nominal = 1.0

[uncertainty.com_offset]
body = "cube"
range = [-0.05, 0.05]
nominal = 0.0
"""
(d / "scenario.toml").write_text(t)
model = mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
traj = pd.make_pick_place(0, model=model)
from critmoment.trajectory import save_trajectory; save_trajectory(traj, d / "traj.npz")
print(traj.actions.shape)
