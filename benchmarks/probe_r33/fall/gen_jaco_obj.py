"""The r32 Jaco scene (jaco_motor.xml) with its 5 cm cube replaced by another object (r33 probe,
part 2): the body 'cube' keeps its free joint and 0.1 kg; the keyframe's object height and the
goal site's height follow the object's half height. usage: gen_jaco_obj.py IN.xml OBJ OUT.xml"""
import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r33/src"), _cm_check.__file__  # r33 snapshot
import sys
import mujoco, numpy as np
G = mujoco.mjtGeom
q0 = [1, 0, 0, 0]; qx = [np.cos(np.pi / 4), np.sin(np.pi / 4), 0, 0]   # 90 deg about x: axis along y
qy = [np.cos(np.pi / 4), 0, np.sin(np.pi / 4), 0]                       # axis along x
OBJ = {  # geoms (type, size, pos, quat), half height
    "cyl_lying": ([(G.mjGEOM_CYLINDER, [0.025, 0.045, 0], [0, 0, 0], qy)], 0.025),
    "cyl_stand": ([(G.mjGEOM_CYLINDER, [0.025, 0.05, 0], [0, 0, 0], q0)], 0.05),
    "sphere": ([(G.mjGEOM_SPHERE, [0.025, 0, 0], [0, 0, 0], q0)], 0.025),
    "mesh": ([("mesh", None, [0, 0, 0], q0)], 0.025),
    "compound": ([(G.mjGEOM_BOX, [0.025, 0.025, 0.025], [0, 0, 0], q0),
                  (G.mjGEOM_CAPSULE, [0.01, 0.03, 0], [0, 0, 0.045], q0)], 0.025),
    "tall": ([(G.mjGEOM_BOX, [0.012, 0.025, 0.07], [0, 0, 0], q0)], 0.07),
}

def pebble(h=0.025):
    a = np.linspace(0, 2 * np.pi, 8, endpoint=False) + np.pi / 8
    r = h / np.cos(np.pi / 8)
    ring = np.stack([r * np.cos(a), r * np.sin(a)], 1)
    top = np.c_[ring, np.full(8, h)]; top[:2, 2] = 0.6 * h
    return np.vstack([top, np.c_[ring, np.full(8, -h)]])

spec = mujoco.MjSpec.from_file(sys.argv[1]); obj = sys.argv[2]
m0 = spec.compile()
body = spec.body("cube"); old = body.geoms[0]
for g in list(body.geoms):
    spec.delete(g)
geoms, hz = OBJ[obj]
for k, (typ, size, pos, quat) in enumerate(geoms):
    kw = dict(name="cube_geom" if k == 0 else f"cube_part{k}", pos=pos, quat=quat, rgba=[0.2, 0.6, 0.9, 1])
    if typ == "mesh":
        mm = spec.add_mesh(name="pebble"); mm.uservert = pebble().ravel().tolist()
        g = body.add_geom(type=G.mjGEOM_MESH, meshname="pebble", **kw)
    else:
        g = body.add_geom(type=typ, size=size, **kw)
    g.mass = 0.1 / len(geoms)
dz = hz - 0.025
body.pos = [0.5, 0.15, 0.125 + dz]
adr = m0.jnt_qposadr[m0.joint("cube_joint").id]
for k in spec.keys:
    q = np.array(k.qpos); q[adr + 2] += dz; k.qpos = q.tolist()
spec.site("goal").pos = [0.5, -0.15, 0.125 + dz]
spec.compile()
open(sys.argv[3], "w").write(spec.to_xml()); print(0.125 + dz)
