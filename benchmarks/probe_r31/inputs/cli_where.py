"""The CLI (cli.main) with every SIGTERM handler wrapped to record the stack it ran in; SIGTERM sent
to itself after OFFSET s. Prints rc and, when rc != 2, where the handler ran (the swallowed interrupt)."""
import os, signal, sys, threading, time, traceback
sys.argv = ["critmoment"] + sys.argv[2:]; off = float(os.environ.get("OFFSET", "-1"))
_orig = signal.signal; seen = []
def wrapped_signal(sig, handler):
    if sig == signal.SIGTERM and callable(handler) and not getattr(handler, "_wrapped", False):
        inner = handler
        def rec(s, frame):
            seen.append("".join(traceback.format_stack(frame)[-6:])); return inner(s, frame)
        rec._wrapped = True; return _orig(sig, rec)
    return _orig(sig, handler)
signal.signal = wrapped_signal
import critmoment; assert critmoment.__file__.startswith("/tmp/r31/src")
from critmoment import cli
t0 = time.time(); fired = []
if off >= 0: threading.Timer(off, lambda: (fired.append(time.time() - t0), os.kill(os.getpid(), signal.SIGTERM))).start()
code = cli.main()
print(f"OFFSET {off}: rc={code} fired={fired} handler_runs={len(seen)}", file=sys.__stdout__ if False else sys.stderr)
import signal as _s; print('SIGTERM disposition at end:', _s.getsignal(_s.SIGTERM), file=sys.stderr)
if code != 2:
    for s in seen: print("  HANDLER RAN AT:\n" + s, file=sys.stderr)
