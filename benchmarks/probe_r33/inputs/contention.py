"""Same audit with a CPU hog competing (timing-dependent thread use: evaluator.busy): report.json
equal to the quiet run's apart from timings?"""
import json, os, subprocess, sys
from common import cm, strip, diff, log, SCRATCH
R = "contention.txt"
ref = json.load(open(os.path.join(SCRATCH, "cons_base", "report.json")))
hog = subprocess.Popen(["taskset", "-c", "0", sys.executable, "-c", "while True: pass"])
try:
    for i, cpu in enumerate(["0,1", "0", "0,1"]):
        out = os.path.join(SCRATCH, f"cont_{i}")
        rc, so, se, dt = cm("analyze", "traj.npz", "--samples", 16, "--figures", "none", "--out", out, cpu=cpu)
        rep = json.load(open(os.path.join(out, "report.json")))
        d = diff(strip(ref), strip(rep))
        log(R, f"hog on cpu0, audit on {cpu}: rc={rc} {rep['verdict']} p={rep['p_success']} dt={dt:.0f}s diffs: {len(d)} {d[:3]}")
finally:
    hog.kill(); hog.wait()
