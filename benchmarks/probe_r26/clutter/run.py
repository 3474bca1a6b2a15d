"""Run `critmoment analyze` and `critmoment validate --samples N --json` on variants built by
gen.py, one at a time (nice 10), and append one row per variant to results.tsv (this folder).

usage: python run.py [--samples N] NAME ...
Outputs go to OUT/v/<name>/ (OUT = $R26_OUT or /tmp/r26/clutter): report/, analyze.json,
analyze.err, validate.json, validate.err. The trajectory is v/<name>/traj.npz where gen.py
wrote one, else OUT/aloha_s0.npz (`critmoment demo --seed 0`).
"""
import json
import os
import subprocess
import sys
import time
from pathlib import Path

OUT = Path(os.environ.get("R26_OUT", "/tmp/r26/clutter"))
HERE = Path(__file__).resolve().parent
COLS = ["variant", "verdict", "p_success", "analyze_rc", "analyze_s", "TS", "FS", "TU", "FU",
        "agreement", "vacuous", "validate_rc", "validate_s", "samples", "safe_region", "note"]


def run(cmd, out, err):
    t0 = time.time()
    with open(out, "w") as fo, open(err, "w") as fe:
        rc = subprocess.call(["nice", "-n", "10", *cmd], stdout=fo, stderr=fe)
    return rc, round(time.time() - t0, 1)


def load(p):
    try:
        return json.load(open(p))
    except Exception:
        return {}


def main():
    args = sys.argv[1:]
    n = 32
    if args[:1] == ["--samples"]:
        n = int(args[1])
        args = args[2:]
    res = HERE / "results.tsv"
    if not res.exists():
        res.write_text("\t".join(COLS) + "\n")
    for name in args:
        v = OUT / "v" / name
        traj = v / "traj.npz" if (v / "traj.npz").exists() else OUT / "aloha_s0.npz"
        ra, ta = run(["critmoment", "analyze", str(traj), "--scenario", str(v), "--out", str(v / "report"),
                      "--json", "--figures", "none"], v / "analyze.json", v / "analyze.err")
        rv, tv = run(["critmoment", "validate", str(traj), "--scenario", str(v), "--samples", str(n), "--json"],
                     v / f"validate{n}.json", v / f"validate{n}.err")
        a, c = load(v / "analyze.json"), load(v / f"validate{n}.json")
        conf = c.get("confusion", {})
        note = ""
        if ra == 2:
            note = "analyze: " + (open(v / "analyze.err").read().strip().splitlines() or [""])[-1][:200]
        if rv == 2 or not c:
            note += " validate: " + (open(v / f"validate{n}.err").read().strip().splitlines() or [""])[-1][:200]
        row = [name, a.get("verdict"), a.get("p_success"), ra, ta, conf.get("true_safe"), conf.get("false_safe"),
               conf.get("true_unsafe"), conf.get("false_unsafe"), c.get("agreement"), c.get("vacuous"), rv, tv, n,
               a.get("safe_region_text", "").split(" (checked")[0], note.strip()]
        with open(res, "a") as f:
            f.write("\t".join(map(str, row)) + "\n")
        print("\t".join(map(str, row)), flush=True)


if __name__ == "__main__":
    main()
