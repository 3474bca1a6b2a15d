"""validate (n Sobol samples, seed 0, verification on, one thread) on a case folder, and per
sample the largest turn of the object in the hand (beyond the nominal run's, between the grasp
and the release) from its own plain-MuJoCo run.  usage: PYTHONPATH=<code> python turn.py DIR [N]
prints (sample, parameters..., outcome, real failed, predicted failed, turn [deg], final tilt
[deg], final position)."""
import sys, json, warnings
import numpy as np, mujoco
import critmoment as cm
from critmoment import validation, recording
from critmoment.trajectory import load_trajectory
warnings.simplefilter("ignore")
d = sys.argv[1]; n = int(sys.argv[2]) if len(sys.argv) > 2 else 32
twin = cm.Twin(cm.load_scenario(d))
traj = load_trajectory(f"{d}/traj.npz")
res = validation.validate(traj, twin=twin, n_samples=n, seed=0, nthread=1)
controls = recording.prepare_controls(twin, traj)
hand = twin.model.body("hand").id; obj = twin.object_body_id
def run(sample):
    m = twin.model.__copy__()
    twin.write_parameters(m, sample[None])
    dd = mujoco.MjData(m)
    s0 = recording.initial_state(twin, traj, m)
    mujoco.mj_setState(m, dd, s0, mujoco.mjtState.mjSTATE_INTEGRATION)
    nsub = controls.shape[0]
    ang = []; held=[]
    for t in range(nsub):
        dd.ctrl[:] = controls[t]
        mujoco.mj_step(m, dd)
        Rh = dd.xmat[hand].reshape(3,3); Ro = dd.xmat[obj].reshape(3,3)
        ang.append(Rh.T @ Ro)
    R = np.array(ang)
    z = dd.xmat[obj].reshape(3,3)[:,2]
    tilt = np.degrees(np.arccos(np.clip(abs(z[2]), -1, 1)))
    return R, tilt, dd.xpos[obj].copy()
Rn, tiltn, _ = run(twin.scenario.box.nominal)
print("nominal final tilt", round(tiltn,1))
rows=[]
for i, smp in enumerate(res.samples):
    R, tilt, pos = run(smp)
    # rotation in grip beyond nominal at each step from grasp (step 1900) to release (3800)
    sl = slice(1900, 3790)
    rel = np.einsum("tji,tjk->tik", Rn[sl], R[sl])   # Rn^T R
    base = rel[0]
    dang = [np.degrees(np.arccos(np.clip((np.trace(base.T @ r)-1)/2, -1, 1))) for r in rel]
    rows.append((i, *np.round(smp,3), str(res.outcome[i]), bool(res.real_failed[i]), bool(res.predicted_failed[i]), round(max(dang),1), round(tilt,1), np.round(pos,3).tolist()))
    print(rows[-1], flush=True)
