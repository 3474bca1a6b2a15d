"""SIGINT/SIGTERM a running analyze at several delays (child gets default signal dispositions)."""
import glob
import hashlib
import os
import shutil
import signal
import subprocess
import time

CM = "/tmp/r28/cli/venv/bin/critmoment"; T = "/tmp/r28/cli/readme/traj.npz"
W = "/tmp/r28/cli/sig"; shutil.rmtree(W, ignore_errors=True); os.makedirs(W); os.chdir(W)
def digest(d): return hashlib.sha256(b"".join(open(os.path.join(d, f), "rb").read() for f in sorted(os.listdir(d)))).hexdigest() if os.path.isdir(d) else None
def one(sig, delay, prev=False, cmd="analyze", extra=()):
    shutil.rmtree("o", ignore_errors=True)
    for g in glob.glob(".o.*"): shutil.rmtree(g, ignore_errors=True)
    if prev: subprocess.run([CM, "rollout", T, "--out", "o"], capture_output=True)
    before = digest("o")
    p = subprocess.Popen([CM, cmd, T, "--out", "o", *extra], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    time.sleep(delay); p.send_signal(sig); out, err = p.communicate()
    after = digest("o"); files = sorted(os.listdir("o")) if os.path.isdir("o") else None
    print(f"{cmd} {signal.Signals(sig).name} after {delay}s prev={prev}: rc={p.returncode} o={files} "
          f"prev_kept={before == after if prev else '-'} leftovers={os.listdir('.')} err={err.strip().splitlines()[-2:]}", flush=True)
for sig in (signal.SIGINT, signal.SIGTERM):
    for d in (0.3, 1, 2.5, 6, 11):
        one(sig, d)
one(signal.SIGINT, 8, prev=True); one(signal.SIGTERM, 8, prev=True)
one(signal.SIGINT, 4, cmd="validate", extra=("--samples", "16"))
one(signal.SIGINT, 1.5, cmd="rollout")
