"""`critmoment analyze` on the demo, end to end, under two checkouts of critmoment, in turn.

    git worktree add /tmp/before <commit>
    python benchmarks/ab_cli.py /tmp/before . [--rounds 3]

Each checkout first writes the demo trajectory (seed 0) with its own `critmoment demo`; then
each round runs, for each checkout in turn, one fresh process of `critmoment analyze TRAJ
--out DIR` importing critmoment from that checkout (``sys.path[0]``): the import, the
frequent rollout, the audit, the figures and the HTML, as a user's command pays them.
Prints the median and all wall times per checkout, and the exit codes (1 for the demo's
CONDITIONAL verdict). `benchmarks/ab_audit.py` times the audit function alone.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

_CHILD = ("import sys; sys.path.insert(0, sys.argv[1]); sys.argv = ['critmoment'] + "
          "sys.argv[2:]; from critmoment.cli import main; sys.exit(main())")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("first")
    parser.add_argument("second")
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    paths = [str(Path(args.first).resolve()), str(Path(args.second).resolve())]
    with tempfile.TemporaryDirectory() as tmp:
        trajs = {}
        for i, path in enumerate(paths):
            trajs[path] = Path(tmp) / f"demo{i}.npz"
            subprocess.run([sys.executable, "-c", _CHILD, path, "demo", "--seed", "0", "--out",
                            str(trajs[path])], capture_output=True, check=True)
        runs: dict[str, list[tuple[float, int]]] = {p: [] for p in paths}
        for _ in range(args.rounds):
            for i, path in enumerate(paths):
                start = time.perf_counter()
                proc = subprocess.run([sys.executable, "-c", _CHILD, path, "analyze",
                                       str(trajs[path]), "--out", str(Path(tmp) / f"r{i}")],
                                      capture_output=True, text=True)
                runs[path].append((time.perf_counter() - start, proc.returncode))
    medians = {}
    for path, got in runs.items():
        medians[path] = statistics.median(t for t, _ in got)
        print(f"{path}: wall median {medians[path]:.2f} s, runs "
              f"{[round(t, 2) for t, _ in got]}, exit codes {sorted({c for _, c in got})}")
    print(f"ratio second / first: {medians[paths[1]] / medians[paths[0]]:.2f}")


if __name__ == "__main__":
    main()
