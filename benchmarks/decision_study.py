"""Decision study: the sparse decision with and without persistence and measured slip.

For every trajectory (the demo generator's nominal family, ``demos.scripted_transfer(seed)``
for ``--seeds``) and box (the scenario's whole box and, with ``--mass-high``, a box whose mass
range ends there), the same Sobol samples are rolled out in full once (the ground truth), and
the audit's sparse prediction at its moments (``analysis.audit_moments``, 8 moments, the
first-failure sweep) is made under each decision:

* ``old``: every excursion of the cost over the threshold counts at once, no slip criterion
  (``persistence = 0``, ``slip_tolerance = inf``): the decision before this study;
* ``new``: contact excursions count when they last ``persistence`` (0.02 s), measured slip
  over 5 mm fails (the defaults);

each alone and with the audit's verification emulated: the samples that pass with a worst
cost of at least 0.8 × threshold, and those that fail only through unlifted failures, take
their ground-truth outcome (no extra rollouts are run: the brute force already holds them).
A nominal sample that fails (other than only unlifted) makes every sample fail, as the
audit's UNSAFE verdict does. Prints one markdown table and, with ``--json``, every number.

    PYTHONPATH=. python benchmarks/decision_study.py --seeds 0-19 --samples 32 --mass-high 1.5
"""

from __future__ import annotations

import argparse
import json
import time
import warnings

import numpy as np

from critmoment import analysis, demos
from critmoment import recording as rollout
from critmoment import sparse as sp
from critmoment.scenario import load_scenario
from critmoment.twin import Twin

try:  # the ground truth moves to critmoment.groundtruth
    from critmoment.groundtruth import brute_force
except ImportError:  # pragma: no cover
    from critmoment.validation import brute_force

DECISIONS = {"old": {"persistence": 0.0, "slip_tolerance": np.inf}, "new": {}}


def seeds_of(text: str) -> list[int]:
    if "-" in text:
        a, b = text.split("-")
        return list(range(int(a), int(b) + 1))
    return [int(s) for s in text.split(",")]


def predict(rec, twin, samples, options: dict, verify: bool, real: np.ndarray):
    """(predicted failed (n,), seconds, rollouts the verification would run)."""
    t0 = time.perf_counter()
    ev = sp.SparseEvaluator(rec, twin, **options)
    _, steps = analysis.audit_moments(rec, twin, ev, 8)
    probe = np.vstack([twin.scenario.box.nominal[None], samples])
    res = ev.evaluate(steps, probe, first_failure=True)
    failed = res.failed_any[1:]
    only_unlifted = res.failed_unlifted_only
    nominal_fails = bool(res.failed_any[0] and not only_unlifted[0])
    rerun = np.zeros_like(failed)
    if verify:
        near = ~failed & (res.worst_cost()[1:] >= 0.8 * twin.scenario.cost.threshold)
        rerun = near | only_unlifted[1:]
        failed = np.where(rerun, real, failed)
    if (nominal_fails and not (verify and only_unlifted[0])) or not rec.completed:
        failed = np.ones_like(failed)
    return failed, time.perf_counter() - t0, int(rerun.sum())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seeds", default="0-19")
    parser.add_argument("--samples", type=int, default=32)
    parser.add_argument("--sample-seed", type=int, default=0)
    parser.add_argument("--mass-high", type=float, default=None)
    parser.add_argument("--json", default=None)
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    base = load_scenario()
    boxes = {"whole box": base.box}
    if args.mass_high is not None:
        boxes[f"mass <= {args.mass_high:g} kg"] = base.box.with_range(
            "mass", base.box.low[base.box.index("mass")], args.mass_high)
    rows, detail = {}, []
    for box_name, box in boxes.items():
        twin = Twin(base.replace(box=box))
        samples = sp.sweep_samples(box, n=args.samples, seed=args.sample_seed)
        for seed in seeds_of(args.seeds):
            traj = demos.scripted_transfer(seed, twin=twin)
            t0 = time.perf_counter()
            real = brute_force(traj, twin=twin, samples=samples).failed
            t_brute = time.perf_counter() - t0
            rec = rollout.rollout(traj, twin=twin)
            entry = {"box": box_name, "seed": seed, "real_failures": int(real.sum()),
                     "brute_seconds": t_brute}
            for name, options in DECISIONS.items():
                for verify in (False, True):
                    key = f"{name}{' + verify' if verify else ''}"
                    pred, sec, reruns = predict(rec, twin, samples, options, verify, real)
                    fs = int((~pred & real).sum())
                    fu = int((pred & ~real).sum())
                    entry[key] = {"false_safe": fs, "false_unsafe": fu, "seconds": sec,
                                  "rollouts": reruns}
                    agg = rows.setdefault((box_name, key), {"n": 0, "real": 0, "fs": 0,
                                                            "fu": 0, "sec": 0.0, "roll": 0,
                                                            "brute": 0.0, "seeds_fs": 0})
                    agg["n"] += samples.shape[0]
                    agg["real"] += int(real.sum())
                    agg["fs"] += fs
                    agg["fu"] += fu
                    agg["sec"] += sec
                    agg["roll"] += reruns
                    agg["brute"] += t_brute
                    agg["seeds_fs"] += int(fs > 0)
            detail.append(entry)
            print(json.dumps(entry), flush=True)
    print()
    print("| box | decision | samples | real failures | false safes | false-safe rate | "
          "false unsafes | agreement | seeds with a false safe | verification rollouts | "
          "sparse s / brute-force s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for (box_name, key), a in rows.items():
        rate = a["fs"] / a["real"] if a["real"] else float("nan")
        agree = 1 - (a["fs"] + a["fu"]) / a["n"]
        print(f"| {box_name} | {key} | {a['n']} | {a['real']} | {a['fs']} | {rate:.3f} | "
              f"{a['fu']} | {agree:.3f} | {a['seeds_fs']} | {a['roll']} | "
              f"{a['sec'] / a['brute']:.3f} |")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({"rows": [{"box": b, "decision": k, **v} for (b, k), v in rows.items()],
                       "detail": detail}, fh, indent=1)


if __name__ == "__main__":
    main()
