"""Round 31 tasks/objects probe: Panda scene copies (objects, supports, distractor, force limit)
and their trajectories. usage: gen.py OUTDIR   (writes OUTDIR/<scen>/{scene.xml,panda.xml,scenario.toml}
and OUTDIR/<case>.npz; cases.tsv lists case -> scenario)"""
import dataclasses, pathlib, re, shutil, sys
import mujoco
import numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r31/src"), critmoment.__file__
from critmoment import panda_demo as pd

OUT = pathlib.Path(sys.argv[1]); OUT.mkdir(parents=True, exist_ok=True)
SRC = pathlib.Path(pd.scene_path()).parent
XML0 = (SRC / "scene.xml").read_text()
TOML0 = (SRC / "scenario.toml").read_text()
CUBE_BODY = re.search(r'    <body name="cube" pos="0.5 -0.15 0.02">.*?\n    </body>\n', XML0, re.S).group(0)
GEOM_ATTR = 'contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001" solref="0.01 1"'
cases = []


def scene(name, body_xml=None, z=0.02, quat="1 0 0 0", extra_world="", extra_qpos="", goal=None,
          toml_edit=None, support=None):
    d = OUT / name; d.mkdir(exist_ok=True)
    shutil.copy(SRC / "panda.xml", d / "panda.xml")
    xml = XML0
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


def body(geoms, z=0.02, quat="1 0 0 0", inertial=""):
    return (f'    <body name="cube" pos="0.5 -0.15 {z}" quat="{quat}">\n      <freejoint name="cube_joint"/>\n'
            f'{inertial}{geoms}    </body>\n')


def traj(name, scen, obj_pose, opt=None, wp=None, segs=None, extra_qpos=None, grip_override=None):
    """pick_place_plan + feed-forward, on the scene copy `scen`, object at obj_pose (7,)"""
    model = mujoco.MjModel.from_xml_path(str(OUT / scen / "scene.xml"))
    opt = opt or pd.PickPlaceOptions()
    o_wp, o_seg = pd._waypoints, pd._SEGMENTS
    if wp: pd._waypoints = wp
    if segs: pd._SEGMENTS = segs
    try:
        q, tcp, grip = pd.pick_place_plan(model, obj_pose, opt)
    finally:
        pd._waypoints, pd._SEGMENTS = o_wp, o_seg
    if grip_override is not None:
        grip = grip_override(grip)
    targets = pd._feed_forward(model, q, grip, 1.0 / opt.fps)
    actions = np.concatenate([targets, grip[:, None]], axis=1)
    joints = [model.joint(j).id for j in pd.ARM_JOINTS]
    qpos0 = model.key("home").qpos.copy()
    qpos0[model.jnt_qposadr[joints]] = pd.READY_POSE
    for i in (1, 2):
        qpos0[model.jnt_qposadr[model.joint(f"finger_joint{i}").id]] = pd.FINGER_OPEN
    a = model.jnt_qposadr[model.joint("cube_joint").id]
    qpos0[a:a + 7] = obj_pose
    start = np.concatenate([pd.READY_POSE, [1.0]])
    np.savez(OUT / f"{name}.npz", actions=actions, fps=opt.fps, start=start, qpos0=qpos0,
             object_pose=np.asarray(obj_pose, float))
    cases.append((name, scen))
    print("wrote", name, actions.shape, "scenario", scen, flush=True)


base = pd.sample_cube_pose(0)          # seed-0 spawn
X, Y = base[0], base[1]
scene("panda")                         # plain copy
cases_scen = {}


def pose(z, quat=(1, 0, 0, 0)):
    return np.array([X, Y, z, *quat], float)


def obj(name, geoms, z, quat="1 0 0 0", goal_z=None, inertial="", place_clear=0.002, grasp=0.01, **kw):
    gz = z if goal_z is None else goal_z
    scene(name, body(geoms, z, quat, inertial),
          z=z, quat=quat, goal=(0.5, 0.15, gz), **kw)
    q = tuple(float(v) for v in quat.split())
    traj("O_" + name, name, pose(z, q),
         pd.PickPlaceOptions(goal=(0.5, 0.15, gz), place_clearance=place_clear, grasp_offset=grasp))


G = lambda s: f'      <geom name="cube" {s} mass="0.1" rgba="0.9 0.1 0.1 1"\n            {GEOM_ATTR}/>\n'
# --- objects
obj("cyl_stand", G('type="cylinder" size="0.02 0.03"'), 0.03)
obj("cyl_lying", G('type="cylinder" size="0.02 0.04"'), 0.02, quat="0.7071068 0 0.7071068 0")
obj("sphere", G('type="sphere" size="0.02"'), 0.02)
obj("plate", G('type="box" size="0.04 0.02 0.006"'), 0.006)
obj("tallbox", G('type="box" size="0.02 0.02 0.06"'), 0.06, grasp=0.015)
obj("tallbox_thin", G('type="box" size="0.012 0.02 0.06"'), 0.06, grasp=0.015)
comp = (G('type="box" size="0.02 0.02 0.02"')
        + '      <geom name="cube_h1" type="capsule" fromto="0.02 0 0.01 0.06 0 0.01" size="0.008" mass="0.05" '
          f'rgba="0.9 0.5 0.1 1" {GEOM_ATTR}/>\n'
        + '      <geom name="cube_h2" type="sphere" pos="-0.035 0 -0.01" size="0.01" mass="0.05" '
          f'rgba="0.9 0.5 0.1 1" {GEOM_ATTR}/>\n')
obj("compound", comp, 0.02)
mesh_asset = ('  <asset>\n    <mesh name="prism" vertex="-0.03 -0.02 -0.02  0.03 -0.02 -0.02  0 -0.02 0.025  '
              '-0.03 0.02 -0.02  0.03 0.02 -0.02  0 0.02 0.025"/>\n  </asset>\n')
XML_SAVE = XML0
XML0 = XML0.replace("  <worldbody>", mesh_asset + "  <worldbody>")
obj("mesh_prism", G('type="mesh" mesh="prism"'), 0.02)
XML0 = XML_SAVE

# --- com offset (cube, along body x: across the pads, which close along y... the pads grip y faces)
scene("com", toml_edit=lambda t: t + '\n[uncertainty.com]\nkind = "com_offset"\nbody = "cube"\n'
      'range = [-0.018, 0.018]\nnominal = 0.0\nprior = "uniform"\n')
traj("P_com", "com", pose(0.02))
# com offset on the tall box (tipping when placed); along x
scene("com_tall", body(G('type="box" size="0.02 0.02 0.06"'), 0.06), z=0.06, goal=(0.5, 0.15, 0.06),
      toml_edit=lambda t: t + '\n[uncertainty.com]\nkind = "com_offset"\nbody = "cube"\n'
      'range = [-0.019, 0.019]\nnominal = 0.0\nprior = "uniform"\n')
traj("P_com_tall", "com_tall", pose(0.06), pd.PickPlaceOptions(goal=(0.5, 0.15, 0.06), grasp_offset=0.015))

# --- supports: shelf 8 cm tall at the goal; bin
shelf = ('    <body name="shelf" pos="0.5 0.15 0.04">\n      <geom name="shelf" type="box" size="0.06 0.06 0.04" '
         'rgba="0.4 0.4 0.4 1" contype="1" conaffinity="1" friction="1 0.005 0.0001"/>\n    </body>\n')
scene("shelf", extra_world=shelf, goal=(0.5, 0.15, 0.10), support='["table", "shelf"]')
traj("P_shelf", "shelf", pose(0.02), pd.PickPlaceOptions(goal=(0.5, 0.15, 0.10)))
# shelf edge: goal 2.5 cm in from the shelf's edge (cube overhangs 0.5 cm... no: centre 3.5 cm in)
traj("P_shelf_edge", "shelf", pose(0.02), pd.PickPlaceOptions(goal=(0.5, 0.205, 0.10)))
binw = "".join(
    f'      <geom name="bin{i}" type="box" size="{sx} {sy} 0.03" pos="{px} {py} 0.03" rgba="0.3 0.3 0.6 1" '
    f'contype="1" conaffinity="1" friction="1 0.005 0.0001"/>\n'
    for i, (sx, sy, px, py) in enumerate([(0.005, 0.06, 0.045, 0), (0.005, 0.06, -0.045, 0),
                                          (0.05, 0.005, 0, 0.06), (0.05, 0.005, 0, -0.06)]))
binb = f'    <body name="bin" pos="0.5 0.15 0">\n{binw}    </body>\n'
scene("bin", extra_world=binb, support='["table"]\nbodies = ["bin"]')
# released 2 cm above the bin floor, carried at 0.2 m to clear 6 cm walls
traj("P_bin", "bin", pose(0.02), pd.PickPlaceOptions(place_clearance=0.02, transport_height=0.2))


# --- drop from height: plan the place at a raised goal, scenario goal on the table
def wp_drop(h):
    def f(cube, opt):
        w = pd.__dict__["_waypoints_orig"](cube, opt)
        return [(s, p + np.array([0, 0, h]) if s in (355, 370, 395) else p, g) for s, p, g in w]
    return f


pd._waypoints_orig = pd._waypoints
ORIG_SEGS = pd._SEGMENTS
traj("P_drop3", "panda", pose(0.02), wp=wp_drop(0.03))
traj("P_drop6", "panda", pose(0.02), wp=wp_drop(0.06))
traj("P_drop10", "panda", pose(0.02), wp=wp_drop(0.10))

# --- timing: the nominal is 10 s (500 steps at 50 Hz); 2 s = time_scale 0.2 (outside the demo's 0.3 bound)
o = pd.PickPlaceOptions(); object.__setattr__(o, "time_scale", 0.2)
traj("P_fast2s", "panda", pose(0.02), o)
o = pd.PickPlaceOptions(); object.__setattr__(o, "time_scale", 0.3)
traj("P_fast3s", "panda", pose(0.02), o)
traj("P_slow10s", "panda", pose(0.02))     # the nominal itself (10 s)


# --- drag: grasp, lift 3 cm, lower back onto the table, drag along the table to the goal, release
def wp_drag(cube, opt):
    w = pd._waypoints_orig(cube, opt)
    g = np.asarray(opt.goal, float)
    out = []
    for s, p, gr in w:
        if s == 230:   # lifted 3 cm only
            p = np.array([cube[0], cube[1], cube[2] + opt.grasp_offset + 0.03])
        if s == 305:   # back on the table, dragged half way
            p = np.array([(cube[0] + g[0]) / 2, (cube[1] + g[1]) / 2, cube[2] + opt.grasp_offset + 0.001])
        if s == 355:
            p = g + [0, 0, opt.grasp_offset + 0.001]
        if s in (370, 395):
            p = g + [0, 0, opt.grasp_offset + 0.001]
        out.append((s, p, gr))
    return out


traj("P_drag", "panda", pose(0.02), wp=wp_drag)


# --- push: hand closed, lowered beside the cube, pushes it along +y to the goal (no lift)
def wp_push(cube, opt):
    g = np.asarray(opt.goal, float)
    behind = np.array([cube[0], cube[1] - 0.05, 0.025])
    tgt = np.array([g[0], g[1] - 0.05 + 0.0, 0.025])
    pts = [np.array([cube[0], cube[1] - 0.05, 0.15]), behind, behind, behind, behind,
           (behind + tgt) / 2, tgt, tgt, tgt, np.array([g[0], g[1] - 0.08, 0.025]),
           np.array([g[0], g[1] - 0.08, 0.15]), np.array([g[0], g[1] - 0.08, 0.15])]
    return [(s, p, 0.0) for s, p in zip(pd._SEGMENTS, pts)]


traj("P_push", "panda", pose(0.02), wp=wp_push)
# push variant with a pick-and-place scenario of lift_height 0 (is a slide accepted then?)
scene("panda_lift0", toml_edit=lambda t: t.replace("lift_height = 0.02", "lift_height = 0.0"))
traj("P_push_lift0", "panda_lift0", pose(0.02), wp=wp_push)


# --- nominal fails: opens mid-carry (drop at 12 cm), and places 5 cm off the goal
def grip_open_mid(g):
    g = g.copy(); g[265:280] = np.linspace(0, 1, 15); g[280:] = np.maximum(g[280:], 1.0); return g


traj("F_drop_mid", "panda", pose(0.02), grip_override=grip_open_mid)
traj("F_off_goal", "panda", pose(0.02), pd.PickPlaceOptions(goal=(0.5, 0.2, 0.02)))
traj("F_drop10_tall", "tallbox", pose(0.06),
     pd.PickPlaceOptions(goal=(0.5, 0.15, 0.06), grasp_offset=0.015), wp=wp_drop(0.10))


# --- regrasp: set down half way at (0.5, 0), open, regrasp, place at the goal (segments doubled)
def wp_regrasp(cube, opt):
    mid = np.array([0.5, 0.0, cube[2]])
    cur = pd._SEGMENTS; pd._SEGMENTS = ORIG_SEGS
    w1 = pd._waypoints_orig(cube, dataclasses.replace(opt, goal=tuple(mid)))
    w2 = pd._waypoints_orig(np.r_[mid, 1, 0, 0, 0], opt)
    out = [(s, p, g) for s, p, g in w1[:10]]
    out += [(395 + s, p, g) for s, p, g in w2]
    pd._SEGMENTS = cur
    return out


segs_rg = pd._SEGMENTS[:10] + tuple(395 + s for s in pd._SEGMENTS)
traj("P_regrasp", "panda", pose(0.02), wp=wp_regrasp, segs=segs_rg)

# --- two objects: a second (distractor) cube at the goal's side, and one the carried cube pushes
d1 = ('    <body name="cube2" pos="0.5 0.1 0.02">\n      <freejoint name="cube2_joint"/>\n      <geom name="cube2" '
      'type="box" size="0.02 0.02 0.02" mass="0.1" rgba="0.1 0.1 0.9 1" contype="1" conaffinity="1" condim="4" '
      'friction="1 0.005 0.0001" solref="0.01 1"/>\n    </body>\n')
scene("two_near", extra_world=d1, extra_qpos="  0.5 0.1 0.02 1 0 0 0")
traj("P_two_near", "two_near", pose(0.02))          # distractor 5 cm from the goal along -y (1 cm gap)
d2 = d1.replace('pos="0.5 0.1 0.02"', 'pos="0.5 0.125 0.02"')
scene("two_touch", extra_world=d2, extra_qpos="  0.5 0.125 0.02 1 0 0 0")
traj("P_two_touch", "two_touch", pose(0.02))        # the open finger lands on the distractor

# --- gripper force limit (finger_left), rated in [limits] and unrated
fl = '\n[uncertainty.grip_left]\nkind = "force_limit"\nactuator = "finger_left"\nrange = [2.0, 35.0]\nnominal = 35.0\nprior = "uniform"\n'
scene("flim", toml_edit=lambda t: t + fl)
traj("P_flim", "flim", pose(0.02))
scene("flim_unrated", toml_edit=lambda t: t.replace("finger_left = 35.0\n", "").replace("finger_right = 35.0\n", "") + fl)
traj("P_flim_unrated", "flim_unrated", pose(0.02))

# --- pick_hold, long hold: lifted then held 20 s at 15 cm (the plan's carry + place replaced)
hold_t = lambda t: re.sub(r'\[task\]\n.*?\n\n', '[task]\nkind = "pick_hold"\ngripper = "hand"\nlift_height = 0.02\n\n', t, flags=re.S)
scene("hold", toml_edit=hold_t)


def wp_hold(cube, opt):
    w = pd._waypoints_orig(cube, opt)
    return [(s, p if s <= 230 else w[5][1], g if s <= 230 else 0.0) for s, p, g in w]


segs_hold = (75, 125, 140, 165, 180, 230, 330, 430, 530, 630, 830, 1230)
traj("H_hold20", "hold", pose(0.02), wp=wp_hold, segs=segs_hold)

(OUT / "cases.tsv").write_text("".join(f"{c}\t{s}\n" for c, s in cases))
