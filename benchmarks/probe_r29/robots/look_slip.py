"""Diagnose a slip disagreement: the object's position in each gripper's frame over time for
one sample and the nominal run (own rollout, truth.Setup), with contact flags, and the
critmoment-style measure (from the first step both runs touch, counted where the nominal
holds with that gripper alone, slide axes projected out) recomputed from these numbers.
usage: look_slip.py SCENARIO TRAJ MASS FRICTION [--every N] [--from S] [--to E]"""
import argparse
import sys

import numpy as np

sys.path.insert(0, "/work/main/benchmarks/probe_r29/robots")
import truth

ap = argparse.ArgumentParser()
ap.add_argument("scenario"); ap.add_argument("traj"); ap.add_argument("mass", type=float); ap.add_argument("friction", type=float)
ap.add_argument("--every", type=int, default=25); ap.add_argument("--from", dest="t0", type=int, default=0); ap.add_argument("--to", type=int, default=None)
a = ap.parse_args()
s = truth.Setup(a.scenario, a.traj)
m = s.model
nomv = [s.unc[n]["nominal"] for n in s.names]
vals = [a.mass if n == "mass" else a.friction for n in s.names]
nom = s.rollout(nomv); rec = s.rollout(vals)
G = list(s.grippers)
print("grippers", G, "sides", {k: [sorted(int(x) for x in sd) for sd in g["sides"]] for k, g in s.grippers.items()})
# slide-axis projector per gripper (own): slide joints between pads and base, axes in base frame
import mujoco

d = mujoco.MjData(m); mujoco.mj_kinematics(m, d)
proj = []
for gname in G:
    g = s.grippers[gname]; R = d.xmat[g["base"]].reshape(3, 3); axes = []
    for geom in g["all"]:
        b = m.geom_bodyid[geom]
        while b not in (g["base"], 0):
            for j in range(m.body_jntadr[b], m.body_jntadr[b] + m.body_jntnum[b]):
                if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE:
                    axes.append(R.T @ d.xaxis[j])
            b = m.body_parentid[b]
    if axes:
        u, sv, _ = np.linalg.svd(np.array(axes).T, full_matrices=False); B = u[:, sv > 1e-9 * sv.max()]
        proj.append(np.eye(3) - B @ B.T)
    else:
        proj.append(np.eye(3))
held = rec["touch"] & ~rec["sup"][:, None]; nheld = nom["touch"] & ~nom["sup"][:, None]
alone = nheld & (nheld.sum(axis=1, keepdims=True) == 1)
T = len(rec["pos"])
cmlike = np.zeros((T, len(G)))
for k in range(len(G)):
    both = held[:, k] & nheld[:, k]
    if not both.any():
        continue
    t0 = int(np.argmax(both))
    rel = (rec["rel"][:, k] - rec["rel"][t0, k]) - (nom["rel"][:, k] - nom["rel"][t0, k])
    rel = rel @ proj[k].T
    cmlike[:, k] = np.where(both & alone[:, k], np.linalg.norm(rel, axis=1), 0)
    print(f"gripper {G[k]}: first step both runs touch t0={t0}; sample first touch {int(np.argmax(held[:, k]))}, "
          f"nominal first touch {int(np.argmax(nheld[:, k]))}; first step both pads (sample) "
          f"{int(np.argmax(rec['both'][:, k])) if rec['both'][:, k].any() else -1}, (nominal) "
          f"{int(np.argmax(nom['both'][:, k])) if nom['both'][:, k].any() else -1}; max cm-like {1000*cmlike[:, k].max():.2f} mm "
          f"at step {int(np.argmax(cmlike[:, k]))}")
ctrl = s.controls
gacts = {gname: s.grippers[gname]["act"] for gname in G}
print("step  z_obj   " + "  ".join(f"[{g[-12:]}: touch both ctrl  rel(mm) sample-vs-t0 | nominal-vs-t0  cmlike]" for g in G))
end = a.to or T
for t in range(a.t0, end, a.every):
    line = f"{t:5d} {rec['pos'][t, 2]:.4f} sup={int(rec['sup'][t])}"
    for k, gname in enumerate(G):
        line += (f" | {int(rec['touch'][t, k])}{int(nom['touch'][t, k])} {int(rec['both'][t, k])}{int(nom['both'][t, k])} "
                 f"c={ctrl[t, gacts[gname][0]]:.4f} rel={np.round(1000 * rec['rel'][t, k], 1)} nrel={np.round(1000 * nom['rel'][t, k], 1)} "
                 f"cm={1000 * cmlike[t, k]:.1f}")
    print(line)
