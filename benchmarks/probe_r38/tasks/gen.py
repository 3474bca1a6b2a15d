"""Round 38 tasks/objects/contact probe: Panda scene copies + trajectories.
usage: gen.py OUTDIR   (writes OUTDIR/<scen>/{scene.xml,panda.xml,scenario.toml[,*.obj]},
OUTDIR/<case>.npz and OUTDIR/cases.tsv: case -> scenario)
Built on benchmarks/probe_r31/tasks/gen.py (same scene()/traj() helpers)."""
import pathlib, re, shutil, sys
import mujoco
import numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r38/tasks/src"), critmoment.__file__
from critmoment import panda_demo as pd

OUT = pathlib.Path(sys.argv[1]); OUT.mkdir(parents=True, exist_ok=True)
SRC = pathlib.Path(pd.scene_path()).parent
XML0 = (SRC / "scene.xml").read_text()
TOML0 = (SRC / "scenario.toml").read_text()
CUBE_BODY = re.search(r'    <body name="cube" pos="0.5 -0.15 0.02">.*?\n    </body>\n', XML0, re.S).group(0)
GEOM_ATTR = 'contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001" solref="0.01 1"'
cases = []


def scene(name, body_xml=None, z=0.02, quat="1 0 0 0", extra_world="", extra_qpos="", goal=None,
          toml_edit=None, support=None, asset="", option=None, files=()):
    d = OUT / name; d.mkdir(exist_ok=True)
    shutil.copy(SRC / "panda.xml", d / "panda.xml")
    for fn, txt in files:
        (d / fn).write_text(txt)
    xml = XML0
    if body_xml is not None:
        xml = xml.replace(CUBE_BODY, body_xml)
    if asset:
        xml = xml.replace("  <worldbody>", asset + "  <worldbody>")
    if option is not None:
        xml = re.sub(r'  <option [^\n]*/>', option, xml)
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


def body(geoms, z=0.02, quat="1 0 0 0", inertial="", x=0.5, y=-0.15):
    return (f'    <body name="cube" pos="{x} {y} {z}" quat="{quat}">\n      <freejoint name="cube_joint"/>\n'
            f'{inertial}{geoms}    </body>\n')


def traj(name, scen, obj_pose, opt=None, wp=None, segs=None, grip_override=None):
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


WP0 = pd._waypoints
base = pd.sample_cube_pose(0)          # seed-0 spawn
X, Y = base[0], base[1]


def pose(z, quat=(1, 0, 0, 0), x=None, y=None):
    return np.array([X if x is None else x, Y if y is None else y, z, *quat], float)


def obj(name, geoms, z, quat="1 0 0 0", goal_z=None, inertial="", place_clear=0.002, grasp=0.01,
        case=None, **kw):
    gz = z if goal_z is None else goal_z
    scene(name, body(geoms, z, quat, inertial), z=z, quat=quat, goal=(0.5, 0.15, gz), **kw)
    q = tuple(float(v) for v in quat.split())
    traj(case or ("O_" + name), name, pose(z, q),
         pd.PickPlaceOptions(goal=(0.5, 0.15, gz), place_clearance=place_clear, grasp_offset=grasp))


G = lambda s, attr=GEOM_ATTR, nm="cube", mass='mass="0.1"': (
    f'      <geom name="{nm}" {s} {mass} rgba="0.9 0.1 0.1 1"\n            {attr}/>\n')


# ---------------------------------------------------------------- objects
def bottle_obj(r_body=0.025, h_body=0.08, r_neck=0.012, h_sh=0.10, h_top=0.12, n=16, z_grip=0.11):
    """convex bottle hull (OBJ): body cylinder, cone shoulder, neck; origin at the grip height"""
    rings = [(r_body, 0.0), (r_body, h_body), (r_neck, h_sh), (r_neck, h_top)]
    v = []
    for r, h in rings:
        for k in range(n):
            a = 2 * np.pi * k / n
            v.append((r * np.cos(a), r * np.sin(a), h - z_grip))
    lines = [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in v]
    # faces: MuJoCo takes the convex hull of a mesh's vertices for collision; write side quads as triangles
    f = []
    for i in range(len(rings) - 1):
        for k in range(n):
            a, b = i * n + k + 1, i * n + (k + 1) % n + 1
            c, d = a + n, b + n
            f += [f"f {a} {b} {d}", f"f {a} {d} {c}"]
    for k in range(1, n - 1):
        f.append(f"f 1 {k + 2} {k + 1}")
        top = (len(rings) - 1) * n
        f.append(f"f {top + 1} {top + k + 1} {top + k + 2}")
    return "\n".join(lines + f) + "\n"


OBJ = bottle_obj()
asset_b = '  <asset>\n    <mesh name="bottle" file="bottle.obj"/>\n  </asset>\n'
# bottle standing, gripped at its neck 1 cm below the top (hangs 11 cm below the grip); origin at the grip
BZ = 0.11
obj("bottle", G('type="mesh" mesh="bottle"'), BZ, asset=asset_b, files=[("bottle.obj", OBJ)], grasp=0.0,
    place_clear=0.003)
obj("bottle_c6", G('type="mesh" mesh="bottle"', GEOM_ATTR.replace('condim="4"', 'condim="6"')
                   .replace('1 0.005 0.0001', '1 0.02 0.002')), BZ, asset=asset_b,
    files=[("bottle.obj", OBJ)], grasp=0.0, place_clear=0.003)
obj("bottle_c3", G('type="mesh" mesh="bottle"', GEOM_ATTR.replace('condim="4"', 'condim="3"')), BZ,
    asset=asset_b, files=[("bottle.obj", OBJ)], grasp=0.0, place_clear=0.003)
# tall thin stick 1.4 (x) x 3 (y, between the pads) x 14 cm, gripped 1.5 cm below its top; origin at the grip
SZ = 0.125
stick = 'type="box" size="0.007 0.015 0.07" pos="0 0 -0.055"'
obj("stick", G(stick), SZ, grasp=0.0, place_clear=0.003)
obj("stick_c3", G(stick, GEOM_ATTR.replace('condim="4"', 'condim="3"')), SZ, grasp=0.0, place_clear=0.003)
obj("stick_c6", G(stick, GEOM_ATTR.replace('condim="4"', 'condim="6"').replace('1 0.005 0.0001', '1 0.05 0.005')),
    SZ, grasp=0.0, place_clear=0.003)
# cube with its centre of mass far off its centre (explicit inertial, 18 mm along x, 15 mm down)
obj("offcom", G('type="box" size="0.02 0.02 0.02"', mass=""), 0.02,
    inertial='      <inertial pos="0.018 0 -0.015" mass="0.1" diaginertia="2.7e-5 2.7e-5 2.7e-5"/>\n')
# several geoms, different frictions and condims: a core (friction 1, condim 4) with rubber plates on
# the faces the pads grip (friction 2, condim 6, own solref), parameter on the core
plates = ('      <geom name="plate_l" type="box" size="0.018 0.002 0.018" pos="0 0.022 0" mass="0.005" '
          'rgba="0.1 0.1 0.1 1" contype="1" conaffinity="1" condim="6" priority="2" friction="2 0.02 0.001" '
          'solref="0.02 1"/>\n'
          '      <geom name="plate_r" type="box" size="0.018 0.002 0.018" pos="0 -0.022 0" mass="0.005" '
          'rgba="0.1 0.1 0.1 1" contype="1" conaffinity="1" condim="6" priority="2" friction="2 0.02 0.001" '
          'solref="0.02 1"/>\n')
obj("multigeom", G('type="box" size="0.02 0.02 0.02"') + plates, 0.02)
# the same with the friction parameter on a plate (the geoms the pads touch)
scene("multigeom_pl", body(G('type="box" size="0.02 0.02 0.02"') + plates, 0.02), goal=(0.5, 0.15, 0.02),
      toml_edit=lambda t: t.replace('[uncertainty.friction]\ngeom = "cube"', '[uncertainty.friction]\ngeom = "plate_l"'))
traj("O_multigeom_pl", "multigeom_pl", pose(0.02))
# the same, plates WITHOUT priority (pads and plates mix: max friction), parameter on the core
plates_np = plates.replace(' priority="2"', '')
obj("multigeom_np", G('type="box" size="0.02 0.02 0.02"') + plates_np, 0.02)
# 5 g and 2.5 kg cubes: covered before (10 g, 2 kg); a 4 kg cube near joint limits with box 2-6 kg
scene("heavy4", body(G('type="box" size="0.02 0.02 0.02"', mass='mass="4.0"'), 0.02), goal=(0.5, 0.15, 0.02),
      toml_edit=lambda t: t.replace('range = [0.05, 3.0]      # [kg]; 3 kg is the Panda\'s quoted payload\nnominal = 0.1',
                                    'range = [2.0, 6.0]\nnominal = 4.0'))
traj("O_heavy4", "heavy4", pose(0.02))

# ---------------------------------------------------------------- tasks
# pick from a surface tilted 15 deg about world y (slope along x): the cube lies on it;
# tan 15 = 0.268 -> frictions below slide before the grasp
ang = np.deg2rad(15.0)
wq = (np.cos(ang / 2), 0, np.sin(ang / 2), 0)   # rotation about +y
cx, cy = X, Y
# wedge top plane passes through the cube's bottom-face centre; cube centre 2 cm along the plane normal
nrm = np.array([np.sin(ang), 0, np.cos(ang)])
ctr = np.array([cx, cy, 0.05])
bot = ctr - 0.02 * nrm
wedge_c = bot - 0.01 * nrm                           # a 2 cm thick slab under it
wedge = (f'    <body name="wedge" pos="{wedge_c[0]:.5f} {wedge_c[1]:.5f} {wedge_c[2]:.5f}" '
         f'quat="{wq[0]:.7f} 0 {wq[2]:.7f} 0">\n      <geom name="wedge" type="box" size="0.06 0.06 0.01" '
         'rgba="0.4 0.4 0.4 1" contype="1" conaffinity="1" friction="1 0.005 0.0001"/>\n    </body>\n'
         f'    <body name="wedge_post" pos="{wedge_c[0]:.5f} {wedge_c[1]:.5f} {wedge_c[2] / 2 - 0.005:.5f}">\n'
         f'      <geom name="wedge_post" type="box" size="0.03 0.03 {wedge_c[2] / 2 - 0.006:.5f}" '
         'rgba="0.4 0.4 0.4 1" contype="1" conaffinity="1"/>\n    </body>\n')
qs = f"{wq[0]:.7f} 0 {wq[2]:.7f} 0"
scene("tilt15", body(G('type="box" size="0.02 0.02 0.02"'), ctr[2], qs, x=cx, y=cy), z=ctr[2], quat=qs,
      extra_world=wedge, support='["table", "wedge", "wedge_post"]')
XML_T = (OUT / "tilt15" / "scene.xml").read_text().replace(
    f"0.5 -0.15 {ctr[2]} {qs}\"", f"{cx} {cy} {ctr[2]} {qs}\"")
(OUT / "tilt15" / "scene.xml").write_text(XML_T)
traj("T_tilt15", "tilt15", np.array([cx, cy, ctr[2], *wq]))

# goal as a site: the bundled 'goal' site lies on the table (z 0.0005), the cube's origin ends 2 cm above it
scene("goalsite", toml_edit=lambda t: t.replace("goal = [0.5, 0.15, 0.02]", 'goal_site = "goal"'))
traj("T_goalsite", "goalsite", pose(0.02))
scene("goalsite_tol15", toml_edit=lambda t: t.replace("goal = [0.5, 0.15, 0.02]", 'goal_site = "goal"')
      .replace("tolerance = 0.03 ", "tolerance = 0.015"))
traj("T_goalsite_tol15", "goalsite_tol15", pose(0.02))
# goal site on a free tray (a body that can move): the site moves with it
tray = ('    <body name="tray" pos="0.5 0.15 0.004">\n      <freejoint name="tray_joint"/>\n'
        '      <geom name="tray" type="box" size="0.05 0.05 0.004" mass="0.3" rgba="0.3 0.6 0.3 1" '
        'contype="1" conaffinity="1" friction="0.05 0.005 0.0001"/>\n'
        '      <site name="tray_goal" pos="0 0 0.024" size="0.005"/>\n    </body>\n')
scene("goaltray", extra_world=tray, extra_qpos=" 0.5 0.15 0.004 1 0 0 0",
      support='["table", "tray"]',
      toml_edit=lambda t: t.replace("goal = [0.5, 0.15, 0.02]", 'goal_site = "tray_goal"'))
traj("T_goaltray", "goaltray", pose(0.02), pd.PickPlaceOptions(goal=(0.5, 0.15, 0.028)))

# pick_hold whose hold ends pressed against a fixed post (+x side), post not a support / post a support
hold_t = lambda t: re.sub(r'\[task\]\n.*?\n\n', '[task]\nkind = "pick_hold"\ngripper = "hand"\nlift_height = 0.02\n\n',
                          t, flags=re.S)
post = ('    <body name="post" pos="0.6 0.0 0.1">\n      <geom name="post" type="box" size="0.02 0.1 0.1" '
        'rgba="0.5 0.5 0.5 1" contype="1" conaffinity="1" friction="1 0.005 0.0001"/>\n    </body>\n')
scene("hold_post", extra_world=post, toml_edit=hold_t)
scene("hold_post_sup", extra_world=post, toml_edit=hold_t, support='["table", "post"]')


def wp_hold_press(cube, opt):
    w = WP0(cube, opt)
    lift = w[5][1]
    # carry to (0.555 - 0.005 push, 0.0, 0.1): the cube's +x face (x + 0.02) 5 mm into the post's face at 0.58
    press = np.array([0.565, 0.0, 0.1 + opt.grasp_offset])
    app = np.array([0.53, 0.0, 0.1 + opt.grasp_offset])
    out = [(s, p, g) for s, p, g in w[:6]]
    out += [(305, app, 0.0), (355, press, 0.0), (370, press, 0.0), (395, press, 0.0), (445, press, 0.0),
            (500, press, 0.0)]
    return out


traj("H_press", "hold_post", pose(0.02), wp=wp_hold_press)
traj("H_press_sup", "hold_post_sup", pose(0.02), wp=wp_hold_press)

# ---------------------------------------------------------------- contact / solver settings (cube, seed-0 motion)
OPT0 = '  <option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>'
def cvar(name, option=None, attr=None):
    geoms = G('type="box" size="0.02 0.02 0.02"', attr or GEOM_ATTR)
    scene(name, body(geoms, 0.02), option=option)
    traj("C_" + name, name, pose(0.02))


cvar("negsolref", attr=GEOM_ATTR.replace('solref="0.01 1"', 'solref="-20000 -200"'))
cvar("negsolref_soft", attr=GEOM_ATTR.replace('solref="0.01 1"', 'solref="-2000 -20"'))
cvar("jacsparse", option=OPT0.replace('/>', ' jacobian="sparse"/>'))
cvar("c6roll", attr=GEOM_ATTR.replace('condim="4"', 'condim="6"').replace('1 0.005 0.0001', '1 0.05 0.01'))
cvar("rk4_noslip_nowarm", option=OPT0.replace('implicitfast', 'RK4').replace('/>', ' noslip_iterations="10">\n'
     '    <flag warmstart="disable"/>\n  </option>'))
cvar("dt05_pyr_sparse", option=OPT0.replace('timestep="0.002"', 'timestep="0.0005"').replace(
     'cone="elliptic" impratio="10"', 'cone="pyramidal" impratio="1" jacobian="sparse"'))
cvar("dt5_multiccd", option=OPT0.replace('timestep="0.002"', 'timestep="0.005"').replace(
     '/>', '>\n    <flag multiccd="enable"/>\n  </option>'))
cvar("padmargin_gap", attr=GEOM_ATTR + ' margin="0.003" gap="0.003"')

(OUT / "cases.tsv").write_text("".join(f"{c}\t{s}\n" for c, s in cases))
