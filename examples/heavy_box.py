"""The same demo with a heavier, uncertain box: the audit comes out CONDITIONAL and says where.

The nominal box weighs 0.3 kg (the trajectory still completes), but the mass is only known
to lie in 0.1–3 kg: part of that range makes the grip slip.

    python examples/heavy_box.py [--out DIR]
"""

import argparse
from pathlib import Path

import critmoment as cm
from critmoment import analysis, demos, report


def main(out: Path, samples: int):
    scenario = cm.load_scenario()
    box = scenario.box.with_range("mass", 0.1, 3.0, nominal=0.3)
    twin = cm.Twin(scenario.replace(box=box))
    traj = demos.scripted_transfer(seed=3, twin=twin)
    audit = analysis.analyze(traj, twin=twin,
                             options=analysis.AnalyzeOptions(seed=0, n_samples=samples))
    report.write_report(audit, out)
    print(report.summary_text(audit))
    return audit


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", type=Path, default=Path("out/heavy_box"))
    parser.add_argument("--samples", type=int, default=256)
    args = parser.parse_args()
    main(args.out, args.samples)
