"""Long trajectories: rollout memory/time at 300 s; an audit of an 8 s motion + 60 s hold."""
import time, resource, sys
from common import *
from critmoment.analysis import AnalyzeOptions
z = np.load(TRAJ); A = z["actions"]; S = z["start"]; P = z["object_pose"]
sc = cm.load_scenario()
hold = lambda sec: np.r_[A, np.repeat(A[-1:], int(sec * 50), axis=0)]
mode = sys.argv[1]
if mode == "rollout":
    sec = float(sys.argv[2]); t0 = time.time()
    rec = cm.rollout(cm.Trajectory(hold(sec), fps=50.0, start=S, object_pose=P), sc)
    print(f"rollout {sec} s hold: {rec.summary()['steps']} steps {time.time()-t0:.1f}s maxrss {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss/1024:.0f} MB completed {rec.summary()['completed']}")
else:
    sec = float(sys.argv[2]); t0 = time.time()
    r = cm.analyze(cm.Trajectory(hold(sec), fps=50.0, start=S, object_pose=P), sc, options=AnalyzeOptions(n_samples=32, nthread=1))
    print(f"analyze {sec} s hold: {r.verdict.value} P={r.p_success} {time.time()-t0:.1f}s maxrss {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss/1024:.0f} MB; moments at {[round(m.moment.time,2) if hasattr(m,'moment') else None for m in r.moments][:8]}")
