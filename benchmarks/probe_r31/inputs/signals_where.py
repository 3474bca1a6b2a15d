"""Where is a SIGTERM swallowed? Library analyze in the main thread; the handler records the Python stack
it ran in and raises KeyboardInterrupt (as the CLI's does); a run that returns normally lost it."""
import os, signal, sys, threading, time, traceback
import critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src")
from critmoment.analysis import AnalyzeOptions
traj = cm.load_trajectory("/tmp/r31/inputs/traj.npz"); sc = cm.load_scenario("/tmp/r31/inputs/safe")
seen = []
def stop(signum, frame):
    seen.append(traceback.format_stack(frame)[-4:]); raise KeyboardInterrupt
signal.signal(signal.SIGTERM, stop)
offsets = [float(x) for x in sys.argv[1:]]
for off in offsets:
    seen.clear()
    fired = []
    def fire(): fired.append(time.time() - t0); os.kill(os.getpid(), signal.SIGTERM)
    t0 = time.time(); tm = threading.Timer(off, fire); tm.start()
    try:
        cm.analyze(traj, sc, options=AnalyzeOptions(n_samples=8))
        tm.cancel(); time.sleep(0.3)
        print(f"off {off}: {'LOST' if fired else 'not fired'} (analyze returned after {time.time()-t0:.1f}s, signal sent at {fired}); handler ran {len(seen)}x at:")
        for s in seen: print("   " + "   ".join(s).replace("\n", "\n   ")[-1500:])
    except KeyboardInterrupt:
        print(f"off {off}: interrupted OK at {time.time()-t0:.1f}s; handler frame: {seen[0][-1].strip()[:160] if seen else '?'}")
    sys.stdout.flush()
