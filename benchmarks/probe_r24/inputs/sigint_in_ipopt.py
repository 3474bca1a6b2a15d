"""Reproducer: a Ctrl-C (SIGINT) that arrives while IPOPT runs inside `critmoment analyze`
is swallowed by CasADi: the audit goes on, writes report.json/html and exits 1 (not 2).
Usage: python sigint_in_ipopt.py TRAJ OUTDIR [delay_s]
A helper thread delivers a real SIGINT to this process `delay_s` after the first IPOPT solve
starts (a stand-in for a user's Ctrl-C landing in that window; the same happens with a real
Ctrl-C about 7 s into `critmoment analyze base.npz` on this machine)."""
import os
import signal
import sys
import threading

import casadi as ca

delay = float(sys.argv[3]) if len(sys.argv) > 3 else 0.0005
_orig = ca.nlpsol
sent = []
class Wrapped:
    def __init__(self, f): self.f = f
    def __call__(self, *a, **k):
        if not sent:
            sent.append(1)
            threading.Timer(delay, lambda: os.kill(os.getpid(), getattr(signal, os.environ.get("SIG", "SIGINT")))).start()
        return self.f(*a, **k)
    def stats(self): return self.f.stats()
ca.nlpsol = lambda *a, **k: Wrapped(_orig(*a, **k))
# imported only after casadi.nlpsol is wrapped above
from critmoment import cli  # noqa: E402

rc = cli.main(["analyze", sys.argv[1], "--out", sys.argv[2]])
print("exit code", rc)
sys.exit(rc)
