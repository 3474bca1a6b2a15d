"""Panda task-shape probes: scripted TCP waypoints -> feed-forward joint targets, as
critmoment.panda_demo does, but with free waypoint lists (regrasp, shelf/bin goals).
usage: gen_panda.py OUTDIR   (writes <case>.npz and scenario copies)"""
import dataclasses, pathlib, re, shutil, sys
import mujoco, numpy as np
from critmoment import panda_demo as pd
from critmoment.trajectory import Trajectory, save_trajectory  # noqa

OUT = pathlib.Path(sys.argv[1]); OUT.mkdir(parents=True, exist_ok=True)
SRC = pathlib.Path(pd.scene_path()).parent


def plan(model, cube, pts, rot=None):
    """pts: [(step, tcp xyz, grip)] after step 0 (ready, open); first move joint space."""
    joints = [model.joint(j).id for j in pd.ARM_JOINTS]
    qadr, dofs = model.jnt_qposadr[joints], model.jnt_dofadr[joints]
    site = model.site("tcp").id
    data = mujoco.MjData(model)
    data.qpos[qadr] = pd.READY_POSE
    mujoco.mj_kinematics(model, data)
    start = data.site_xpos[site].copy(); R = data.site_xmat[site].reshape(3, 3).copy()
    points = [(0, start, 1.0), *pts]
    n = points[-1][0]
    tcp = np.empty((n, 3)); grip = np.empty(n); seg = np.empty(n, int)
    for k in range(len(points) - 1):
        t0, t1 = points[k][0], points[k + 1][0]
        s = pd._min_jerk((np.arange(t0, t1) - t0) / (t1 - t0))
        tcp[t0:t1] = points[k][1] + s[:, None] * (np.asarray(points[k + 1][1]) - points[k][1])
        grip[t0:t1] = points[k][2] + s * (points[k + 1][2] - points[k][2]); seg[t0:t1] = k
    q = np.empty((n, 7))
    data.qpos[qadr] = pd.READY_POSE
    err = pd.ik_tcp(model, data, site, qadr, dofs, np.asarray(points[1][1]), R, rest=pd.READY_POSE, iters=2000)
    assert err < 1e-5, err
    qa = data.qpos[qadr].copy(); first = seg == 0
    s = pd._min_jerk(np.arange(points[1][0]) / points[1][0])
    q[first] = pd.READY_POSE + s[:, None] * (qa - pd.READY_POSE)
    for i in np.flatnonzero(~first):
        err = pd.ik_tcp(model, data, site, qadr, dofs, tcp[i], R, rest=pd.READY_POSE)
        assert err < 1e-5, (i, err)
        q[i] = data.qpos[qadr]
    return q, grip


def build(model, cube, pts, name):
    q, grip = plan(model, cube, pts)
    u = pd._feed_forward(model, q, grip, 1 / 50.0)
    joints = [model.joint(j).id for j in pd.ARM_JOINTS]
    qpos0 = model.key("home").qpos.copy()
    qpos0[model.jnt_qposadr[joints]] = pd.READY_POSE
    for i in (1, 2):
        qpos0[model.jnt_qposadr[model.joint(f"finger_joint{i}").id]] = pd.FINGER_OPEN
    a = model.jnt_qposadr[model.joint("cube_joint").id]; qpos0[a:a + 7] = cube
    np.savez(OUT / f"{name}.npz", actions=np.concatenate([u, grip[:, None]], 1), fps=50.0,
             start=np.concatenate([pd.READY_POSE, [1.0]]), qpos0=qpos0, object_pose=cube)
    print("wrote", name, len(u))


def scene_copy(name, extra_geoms, goal, support_extra=()):
    d = OUT / name; d.mkdir(exist_ok=True)
    shutil.copy(SRC / "panda.xml", d / "panda.xml")
    xml = (SRC / "scene.xml").read_text()
    xml = xml.replace("<!-- where the cube must be placed", extra_geoms + "\n    <!-- where the cube must be placed")
    (d / "scene.xml").write_text(xml)
    toml = (SRC / "scenario.toml").read_text()
    toml = re.sub(r"goal = \[[^\]]*\]", f"goal = [{goal[0]}, {goal[1]}, {goal[2]}]", toml)
    if support_extra:
        toml = toml.replace('geoms = ["table"]', "geoms = [" + ", ".join(f'"{g}"' for g in ["table", *support_extra]) + "]")
    (d / "scenario.toml").write_text(toml)
    return d / "scenario.toml"


cube = pd.sample_cube_pose(0)
G = np.array(pd.GOAL); H = 0.15; go = 0.01
model = mujoco.MjModel.from_xml_path(str(pd.scene_path()))
grasp = cube[:3] + [0, 0, go]; above = np.array([cube[0], cube[1], H])
mid = np.array([0.5, 0.0, pd.CUBE_HALF])   # set-down spot between pick and goal
over_goal = np.array([G[0], G[1], H]); place = G + [0, 0, go + 0.002]


def pick(t0, at, ofs=(0, 0, 0)):
    g = at + [0, 0, go] + np.asarray(ofs); ab = np.array([at[0], at[1], H]) + [ofs[0], ofs[1], 0]
    return [(t0 + 75, ab, 1.0), (t0 + 125, g, 1.0), (t0 + 140, g, 1.0), (t0 + 165, g, 0.0), (t0 + 180, g, 0.0)]


def place_at(t0, at, clear=0.002, ofs=(0, 0, 0)):
    p = np.asarray(at) + [0, 0, go + clear] + np.asarray(ofs); og = np.array([at[0], at[1], H]) + [ofs[0], ofs[1], 0]
    return [(t0 + 75, og, 0.0), (t0 + 125, p, 0.0), (t0 + 140, p, 0.0), (t0 + 165, p, 1.0), (t0 + 215, og, 1.0)]


# 1a regrasp, same grasp: pick at spawn, set down at mid, re-grasp at mid, place at goal
pts = pick(0, cube[:3]) + [(t + 180, p, g) for t, p, g in place_at(0, mid)]
t = pts[-1][0]
pts += [(t + 50, mid + [0, 0, go], 1.0), (t + 65, mid + [0, 0, go], 1.0), (t + 90, mid + [0, 0, go], 0.0), (t + 105, mid + [0, 0, go], 0.0)]
t = pts[-1][0]
pts += [(t + 50, np.array([mid[0], mid[1], H]), 0.0)] + [(t + 50 + tt, p, g) for tt, p, g in place_at(0, G)] + [(t + 50 + 265, over_goal, 1.0)]
build(model, cube, pts, "P_regrasp_same")


# 1b regrasp at another place on the cube: second grasp 1.2 cm off-centre along x and 6 mm lower
def regrasp(ofs, name):
    pts = pick(0, cube[:3]) + [(t + 180, p, g) for t, p, g in place_at(0, mid)]
    t = pts[-1][0]; g2 = mid + [0, 0, go] + np.asarray(ofs)
    pts += [(t + 50, g2, 1.0), (t + 65, g2, 1.0), (t + 90, g2, 0.0), (t + 105, g2, 0.0)]
    t = pts[-1][0]
    pts += [(t + 50, np.array([mid[0] + ofs[0], mid[1] + ofs[1], H]), 0.0)]
    pts += [(t + 50 + tt, p, g) for tt, p, g in place_at(0, G, ofs=ofs)] + [(t + 50 + 265, over_goal + [ofs[0], ofs[1], 0], 1.0)]
    build(model, cube, pts, name)


regrasp((0.012, 0, -0.006), "P_regrasp_off")
regrasp((0.012, 0, 0.004), "P_regrasp_off_high")

# 2 place on a shelf (block 6 cm tall at the goal), listed in [support]
for hgt, nm in ((0.06, "shelf6"), (0.10, "shelf10")):
    box = (f'<body name="shelf" pos="0.5 0.15 {hgt/2}"><geom name="shelf" type="box" size="0.05 0.05 {hgt/2}" '
           f'rgba="0.3 0.3 0.6 1" contype="1" conaffinity="1" friction="1 0.005 0.0001"/></body>')
    g = (0.5, 0.15, hgt + pd.CUBE_HALF)
    scene_copy(nm, box, g, ["shelf"])
    m2 = mujoco.MjModel.from_xml_path(str(OUT / nm / "scene.xml"))
    pts = pick(0, cube[:3]) + [(t + 180, p, gg) for t, p, gg in place_at(0, np.array(g))] + [(180 + 265, over_goal, 1.0)]
    build(m2, cube, pts, f"P_{nm}")
    # same, shelf NOT in support (shelf_nosup) reusing scene
    d = scene_copy(nm + "_nosup", box, g)
# 2b shallow bin: floor = table, 4 walls 3 cm tall around goal, inner half-width 4 cm
walls = "".join(
    f'<geom name="bin{i}" type="box" pos="{x} {y} 0.015" size="{sx} {sy} 0.015" rgba="0.3 0.6 0.3 1" contype="1" conaffinity="1"/>'
    for i, (x, y, sx, sy) in enumerate([(0.5 + 0.045, 0.15, 0.005, 0.05), (0.5 - 0.045, 0.15, 0.005, 0.05),
                                         (0.5, 0.15 + 0.045, 0.05, 0.005), (0.5, 0.15 - 0.045, 0.05, 0.005)]))
scene_copy("bin", f'<body name="bin">{walls}</body>', tuple(G), ["bin0", "bin1", "bin2", "bin3"])
m3 = mujoco.MjModel.from_xml_path(str(OUT / "bin" / "scene.xml"))
pts = pick(0, cube[:3]) + [(t + 180, p, gg) for t, p, gg in place_at(0, G, clear=0.01)] + [(180 + 265, over_goal, 1.0)]
build(m3, cube, pts, "P_bin")
