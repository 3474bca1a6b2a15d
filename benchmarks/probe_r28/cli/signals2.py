"""SIGHUP / SIGQUIT / SIGUSR1 to a running analyze --out: is a temporary folder left behind?"""
import glob
import os
import shutil
import signal
import subprocess
import time

CM = "/tmp/r28/cli/venv/bin/critmoment"; T = "/tmp/r28/cli/readme/traj.npz"
W = "/tmp/r28/cli/sig2"; shutil.rmtree(W, ignore_errors=True); os.makedirs(W); os.chdir(W)
for sig, d in ((signal.SIGHUP, 6), (signal.SIGQUIT, 6), (signal.SIGUSR1, 6), (signal.SIGHUP, 11.5)):
    for g in glob.glob(".o.*") + ["o"]: shutil.rmtree(g, ignore_errors=True)
    p = subprocess.Popen([CM, "analyze", T, "--out", "o"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(d); p.send_signal(sig); out, err = p.communicate()
    print(f"{signal.Signals(sig).name} after {d}s: rc={p.returncode} left={sorted(os.listdir('.'))} err={err.strip().splitlines()[-1:] if err.strip() else ''}", flush=True)
