"""SIGTERM/SIGINT landing while CasADi/IPOPT runs (the 'analytic bounds and search' stage)."""
import os, signal, subprocess, sys, time, shutil
CM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cm.sh")
W = "/tmp/r31/inputs/sigw2"; shutil.rmtree(W, ignore_errors=True); os.makedirs(W)
sig = getattr(signal, sys.argv[1] if len(sys.argv) > 1 else "SIGTERM")
args = ["analyze", "/tmp/r31/inputs/traj.npz", "--scenario", "/tmp/r31/inputs/safe", "--samples", "8", "--figures", "none", "-v"]
for i in range(int(sys.argv[2]) if len(sys.argv) > 2 else 6):
    q = subprocess.Popen([CM] + args + ["--out", f"o{i}"], cwd=W, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    start = time.time(); sent = False; lines = []
    # wait for the search stage to begin, then signal
    for line in q.stderr:
        lines.append(line.rstrip())
        if not sent and "analytic bounds and search ..." in line:
            time.sleep(float(os.environ.get("STEP", "0.05")) * i); q.send_signal(sig); sent = time.time() - start
    q.wait()
    print(f"run {i}: signal at {sent:.2f}s rc={q.returncode} out_written={os.path.exists(os.path.join(W, f'o{i}'))}; "
          f"casadi={[l[:90] for l in lines if 'CasADi' in l or 'Interrupt' in l][:2]} last={lines[-1][:120]}", flush=True)
