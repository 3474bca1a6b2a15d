"""SIGKILL / SIGTERM / SIGINT at t seconds into `analyze --out PREV` (PREV holds an earlier
report): is PREV intact or wholly new, what is left beside it, does a rerun work?
usage: kill.py [--validate] [SIG@t ...]   (--validate: the same for `validate --out PREV`,
PREV an earlier validation.json; results in kill_validate.txt)"""
import hashlib, json, os, shutil, signal, subprocess, sys, time, glob
from common import CM, SCRATCH, log
VALIDATE = sys.argv[1:2] == ["--validate"]
ARGS = sys.argv[2:] if VALIDATE else sys.argv[1:]
CMD = "validate" if VALIDATE else "analyze"
R = "kill_validate.txt" if VALIDATE else "kill.txt"
DOC = "validation.json" if VALIDATE else "report.json"
RERUN = [] if VALIDATE else ["--figures", "none"]
def snap(d):
    return {n: hashlib.sha256(open(os.path.join(d, n), "rb").read()).hexdigest()[:12]
            for n in sorted(os.listdir(d))} if os.path.isdir(d) else None
plan = [(s, t) for s in ("SIGKILL",) for t in (0.5, 1.5, 3, 5, 7)] + \
       [(s, t) for s in ("SIGTERM", "SIGINT") for t in (2, 5, 6.5)]
if ARGS:
    plan = [(a.split("@")[0], float(a.split("@")[1])) for a in ARGS]
base = os.path.join(SCRATCH, "val1" if VALIDATE else "base1")
for sig, t in plan:
    root = os.path.join(SCRATCH, f"kill_{sig}_{t}")
    shutil.rmtree(root, ignore_errors=True); os.makedirs(root)
    prev = os.path.join(root, "PREV")
    shutil.copytree(base, prev)
    before = snap(prev)
    p = subprocess.Popen(["taskset", "-c", "0", CM, CMD, os.path.join(SCRATCH, "traj.npz"),
                          "--samples", "16", "--seed", "7", "--out", prev], cwd=root,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(t)
    alive = p.poll() is None
    if alive:
        p.send_signal(getattr(signal, sig))
    so, se = p.communicate()
    after = snap(prev)
    left = sorted(set(os.listdir(root)) - {"PREV"})
    state = "unchanged" if after == before else ("new-whole" if after and set(after) == set(before) else f"CHANGED {after}")
    if after and after != before:
        try:
            rep = json.load(open(os.path.join(prev, DOC)))
            if not VALIDATE:
                state += f" seed={rep['manifest']['seed']}"
        except Exception as e:
            state += f" report.json unreadable {e}"
    open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "results", f"kill_{sig}_{t}_{int(time.time())}.stderr"), "w").write(se)
    log(R, f"{sig}@{t}s alive={alive} rc={p.returncode} PREV={state} leftovers={left} stderr={se.strip()[-150:]!r}")
    # rerun into PREV with leftovers present
    if left:
        q = subprocess.run(["taskset", "-c", "0", CM, CMD, os.path.join(SCRATCH, "traj.npz"),
                            "--samples", "16", *RERUN, "--out", prev], cwd=root,
                           capture_output=True, text=True)
        log(R, f"   rerun rc={q.returncode} leftovers now={sorted(set(os.listdir(root)) - {'PREV'})} files={sorted(os.listdir(prev))} err={q.stderr.strip()[-150:]!r}")
