"""A hammer (16 cm handle, a 150 g head at one end) on the bundled Panda, gripped at the
handle's middle; box mass x friction.  usage: PYTHONPATH=. python make_hammer.py OUTDIR"""
import re, shutil, pathlib, sys
import numpy as np, mujoco
from critmoment import panda_demo as pd
from critmoment.trajectory import save_trajectory
SRC = pathlib.Path(pd.scene_path()).parent
d = pathlib.Path(sys.argv[1]); d.mkdir(parents=True, exist_ok=True)
shutil.copy(SRC / "panda.xml", d / "panda.xml")
xml = (SRC / "scene.xml").read_text()
old = re.search(r'      <geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1"', xml).group(0)
# handle 16 cm along x (gripped at its middle, the body origin), a head at +x end
xml = xml.replace(old, '      <geom name="head" type="box" size="0.015 0.03 0.018" pos="0.075 0 0" mass="0.15" rgba="0.3 0.3 0.3 1"\n'
                  '            contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001" solref="0.01 1"/>\n'
                  '      <geom name="cube" type="box" size="0.08 0.0125 0.012" mass="0.05"')
xml = xml.replace('<body name="cube" pos="0.5 -0.15 0.02">', '<body name="cube" pos="0.5 -0.15 0.018">')
xml = xml.replace("0.5 -0.15 0.02 1 0 0 0", "0.5 -0.15 0.018 1 0 0 0")
(d / "scene.xml").write_text(xml)
t = (SRC / "scenario.toml").read_text()
t = t.replace("goal = [0.5, 0.15, 0.02]", "goal = [0.5, 0.15, 0.018]")
t = re.sub(r"\[uncertainty.*", "", t, flags=re.S)
t += """[uncertainty.mass]
body = "cube"
range = [0.04, 0.6]
nominal = 0.06

[uncertainty.friction]
geom = "cube"
range = [0.3, 1.2]
nominal = 1.0
"""
(d / "scenario.toml").write_text(t)
model = mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
cube = pd.sample_cube_pose(0); cube[2] = 0.018
q, _, grip = pd.pick_place_plan(model, cube, pd.PickPlaceOptions(goal=(0.5, 0.15, 0.018)))
targets = pd._feed_forward(model, q, grip, 1 / 50)
from critmoment.trajectory import Trajectory
joints = [model.joint(j).id for j in pd.ARM_JOINTS]
qpos0 = model.key("home").qpos.copy(); qpos0[model.jnt_qposadr[joints]] = pd.READY_POSE
for i in (1, 2): qpos0[model.jnt_qposadr[model.joint(f"finger_joint{i}").id]] = pd.FINGER_OPEN
a = model.jnt_qposadr[model.joint("cube_joint").id]; qpos0[a:a+7] = cube
traj = Trajectory(actions=np.concatenate([targets, grip[:, None]], 1), fps=50.0, start=np.concatenate([pd.READY_POSE, [1.0]]), qpos0=qpos0, object_pose=cube)
save_trajectory(traj, d / "traj.npz")
print("ok", traj.actions.shape)
