"""Print pad / hand geometry of a scene at its home keyframe (and with the gripper joint at given values)."""
import sys, mujoco, numpy as np
m = mujoco.MjModel.from_xml_path(sys.argv[1]); d = mujoco.MjData(m)
hand = sys.argv[2]; gj = sys.argv[3]; vals = [float(v) for v in sys.argv[4:]]
mujoco.mj_resetDataKeyframe(m, d, 0)
for v in vals:
    d.qpos[m.jnt_qposadr[m.joint(gj).id]] = v
    mujoco.mj_kinematics(m, d)
    b = m.body(hand).id
    R = d.xmat[b].reshape(3, 3); p = d.xpos[b]
    print(f"{gj}={v}: hand {hand} at {np.round(p,4)}, axes(cols)=\n{np.round(R,3)}")
    for g in range(m.ngeom):
        bb = m.geom_bodyid[g]
        anc = bb
        inside = False
        while anc:
            if anc == b: inside = True; break
            anc = m.body_parentid[anc]
        if not inside or m.geom_contype[g] == 0 and m.geom_conaffinity[g] == 0: continue
        loc = R.T @ (d.geom_xpos[g] - p)
        # mesh AABB in hand frame
        name = m.geom(g).name or f"#{g}"
        extra = ""
        if m.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH:
            mid = m.geom_dataid[g]; a = m.mesh_vertadr[mid]; n = m.mesh_vertnum[mid]
            V = m.mesh_vert[a:a+n] @ d.geom_xmat[g].reshape(3,3).T + d.geom_xpos[g]
            L = (V - p) @ R
            extra = f" aabb lo {np.round(L.min(0),4)} hi {np.round(L.max(0),4)}"
        print(f"  {name:35s} body {m.body(bb).name:28s} type {m.geom_type[g]} pos_hand {np.round(loc,4)} size {np.round(m.geom_size[g],4)}{extra}")
