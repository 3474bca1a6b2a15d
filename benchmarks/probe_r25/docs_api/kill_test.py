"""Kill `critmoment analyze --out rep` with SIGTERM/SIGINT at random points; the folder must hold
either the old complete report or none: every file parses, report.html is complete.

    python kill_test.py WORKDIR TRAJ [TRIES]
"""
import json
import os
import random
import signal
import subprocess
import sys
import time
from pathlib import Path

work = Path(sys.argv[1])
traj = Path(sys.argv[2]).resolve()
tries = int(sys.argv[3]) if len(sys.argv) > 3 else 10
work.mkdir(parents=True, exist_ok=True)
rep = work / "rep"
rng = random.Random(0)


def state():
    if not rep.exists():
        return "absent", None
    files = sorted(p.name for p in rep.iterdir())
    try:
        d = json.loads((rep / "report.json").read_text())
        html = (rep / "report.html").read_text()
        ok_html = html.rstrip().endswith("</html>")
        marker = json.loads((rep / ".critmoment-output.json").read_text())
        return ("complete" if ok_html and set(marker["files"]) <= set(files) else "PARTIAL"), d["manifest"]["seed"]
    except Exception as e:  # noqa: BLE001
        return f"BROKEN {type(e).__name__}: {e}", files


rows = []
for i in range(tries):
    seed = i
    sig = signal.SIGTERM if i % 2 == 0 else signal.SIGINT
    delay = rng.uniform(0.5, 10.0)
    before = state()
    p = subprocess.Popen(["critmoment", "analyze", str(traj), "--out", str(rep), "--seed", str(seed),
                          "--samples", os.environ.get("KT_SAMPLES", "32")], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    time.sleep(delay)
    p.send_signal(sig)
    t0 = time.time()
    try:
        _, err = p.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        p.kill()
        _, err = p.communicate()
        err = b"(did not stop within 60 s) " + err
    after = state()
    leftovers = [x.name for x in work.iterdir() if "critmoment-tmp" in x.name]
    line = (f"{i}\t{sig.name}\t{delay:.2f}\trc={p.returncode}\tstop {time.time() - t0:.2f}s\tbefore={before}\t"
            f"after={after}\tleft={leftovers}\terr={err.decode().strip()[-150:]!r}")
    print(line, flush=True)
