"""ACT's gym-aloha transfer-cube scene (as shipped): the scripted nominal of benchmarks/real_models.py and
ACT-like chunked / ensembled executions of it. usage: gen_act.py SCENARIO.toml OUTDIR
(CRITMOMENT_REAL_MODELS must point at a folder holding gym_aloha/ unzipped)"""
import dataclasses, pathlib, sys, tomllib
import numpy as np, mujoco
sys.path.insert(0, "/work/main/benchmarks")
import critmoment
assert critmoment.__file__.startswith("/tmp/r30/src"), critmoment.__file__
from real_models import scripted, scenes
from critmoment.trajectory import save_trajectory
from chunks import chunked, ensembled, ar_noise, insert_bump

scen = pathlib.Path(sys.argv[1]); OUT = pathlib.Path(sys.argv[2]); OUT.mkdir(parents=True, exist_ok=True)
model = mujoco.MjModel.from_xml_path(str(scenes.act_scene()))
traj = scripted.act_transfer(model, 0, grasp_height=0.015)
mine = [f"vx300s_{s}/{j}" for s in ("left", "right") for j in (*scripted.ACT_JOINTS, "gripper")]
raw = tomllib.loads(scen.read_text())
cols = []
for ch in raw["actions"]["channel"]:
    acts = ch["actuators"]
    key = (acts[0].rsplit("/", 1)[0] + "/gripper") if ch.get("normalised") else acts[0]
    cols.append(mine.index(key))
nom = dataclasses.replace(traj, actions=traj.actions[:, cols], start=traj.start[cols])
save_trajectory(nom, OUT / "C_nominal.npz")
labels = [ch.get("label", "") for ch in raw["actions"]["channel"]]
grip = [i for i, ch in enumerate(raw["actions"]["channel"]) if ch.get("normalised")]
arm = [i for i in range(len(cols)) if i not in grip]
print("channels", [raw["actions"]["channel"][i]["actuators"][0] for i in range(len(cols))], "grip", grip, "T", len(nom.actions), nom.fps)
def save(name, a):
    save_trajectory(dataclasses.replace(nom, actions=a), OUT / f"{name}.npz"); print("wrote", name, a.shape)
save("C_chunk100", chunked(nom.actions, 100, arm, grip, sigma=0.015, shift=3, seed=1))
save("C_chunk50", chunked(nom.actions, 50, arm, grip, sigma=0.03, shift=3, seed=2))
save("C_chunk100_te", ensembled(nom.actions, 100, arm, grip, sigma=0.015, shift=3, seed=1))
save("C_noise_w20", ar_noise(nom.actions, arm, sigma=0.02, rho=0.0, seed=4))
