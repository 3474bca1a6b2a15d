"""rc vs verdict vs text vs --json vs report.json; env-var determinism."""
import json, os, sys
from common import cm, strip, diff, log, SCRATCH
R = "consistency.txt"
runs = {}
def go(tag, *args, env=None):
    out = os.path.join(SCRATCH, "cons_" + tag)
    rc, so, se, dt = cm("analyze", "traj.npz", "--samples", 16, "--figures", "none", "--out", out, *args, env=env)
    rep = json.load(open(os.path.join(out, "report.json")))
    raw = open(os.path.join(out, "report.json")).read()
    bad_tokens = [t for t in ("NaN", "Infinity") if t in raw]
    runs[tag] = rep
    log(R, f"{tag}: rc={rc} verdict={rep['verdict']} p={rep['p_success']} dt={dt:.1f}s tokens={bad_tokens} stderr_lines={len(se.splitlines())}")
    return rc, so, se, rep
rc, so, se, rep = go("json", "--json")
j = json.loads(so)
log(R, f"  --json stdout vs report.json diffs: {diff(strip(j), strip(rep))[:5]}")
go("base")
for tag, env in [("hash1", {"PYTHONHASHSEED": "1"}), ("hash2", {"PYTHONHASHSEED": "12345"}),
                 ("omp2", {"OMP_NUM_THREADS": "2", "MKL_NUM_THREADS": "2", "OPENBLAS_NUM_THREADS": "2"}),
                 ("omp1", {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"})]:
    go(tag, env=env)
for tag in list(runs):
    d = diff(strip(runs["base"]), strip(runs[tag]))
    log(R, f"  base vs {tag}: {len(d)} diffs {d[:4]}")
