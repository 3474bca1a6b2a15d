"""SIGTERM/SIGINT late in `analyze --figures all` (figure rendering, writing, the swap):
the --out folder must hold one whole run, the one the exit code says.

    PYTHONPATH=/tmp/r29/src python kill_late.py [TRIES]
rc 2 -> folder still holds the previous run (other seed); rc 1 -> the new run; every file whole.
"""
import json
import os
import random
import signal
import subprocess
import sys
import time

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from common import CLI, SCRATCH, demo_traj, env  # noqa: E402

tries = int(sys.argv[1]) if len(sys.argv) > 1 else 10
work = SCRATCH / "kill_late"
work.mkdir(exist_ok=True)
tp = demo_traj()
out = work / "rep"
ARGS = ["analyze", str(tp), "--samples", "32", "--figures", "all", "--out", str(out)]


def start(seed):
    return subprocess.Popen([*CLI, *ARGS, "--seed", str(seed)], env=env(), stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)


def whole(folder):
    """(seed, problems) of an output folder."""
    problems = []
    try:
        doc = json.loads((folder / "report.json").read_text())
        seed = doc["manifest"]["seed"]
    except Exception as exc:  # noqa: BLE001
        return None, [f"report.json: {exc}"]
    html = (folder / "report.html").read_text(errors="replace")
    if not html.rstrip().endswith("</html>"):
        problems.append("report.html truncated")
    marker = json.loads((folder / ".critmoment-output.json").read_text())
    names = set(marker.get("files", []))
    present = {p.name for p in folder.iterdir()} - {".critmoment-output.json"}
    if names and names != present:
        problems.append(f"marker lists {sorted(names ^ present)} differently")
    for png in folder.glob("*.png"):
        b = png.read_bytes()
        if not (b.startswith(b"\x89PNG") and b.rstrip().endswith(b"IEND\xaeB`\x82")):
            problems.append(f"{png.name} truncated")
    return seed, problems


# a timed run, seed 1, to learn when the writing happens
t0 = time.perf_counter()
p = start(1)
p.communicate()
total = time.perf_counter() - t0
print(f"full run {total:.1f} s, rc {p.returncode}; files: {sorted(x.name for x in out.iterdir())}")
random.seed(0)
for i in range(tries):
    before, _ = whole(out)
    seed = 1 - before
    delay = random.uniform(max(0.5, total - 3.0), total + 0.3)
    sig = random.choice([signal.SIGTERM, signal.SIGINT])
    p = start(seed)
    time.sleep(delay)
    try:
        os.kill(p.pid, sig)
    except ProcessLookupError:
        pass
    _, err = p.communicate()
    after, problems = whole(out)
    leftovers = [x.name for x in work.iterdir() if "critmoment-tmp" in x.name]
    expect = {2: before, 1: seed}.get(p.returncode)
    ok = after == expect and not problems and not leftovers
    print(f"try {i}: {sig.name} at {delay:.2f} s -> rc {p.returncode}, folder seed {after} "
          f"(previous {before}, new {seed}) {'OK' if ok else 'MISMATCH'} {problems} {leftovers} "
          f"| {err.strip().splitlines()[-1][:120] if err.strip() else ''}")
