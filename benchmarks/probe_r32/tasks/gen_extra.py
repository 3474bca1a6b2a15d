"""Round 32 extra tasks (written after gen.py found 0 false safes): the cube placed on a ramp
(the goal spot lies on a tilted surface, so low-friction samples slide off after the release),
and a carry with a wrist tilt. usage: gen_extra.py OUTDIR -> OUTDIR/<case>.npz, OUTDIR/cases_extra.tsv"""
import pathlib, shutil, sys
import mujoco
import numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r32/src"), critmoment.__file__
from critmoment import panda_demo as pd

OUT = pathlib.Path(sys.argv[1]); OUT.mkdir(parents=True, exist_ok=True)
SRC = pathlib.Path(pd.scene_path()).parent
XML0 = (SRC / "scene.xml").read_text()
TOML0 = (SRC / "scenario.toml").read_text()
rows = []
base = pd.sample_cube_pose(0)
POSE = np.array([base[0], base[1], 0.02, 1, 0, 0, 0], float)


def scene(name, extra_world="", goal=None, support=None):
    d = OUT / name; d.mkdir(exist_ok=True)
    shutil.copy(SRC / "panda.xml", d / "panda.xml")
    (d / "scene.xml").write_text(XML0.replace("  </worldbody>", extra_world + "  </worldbody>"))
    t = TOML0
    if goal is not None:
        t = t.replace("goal = [0.5, 0.15, 0.02]", f"goal = [{goal[0]:.4f}, {goal[1]:.4f}, {goal[2]:.4f}]")
    if support is not None:
        t = t.replace('[support]\ngeoms = ["table"]', f'[support]\ngeoms = {support}')
    (d / "scenario.toml").write_text(t)


def save(name, scen, opt, q_post=None):
    model = mujoco.MjModel.from_xml_path(str(OUT / scen / "scene.xml"))
    q, tcp, grip = pd.pick_place_plan(model, POSE, opt)
    if q_post is not None:
        q, grip = q_post(q, grip)
    targets = pd._feed_forward(model, q, grip, 1.0 / opt.fps)
    actions = np.concatenate([targets, grip[:, None]], axis=1)
    joints = [model.joint(j).id for j in pd.ARM_JOINTS]
    qpos0 = model.key("home").qpos.copy()
    qpos0[model.jnt_qposadr[joints]] = pd.READY_POSE
    for i in (1, 2):
        qpos0[model.jnt_qposadr[model.joint(f"finger_joint{i}").id]] = pd.FINGER_OPEN
    a = model.jnt_qposadr[model.joint("cube_joint").id]
    qpos0[a:a + 7] = POSE
    np.savez(OUT / f"{name}.npz", actions=actions, fps=opt.fps, start=np.concatenate([pd.READY_POSE, [1.0]]),
             qpos0=qpos0, object_pose=POSE)
    rows.append(f"{name}\t{scen}\n"); print("wrote", name, actions.shape, "scenario", scen, flush=True)


def ramp(deg, hs=0.04, gx=0.5, gy=0.15):
    """a ramp whose surface passes through (gx, gy, hs), falling towards +x at `deg` degrees;
    the goal: the level-held cube just touching it (centre above the uphill bottom edge)"""
    th = np.radians(deg); n = np.array([np.sin(th), 0, np.cos(th)])
    c = np.array([gx, gy, hs]) - 0.01 * n
    q = (np.cos(th / 2), 0, np.sin(th / 2), 0)
    xml = (f'    <body name="ramp" pos="{c[0]:.5f} {c[1]:.5f} {c[2]:.5f}" quat="{q[0]:.6f} {q[1]} {q[2]:.6f} {q[3]}">\n'
           f'      <geom name="ramp" type="box" size="0.12 0.06 0.01" rgba="0.4 0.4 0.4 1" contype="1" conaffinity="1" '
           f'friction="1 0.005 0.0001"/>\n    </body>\n')
    goal = (gx, gy, hs + 0.02 + 0.02 * np.tan(th))
    return xml, goal


for deg in (10, 20, 30):
    xml, goal = ramp(deg)
    scene(f"ramp{deg}", xml, goal, '["table", "ramp"]')
    save(f"R_ramp{deg}", f"ramp{deg}", pd.PickPlaceOptions(goal=goal))


def tilt(j, amount, s0=250, s1=290):
    """rotate arm joint j by `amount` rad over the carry (steps s0..s0+20) and back (s1..s1+20)"""
    def f(q, g):
        q = q.copy(); ramp_ = np.zeros(len(q))
        ramp_[s0:s0 + 20] = np.linspace(0, 1, 20); ramp_[s0 + 20:s1] = 1; ramp_[s1:s1 + 20] = np.linspace(1, 0, 20)
        q[:, j] += amount * ramp_
        return q, g
    return f


save("W_tilt_j6_05", "panda", pd.PickPlaceOptions(), q_post=tilt(5, 0.5))     # joint6 (wrist pitch)
save("W_tilt_j6_10", "panda", pd.PickPlaceOptions(), q_post=tilt(5, 1.0))
save("W_twist_j7_15", "panda", pd.PickPlaceOptions(), q_post=tilt(6, 1.5))    # joint7 (wrist roll)
(OUT / "cases_extra.tsv").write_text("".join(rows))


def late_open(d):
    """the hand opens d action steps later than planned (370..395), while it already rises (395..445)"""
    def f(q, g):
        g2 = g.copy(); g2[370 + d:] = g[370:len(g) - d]; g2[370:370 + d] = 0.0
        return q, g2
    return f


rows2 = []
for d in (15, 30, 50):
    save(f"L_lateopen{d}", "panda", pd.PickPlaceOptions(), q_post=late_open(d))
(OUT / "cases_extra2.tsv").write_text("".join(r for r in rows if r.startswith("L_")))
