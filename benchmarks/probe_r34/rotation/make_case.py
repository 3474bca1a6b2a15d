"""A bundled-Panda copy whose cube is a plank or a hammer, gripped at its middle, with its
scenario box and scripted pick-and-place (seed 0 spawn).

    PYTHONPATH=. python make_case.py plank|hammer OUTDIR

plank: 12 x 2.5 x 4 cm, box mass 0.05-1.5 kg x friction 0.3-1.2 x com_offset +-5 cm.
hammer: a 16 cm handle (50 g) with a 150 g head at one end, box mass 0.04-0.6 kg (nominal
0.06) x friction 0.3-1.2."""
import re, shutil, pathlib, sys
import numpy as np, mujoco
from critmoment import panda_demo as pd
from critmoment.trajectory import Trajectory, save_trajectory

CUBE = 'size="0.02 0.02 0.02" mass="0.1"'
HEAD = ('<geom name="head" type="box" size="0.015 0.03 0.018" pos="0.075 0 0" mass="0.15" '
        'contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001" '
        'solref="0.01 1"/>\n      ')
CASES = {  # scene edits, centre height [m], box rows (name, target key, range, nominal)
    "plank": ([(CUBE, 'size="0.06 0.0125 0.02" mass="0.1"')], 0.02,
              [("mass", "body", [0.05, 1.5], 0.1), ("friction", "geom", [0.3, 1.2], 1.0),
               ("com_offset", "body", [-0.05, 0.05], 0.0)]),
    "hammer": ([('<geom name="cube" type="box" ' + CUBE,
                 HEAD + '<geom name="cube" type="box" size="0.08 0.0125 0.012" mass="0.05"'),
                ('<body name="cube" pos="0.5 -0.15 0.02">', '<body name="cube" pos="0.5 -0.15 0.018">'),
                ("0.5 -0.15 0.02 1 0 0 0", "0.5 -0.15 0.018 1 0 0 0")], 0.018,
               [("mass", "body", [0.04, 0.6], 0.06), ("friction", "geom", [0.3, 1.2], 1.0)]),
}
case, d = sys.argv[1], pathlib.Path(sys.argv[2])
edits, z, box = CASES[case]
src = pathlib.Path(pd.scene_path()).parent
d.mkdir(parents=True, exist_ok=True)
shutil.copy(src / "panda.xml", d / "panda.xml")
xml = (src / "scene.xml").read_text()
for old, new in edits:
    assert old in xml, old
    xml = xml.replace(old, new, 1)
(d / "scene.xml").write_text(xml)
toml = re.sub(r"\[uncertainty.*", "", (src / "scenario.toml").read_text(), flags=re.S)
toml = toml.replace("goal = [0.5, 0.15, 0.02]", f"goal = [0.5, 0.15, {z}]")
for name, key, rng, nominal in box:
    toml += f'[uncertainty.{name}]\n{key} = "cube"\nrange = {rng}\nnominal = {nominal}\n\n'
(d / "scenario.toml").write_text(toml)
model = mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
cube = pd.sample_cube_pose(0)
cube[2] = z
q, _, grip = pd.pick_place_plan(model, cube, pd.PickPlaceOptions(goal=(0.5, 0.15, z)))
targets = pd._feed_forward(model, q, grip, 1 / 50)
joints = [model.joint(j).id for j in pd.ARM_JOINTS]
qpos0 = model.key("home").qpos.copy()
qpos0[model.jnt_qposadr[joints]] = pd.READY_POSE
for i in (1, 2):
    qpos0[model.jnt_qposadr[model.joint(f"finger_joint{i}").id]] = pd.FINGER_OPEN
a = model.jnt_qposadr[model.joint("cube_joint").id]
qpos0[a:a + 7] = cube
traj = Trajectory(actions=np.concatenate([targets, grip[:, None]], 1), fps=50.0,
                  start=np.concatenate([pd.READY_POSE, [1.0]]), qpos0=qpos0, object_pose=cube)
save_trajectory(traj, d / "traj.npz")
print(case, traj.actions.shape, "->", d)
