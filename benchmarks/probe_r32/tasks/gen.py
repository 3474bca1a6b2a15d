"""Round 32 tasks/trajectories probe: Panda scene copies + policy-like trajectories, ALOHA policy-like
trajectories. usage: gen.py OUTDIR  -> OUTDIR/<scen>/..., OUTDIR/<case>.npz, OUTDIR/cases.tsv (case scen)"""
import dataclasses, pathlib, re, shutil, sys
import mujoco
import numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r32/src"), critmoment.__file__
from critmoment import panda_demo as pd, demos

OUT = pathlib.Path(sys.argv[1]); OUT.mkdir(parents=True, exist_ok=True)
SRC = pathlib.Path(pd.scene_path()).parent
XML0 = (SRC / "scene.xml").read_text()
TOML0 = (SRC / "scenario.toml").read_text()
CUBE_BODY = re.search(r'    <body name="cube" pos="0.5 -0.15 0.02">.*?\n    </body>\n', XML0, re.S).group(0)
GEOM_ATTR = 'contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001" solref="0.01 1"'
cases = []
rng = np.random.default_rng(32)


def scene(name, body_xml=None, z=0.02, quat="1 0 0 0", extra_world="", extra_qpos="", goal=None,
          toml_edit=None, support=None, asset=""):
    d = OUT / name; d.mkdir(exist_ok=True)
    shutil.copy(SRC / "panda.xml", d / "panda.xml")
    xml = XML0
    if asset:
        xml = xml.replace("  <worldbody>", asset + "  <worldbody>")
    if body_xml is not None:
        xml = xml.replace(CUBE_BODY, body_xml)
    xml = xml.replace("  </worldbody>", extra_world + "  </worldbody>")
    xml = xml.replace("0.5 -0.15 0.02 1 0 0 0\"", f"0.5 -0.15 {z} {quat}{extra_qpos}\"")
    (d / "scene.xml").write_text(xml)
    t = TOML0
    if goal is not None:
        t = t.replace("goal = [0.5, 0.15, 0.02]", f"goal = [{goal[0]}, {goal[1]}, {goal[2]}]")
    if support is not None:
        t = t.replace('[support]\ngeoms = ["table"]', f'[support]\ngeoms = {support}')
    if toml_edit:
        t = toml_edit(t)
    (d / "scenario.toml").write_text(t)
    return d


def body(geoms, z=0.02, quat="1 0 0 0"):
    return (f'    <body name="cube" pos="0.5 -0.15 {z}" quat="{quat}">\n      <freejoint name="cube_joint"/>\n'
            f'{geoms}    </body>\n')


G = lambda s, m=0.1: f'      <geom name="cube" {s} mass="{m}" rgba="0.9 0.1 0.1 1"\n            {GEOM_ATTR}/>\n'
_orig_wp = pd._waypoints
ORIG_SEGS = pd._SEGMENTS


def plan(scen, obj_pose, opt=None, wp=None, segs=None):
    model = mujoco.MjModel.from_xml_path(str(OUT / scen / "scene.xml"))
    opt = opt or pd.PickPlaceOptions()
    if wp: pd._waypoints = wp
    if segs: pd._SEGMENTS = segs
    try:
        q, tcp, grip = pd.pick_place_plan(model, obj_pose, opt)
    finally:
        pd._waypoints, pd._SEGMENTS = _orig_wp, ORIG_SEGS
    return model, q, grip, opt


def save(name, scen, model, actions, fps, obj_pose):
    joints = [model.joint(j).id for j in pd.ARM_JOINTS]
    qpos0 = model.key("home").qpos.copy()
    qpos0[model.jnt_qposadr[joints]] = pd.READY_POSE
    for i in (1, 2):
        qpos0[model.jnt_qposadr[model.joint(f"finger_joint{i}").id]] = pd.FINGER_OPEN
    a = model.jnt_qposadr[model.joint("cube_joint").id]
    qpos0[a:a + 7] = obj_pose
    start = np.concatenate([pd.READY_POSE, [1.0]])
    np.savez(OUT / f"{name}.npz", actions=actions, fps=fps, start=start, qpos0=qpos0,
             object_pose=np.asarray(obj_pose, float))
    cases.append((name, scen)); print("wrote", name, actions.shape, fps, "scenario", scen, flush=True)


def traj(name, scen, obj_pose, opt=None, wp=None, segs=None, post=None, q_post=None):
    """post(actions)->actions on the feed-forward action array; q_post(q, grip)->(q, grip) before feed-forward"""
    model, q, grip, opt = plan(scen, obj_pose, opt, wp, segs)
    if q_post is not None:
        q, grip = q_post(q, grip)
    targets = pd._feed_forward(model, q, grip, 1.0 / opt.fps)
    actions = np.concatenate([targets, grip[:, None]], axis=1)
    fps = opt.fps
    if post is not None:
        r = post(actions)
        actions, fps = (r if isinstance(r, tuple) else (r, fps))
    save(name, scen, model, actions, fps, obj_pose)


base = pd.sample_cube_pose(0)
X, Y = base[0], base[1]
pose = lambda z, quat=(1, 0, 0, 0): np.array([X, Y, z, *quat], float)
scene("panda")

# ---------------- policy-like trajectories on the bundled Panda (seed-0 spawn)
def chunk_step(a, n=50, sd=0.01):      # ACT chunks: a constant offset per chunk (jumps at boundaries)
    a = a.copy()
    for k in range(0, len(a), n):
        a[k:k + n, :7] += rng.normal(0, sd, 7)
    return a
def chunk_saw(a, n=50, drift=0.03):    # each chunk drifts from its start state; reset at the boundary
    a = a.copy(); d = rng.normal(0, drift, 7)
    for k in range(0, len(a), n):
        d = rng.normal(0, drift, 7)
        L = min(n, len(a) - k); a[k:k + L, :7] += np.outer(np.arange(L) / n, d)
    return a
def noise(a, sd=0.005, gsd=0.03):
    a = a.copy(); a[:, :7] += rng.normal(0, sd, a[:, :7].shape)
    a[:, 7] = np.clip(a[:, 7] + rng.normal(0, gsd, len(a)), 0, 1); return a
def pause_at(step, n):                   # hold the action (plan-level so feed-forward sees zero velocity)
    def f(q, g):
        return (np.concatenate([q[:step], np.repeat(q[step:step + 1], n, 0), q[step:]]),
                np.concatenate([g[:step], np.repeat(g[step:step + 1], n), g[step:]]))
    return f
def hesitate(step, back, n):             # go back `back` steps' worth along the path and return, n steps each way
    def f(q, g):
        s = np.r_[np.linspace(step, step - back, n), np.linspace(step - back, step, n)]
        qi = np.stack([np.interp(s, np.arange(len(q)), q[:, j]) for j in range(7)], 1)
        return np.concatenate([q[:step], qi, q[step:]]), np.concatenate([g[:step], np.full(2 * n, g[step]), g[step:]])
    return f
def late_grip(shift):
    def f(q, g):
        g = g.copy(); g2 = g.copy(); g2[140 + shift:] = g[140:len(g) - shift]; g2[140:140 + shift] = 1.0
        return q, g2
    return f
def grip_level(level):
    def f(q, g):
        return q, np.where(g < level, level, g) if level > 0 else g
    return f
def grip_glitch(a):
    a = a.copy(); a[280:286, 7] = 0.35; return a
def resample(fps_new):
    def f(a):
        t0 = np.arange(len(a)) / 50.0; n = int(len(a) * fps_new / 50.0)
        t1 = np.arange(n) / fps_new
        return np.stack([np.interp(t1, t0, a[:, j]) for j in range(a.shape[1])], 1), float(fps_new)
    return f
def lp_policy(a, tau=5):                 # a policy whose actions lag: first-order filter (temporal ensembling-like)
    b = a.copy()
    for k in range(1, len(a)):
        b[k, :7] = b[k - 1, :7] + (a[k, :7] - b[k - 1, :7]) / tau
    return b

traj("P_nominal", "panda", pose(0.02))
traj("P_chunk50_step", "panda", pose(0.02), post=chunk_step)
traj("P_chunk50_saw", "panda", pose(0.02), post=chunk_saw)
traj("P_chunk100_step2", "panda", pose(0.02), post=lambda a: chunk_step(a, 100, 0.02))
traj("P_noise", "panda", pose(0.02), post=noise)
traj("P_pause_carry", "panda", pose(0.02), q_post=pause_at(270, 50))
traj("P_pause_grasp", "panda", pose(0.02), q_post=pause_at(190, 75))
traj("P_hesitate", "panda", pose(0.02), q_post=hesitate(280, 40, 20))
o = dataclasses.replace(pd.PickPlaceOptions(), time_scale=0.67); traj("P_fast15", "panda", pose(0.02), o)
o = dataclasses.replace(pd.PickPlaceOptions(), time_scale=0.5); traj("P_fast2x", "panda", pose(0.02), o)
traj("P_lategrip20", "panda", pose(0.02), q_post=late_grip(20))
traj("P_lategrip40", "panda", pose(0.02), q_post=late_grip(40))
traj("P_grip035", "panda", pose(0.02), q_post=grip_level(0.35))
traj("P_glitch", "panda", pose(0.02), post=grip_glitch)
traj("P_fps100", "panda", pose(0.02), post=resample(100))
traj("P_fps20", "panda", pose(0.02), post=resample(20))
traj("P_lowpass", "panda", pose(0.02), post=lp_policy)

# ---------------- objects, masses
obj = lambda name, geoms, z, quat="1 0 0 0", grasp=0.01, **kw: (
    scene(name, body(geoms, z, quat), z=z, quat=quat, goal=(0.5, 0.15, z), **kw),
    traj("O_" + name, name, pose(z, tuple(float(v) for v in quat.split())),
         pd.PickPlaceOptions(goal=(0.5, 0.15, z), grasp_offset=grasp)))
obj("cyl_lying_y", G('type="cylinder" size="0.02 0.03"'), 0.02, quat="0.7071068 0.7071068 0 0")  # flat ends to the pads
obj("capsule_stand", G('type="capsule" size="0.018 0.025"'), 0.043, grasp=0.015)
obj("ellipsoid", G('type="ellipsoid" size="0.03 0.02 0.025"'), 0.025)
obj("plate_upright", G('type="box" size="0.04 0.006 0.03"'), 0.03)          # 1.2 cm thick, faces to the pads
hexv = " ".join(f"{0.022*np.cos(a):.4f} {0.022*np.sin(a):.4f} {z}" for z in (-0.02, 0.02) for a in np.arange(6) * np.pi / 3 + np.pi / 6)
obj("mesh_hex", G('type="mesh" mesh="hex"'), 0.02, asset=f'  <asset>\n    <mesh name="hex" vertex="{hexv}"/>\n  </asset>\n')
massbox = lambda nom, lo, hi: (lambda t: t.replace("range = [0.05, 3.0]", f"range = [{lo}, {hi}]").replace("nominal = 0.1\n", f"nominal = {nom}\n"))
scene("heavy1", body(G('type="box" size="0.02 0.02 0.02"', 1.0)), toml_edit=massbox(1.0, 0.5, 2.5))
traj("O_heavy1kg", "heavy1", pose(0.02))
scene("light", body(G('type="box" size="0.02 0.02 0.02"', 0.01)), toml_edit=massbox(0.01, 0.005, 0.2))
traj("O_light10g", "light", pose(0.02))

# ---------------- goals, tolerance, hold at end
shelf = ('    <body name="shelf" pos="0.5 0.15 0.09">\n      <geom name="shelf" type="box" size="0.05 0.05 0.09" '
         'rgba="0.4 0.4 0.4 1" contype="1" conaffinity="1" friction="1 0.005 0.0001"/>\n    </body>\n')
scene("shelf18", extra_world=shelf, goal=(0.5, 0.15, 0.2), support='["table", "shelf"]')
traj("G_shelf18", "shelf18", pose(0.02), pd.PickPlaceOptions(goal=(0.5, 0.15, 0.2), transport_height=0.3))
scene("far", goal=(0.68, 0.3, 0.02))
traj("G_far", "far", pose(0.02), pd.PickPlaceOptions(goal=(0.68, 0.3, 0.02)))
scene("near", goal=(0.32, 0.05, 0.02))
traj("G_near", "near", pose(0.02), pd.PickPlaceOptions(goal=(0.32, 0.05, 0.02)))
scene("tol005", toml_edit=lambda t: t.replace("tolerance = 0.03 ", "tolerance = 0.005"))
traj("T_tol005", "tol005", pose(0.02))
traj("T_tol005_off4mm", "tol005", pose(0.02), pd.PickPlaceOptions(goal=(0.5, 0.154, 0.02)))
traj("T_off25mm", "panda", pose(0.02), pd.PickPlaceOptions(goal=(0.5, 0.175, 0.02)))   # inside 3 cm
# never released: held at the goal to the end (pick_place must fail: gripper contact in the final window)
traj("T_noreleasе".replace("е", "e"), "panda", pose(0.02), q_post=lambda q, g: (q, np.where(np.arange(len(g)) >= 370, 0.0, g)))
hold_t = lambda t: re.sub(r'\[task\]\n.*?\n\n', '[task]\nkind = "pick_hold"\ngripper = "hand"\nlift_height = 0.02\n\n', t, flags=re.S)
scene("hold", toml_edit=hold_t)
def wp_hold_over_goal(cube, opt):
    w = _orig_wp(cube, opt)
    return [(s, p if s <= 305 else w[6][1], g if s <= 305 else 0.0) for s, p, g in w]
traj("H_carry_hold", "hold", pose(0.02), wp=wp_hold_over_goal)
# pick_place motion audited as pick_hold (it releases: must fail)
traj("H_place_as_hold", "hold", pose(0.02))

# ---------------- clutter
d1 = ('    <body name="cube2" pos="0.545 -0.15 0.02">\n      <freejoint name="cube2_joint"/>\n      <geom name="cube2" '
      'type="box" size="0.02 0.02 0.02" mass="0.1" rgba="0.1 0.1 0.9 1" contype="1" conaffinity="1" condim="4" '
      'friction="1 0.005 0.0001" solref="0.01 1"/>\n    </body>\n')
scene("clutter_x", extra_world=d1.replace("0.545 -0.15", f"{X+0.041:.4f} {Y:.4f}"), extra_qpos=f"  {X+0.041:.4f} {Y:.4f} 0.02 1 0 0 0")
traj("C_touch_x", "clutter_x", pose(0.02))
scene("clutter_path", extra_world=d1.replace("0.545 -0.15 0.02", "0.5 0.0 0.02"), extra_qpos="  0.5 0.0 0.02 1 0 0 0")
def wp_low(cube, opt):   # carried low (6 cm) so the cube's bottom passes 1 cm... over a cube on the path
    w = _orig_wp(cube, opt)
    return w
traj("C_path_low", "clutter_path", pose(0.02), pd.PickPlaceOptions(transport_height=0.08))

# ---------------- uncertain parameters other than mass/friction
comx = '\n[uncertainty.com]\nkind = "com_offset"\nbody = "cube"\nrange = [-0.019, 0.019]\nnominal = 0.0\nprior = "uniform"\n'
scene("com_only", toml_edit=lambda t: re.sub(r'\[uncertainty\.mass\].*?\n\n\[uncertainty\.friction\].*?\n\n', '', t, flags=re.S) + comx)
traj("U_com_only", "com_only", pose(0.02))
fl2 = ('\n[uncertainty.grip_l]\nkind = "force_limit"\nactuator = "finger_left"\nrange = [1.0, 35.0]\nnominal = 35.0\nprior = "loguniform"\n'
       '\n[uncertainty.grip_r]\nkind = "force_limit"\nactuator = "finger_right"\nrange = [1.0, 35.0]\nnominal = 35.0\nprior = "loguniform"\n')
scene("flim2", toml_edit=lambda t: t + fl2)
traj("U_flim_both", "flim2", pose(0.02))
flj = '\n[uncertainty.j4]\nkind = "force_limit"\nactuator = "joint4"\nrange = [5.0, 87.0]\nnominal = 87.0\nprior = "uniform"\n'
scene("flim_j4", toml_edit=lambda t: t + flj)
traj("U_flim_j4", "flim_j4", pose(0.02))
flj6 = '\n[uncertainty.j6]\nkind = "force_limit"\nactuator = "joint6"\nrange = [0.5, 12.0]\nnominal = 12.0\nprior = "uniform"\n'
scene("flim_j6_heavy", body(G('type="box" size="0.02 0.02 0.02"', 1.0)), toml_edit=lambda t: massbox(1.0, 0.5, 2.5)(t) + flj6)
traj("U_flim_j6_heavy", "flim_j6_heavy", pose(0.02))
scene("padfric", toml_edit=lambda t: t.replace('[uncertainty.friction]\ngeom = "cube"', '[uncertainty.friction]\ngeom = "left_pad"'))
traj("U_padfric", "padfric", pose(0.02))

(OUT / "cases.tsv").write_text("".join(f"{c}\t{s}\n" for c, s in cases))
