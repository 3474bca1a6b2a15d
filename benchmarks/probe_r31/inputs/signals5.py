"""External SIGTERM into cli_where.py (handler stack recorded)."""
import os, signal, subprocess, sys, time
here = os.path.dirname(os.path.abspath(__file__))
env = dict(os.environ, PYTHONPATH="/tmp/r31/src")
for off in (float(x) for x in sys.argv[1:]):
    q = subprocess.Popen(["/work/venv/bin/python", os.path.join(here, "cli_where.py"), "x", "analyze", "/tmp/r31/inputs/traj.npz", "--scenario",
                          "/tmp/r31/inputs/safe", "--samples", "8", "--figures", "none", "--json"], env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    time.sleep(off); q.send_signal(signal.SIGTERM); _, err = q.communicate()
    lines = err.strip().splitlines()
    print(f"off {off}: rc={q.returncode}; " + " | ".join(l for l in lines if l.startswith(("OFFSET", "SIGTERM disp"))), flush=True)
    if q.returncode == 0: print("   " + "\n   ".join(lines[-40:]))
