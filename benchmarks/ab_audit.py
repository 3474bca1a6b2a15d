"""The demo's audit under two checkouts of critmoment, alternating, in fresh subprocesses.

    git worktree add /tmp/before <commit>
    python benchmarks/ab_audit.py /tmp/before . [--rounds 3] [--per-round 2] [--samples 256]

Each round runs, for each checkout in turn, one subprocess that imports critmoment from that
checkout (``sys.path[0]``), warms up with one audit of demo seed 0 and times ``--per-round``
more (1 s of rest before each). Prints the medians (and the fastest runs) of the wall and CPU times per checkout:
on a shared machine only runs interleaved like this compare two versions fairly.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys

_CHILD = r'''
import json, sys, time, warnings
sys.path.insert(0, sys.argv[1])
import critmoment as cm
from critmoment import analysis, demos
warnings.simplefilter("ignore")
twin = cm.Twin(cm.load_scenario())
traj = demos.scripted_transfer(0, twin=twin)
opts = analysis.AnalyzeOptions(seed=0, n_samples=int(sys.argv[3]))
analysis.analyze(traj, twin=twin, options=opts)
out = []
for _ in range(int(sys.argv[2])):
    time.sleep(1.0)
    t0, c0 = time.perf_counter(), time.process_time()
    analysis.analyze(traj, twin=twin, options=opts)
    out.append((time.perf_counter() - t0, time.process_time() - c0))
print(json.dumps(out))
'''


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("first")
    parser.add_argument("second")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--per-round", type=int, default=2)
    parser.add_argument("--samples", type=int, default=256)
    args = parser.parse_args()
    times: dict[str, list] = {args.first: [], args.second: []}
    for _ in range(args.rounds):
        for path in times:
            proc = subprocess.run([sys.executable, "-c", _CHILD, path, str(args.per_round),
                                   str(args.samples)], capture_output=True, text=True,
                                  check=True)
            times[path] += json.loads(proc.stdout.strip().splitlines()[-1])
    for path, runs in times.items():
        wall = statistics.median(w for w, _ in runs)
        cpu = statistics.median(c for _, c in runs)
        # on a noisy machine the fastest run says more about the code than the median
        print(f"{path}: wall median {wall:.3f} s (fastest {min(w for w, _ in runs):.3f} s), "
              f"CPU median {cpu:.3f} s (least {min(c for _, c in runs):.3f} s), "
              f"runs {[round(w, 2) for w, _ in runs]}")


if __name__ == "__main__":
    main()
