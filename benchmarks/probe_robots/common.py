import mujoco, numpy as np

def ik(m, site, joints, target, down=True, q0=None, iters=400):
    d = mujoco.MjData(m)
    if q0 is not None:
        d.qpos[:] = q0
    sid = m.site(site).id
    qadr = [m.joint(j).qposadr[0] for j in joints]
    dadr = [m.joint(j).dofadr[0] for j in joints]
    for _ in range(iters):
        mujoco.mj_forward(m, d)
        p = d.site_xpos[sid]; R = d.site_xmat[sid].reshape(3, 3)
        err = np.asarray(target) - p
        jp = np.zeros((3, m.nv)); jr = np.zeros((3, m.nv))
        mujoco.mj_jacSite(m, d, jp, jr, sid)
        J = jp[:, dadr]; e = err
        if down:
            z = R[:, 2]
            eo = np.cross(z, [0, 0, -1])
            J = np.vstack([J, 0.3 * jr[:, dadr]]); e = np.concatenate([err, 0.3 * eo])
        dq = J.T @ np.linalg.solve(J @ J.T + 1e-4 * np.eye(len(e)), e)
        for a, v in zip(qadr, dq):
            d.qpos[a] += 0.5 * v
        for a, j in zip(qadr, joints):
            lo, hi = m.joint(j).range
            if hi > lo:
                d.qpos[a] = np.clip(d.qpos[a], lo, hi)
    mujoco.mj_forward(m, d)
    return np.array([d.qpos[a] for a in qadr]), np.linalg.norm(np.asarray(target) - d.site_xpos[sid])

def segments(waypoints, fps=50):
    """waypoints: list of (duration_s, arm_q(array), grip(0..1)); smooth cosine interp."""
    rows = [np.concatenate([waypoints[0][1], [waypoints[0][2]]])]
    for (_, qa, ga), (dur, qb, gb) in zip(waypoints[:-1], waypoints[1:]):
        n = max(1, int(round(dur * fps)))
        for k in range(1, n + 1):
            s = 0.5 - 0.5 * np.cos(np.pi * k / n)
            rows.append(np.concatenate([qa + s * (qb - qa), [ga + s * (gb - ga)]]))
    return np.array(rows)

def plan(m, site, joints, obj, goal, q_seed, clear=0.08, lift=0.12, hold_only=False):
    qs = {}
    qs['pre'], e1 = ik(m, site, joints, obj + [0, 0, clear], q0=q_seed)
    qs['grasp'], e2 = ik(m, site, joints, obj, q0=q_seed)
    qs['lift'], e3 = ik(m, site, joints, obj + [0, 0, lift], q0=q_seed)
    errs = [e1, e2, e3]
    if not hold_only:
        qs['carry'], e4 = ik(m, site, joints, goal + [0, 0, lift], q0=q_seed)
        qs['place'], e5 = ik(m, site, joints, goal + [0, 0, 0.002], q0=q_seed)
        qs['retreat'], e6 = ik(m, site, joints, goal + [0, 0, clear], q0=q_seed)
        errs += [e4, e5, e6]
    return qs, errs

def waypoints(qs, home, hold_only=False):
    W = [(0, home, 1.0), (1.5, qs['pre'], 1.0), (1.0, qs['grasp'], 1.0), (0.3, qs['grasp'], 1.0),
         (0.8, qs['grasp'], 0.0), (0.3, qs['grasp'], 0.0), (1.2, qs['lift'], 0.0)]
    if hold_only:
        W += [(1.0, qs['lift'], 0.0)]
    else:
        W += [(1.5, qs['carry'], 0.0), (1.2, qs['place'], 0.0), (0.3, qs['place'], 0.0),
              (0.6, qs['place'], 1.0), (0.8, qs['retreat'], 1.0), (0.5, qs['retreat'], 1.0)]
    return W

def run_plain(m, arm_ctrl_fn, grip_ctrl_fn, rows, fps, objbody, settle=0.5, qinit=None):
    """Drive: rows (T, n_arm+1) -> ctrl via fns; returns object trajectory."""
    d = mujoco.MjData(m)
    if qinit is not None:
        qinit(m, d)
    mujoco.mj_forward(m, d)
    nsub = int(round(1 / fps / m.opt.timestep))
    bid = m.body(objbody).id
    zs = []
    for r in rows:
        arm_ctrl_fn(d, r[:-1]); grip_ctrl_fn(d, r[-1])
        for _ in range(nsub):
            mujoco.mj_step(m, d)
        zs.append(d.xpos[bid].copy())
    return np.array(zs), d
