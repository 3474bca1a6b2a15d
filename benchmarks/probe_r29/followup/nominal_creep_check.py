"""critmoment's warned nominal_creep (contactmodel._nominal_creep: from the first state of the
longest held-alone stretch) vs the nominal's displacement in the grip the way the ground truth
counts it (groundtruth.grip_slip: from the first step the gripper holds the object, t0, over the
steps where slip counts), both in the gripper base frame with the closing axes projected out.
usage: PYTHONPATH=/tmp/r29b/src python nominal_creep_check.py NAME SCEN TRAJ [NAME SCEN TRAJ ...]"""
import sys, warnings
import numpy as np, mujoco
import critmoment as cm
from critmoment import contactmodel as cmod
from critmoment.recording import at_scenario_rate, rollout
from critmoment.sparse import grip_frames
from critmoment.trajectory import load_trajectory
from critmoment.twin import STATE_SPEC
warnings.simplefilter("ignore")
a = sys.argv[1:]
for name, scen, tp in zip(a[::3], a[1::3], a[2::3]):
    twin = cm.Twin(scen); traj = at_scenario_rate(load_trajectory(tp), twin)
    rec = rollout(traj, twin=twin)
    rep = cmod.check_contact_model(twin, rec, warn=False)
    m = twin.model; sc = twin.scenario; sig = rec.signals
    anchors, proj = grip_frames(m, sc)
    held = (np.asarray(sig.contact_gripper, bool).reshape(rec.n_steps, -1)
            & ~np.asarray(sig.contact_support, bool).reshape(rec.n_steps, 1))  # groundtruth._Frames.held
    counted = np.asarray(twin.slip_counted(sig.contact_gripper, sig.contact_support, rec.controls), bool)
    ob = m.body(sc.object_body).id; d = mujoco.MjData(m)
    out = []
    for g in range(len(anchors)):
        if not held[:, g].any(): continue
        t0 = int(np.argmax(held[:, g]))
        steps = np.flatnonzero(counted[:, g]); steps = steps[steps >= t0]
        if steps.size == 0: continue
        picks = np.unique(np.r_[t0, steps[np.linspace(0, steps.size - 1, min(400, steps.size)).astype(int)]])
        rel = []
        for k in picks:
            mujoco.mj_setState(m, d, np.asarray(rec.states[k + 1], float), STATE_SPEC); mujoco.mj_kinematics(m, d)
            an = int(anchors[g]); rel.append(d.xmat[an].reshape(3, 3).T @ (d.xpos[ob] - d.xpos[an]))
        rel = np.array(rel); moved = (rel - rel[0]) @ np.asarray(proj[g]).T
        out.append(f"gripper {g}: t0 {t0*rec.dt:.2f}s, counted from {steps[0]*rec.dt:.2f}s; GT-rule nominal displacement max {np.linalg.norm(moved, axis=1).max()*1e3:.2f} mm")
    print(f"{name}: warned nominal_creep {rep.nominal_creep*1e3:.2f} mm; " + "; ".join(out), flush=True)
