"""External SIGTERM (from this parent process, as `kill` does) at fixed offsets from start, no -v."""
import os, signal, subprocess, sys, time, shutil
CM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cm.sh")
W = "/tmp/r31/inputs/sigw4"; shutil.rmtree(W, ignore_errors=True); os.makedirs(W)
args = ["analyze", "/tmp/r31/inputs/traj.npz", "--scenario", "/tmp/r31/inputs/safe", "--samples", "8", "--figures", "none"]
for i, off in enumerate(float(x) for x in sys.argv[1:]):
    q = subprocess.Popen([CM] + args + ["--out", f"o{i}"], cwd=W, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(off); alive = q.poll() is None; t1 = time.time(); os.kill(q.pid, signal.SIGTERM) if alive else None; out, err = q.communicate(); lag = time.time() - t1
    print(f"off {off}: alive_at_signal={alive} exit_lag={lag:.2f}s rc={q.returncode} written={os.path.exists(os.path.join(W, f'o{i}'))} stderr={err.strip().splitlines()[-1:]}", flush=True)
