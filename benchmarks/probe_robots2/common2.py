"""Helpers for probe_robots2: cosine-blended waypoints and a plain-MuJoCo check run."""
import mujoco
import numpy as np


def segments(waypoints, fps=50):
    """waypoints: list of (duration_s, target(array incl. gripper channel)); cosine blend."""
    rows = [np.asarray(waypoints[0][1], float)]
    for (_, a), (dur, b) in zip(waypoints[:-1], waypoints[1:]):
        a = np.asarray(a, float); b = np.asarray(b, float)
        n = max(1, int(round(dur * fps)))
        for k in range(1, n + 1):
            s = 0.5 - 0.5 * np.cos(np.pi * k / n)
            rows.append(a + s * (b - a))
    return np.array(rows)


def run_plain(m, ctrl_fn, rows, fps, objbody, qinit=None):
    d = mujoco.MjData(m)
    if qinit is not None:
        qinit(m, d)
    mujoco.mj_forward(m, d)
    nsub = int(round(1 / fps / m.opt.timestep))
    bid = m.body(objbody).id
    xs = []
    for r in rows:
        ctrl_fn(d, r)
        for _ in range(nsub):
            mujoco.mj_step(m, d)
        xs.append(d.xpos[bid].copy())
    return np.array(xs), d


def ik(m, site, joints, target, q0, iters=500, down=True, w_ori=0.3):
    d = mujoco.MjData(m)
    d.qpos[:] = q0
    sid = m.site(site).id
    qadr = [m.joint(j).qposadr[0] for j in joints]
    dadr = [m.joint(j).dofadr[0] for j in joints]
    for _ in range(iters):
        mujoco.mj_forward(m, d)
        err = np.asarray(target) - d.site_xpos[sid]
        jp = np.zeros((3, m.nv)); jr = np.zeros((3, m.nv))
        mujoco.mj_jacSite(m, d, jp, jr, sid)
        J = jp[:, dadr]; e = err
        if down:
            z = d.site_xmat[sid].reshape(3, 3)[:, 2]
            J = np.vstack([J, w_ori * jr[:, dadr]]); e = np.concatenate([err, w_ori * np.cross(z, [0, 0, -1])])
        dq = J.T @ np.linalg.solve(J @ J.T + 1e-4 * np.eye(len(e)), e)
        for a, v, j in zip(qadr, dq, joints):
            d.qpos[a] += 0.5 * v
            lo, hi = m.joint(j).range
            if hi > lo:
                d.qpos[a] = np.clip(d.qpos[a], lo, hi)
    mujoco.mj_forward(m, d)
    return np.array([d.qpos[a] for a in qadr]), float(np.linalg.norm(np.asarray(target) - d.site_xpos[sid]))
