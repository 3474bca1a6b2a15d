"""Run analyze + validate on every case that gen.py wrote, two at a time.

Run: ``python benchmarks/probe_r24/tasks/run.py GENDIR [CASE ...]`` (default ``/tmp/r24t/gen``;
``--samples N`` overrides the cases' counts). Writes ``GENDIR/results.tsv`` (case, verdict,
p_success, FS, FU, agreement, vacuous, analyze rc, validate rc, warnings/errors) and prints
each row as it finishes.
"""

import json
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path


def run(cmd: list[str], cwd: Path) -> tuple[int, str, str]:
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    return proc.returncode, proc.stdout, proc.stderr


def notes(stderr: str) -> list[str]:
    return [line.split(": ", 1)[1] for line in stderr.splitlines()
            if ": warning: " in line or ": error: " in line]


def one(gen: Path, row: dict, samples: str | None) -> dict:
    traj, scen = row["trajectory"], row["scenario"]
    rc_a, out_a, err_a = run(["critmoment", "analyze", traj, "--scenario", scen, "--json",
                              "--figures", "none", "--seed", "0"], gen)
    rep = json.loads(out_a) if rc_a in (0, 1) and out_a.strip() else {}
    rc_v, out_v, err_v = run(["critmoment", "validate", traj, "--scenario", scen, "--json",
                              "--samples", samples or row["samples"], "--seed", "0"], gen)
    val = json.loads(out_v) if rc_v in (0, 1) and out_v.strip() else {}
    conf = val.get("confusion", {})
    return {
        "case": row["case"],
        "verdict": rep.get("verdict", "-"),
        "p_success": rep.get("p_success", "-"),
        "completed": rep.get("rollout", {}).get("completed", "-"),
        "FS": conf.get("false_safe", "-"),
        "FU": conf.get("false_unsafe", "-"),
        "TS": conf.get("true_safe", "-"),
        "TU": conf.get("true_unsafe", "-"),
        "agreement": val.get("agreement", "-"),
        "vacuous": val.get("vacuous", "-"),
        "rc_analyze": rc_a,
        "rc_validate": rc_v,
        "notes": " | ".join(dict.fromkeys(notes(err_a) + notes(err_v))),
    }


def main() -> None:
    args = sys.argv[1:]
    samples = None
    if "--samples" in args:
        i = args.index("--samples")
        samples = args[i + 1]
        del args[i:i + 2]
    gen = Path(args[0] if args else "/tmp/r24t/gen")
    wanted = set(args[1:])
    lines = (gen / "cases.tsv").read_text().splitlines()
    head = lines[0].split("\t")
    rows = [dict(zip(head, line.split("\t"), strict=True)) for line in lines[1:]]
    rows = [r for r in rows if not wanted or r["case"] in wanted]
    name = "results.tsv" if not wanted and samples is None else "results_extra.tsv"
    with ThreadPoolExecutor(2) as pool, open(gen / name, "a") as fh:
        for res in pool.map(lambda r: one(gen, r, samples), rows):
            line = "\t".join(str(v) for v in res.values())
            fh.write(line + "\n")
            fh.flush()
            print(line, flush=True)


if __name__ == "__main__":
    main()
