"""Same audit twice in one process, after failed audits, in two threads, with a reused twin;
fd-level stdout capture (anything printed to stdout by the library is a leak)."""
import os, sys, json, time, threading, tempfile
from common import *
from critmoment.analysis import AnalyzeOptions
from critmoment import budget
traj = cm.load_trajectory(TRAJ)
sc = cm.load_scenario()
OPT = AnalyzeOptions(n_samples=32, nthread=1)
cap = tempfile.TemporaryFile(mode="w+b"); saved = os.dup(1)
def stdout_to_cap(): sys.stdout.flush(); os.dup2(cap.fileno(), 1)
def stdout_back(): sys.stdout.flush(); os.dup2(saved, 1)
def log(*a): stdout_back(); print(*a, flush=True); stdout_to_cap()
def diff(a, b, path=""):
    out = []
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b), key=str):
            if k not in a or k not in b: out.append(f"{path}/{k}: missing on one side"); continue
            out += diff(a[k], b[k], f"{path}/{k}")
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)): out += diff(x, y, f"{path}[{i}]")
    elif a != b and not (isinstance(a, float) and isinstance(b, float) and a != a and b != b):
        out.append(f"{path}: {str(a)[:80]} != {str(b)[:80]}")
    return out
def J(r): return json.loads(json.dumps(r.to_json(timings=False), default=str))
stdout_to_cap()
t0 = time.time(); R1 = cm.analyze(traj, sc, options=OPT); j1 = J(R1)
log("R1", R1.verdict, R1.p_success, f"{time.time()-t0:.1f}s")
R2 = cm.analyze(traj, sc, options=OPT); log("R2 same process: diffs", diff(j1, J(R2))[:10])
# failed audits: a progress callback that raises at a given stage, then the same audit again
for stage_word, exc in (("search", RuntimeError("boom")), ("verification", KeyboardInterrupt()),
                        ("critical", ValueError("x")), ("region", KeyboardInterrupt())):
    def prog(msg, w=stage_word, e=exc):
        if w in msg: raise e
    try:
        cm.analyze(traj, sc, options=OPT, progress=prog); log(f"progress raising at {stage_word!r}: never raised")
    except BaseException as e:
        log(f"progress raising {type(exc).__name__} at {stage_word!r}: audit raised {type(e).__name__}: {str(e)[:120]}")
    R = cm.analyze(traj, sc, options=OPT); log(f"  next audit: diffs", diff(j1, J(R))[:10])
# resource limit failure then again
try:
    with budget.limits(max_batch_steps=1000): cm.analyze(traj, sc, options=OPT)
except BaseException as e: log("limits(max_batch_steps=1000):", type(e).__name__, str(e)[:150])
R = cm.analyze(traj, sc, options=OPT); log("  next audit after ResourceLimitError: diffs", diff(j1, J(R))[:10])
# a failing trajectory then the good one (same twin reused)
twin = cm.Twin(sc)
bad = cm.Trajectory(np.where(np.arange(14) == 1, 1.5, traj.actions), fps=50.0, start=traj.start, object_pose=traj.object_pose)
try: cm.analyze(bad, twin=twin, options=OPT)
except BaseException as e: log("bad traj:", type(e).__name__, str(e)[:100])
R = cm.analyze(traj, twin=twin, options=OPT); log("  reused twin after failure: diffs", diff(j1, J(R))[:10])
R = cm.analyze(traj, twin=twin, options=OPT); log("  reused twin again: diffs", diff(j1, J(R))[:10])
# two audits in threads (same scenario; one on the shared twin)
res = {}
def run(k, **kw):
    try: res[k] = J(cm.analyze(traj, options=OPT, **kw))
    except BaseException as e: res[k] = f"{type(e).__name__}: {e}"
th = [threading.Thread(target=run, args=("a",), kwargs={"scenario": sc}), threading.Thread(target=run, args=("b",), kwargs={"scenario": sc})]
t0 = time.time(); [x.start() for x in th]; [x.join() for x in th]
log(f"threads (own twins) {time.time()-t0:.1f}s:", {k: (diff(j1, v)[:5] if isinstance(v, dict) else v) for k, v in res.items()})
res.clear()
th = [threading.Thread(target=run, args=("c",), kwargs={"twin": twin}), threading.Thread(target=run, args=("d",), kwargs={"twin": twin})]
t0 = time.time(); [x.start() for x in th]; [x.join() for x in th]
log(f"threads (one shared twin) {time.time()-t0:.1f}s:", {k: (diff(j1, v)[:5] if isinstance(v, dict) else v) for k, v in res.items()})
stdout_back()
cap.seek(0); leaked = cap.read().decode(errors="replace")
print("bytes printed to fd 1 by the library during all audits:", len(leaked), repr(leaked[:500]))
json.dump(j1, open("/tmp/r32/inputs/j1.json", "w"))
