"""The same motion at other control rates (resampled here), time vectors in npz, short and long
trajectories, joint-limit excursions: rollout summaries and, for a few, the audit."""
import time, os
from common import *
from scipy.interpolate import CubicSpline, PchipInterpolator
from critmoment.analysis import AnalyzeOptions
z = np.load(TRAJ); A = z["actions"]; S = z["start"]; P = z["object_pose"]; META = str(z["meta"])
sc = cm.load_scenario(); twin = cm.Twin(sc)
grip = np.asarray(twin.channel_normalised)
T0 = np.arange(len(A)) / 50.0
def resample(f):
    n = int(round(len(A) / 50.0 * f)); tt = np.arange(n) / f; tt = np.minimum(tt, T0[-1])
    out = np.empty((n, A.shape[1]))
    out[:, ~grip] = CubicSpline(T0, A[:, ~grip], axis=0)(tt)
    out[:, grip] = PchipInterpolator(T0, A[:, grip], axis=0)(tt)
    return out
def summ(tr, label):
    t0 = time.time()
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        rec = cm.rollout(tr, twin=twin)
    s = rec.summary()
    keys = ("steps", "completed", "max_stage", "min_fos_contact", "min_fos_motor", "max_cost", "max_cost_step")
    print(f"{label:28s}", {k: (round(s[k], 4) if isinstance(s[k], float) else s[k]) for k in keys},
          "stage1..4", [s["stage_first_step"].get(k) for k in ("1", "2", "3", "4")] if isinstance(s["stage_first_step"], dict) else s["stage_first_step"],
          f"{time.time()-t0:.1f}s", [str(x.message)[:100] for x in w][:2], flush=True)
    return rec
print("== rates (same motion resampled)")
for f in (50, 10, 25, 30, 33.3, 60, 100, 125, 250, 333, 499, 500):
    a = resample(f)
    summ(cm.Trajectory(a, fps=f, start=S, object_pose=P), f"{f} Hz ({len(a)} rows)")
t("501 Hz", lambda: cm.rollout(cm.Trajectory(resample(501), fps=501, start=S, object_pose=P), twin=twin))
t("500.0000001 Hz", lambda: cm.rollout(cm.Trajectory(resample(500), fps=500.0000001, start=S, object_pose=P), twin=twin))
print("== time vectors (npz)")
def npz(name, **kw):
    d = {"actions": A, "start": S, "object_pose": P, "meta": META, **kw}
    d = {k: v for k, v in d.items() if v is not None}
    p = f"/tmp/r32/inputs/{name}.npz"; np.savez(p, **d); return p
def load(name, **kw):
    tr = t(name, lambda: cm.load_trajectory(npz(name, **kw)))
    if tr is not None:
        print(f"      fps={tr.fps} assumed={tr.fps_assumed} duration={tr.duration}")
        return tr
load("time from 0", time=T0)
load("time from 5 s", time=T0 + 5)
load("time from -3 s", time=T0 - 3)
load("time epoch f64", time=T0 + 1.7e9)
load("time decreasing", time=T0[::-1])
load("time with duplicate", time=np.r_[T0[:10], T0[9], T0[11:]])
load("time non-uniform 2%", time=np.cumsum(np.r_[0, np.where(np.arange(399) % 2, 0.0204, 0.0196)]))
load("time non-uniform 0.9%", time=np.cumsum(np.r_[0, np.where(np.arange(399) % 2, 0.02018, 0.01982)]))
load("time one gap (dropped frame)", time=np.r_[T0[:200], T0[200:] + 0.02])
load("time jittered 0.5%", time=T0 + np.random.default_rng(0).uniform(-1e-4, 1e-4, 400))
load("time slow drift 0.9% over run", time=T0 * np.linspace(1, 1.009, 400))
load("time + fps agree", time=T0, fps=50.0)
load("time + fps disagree (25)", time=T0, fps=25.0)
load("time float32", time=T0.astype(np.float32))
load("time int ms", time=(T0 * 1000).astype(int))
load("time (400,1)", time=T0[:, None])
load("time object", time=T0.astype(object))
load("time datetime64", time=(T0 * 1e3).astype("timedelta64[ms]"))
print("== short / long")
for n in (2, 3, 5, 10, 20):
    tr = t(f"T={n} trajectory", lambda: cm.Trajectory(A[:n], fps=50.0, start=S, object_pose=P))
    if tr is not None:
        t(f"  rollout T={n}", lambda: cm.rollout(tr, twin=twin).summary()["steps"])
        t(f"  analyze T={n}", lambda: cm.analyze(tr, twin=twin, options=AnalyzeOptions(n_samples=8, nthread=1)).verdict)
        t(f"  validate T={n}", lambda: cm.validate(tr, twin=twin, n_samples=8, nthread=1).confusion)
hold = lambda sec: np.r_[A, np.repeat(A[-1:], int(sec * 50), axis=0)]
t("T = 1001 s (over 500k steps)", lambda: cm.rollout(cm.Trajectory(hold(993), fps=50.0, start=S, object_pose=P), twin=twin))
import resource
for sec in (60,):
    tr = cm.Trajectory(hold(sec), fps=50.0, start=S, object_pose=P)
    r0 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    summ(tr, f"{sec} s hold appended")
    print("   maxrss MB", resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, "before", r0 / 1024)
print("== joint limits")
lo, hi = np.asarray(twin.channel_lower), np.asarray(twin.channel_upper)
print("lower", lo.round(3).tolist()); print("upper", hi.round(3).tolist())
j = 1
a2 = A.copy(); a2[150:160, j] = hi[j] + 0.2
t("one joint +0.2 rad past limit (error policy)", lambda: cm.rollout(cm.Trajectory(a2, fps=50.0, start=S, object_pose=P), twin=twin))
clip = cm.Twin(sc.replace(range_policy="clip")); warn = cm.Twin(sc.replace(range_policy="warn"))
t("same, clip policy", lambda: cm.rollout(cm.Trajectory(a2, fps=50.0, start=S, object_pose=P), twin=clip).summary()["completed"])
t("same, warn policy", lambda: cm.rollout(cm.Trajectory(a2, fps=50.0, start=S, object_pose=P), twin=warn).summary()["completed"])
a3 = A.copy(); a3[:, 6] = 1.3
t("gripper channel 1.3 (normalised)", lambda: cm.rollout(cm.Trajectory(a3, fps=50.0, start=S, object_pose=P), twin=twin))
a4 = A.copy(); a4[200, j] = hi[j]; a4[199, j] = hi[j] - 0.3; a4[201, j] = hi[j] - 0.3
t("spike to exactly the limit (spline overshoot)", lambda: cm.rollout(cm.Trajectory(a4, fps=50.0, start=S, object_pose=P), twin=twin).summary()["completed"])
t("start past limit by 3% of range", lambda: cm.rollout(cm.Trajectory(A, fps=50.0, start=np.where(np.arange(14)==j, hi[j] + 0.03*(hi[j]-lo[j]), S), object_pose=P), twin=twin).summary()["completed"])
t("start past limit by 8% of range", lambda: cm.rollout(cm.Trajectory(A, fps=50.0, start=np.where(np.arange(14)==j, hi[j] + 0.08*(hi[j]-lo[j]), S), object_pose=P), twin=twin).summary()["completed"])
