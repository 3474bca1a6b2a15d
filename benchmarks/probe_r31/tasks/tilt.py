"""object's rotation relative to the nominal's, in the hand frame, along a full run at given points (critmoment's simulate).
usage: tilt.py SCEN TRAJ v1,v2,.. ..."""
import sys, numpy as np, mujoco, critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src")
from critmoment.trajectory import load_trajectory
from critmoment.recording import prepare_controls, initial_state, simulate
twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2])
pts = np.array([[float(v) for v in a.split(",")] for a in sys.argv[3:]])
ctrl = prepare_controls(twin, traj); s0 = initial_state(twin, traj)
out = simulate(twin, s0, ctrl, samples=np.vstack([twin.scenario.box.nominal, pts]), record_state=True, nthread=1)
m = twin.model; d = mujoco.MjData(m); a = m.jnt_qposadr[m.body_jntadr[m.body(twin.scenario.object_body).id]]
hand = m.body("hand").id
def rel_angle(st):
    ang = []
    for k in range(0, st.shape[0], 10):
        mujoco.mj_setState(m, d, st[k], mujoco.mjtState.mjSTATE_INTEGRATION); mujoco.mj_kinematics(m, d)
        R = d.xmat[hand].reshape(3, 3).T @ d.xmat[m.body(twin.scenario.object_body).id].reshape(3, 3)
        ang.append(R)
    return ang
Rn = rel_angle(out["state"][0])
for i, p in enumerate(pts):
    Rs = rel_angle(out["state"][i + 1]); th = []
    for k, (A, B) in enumerate(zip(Rn, Rs)):
        c = (np.trace(A.T @ B) - 1) / 2; th.append(np.degrees(np.arccos(np.clip(c, -1, 1))))
    th = np.array(th); k = int(np.argmax(th[:370]))  # before the release (step 3700)
    print("   at steps 1900/2200/2600/3000/3300/3500:", [round(float(th[j//10]),1) for j in (1900,2200,2600,3000,3300,3500)])
    print(p.tolist(), f"max rotation vs nominal in the hand before the release: {th[:370].max():.1f} deg at step {k*10}")
