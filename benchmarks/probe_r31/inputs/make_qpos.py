import os

import numpy as np

import critmoment as cm

D = "/tmp/r31/inputs/in"
z = np.load("/tmp/r31/inputs/traj.npz"); base = {k: z[k] for k in z.files}
tw = cm.Twin(cm.load_scenario()); m = tw.model
nq, nv = m.nq, m.nv; print("nq", nq, "nv", nv)
def save(name, **kw):
    d = dict(base); d.update({k: v for k, v in kw.items() if v is not None})
    for k, v in kw.items():
        if v is None: d.pop(k, None)
    np.savez(os.path.join(D, name), **d)
q = m.qpos0.copy()
save("qpos0_short1.npz", qpos0=q[:-1])
save("qpos0_long1.npz", qpos0=np.r_[q, 0.0])
save("qpos0_nan.npz", qpos0=np.r_[q[:-1], np.nan])
save("qpos0_ok.npz", qpos0=q)
save("qpos0_ok_nostart.npz", qpos0=q, start=None)
save("qpos0_len14.npz", qpos0=base["start"].copy())  # user passes the joint state as qpos0
save("qpos0_zeroquat.npz", qpos0=np.where(np.arange(nq) >= nq - 4, 0.0, q))
save("qvel0_wrong.npz", qpos0=q, qvel0=np.zeros(nv - 1))
save("qvel0_ok.npz", qpos0=q, qvel0=np.zeros(nv))
save("qvel0_nan.npz", qpos0=q, qvel0=np.full(nv, np.nan))
save("qvel0_huge.npz", qpos0=q, qvel0=np.full(nv, 1e6))
