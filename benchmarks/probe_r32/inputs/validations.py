"""validate() (32 samples) on inputs the library accepted in odd forms: the brute-force check
that the odd form does not change the verdict quality. Also validate(samples=...) edge cases."""
import time, json
from common import *
from scipy.interpolate import CubicSpline, PchipInterpolator
z = np.load(TRAJ); A = z["actions"]; S = z["start"]; P = z["object_pose"]
sc = cm.load_scenario(); light = sc.replace(box=sc.box.with_range("mass", 0.05, 1.5))
twin = cm.Twin(light); grip = np.asarray(twin.channel_normalised)
T0 = np.arange(len(A)) / 50.0
def resample(f):
    n = int(round(len(A) / 50.0 * f)); tt = np.minimum(np.arange(n) / f, T0[-1]); out = np.empty((n, 14))
    out[:, ~grip] = CubicSpline(T0, A[:, ~grip], axis=0)(tt); out[:, grip] = PchipInterpolator(T0, A[:, grip], axis=0)(tt); return out
pz = np.load(PANDA); ps = cm.load_scenario("panda_pick_place")
cases = [
  ("ALOHA float32 actions, mass<=1.5", cm.Trajectory(A.astype(np.float32), fps=50.0, start=S, object_pose=P), twin),
  ("ALOHA resampled 30 Hz, mass<=1.5", cm.Trajectory(resample(30), fps=30.0, start=S, object_pose=P), twin),
  ("ALOHA resampled 250 Hz, mass<=1.5", cm.Trajectory(resample(250), fps=250.0, start=S, object_pose=P), twin),
  ("ALOHA big-endian non-contiguous, mass<=1.5", cm.Trajectory(np.asfortranarray(A.astype('>f8')), fps=np.float32(50), start=S, object_pose=P), twin),
  ("Panda float16 actions, bundled box", cm.Trajectory(pz["actions"].astype(np.float16), fps=50.0, start=pz["start"], object_pose=pz["object_pose"]), cm.Twin(ps)),
]
tot = {"n": 0, "fs": 0, "fu": 0}
for label, tr, tw in cases:
    t0 = time.time()
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        v = cm.validate(tr, twin=tw, n_samples=32, nthread=1)
    c = v.confusion
    tot["n"] += 32; tot["fs"] += c["false_safe"]; tot["fu"] += c["false_unsafe"]
    print(f"{label}: {c} agreement {v.agreement:.3f} vacuous {v.vacuous} nominal_completed {v.nominal_completed} {time.time()-t0:.0f}s warn={[str(x.message)[:80] for x in w][:2]}", flush=True)
print("TOTAL", tot)
tr = cm.Trajectory(A, fps=50.0, start=S, object_pose=P)
print("-- validate(samples=...)")
for name, s in (("float32 (4,2)", np.array([[0.05, 1.0], [0.5, 0.8], [1.0, 0.5], [1.4, 0.3]], np.float32)),
                ("outside the box: mass 20 kg", np.array([[20.0, 1.0], [0.05, 1.0]])),
                ("friction 0 ", np.array([[0.05, 0.0], [0.05, 1.0]])),
                ("NaN", np.array([[np.nan, 1.0], [0.05, 1.0]])),
                ("1-D (2,)", np.array([0.05, 1.0])),
                ("empty (0,2)", np.zeros((0, 2))),
                ("one sample (1,2)", np.array([[0.05, 1.0]])),
                ("list of lists", [[0.05, 1.0], [1.0, 0.5]]),
                ("(2,3)", np.ones((2, 3)))):
    v = t(name, lambda: cm.validate(tr, twin=twin, samples=s, nthread=1))
    if v is not None: print("      ", v.confusion, "vacuous", v.vacuous, "samples", v.to_json()["samples"] if hasattr(v, "to_json") else "")
