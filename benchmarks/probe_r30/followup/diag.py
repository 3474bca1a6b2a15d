"""diag.py SCENARIO TRAJ m,f : nominal's holds/anchors per gripper (new code), the sample's and nominal's
object position in the gripper frame at the old anchor (first held by both) and the new one (formed), the
slip from each anchor over time (beyond nominal), the gripper command."""
import sys, numpy as np, critmoment as cm
assert cm.__file__.startswith("/tmp/r30b/src"), cm.__file__
from critmoment import groundtruth as gt
from critmoment.trajectory import load_trajectory
from critmoment.recording import prepare_controls
twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2])
pt = np.array([[float(v) for v in sys.argv[3].split(",")]])
cap = {}
orig = gt._classify_frames
def spy(frames, reference, controls, probe, dt, criteria, dv, ds, counted, segments, formed):
    cap.update(frames=frames, ref=reference, controls=controls, counted=counted, segments=segments, formed=formed, probe=probe)
    return orig(frames, reference, controls, probe, dt, criteria, dv, ds, counted, segments, formed)
gt._classify_frames = spy
bf = gt.brute_force(traj, twin=twin, samples=pt, nthread=1)
print("outcome", bf.outcome[-1].value, "max_slip mm", bf.classification.max_slip[-1]*1000, "first", bf.classification.first_failure_step[-1])
f, r, ctl = cap["frames"], cap["ref"], cap["controls"]
op = twin.gripper_opening(ctl)
dt = float(twin.model.opt.timestep)
G = r.contact_gripper.shape[1]
for g in range(G):
    tch = r.contact_gripper[:, g]
    seg = cap["segments"][:, g]; fo = cap["formed"][:, g]
    idx = np.flatnonzero(tch)
    if not idx.size: print("g", g, "never touches"); continue
    print(f"g{g}: nominal touches {idx[0]}..{idx[-1]} ({tch.sum()} steps); segments change at", np.flatnonzero(np.diff(seg)) + 1,
          "formed from", np.flatnonzero(np.diff(fo.astype(int)) == 1) + 1, "counted steps", int(cap["counted"][:, g].sum()))
    both = f.held[-1, :, g] & r.held[:, g]
    t_old = int(np.argmax(both)); t_new = int(np.argmax(both & fo))
    print(f"   held-by-both first {t_old} ({t_old*dt:.3f}s), anchored (formed) {t_new} ({t_new*dt:.3f}s); opening at touch {op[idx[0], g]:.3f} at old {op[t_old,g]:.3f} new {op[t_new,g]:.3f}")
    P = cap["probe"]
    pos = f.position[-1, :, g]; npos = r.position[:, g]
    proj = P.projectors[g] if P.projectors is not None else np.eye(3)
    for name, t0 in (("old", t_old), ("new", t_new)):
        m = (pos - pos[t0]) @ proj.T; nm = (npos - npos[t0]) @ proj.T
        d = np.linalg.norm(m, axis=1) - np.linalg.norm(nm, axis=1)
        mask = both & cap["counted"][:, g] & (np.arange(len(d)) >= t0)
        dd = np.where(mask, d, 0)
        k = int(np.argmax(dd)); print(f"   from {name} anchor: max beyond-nominal {dd[k]*1000:.1f} mm at step {k}")
    # slip between the two anchors
    print(f"   object moved in gripper between old and new anchor: sample {np.linalg.norm((pos[t_new]-pos[t_old])@proj.T)*1000:.1f} mm, nominal {np.linalg.norm((npos[t_new]-npos[t_old])@proj.T)*1000:.1f} mm")
    ss = list(range(max(0, idx[0]-20), min(len(op), t_new + 40), max(1, (t_new + 60 - idx[0]) // 15)))
    print("   step:opening:z_world? ", " ".join(f"{s}:{op[s,g]:.3f}" for s in ss))
