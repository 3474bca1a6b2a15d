"""robosuite Panda + Robotiq 2F-85 (real_models' composition) with other objects and a
'loosen over the goal' pick-and-place (fall-rule probe, r33).
usage: gen_panda.py scene OBJ OUT.xml            -> writes the scene with object OBJ (see OBJECTS)
       gen_panda.py traj SCEN.toml OBJ OUT.npz [--loosen H G] [--grasp-dz DZ]
The trajectory = real_models' pick_place timeline; with --loosen: over the goal the hand stops
H above the place pose, the gripper goes to G (0 closed..1 open) for 0.3 s, closes again, then
places as usual (so a sample that loses the object there falls H onto the goal)."""
import dataclasses, sys, tomllib
from pathlib import Path
import mujoco, numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r33/src"), cm.__file__
sys.path.insert(0, "/tmp/r33/src/benchmarks")
from real_models import scripted as S, scenes
from critmoment.trajectory import Trajectory, save_trajectory

TT = scenes.TABLE_TOP
G = mujoco.mjtGeom
# name -> (list of geoms (type, size, pos, quat, mass share), half height of the object, shelf)
def _ob(name):
    q0 = [1, 0, 0, 0]
    qy = [np.cos(np.pi / 4), 0, np.sin(np.pi / 4), 0]   # 90 deg about y: cylinder axis along x
    return {
        "cube": ([(G.mjGEOM_BOX, [0.02] * 3, [0, 0, 0], q0)], 0.02, None),
        "cyl_lying": ([(G.mjGEOM_CYLINDER, [0.02, 0.04, 0], [0, 0, 0], qy)], 0.02, None),
        "cyl_stand": ([(G.mjGEOM_CYLINDER, [0.02, 0.04, 0], [0, 0, 0], q0)], 0.04, None),
        "sphere": ([(G.mjGEOM_SPHERE, [0.025, 0, 0], [0, 0, 0], q0)], 0.025, None),
        "mesh": ([("mesh", None, [0, 0, 0], q0)], 0.02, None),
        "compound": ([(G.mjGEOM_BOX, [0.02, 0.02, 0.02], [0, 0, 0], q0),
                      (G.mjGEOM_BOX, [0.01, 0.01, 0.02], [0, 0, 0.04], q0)], 0.02, None),
        "tall": ([(G.mjGEOM_BOX, [0.012, 0.012, 0.07], [0, 0, 0], q0)], 0.07, None),
        "shelf": ([(G.mjGEOM_BOX, [0.02] * 3, [0, 0, 0], q0)], 0.02, 0.10),
    }[name]

def mesh_vertices():
    # an irregular convex 'pebble': an octagonal prism, 4 cm across, 4 cm tall, one side bevelled
    a = np.linspace(0, 2 * np.pi, 8, endpoint=False) + np.pi / 8
    r = 0.02 / np.cos(np.pi / 8)
    ring = np.stack([r * np.cos(a), r * np.sin(a)], 1)
    top = np.c_[ring * [1, 1], np.full(8, 0.02)]; top[:2, 2] = 0.012   # bevel
    bot = np.c_[ring, np.full(8, -0.02)]
    return np.vstack([top, bot])

def scene(obj, out):
    spec = mujoco.MjSpec.from_file(str(Path(__file__).parent / "_dummy") if False else str(Path("/tmp/r33/fall/panda_robotiq85.xml")))
    geoms, hz, shelf = _ob(obj)
    body = spec.body("cube")
    for g in list(body.geoms):
        spec.delete(g)
    z = TT + hz + (shelf or 0.0)
    body.pos = [0, 0, z]
    for k, (typ, size, pos, quat) in enumerate(geoms):
        kw = dict(name="cube" if k == 0 else f"cube_part{k}", pos=pos, quat=quat, condim=4,
                  friction=[1, 0.005, 0.0001], rgba=[0.8, 0.1, 0.1, 1])
        if typ == "mesh":
            m = spec.add_mesh(name="pebble"); m.uservert = mesh_vertices().ravel().tolist()
            g = body.add_geom(type=G.mjGEOM_MESH, meshname="pebble", **kw)
        else:
            g = body.add_geom(type=typ, size=size, **kw)
        g.mass = scenes.CUBE_MASS / len(geoms)
    if shelf:
        sh = spec.worldbody.add_body(name="shelf", pos=[0, -0.1, TT + shelf / 2])
        sh.add_geom(name="shelf_collision", type=G.mjGEOM_BOX, size=[0.08, 0.08, shelf / 2],
                    friction=[1, 0.005, 0.0001])
    spec.site("goal").pos = [0.0, 0.2, TT + hz]
    m = spec.compile()
    Path(out).write_text(spec.to_xml()); print("wrote", out, "nbody", m.nbody)

def traj(scen, obj, out, loosen=None, dz=0.0):
    raw = tomllib.loads(Path(scen).read_text())
    model = mujoco.MjModel.from_xml_path(str(Path(scen).parent / raw["model"]["mjcf"]))
    cfg = scenes.ROBOTS["panda_robotiq85"]
    _, hz, shelf = _ob(obj)
    robot = "panda_robotiq85"; rest = S.REST[robot]
    cube = S.cube_pose(0, TT + (shelf or 0.0), hz)
    if shelf: cube[1] = -0.1   # on the shelf
    data = mujoco.MjData(model)
    joints = cfg["joints"]; arm_ids = [model.joint(j).id for j in joints]
    qpos0 = data.qpos.copy(); qpos0[model.jnt_qposadr[arm_ids]] = rest
    cj = model.joint("cube_joint").id
    qpos0[model.jnt_qposadr[cj]:model.jnt_qposadr[cj] + 7] = cube
    pads = [model.geom(g).name for g in range(model.ngeom) if "pad" in model.geom(g).name
            and (model.geom_contype[g] or model.geom_conaffinity[g])]
    arm = S.Arm(model, tuple(joints), "gripper0_eef", tuple(pads), qpos0)
    data.qpos[:] = qpos0; mujoco.mj_kinematics(model, data)
    p0, r0 = arm.tcp(data)
    down = S._frame([1, 0, 0], [0, 1, 0]) @ np.diag([1, -1, -1])
    if np.trace(down.T @ r0) < np.trace((down @ np.diag([-1, -1, 1])).T @ r0):
        down = down @ np.diag([-1, -1, 1])
    goal = model.site("goal").pos.copy()
    grasp = cube[:3] + [0, 0, dz]
    top = TT + 0.15 + max(0.0, 2 * hz - 0.04) + (shelf or 0.0)
    above = np.array([cube[0], cube[1], top]); place = goal + [0, 0, dz + 0.002]
    over = np.array([goal[0], goal[1], top])
    pts = [(0, p0, r0, 1.0), (75, above, down, 1.0), (125, grasp, down, 1.0), (140, grasp, down, 1.0),
           (165, grasp, down, 0.0), (180, grasp, down, 0.0), (230, above, down, 0.0), (305, over, down, 0.0)]
    D = 0
    if loosen:
        H, Gv = loosen; up = place + [0, 0, H]
        pts += [(335, up, down, 0.0), (345, up, down, 0.0), (349, up, down, Gv), (364, up, down, Gv),
                (370, up, down, 0.0), (380, up, down, 0.0)]
        D = 55
    pts += [(355 + D, place, down, 0.0), (370 + D, place, down, 0.0), (395 + D, place, down, 1.0),
            (445 + D, over, down, 1.0), (500 + D, over, down, 1.0)]
    n = 500 + D
    q, grip = S.joint_path(arm, data, pts, n, start=rest, rest=rest)
    actions = np.concatenate([arm.feed_forward(q, 0.02, qpos0), grip[:, None]], axis=1)
    start = np.concatenate([rest, [1.0]])
    mine = [f"{j}_servo" for j in joints] + ["gripper"]
    cols = [mine.index("gripper" if ch.get("normalised") else ch["actuators"][0]) for ch in raw["actions"]["channel"]]
    t = Trajectory(actions=actions[:, cols], fps=50.0, start=start[cols], qpos0=qpos0, object_pose=cube,
                   meta={"generator": "probe_r33 gen_panda", "obj": obj, "loosen": loosen, "dz": dz},
                   source="probe_r33 gen_panda")
    save_trajectory(t, out); print("wrote", out, t.actions.shape)

if __name__ == "__main__":
    if sys.argv[1] == "scene":
        scene(sys.argv[2], sys.argv[3])
    else:
        a = sys.argv[2:]
        lo = None; dz = 0.0
        if "--loosen" in a:
            i = a.index("--loosen"); lo = (float(a[i + 1]), float(a[i + 2])); a = a[:i] + a[i + 3:]
        if "--grasp-dz" in a:
            i = a.index("--grasp-dz"); dz = float(a[i + 1]); a = a[:i] + a[i + 2:]
        traj(a[0], a[1], a[2], lo, dz)
