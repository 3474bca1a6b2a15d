from common import *
from critmoment.analysis import AnalyzeOptions
z = np.load(TRAJ); A = z["actions"]; S = z["start"]; P = z["object_pose"]
sc = cm.load_scenario(); twin = cm.Twin(sc)
for n in (5, 20):
    r = t(f"analyze T={n}", lambda: cm.analyze(cm.Trajectory(A[:n], fps=50.0, start=S, object_pose=P), twin=twin, options=AnalyzeOptions(n_samples=8, nthread=1)))
    if r is not None: print(f"      verdict {r.verdict.value} passes {r.passes()} causes {[c[:120] for c in r.failure_causes][:2]}")
t("fps=0.02 (a period, not a rate)", lambda: cm.rollout(cm.Trajectory(A, fps=0.02, start=S, object_pose=P), twin=twin))
t("fps=0.02 analyze", lambda: cm.analyze(cm.Trajectory(A, fps=0.02, start=S, object_pose=P), twin=twin, options=AnalyzeOptions(n_samples=8, nthread=1)))
t("fps=1.0", lambda: cm.rollout(cm.Trajectory(A, fps=1.0, start=S, object_pose=P), twin=twin).summary()["completed"])
t("fps=20000 (period in us?)", lambda: cm.rollout(cm.Trajectory(A, fps=20000, start=S, object_pose=P), twin=twin))
t("no object_pose (library)", lambda: cm.rollout(cm.Trajectory(A, fps=50.0, start=S), twin=twin).summary()["completed"])
t("no object_pose analyze (library)", lambda: cm.analyze(cm.Trajectory(A, fps=50.0, start=S), twin=twin, options=AnalyzeOptions(n_samples=8, nthread=1, search=False)).verdict.value)
