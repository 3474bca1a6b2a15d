"""SIGTERM/SIGINT/SIGHUP/SIGQUIT/SIGUSR1 at various times into analyze --out PREV (an earlier output).
Checks: rc == 2, one error line, PREV unchanged (hash), no .PREV.critmoment-tmp-* left."""
import hashlib, os, signal, subprocess, sys, time, shutil, json
CM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cm.sh")
W = "/tmp/r31/inputs/sigw"; shutil.rmtree(W, ignore_errors=True); os.makedirs(W)
args = ["analyze", "/tmp/r31/inputs/traj.npz", "--scenario", "/tmp/r31/inputs/safe", "--samples", "8", "--out", "prev"]
def digest(d):
    h = hashlib.sha256()
    for n in sorted(os.listdir(d)):
        h.update(n.encode()); h.update(open(os.path.join(d, n), "rb").read())
    return h.hexdigest()[:12]
p = subprocess.run([CM] + args + ["--figures", "none"], cwd=W, capture_output=True, text=True); print("seed prev rc", p.returncode)
before = digest(os.path.join(W, "prev"))
cases = [(s, t) for s in ("SIGTERM",) for t in (0.3, 1.0, 3, 6, 9, 12, 15)] + \
        [(s, 6) for s in ("SIGINT", "SIGHUP", "SIGQUIT", "SIGUSR1", "SIGUSR2")]
for sig, t in cases:
    q = subprocess.Popen([CM] + args, cwd=W, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(t); t0 = time.time(); q.send_signal(getattr(signal, sig))
    out, err = q.communicate(); lag = time.time() - t0
    after = digest(os.path.join(W, "prev")); left = [n for n in os.listdir(W) if "critmoment-tmp" in n]
    ok = q.returncode == 2 and after == before and not left
    wrote = after != before
    print(f"{sig} at {t}s: rc={q.returncode} lag={lag:.1f}s prev_changed={wrote} leftovers={left} {'OK' if ok else ('REPLACED-WHOLE' if wrote and q.returncode==2 else 'CHECK')} :: {err.strip().splitlines()[-1:] }", flush=True)
    if wrote:  # it finished before the signal: new baseline
        before = after
    for n in left: shutil.rmtree(os.path.join(W, n), ignore_errors=True)
