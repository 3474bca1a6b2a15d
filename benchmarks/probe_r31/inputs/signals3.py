"""Hunt for a lost SIGTERM: signal at offsets after 'analytic bounds and search ...', keep full stderr."""
import os, signal, subprocess, sys, time, shutil
CM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cm.sh")
W = "/tmp/r31/inputs/sigw3"; shutil.rmtree(W, ignore_errors=True); os.makedirs(W)
sig = getattr(signal, sys.argv[1]); offs = [float(x) for x in sys.argv[2:]]
args = ["analyze", "/tmp/r31/inputs/traj.npz", "--scenario", "/tmp/r31/inputs/safe", "--samples", "8", "--figures", "none", "-v"]
for i, off in enumerate(offs):
    q = subprocess.Popen([CM] + args + ["--out", f"o{i}"], cwd=W, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    start = time.time(); lines = []; sent = None
    import threading
    def pump():
        for line in q.stderr: lines.append((time.time() - start, line.rstrip()))
    th = threading.Thread(target=pump); th.start()
    while not any("analytic bounds and search ..." in l for _, l in lines): time.sleep(0.01)
    t_stage = time.time() - start
    time.sleep(off); q.send_signal(sig); sent = time.time() - start
    q.wait(); th.join()
    before = [l for t, l in lines if t <= sent][-1:]
    print(f"off {off}: sent {sent:.2f}s rc={q.returncode} written={os.path.exists(os.path.join(W, f'o{i}'))} last-before={before} after={[l[:100] for t, l in lines if t > sent][:3]}", flush=True)
    if q.returncode != 2: open(f"{W}/lost_{i}.err", "w").write("\n".join(f"{t:.2f} {l}" for t, l in lines))
