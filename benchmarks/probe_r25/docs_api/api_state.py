"""Library API as an automated audit would use it: repeated calls in one process, global state,
Trajectory built from numpy arrays, report JSON round trip.

    python api_state.py OUTDIR      (writes OUTDIR/*.json; prints one line per check)
"""
import json
import logging
import os
import random
import signal
import sys
import threading
import warnings
from pathlib import Path

import numpy as np

import critmoment as cm
from critmoment import demos

out = Path(sys.argv[1] if len(sys.argv) > 1 else "/tmp/r25/docs_api/b_state")
out.mkdir(parents=True, exist_ok=True)
N = 32


def snapshot():
    return {
        "warnings.filters": list(warnings.filters),
        "np.random": np.random.get_state()[1][:5].tolist() + [np.random.get_state()[2]],
        "random": hash(random.getstate()),
        "logging.root": (logging.root.level, list(logging.root.handlers)),
        "loggers": sorted(k for k in logging.Logger.manager.loggerDict),
        "signals": {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)},
        "environ": dict(os.environ),
        "cwd": os.getcwd(),
        "threads": threading.active_count(),
        "np.seterr": np.geterr(),
        "printoptions": np.get_printoptions(),
    }


def report_doc(rep):
    d = rep.to_json(timings=False)
    s = json.dumps(d, allow_nan=False, sort_keys=True)
    return s


def check(label, ok, detail=""):
    print(f"{'OK  ' if ok else 'FAIL'} {label} {detail}")


traj = demos.scripted_transfer(seed=0)
cm.save_trajectory(traj, out / "traj.npz")
actions_before = traj.actions.copy()
np.random.seed(1234)
random.seed(1234)
before = snapshot()
docs = []
for i in range(3):
    rep = cm.analyze(traj, seed=0, options=cm.AnalyzeOptions(n_samples=N))
    docs.append(report_doc(rep))
    print(f"analyze #{i}: {rep.verdict.value} P={rep.p_success} region={rep.safe_region}")
check("analyze x3 identical report.json (no timings)", len(set(docs)) == 1)
(out / "inproc.json").write_text(docs[0])
check("traj.actions not mutated by analyze", np.array_equal(actions_before, traj.actions))
after = snapshot()
for k in before:
    if k == "loggers":
        new = sorted(set(after[k]) - set(before[k]))
        check(f"global state {k}", True, f"new loggers: {new[:12]}{'...' if len(new) > 12 else ''}")
        continue
    same = before[k] == after[k]
    detail = ""
    if not same and k == "warnings.filters":
        detail = f"added: {[f for f in after[k] if f not in before[k]][:5]}"
    elif not same and k == "environ":
        detail = f"{set(after[k].items()) ^ set(before[k].items())}"
    elif not same:
        detail = f"{before[k]} -> {after[k]}"
    check(f"global state {k} unchanged", same, detail)

# validate twice
v1 = cm.validate(traj, n_samples=16, seed=0)
v2 = cm.validate(traj, n_samples=16, seed=0)
j1 = json.dumps(v1.to_json(timings=False), sort_keys=True, allow_nan=False)
j2 = json.dumps(v2.to_json(timings=False), sort_keys=True, allow_nan=False)
check("validate x2 identical (no timings)", j1 == j2, f"{v1.confusion}")

# report round trip
rep = cm.analyze(traj, seed=0, options=cm.AnalyzeOptions(n_samples=N))
d = rep.to_json()
s = json.dumps(d, allow_nan=False)
back = json.loads(s)
check("to_json -> json.dumps(allow_nan=False) -> loads == to_json", back == json.loads(json.dumps(d)),)
check("to_json keys are str and values JSON-native", json.dumps(back, allow_nan=False) == s)
check("timings only differ", report_doc(rep) == docs[0])

# Trajectory built in code from numpy arrays (no file)
t2 = cm.Trajectory(actions=np.array(traj.actions, dtype=np.float64), fps=float(traj.fps),
                   object_pose=np.array(traj.object_pose), meta={})
rep2 = cm.analyze(t2, seed=0, options=cm.AnalyzeOptions(n_samples=N))
d2 = rep2.to_json(timings=False)
d0 = json.loads(docs[0])
diff = [k for k in d0 if d0[k] != d2.get(k)]
check("Trajectory from numpy arrays == demo trajectory (except manifest)", diff in ([], ["manifest"]), f"differ: {diff}")
t3 = cm.Trajectory(actions=traj.actions.astype(np.float32), fps=50, object_pose=tuple(traj.object_pose))
rep3 = cm.analyze(t3, seed=0, options=cm.AnalyzeOptions(n_samples=N))
check("float32 actions, tuple object_pose accepted", True, f"{rep3.verdict.value} P={rep3.p_success}")
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    t4 = cm.Trajectory(actions=traj.actions.copy(), fps=50)
    rep4 = cm.analyze(t4, seed=0, options=cm.AnalyzeOptions(n_samples=N))
check("no object_pose -> warning", any("pose" in str(x.message) for x in w),
      f"{rep4.verdict.value} P={rep4.p_success}; warnings: {[str(x.message)[:80] for x in w][:3]}")
# the CLI's report of the same trajectory
(out / "inproc_full.json").write_text(json.dumps(rep.to_json(timings=False), sort_keys=True, indent=1))
print("done")
