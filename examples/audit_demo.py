"""Generate a scripted demo, audit it, and read the report from Python.

    python examples/audit_demo.py [--out DIR] [--samples N]
"""

import argparse
import json
from pathlib import Path

import critmoment as cm
from critmoment import analysis, demos, report


def main(out: Path, samples: int) -> dict:
    scenario = cm.load_scenario()                       # the bundled ALOHA twin
    twin = cm.Twin(scenario)
    traj = demos.scripted_transfer(seed=0, twin=twin)   # right arm picks, hands over to the left
    cm.save_trajectory(traj, out / "traj.npz")

    audit = analysis.analyze(traj, twin=twin,
                             options=analysis.AnalyzeOptions(seed=0, n_samples=samples))
    report.write_report(audit, out)
    print(report.summary_text(audit))

    # report.json is the stable, versioned interface for automated safety gates
    doc = json.loads((out / "report.json").read_text())
    for m in doc["moments"]:
        print(f"{m['label']:>12} at {m['time']:.2f} s: critical mass {m['critical']['mass']}, "
              f"dominant {m['dominant']}")
    return doc


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", type=Path, default=Path("out/audit_demo"))
    parser.add_argument("--samples", type=int, default=256)
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    main(args.out, args.samples)
