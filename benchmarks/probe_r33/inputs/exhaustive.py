"""docs/cli.md: --exhaustive gives the 'same verdict and P(success)' as the default early stop."""
import json, os, sys
from common import cm, strip, diff, log, SCRATCH
R = "exhaustive.txt"
trajs = sys.argv[1:] or ["traj.npz", "fam_fast.npz", "fam_shallow_grasp.npz", "fam_early_open.npz",
                         "fam_jitter.npz", "fam_no_grasp.npz", "panda.npz"]
for t in trajs:
    res = {}
    for mode in ("default", "exhaustive"):
        out = os.path.join(SCRATCH, f"ex_{mode}_{t[:-4]}")
        extra = ["--exhaustive"] if mode == "exhaustive" else []
        rc, so, se, dt = cm("analyze", t, "--samples", 16, "--figures", "none", "--out", out, *extra)
        if rc == 2:
            log(R, f"{t} {mode}: rc=2 {se.strip()[-200:]}"); continue
        rep = json.load(open(os.path.join(out, "report.json")))
        res[mode] = rep
        log(R, f"{t} {mode}: rc={rc} {rep['verdict']} p={rep['p_success']} region={rep['safe_region_text'][:70]!r} dt={dt:.0f}s")
    if len(res) == 2:
        same = (res['default']['verdict'], res['default']['p_success']) == (res['exhaustive']['verdict'], res['exhaustive']['p_success'])
        log(R, f"  {t}: same verdict+P: {same}; region same: {res['default']['safe_region']==res['exhaustive']['safe_region']}")
