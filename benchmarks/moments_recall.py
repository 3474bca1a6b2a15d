"""Recall of the lift-off and hand-over events by critmoment's moment detection, seeds 0–19.

    python benchmarks/moments_recall.py [--seeds 20] [--tolerance 10]

Ground truth per seed from the frequent rollout's contact flags: lift-off = the object leaves
the table while the picker holds it (the last time it does before being carried), hand-over =
the picker lets go while the receiver holds it. A detection counts when a candidate lies
within ``tolerance`` physics steps (10 = 20 ms). Prints recall and candidate counts.
"""

import argparse
import warnings

import numpy as np

import critmoment as cm
from critmoment import analysis, demos


def ground_truth(rec, scenario):
    names = scenario.gripper_names
    pick, recv = names.index(scenario.task.picker), names.index(scenario.task.receiver)
    sup = rec.contact_support
    grip = rec.contact_gripper
    carried = ~sup & grip[:, pick]
    lift = np.flatnonzero(carried[1:] & ~carried[:-1]) + 1
    lift = int(lift[0]) if lift.size else None
    release = np.flatnonzero(grip[:-1, pick] & ~grip[1:, pick] & grip[1:, recv]) + 1
    handover = int(release[-1]) if release.size else None
    return lift, handover


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seeds", type=int, default=20)
    parser.add_argument("--tolerance", type=int, default=10)
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    twin = cm.Twin(cm.load_scenario())
    hits = {"lift-off": 0, "hand-over": 0}
    counts = []
    for seed in range(args.seeds):
        rec = cm.rollout(demos.scripted_transfer(seed, twin=twin), twin=twin)
        moments = analysis.detect_moments(rec, twin)
        steps = np.array([m.step for m in moments])
        counts.append(len(moments))
        lift, handover = ground_truth(rec, twin.scenario)
        row = []
        for name, truth in (("lift-off", lift), ("hand-over", handover)):
            err = None if truth is None else int(np.min(np.abs(steps - truth)))
            ok = err is not None and err <= args.tolerance
            hits[name] += ok
            row.append(f"{name} {truth} (nearest candidate {err:+d} steps)" if err is not None
                       else f"{name} missing")
        print(f"seed {seed:2d}: {len(moments)} candidates; " + "; ".join(row))
    n = args.seeds
    print(f"recall lift-off {hits['lift-off']}/{n}, hand-over {hits['hand-over']}/{n} within "
          f"±{args.tolerance} steps; candidates per trajectory: min {min(counts)}, "
          f"max {max(counts)}, mean {np.mean(counts):.1f}")


if __name__ == "__main__":
    main()
