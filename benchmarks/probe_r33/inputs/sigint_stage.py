"""SIGINT vs SIGTERM timed off a -v stage line of `analyze --out PREV` (PREV holds an
earlier report). A 'LOST' row: the process was alive when signalled, yet exited 0/1 and
replaced PREV (docs/cli.md: an interrupt exits 2 and keeps the previous output).
usage: sigint_stage.py SIG 'stage text' off1 off2 ..."""
import hashlib, json, os, shutil, signal, subprocess, sys, threading, time
from common import CM, SCRATCH, log
R = "sigint_stage.txt"
sig, stage, offs = sys.argv[1], sys.argv[2], [float(x) for x in sys.argv[3:]]
def snap(d):
    return {n: hashlib.sha256(open(os.path.join(d, n), "rb").read()).hexdigest()[:12] for n in sorted(os.listdir(d))}
for off in offs:
    root = os.path.join(SCRATCH, "sigst"); shutil.rmtree(root, ignore_errors=True); os.makedirs(root)
    prev = os.path.join(root, "PREV"); shutil.copytree(os.path.join(SCRATCH, "base1"), prev); before = snap(prev)
    p = subprocess.Popen(["taskset", "-c", "0", CM, "-v", "analyze", os.path.join(SCRATCH, "traj.npz"), "--samples", "16",
                          "--seed", "7", "--figures", os.environ.get("FIGS", "none"), "--out", prev], cwd=root,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    lines, t0 = [], time.monotonic()
    seen = threading.Event()
    def reader():
        for line in p.stderr:
            lines.append((time.monotonic() - t0, line.rstrip()))
            if stage in line: seen.set()
    th = threading.Thread(target=reader); th.start()
    outl = []
    def oreader():
        for line in p.stdout:
            outl.append((time.monotonic() - t0, line.rstrip()))
            if stage.startswith("OUT:") and stage[4:] in line: seen.set()
    th2 = threading.Thread(target=oreader); th2.start()
    sent_at = None
    if seen.wait(60):
        time.sleep(off)
        if p.poll() is None:
            p.send_signal(getattr(signal, sig)); sent_at = time.monotonic() - t0
    p.wait(); t_exit = time.monotonic() - t0; th.join(); th2.join()
    t_first_out = outl[0][0] if outl else None
    after = snap(prev)
    lost = sent_at is not None and p.returncode in (0, 1) and not stage.startswith("OUT:")
    after_lines = [f"{t:.2f} {l[:110]}" for t, l in lines if sent_at is not None and t >= sent_at]
    log(R, f"{sig} +{off}s after {stage!r}: sent_at={sent_at and round(sent_at,2)} rc={p.returncode} "
           f"PREV={'unchanged' if after == before else 'REPLACED'} {'LOST' if lost else ''} first_stdout_at={t_first_out and round(t_first_out,2)} exit_at={t_exit:.2f}")
    if lost or (se_tb := any("Traceback" in l for _, l in lines)):
        log(R, "    TRACEBACK on stderr" if any("Traceback" in l for _, l in lines) else "    lost")
        with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "results", f"sigint_lost_{sig}_{off}.stderr"), "w") as f:
            f.write("\n".join(f"{t:.3f} {l}" for t, l in lines) + f"\nsignal sent at {sent_at:.3f}\n")
        for l in after_lines[:8]: log(R, "    " + l)
