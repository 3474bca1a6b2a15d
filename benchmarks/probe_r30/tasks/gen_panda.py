"""Panda pick-and-place variants (seed 0) of round 30. usage: gen_panda.py OUTDIR"""
import pathlib, sys, shutil, re
import numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r30/src"), critmoment.__file__
from critmoment import panda_demo as pd
from chunks import chunked, ensembled, ar_noise, insert_bump

OUT = pathlib.Path(sys.argv[1]); OUT.mkdir(parents=True, exist_ok=True)


def save(name, tr, actions=None, qpos0=True):
    a = tr.actions if actions is None else actions
    kw = dict(qpos0=tr.qpos0) if qpos0 else {}
    np.savez(OUT / f"{name}.npz", actions=a, fps=tr.fps, start=tr.start, object_pose=tr.object_pose, **kw)
    print("wrote", name, a.shape)


nom = pd.make_pick_place(0)
save("P_nominal", nom)
arm = list(range(7)); grip = [7]
save("P_chunk100", nom, chunked(nom.actions, 100, arm, grip, sigma=0.015, shift=3, seed=1))
save("P_chunk50", nom, chunked(nom.actions, 50, arm, grip, sigma=0.03, shift=3, seed=2))
save("P_chunk100_te", nom, ensembled(nom.actions, 100, arm, grip, sigma=0.015, shift=3, seed=1))
save("P_noise_ar", nom, ar_noise(nom.actions, arm, sigma=0.01, rho=0.9, seed=3))
save("P_noise_w20", nom, ar_noise(nom.actions, arm, sigma=0.02, rho=0.0, seed=4))
for ts, nm in ((0.5, "P_fast05"), (2.0, "P_slow2")):
    try:
        save(nm, pd.make_pick_place(0, options=pd.PickPlaceOptions(time_scale=ts)))
    except Exception as e:
        print(nm, "failed:", e)
# carry (above -> over_goal, 230 -> 305) at half duration; later waypoints 38 steps earlier
orig_seg = pd._SEGMENTS
pd._SEGMENTS = tuple(s if s <= 230 else s - 38 for s in orig_seg)
save("P_carryfast", pd.make_pick_place(0))
pd._SEGMENTS = orig_seg
# overshoot: past the goal by 8 cm along the carry (+y), then back over the goal
orig_wp = pd._waypoints
# pick_place_plan reads _waypoints(cube, opt) -> list; monkeypatch it with the overshoot list
def _wp(cube, opt):
    w = orig_wp(cube, opt)
    out = []
    for s, pos, g in w:
        if s == 305:
            out.append((305, pos + np.array([0.0, 0.08, 0.0]), g)); out.append((345, pos, g)); continue
        out.append((s + 40 if s > 305 else s, pos, g))
    return out
pd._waypoints = _wp
save("P_overshoot", pd.make_pick_place(0))
pd._waypoints = orig_wp
# pause: a 4 s stop mid-carry (the motion frozen at step 268, half way above -> over goal)
save("P_pause4", nom, insert_bump(nom.actions, 268, 200, 0, 0.0, 30))
# pause holding still over the cube after the lift (step 230)
save("P_pause4_lift", nom, insert_bump(nom.actions, 230, 200, 0, 0.0, 30))
# wrist motions while carrying, joint space, at the lifted point (230): 30 up, 40 hold, 30 back
save("P_j6tilt45", nom, insert_bump(nom.actions, 230, 100, 5, np.pi / 4, 30))
save("P_j6tiltm45", nom, insert_bump(nom.actions, 230, 100, 5, -np.pi / 4, 30))
save("P_j5roll60", nom, insert_bump(nom.actions, 230, 100, 4, np.pi / 3, 30))
save("P_j7rot90", nom, insert_bump(nom.actions, 230, 100, 6, np.pi / 2, 30))
# tilted carry: joint 6 tilted 40 deg from the lift to just before the descent (230..305)
a = nom.actions.copy(); s = np.arange(len(a)); mj = lambda x: x ** 3 * (10 - 15 * x + 6 * x ** 2)
prof = np.minimum(mj(np.clip((s - 230) / 25, 0, 1)), mj(np.clip((330 - s) / 25, 0, 1)))
a[:, 5] += np.deg2rad(40) * prof
save("P_tiltcarry40", nom, a)
# stacking: a second free cube at the goal, the goal on top of it (z 0.06)
src = pathlib.Path(pd.scene_path()).parent
for name, sup in (("stack", '["table", "base_cube"]'), ("stack_nosup", '["table"]')):
    d = OUT / name; d.mkdir(exist_ok=True)
    shutil.copy(src / "panda.xml", d / "panda.xml")
    xml = (src / "scene.xml").read_text()
    xml = xml.replace('    <body name="cube" pos="0.5 -0.15 0.02">',
                      '    <body name="base_cube" pos="0.5 0.15 0.02">\n      <freejoint name="base_joint"/>\n'
                      '      <geom name="base_cube" type="box" size="0.02 0.02 0.02" mass="0.1" rgba="0.1 0.1 0.9 1"\n'
                      '            contype="1" conaffinity="1" condim="4" friction="1 0.005 0.0001" solref="0.01 1"/>\n    </body>\n'
                      '    <body name="cube" pos="0.5 -0.15 0.02">')
    xml = re.sub(r'(<key name="home"\s+qpos="[^"]*?0\.04 0\.04\s+)(0\.5 -0\.15 0\.02 1 0 0 0)', r'\g<1>0.5 0.15 0.02 1 0 0 0 \2', xml)
    (d / "scene.xml").write_text(xml)
    toml = (src / "scenario.toml").read_text()
    toml = re.sub(r'goal = \[0.5, 0.15, 0.02\]', 'goal = [0.5, 0.15, 0.06]', toml)
    toml = re.sub(r'\[support\]\ngeoms = \["table"\]', f'[support]\ngeoms = {sup}', toml)
    (d / "scenario.toml").write_text(toml)
pd_goal = pd.PickPlaceOptions(goal=(0.5, 0.15, 0.06))
import mujoco
st = pd.make_pick_place(0, options=pd_goal)
save("P_stack", st, qpos0=False)
# stacking, harder: released 2 cm above the base cube; placed 1.5 cm / 1.8 cm off its centre along y
save("P_stack_drop", pd.make_pick_place(0, options=pd.PickPlaceOptions(goal=(0.5, 0.15, 0.06), place_clearance=0.02)), qpos0=False)
save("P_stack_off15", pd.make_pick_place(0, options=pd.PickPlaceOptions(goal=(0.5, 0.165, 0.06))), qpos0=False)
save("P_stack_off18", pd.make_pick_place(0, options=pd.PickPlaceOptions(goal=(0.5, 0.168, 0.06))), qpos0=False)
