"""Plain MuJoCo (r30's truth.Setup for the model/controls, own loop): the object's origin and
its box corners in the gripper base frame, sample vs nominal, displacement since an anchor step
beyond the nominal's (difference of displacements), max over steps >= anchor until END.
usage: measure_rel.py SCENARIO TRAJ END ANCHOR[,ANCHOR..] "m f" ["m f" ...]"""
import sys
from pathlib import Path
sys.path.insert(0, "/tmp/r36f/followup/r30p")
import mujoco
import numpy as np
import truth

scen, traj, end, anchors = sys.argv[1], sys.argv[2], int(sys.argv[3]), [int(x) for x in sys.argv[4].split(",")]
s = truth.Setup(scen, traj)
m = s.model
g = list(s.grippers.values())[0]
geom = [i for i in range(m.ngeom) if m.geom_bodyid[i] == s.obj_body][0]
h = m.geom_size[geom]
corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * h + m.geom_pos[geom]
def run(vals):
    s.apply(vals); d = mujoco.MjData(m); mujoco.mj_setConst(m, d); s.initial(d)
    T = min(end + 1, s.controls.shape[0]); P = np.zeros((T, 9, 3))
    for t in range(T):
        d.ctrl[:] = s.controls[t]; mujoco.mj_step(m, d)
        R = d.xmat[g["base"]].reshape(3, 3); Ro = d.xmat[s.obj_body].reshape(3, 3)
        pts = np.vstack([[0, 0, 0], corners]) @ Ro.T + d.xpos[s.obj_body]
        P[t] = (pts - d.xpos[g["base"]]) @ R
    return P
nom = run([s.unc[n]["nominal"] for n in s.names])
for p in sys.argv[5:]:
    S = run([float(x) for x in p.split()])
    out = []
    for a in anchors:
        rel = (S[a:] - S[a]) - (nom[a:] - nom[a])
        dist = np.linalg.norm(rel, axis=-1) * 1e3
        k = int(dist[:, 1:].max(axis=1).argmax())
        out.append(f"anchor {a}: origin {dist[:, 0].max():.2f} mm, farthest corner {dist[:, 1:].max():.2f} mm @ step {a + k}")
    print(p, "|", "; ".join(out))
