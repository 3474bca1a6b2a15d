"""gym-aloha's ACT scene (the shipped file, read with MjSpec) with its red box replaced by another
object (r33 probe, part 2); written next to the shipped XML (outside the repository).
usage: gen_act_obj.py SHIPPED.xml OBJ OUT.xml (OUT next to SHIPPED: relative mesh paths)   -> prints the object's settled centre height"""
import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r33/src"), _cm_check.__file__  # r33 snapshot
import sys
from pathlib import Path
import mujoco, numpy as np
G = mujoco.mjtGeom
q0 = [1, 0, 0, 0]; qy = [np.cos(np.pi / 4), 0, np.sin(np.pi / 4), 0]
OBJ = {  # geoms (type, size, pos, quat), centre height over the table, shelf height
    "cyl_lying": ([(G.mjGEOM_CYLINDER, [0.02, 0.04, 0], [0, 0, 0], qy)], 0.02, 0),
    "cyl_stand": ([(G.mjGEOM_CYLINDER, [0.02, 0.035, 0], [0, 0, 0], q0)], 0.035, 0),
    "sphere": ([(G.mjGEOM_SPHERE, [0.02, 0, 0], [0, 0, 0], q0)], 0.02, 0),
    "mesh": ([("mesh", None, [0, 0, 0], q0)], 0.02, 0),
    "compound": ([(G.mjGEOM_BOX, [0.02, 0.02, 0.02], [0, 0, 0], q0),
                  (G.mjGEOM_BOX, [0.008, 0.008, 0.015], [0, 0, 0.035], q0)], 0.02, 0),
    "tall": ([(G.mjGEOM_BOX, [0.008, 0.02, 0.05], [0, 0, 0], q0)], 0.05, 0),
    "shelf": ([(G.mjGEOM_BOX, [0.02, 0.02, 0.02], [0, 0, 0], q0)], 0.02, 0.06),
}

def pebble():
    a = np.linspace(0, 2 * np.pi, 8, endpoint=False) + np.pi / 8
    r = 0.02 / np.cos(np.pi / 8)
    ring = np.stack([r * np.cos(a), r * np.sin(a)], 1)
    top = np.c_[ring, np.full(8, 0.02)]; top[:2, 2] = 0.012   # one bevelled side
    return np.vstack([top, np.c_[ring, np.full(8, -0.02)]])

if __name__ == "__main__":
    src, obj, out = sys.argv[1], sys.argv[2], sys.argv[3]
    spec = mujoco.MjSpec.from_file(src)
    base = Path(src).parent
    body = spec.body("box")
    old = body.geoms[0]
    mass = old.mass if old.mass > 0 else 0.05
    fr, condim, rgba, solref, solimp = list(old.friction), old.condim, list(old.rgba), list(old.solref), list(old.solimp)
    for g in list(body.geoms):
        spec.delete(g)
    geoms, hz, shelf = OBJ[obj]
    for k, (typ, size, pos, quat) in enumerate(geoms):
        kw = dict(name="red_box" if k == 0 else f"red_box_part{k}", pos=pos, quat=quat, condim=condim,
                  friction=fr, rgba=rgba, solref=solref, solimp=solimp)
        if typ == "mesh":
            m = spec.add_mesh(name="pebble"); m.uservert = pebble().ravel().tolist()
            g = body.add_geom(type=G.mjGEOM_MESH, meshname="pebble", **kw)
        else:
            g = body.add_geom(type=typ, size=size, **kw)
        g.mass = mass / len(geoms)
    if shelf:
        sh = spec.worldbody.add_body(name="shelf", pos=[0.1, 0.5, shelf / 2])
        sh.add_geom(name="shelf_top", type=G.mjGEOM_BOX, size=[0.12, 0.12, shelf / 2], friction=[1, 0.005, 0.0001])
    spec.compile()
    Path(out).write_text(spec.to_xml())
    print(hz + shelf)
