"""validate (as the CLI does, nthread=1) -> JSON: python runval.py VARIANT [samples] [seed] [tag]
VARIANT: folder under /tmp/r32/contact/v (trajectory: its traj.npz, else aloha_s0/panda_s0).
Appends a row to /tmp/r32/contact/val.tsv."""
import json, sys, time, warnings
from pathlib import Path
import critmoment as cm
from critmoment.analysis import AnalyzeOptions
from critmoment.trajectory import load_trajectory
from critmoment.validation import validate

assert cm.__file__.startswith("/tmp/r32/src"), cm.__file__
R = Path("/tmp/r32/contact")
v = sys.argv[1]
n = int(sys.argv[2]) if len(sys.argv) > 2 else 32
seed = int(sys.argv[3]) if len(sys.argv) > 3 else 0
tag = sys.argv[4] if len(sys.argv) > 4 else ""
vd = R / "v" / v
import os
tp = Path(os.environ["TRAJ"]) if os.environ.get("TRAJ") else vd / "traj.npz"
if not tp.exists():
    tp = R / ("aloha_s0.npz" if v.startswith("a_") else "panda_s0.npz")
t = time.time()
with warnings.catch_warnings(record=True) as W:
    warnings.simplefilter("always")
    try:
        twin = cm.Twin(cm.load_scenario(str(vd)))
        traj = load_trajectory(str(tp))
        d = AnalyzeOptions()
        r = validate(traj, twin=twin, n_samples=n, seed=seed, max_moments=d.max_moments, verify=d.verify, nthread=1)
    except Exception as e:  # r32: record the refusal / crash and go on
        import traceback
        msg = f"{type(e).__module__}.{type(e).__name__}: {e}".replace("\n", " ")
        (vd / f"val{tag}_{n}_{seed}.err").write_text(traceback.format_exc() + "\n" + "\n".join(str(w.message) for w in W))
        row = [v + tag, n, seed, "ERR", f"{time.time() - t:.0f}", msg[:600]]
        with open(R / "val.tsv", "a") as f:
            f.write("\t".join(map(str, row)) + "\n")
        print(*row, sep="\t")
        for w in W:
            print("  WARN", str(w.message)[:300])
        sys.exit(0)
j = r.to_json()
j["_wall_s"] = time.time() - t
j["_warnings"] = [str(w.message) for w in W]
(vd / f"val{tag}_{n}_{seed}.json").write_text(json.dumps(j, indent=1, default=str))
c = j["confusion"]
rs = c["true_safe"] + c["false_unsafe"]
rf = c["true_unsafe"] + c["false_safe"]
row = [v + tag, n, seed, rs, rf, c["false_safe"], c["false_unsafe"], f"{j['agreement']:.3f}", j["vacuous"],
       f"{j['_wall_s']:.0f}", json.dumps(j["outcomes"])]
with open(R / "val.tsv", "a") as f:
    f.write("\t".join(map(str, row)) + "\n")
print(*row, sep="\t")
for w in j["_warnings"]:
    print("  WARN", w[:300])
for m in j["missed"]:
    print("  MISSED", m)
