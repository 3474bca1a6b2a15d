"""Same audit under CPU affinity {0} vs {0,1} and from another cwd: report.json equal apart from timings?"""
import json, os
from common import cm, strip, diff, log, SCRATCH
R = "affinity.txt"
ref = json.load(open(os.path.join(SCRATCH, "cons_base", "report.json")))
for tag, cpu, cwd, traj in [("cpu01", "0,1", SCRATCH, "traj.npz"), ("cwd_tmp", "0", "/tmp", os.path.join(SCRATCH, "traj.npz"))]:
    out = os.path.join(SCRATCH, "aff_" + tag)
    rc, so, se, dt = cm("analyze", traj, "--samples", 16, "--figures", "none", "--out", out, cpu=cpu, cwd=cwd)
    rep = json.load(open(os.path.join(out, "report.json")))
    d = diff(strip(ref), strip(rep))
    log(R, f"{tag}: rc={rc} {rep['verdict']} p={rep['p_success']} diffs vs cons_base: {len(d)} {d[:3]}")
