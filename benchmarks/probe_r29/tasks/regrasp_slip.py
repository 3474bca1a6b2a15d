"""Regrasp slip reference check. P_regrasp_low: pick at spawn (TCP 1 cm above the cube centre),
set down at (0.5, 0, 0.02), re-grasp 10 mm LOWER (TCP at the cube centre), place at the goal.
The ground truth measures slip from the FIRST grasp (groundtruth.grip_slip t0 = first step both
hold), so the second hold starts with the nominal's 10 mm regrasp offset already 'moved'.
Reference: the second half alone as a chunk (qpos0/qvel0 = nominal state at action 395, cube
resting at the set-down spot), whose slip counts from the second grasp.
usage: regrasp_slip.py OUTDIR  (writes P_regrasp_low.npz, P_regrasp_low_half2.npz)"""
import pathlib, sys
import numpy as np
import critmoment as cm
from critmoment.groundtruth import brute_force
from critmoment.recording import rollout
from critmoment.trajectory import load_trajectory

OUT = pathlib.Path(sys.argv[1])
src = pathlib.Path(__file__).with_name("gen_panda.py").read_text().split("# 1a regrasp")[0]
sys.argv = [sys.argv[0], str(OUT)]
g = {"__name__": "gp"}; exec(compile(src, "gen_panda.py", "exec"), g)
np_, pd, cube, model, H, go = np, g["pd"], g["cube"], g["model"], g["H"], g["go"]
G = np.array(pd.GOAL); mid = g["mid"] if "mid" in g else np.array([0.5, 0.0, pd.CUBE_HALF])
pick, place_at = g["pick"], g["place_at"]
ofs = (0, 0, -0.010)
pts = pick(0, cube[:3]) + [(t + 180, p, gg) for t, p, gg in place_at(0, mid)]
t = pts[-1][0]; g2 = mid + [0, 0, go] + np.asarray(ofs)
pts += [(t + 50, g2, 1.0), (t + 65, g2, 1.0), (t + 90, g2, 0.0), (t + 105, g2, 0.0)]
t = pts[-1][0]
pts += [(t + 50, np.array([mid[0], mid[1], H]), 0.0)]
pts += [(t + 50 + tt, p, gg) for tt, p, gg in place_at(0, G, ofs=ofs)] + [(t + 50 + 265, np.array([G[0], G[1], H]), 1.0)]
g["build"](model, cube, pts, "P_regrasp_low")

scen = str(pd.scene_path().parent / "scenario.toml")
twin = cm.Twin(scen)
full = load_trajectory(OUT / "P_regrasp_low.npz")
rec = rollout(full, twin=twin)
k = 395  # action index: arm above the set-down spot, hand open, cube resting
st = np.asarray(rec.states)[k * 10]
from critmoment.twin import state_slice
import mujoco
qpos0 = st[state_slice(twin.model, mujoco.mjtState.mjSTATE_QPOS)]
qvel0 = st[state_slice(twin.model, mujoco.mjtState.mjSTATE_QVEL)]
d = dict(np.load(OUT / "P_regrasp_low.npz"))
cube_adr = twin.object_qposadr
np.savez(OUT / "P_regrasp_low_half2.npz", actions=d["actions"][k:], fps=50.0, qpos0=qpos0, qvel0=qvel0,
         object_pose=qpos0[cube_adr:cube_adr + 7])
half = load_trajectory(OUT / "P_regrasp_low_half2.npz")
# masses 0.05..3 at low-ish friction: where a second-hold slip is likely
m = np.linspace(0.3, 2.4, 15); f = np.array([0.5, 0.7, 1.0])
pts = np.array([[a, b] for b in f for a in m])
bf_full = brute_force(full, twin=twin, samples=pts, nthread=1)
bf_half = brute_force(half, twin=twin, samples=pts, nthread=1)
print("nominal completed: full", bf_full.nominal_completed, "half2", bf_half.nominal_completed)
n_diff = 0
for i, p in enumerate(pts):
    a, b = bf_full.classification, bf_half.classification
    flag = "  <-- differs" if a.outcome[i] != b.outcome[i] else ""
    n_diff += bool(flag)
    print(f"mass {p[0]:.2f} fric {p[1]:.2f}: full {a.outcome[i].value:8s} max_slip {1e3*a.max_slip[i]:6.1f} mm "
          f"completed {a.completed[i]!s:5s} | half2 {b.outcome[i].value:8s} max_slip {1e3*b.max_slip[i]:6.1f} mm "
          f"completed {b.completed[i]!s:5s}{flag}")
print("differing outcomes:", n_diff, "of", len(pts))
