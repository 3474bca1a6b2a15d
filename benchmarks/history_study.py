"""History study: do the drift detector and chained segments (critmoment.history) catch the
false safes that come from each sample's own history?

For the demo generator's nominal family (``demos.scripted_transfer(seed)``, ``--seeds``) on a
box whose mass range ends at ``--mass-high`` (1.5 kg: where the issue found false safes in
10 of 20 seeds), the same Sobol samples are rolled out in full (the ground truth) and
predicted by the audit's sparse decision with its verification emulated (samples that pass
with a worst cost >= 0.8 × threshold, or fail only through unlifted failures, take their
ground-truth outcome; see benchmarks/decision_study.py), then again with the samples the drift
detector escalates taking their ground-truth outcome too, and with chained segments
(``history.chained_failures``: every sample predicted safe carried on its own state from the
first moment through the later ones, its chained failure a predicted failure). Prints false safes before/after,
the escalated rollouts, and the compute: sparse seconds, drift seconds, and escalated
rollouts × the brute force's seconds per sample, against brute force.

    PYTHONPATH=. python benchmarks/history_study.py --seeds 0-19 --samples 32 --mass-high 1.5
"""

from __future__ import annotations

import argparse
import json
import time
import warnings

import numpy as np

from critmoment import analysis, demos, history
from critmoment import recording as rollout
from critmoment import sparse as sp
from critmoment.scenario import load_scenario
from critmoment.twin import Twin

try:  # the ground truth moves to critmoment.groundtruth
    from critmoment.groundtruth import brute_force
except ImportError:  # pragma: no cover
    from critmoment.validation import brute_force


def seeds_of(text: str) -> list[int]:
    if "-" in text:
        a, b = text.split("-")
        return list(range(int(a), int(b) + 1))
    return [int(s) for s in text.split(",")]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seeds", default="0-19")
    parser.add_argument("--samples", type=int, default=32)
    parser.add_argument("--sample-seed", type=int, default=0)
    parser.add_argument("--mass-high", type=float, default=1.5)
    parser.add_argument("--trace", type=int, default=25, help="steps of each drift trace")
    parser.add_argument("--drift-tolerance", type=float, default=history.DRIFT_TOLERANCE)
    parser.add_argument("--lag-tolerance", type=float, default=history.LAG_TOLERANCE)
    parser.add_argument("--scales", default="1,2.5,5",
                        help="multiples of both tolerances to report (the detector runs once)")
    parser.add_argument("--json", default=None)
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    base = load_scenario()
    box = base.box.with_range("mass", base.box.low[base.box.index("mass")], args.mass_high)
    twin = Twin(base.replace(box=box))
    samples = sp.sweep_samples(box, n=args.samples, seed=args.sample_seed)
    threshold = twin.scenario.cost.threshold
    total = {"real": 0, "fs_before": 0, "fs_after": 0, "fu_before": 0, "fu_after": 0,
             "verify_rollouts": 0, "escalated": 0, "escalated_new": 0, "sparse_s": 0.0,
             "drift_s": 0.0, "brute_s": 0.0, "n": 0, "seeds_fs_before": 0, "seeds_fs_after": 0}
    detail = []
    scales = [float(x) for x in args.scales.split(",")]
    sweep_rows: dict[float, dict] = {}
    trivial = {"esc": 0}
    chained = {"fs": 0, "fu": 0, "s": 0.0, "seeds_fs": 0, "n_chained": 0, "stepped": 0,
               "full_steps": 0}
    for seed in seeds_of(args.seeds):
        traj = demos.scripted_transfer(seed, twin=twin)
        t0 = time.perf_counter()
        real = brute_force(traj, twin=twin, samples=samples).failed
        t_brute = time.perf_counter() - t0
        t0 = time.perf_counter()
        rec = rollout.rollout(traj, twin=twin)
        ev = sp.SparseEvaluator(rec, twin)
        _, steps = analysis.audit_moments(rec, twin, ev, 8)
        res = ev.evaluate(steps, np.vstack([box.nominal[None], samples]), first_failure=True)
        failed = res.failed_any[1:]
        only = res.failed_unlifted_only[1:]
        near = ~failed & (res.worst_cost()[1:] >= 0.8 * threshold)
        verified = near | only
        before = np.where(verified, real, failed)
        nominal_fails = bool(res.failed_any[0] and not res.failed_unlifted_only[0])
        if nominal_fails or not rec.completed:
            before = np.ones_like(before)
        t_sparse = time.perf_counter() - t0
        t0 = time.perf_counter()
        drift = history.estimate_drift(ev, steps, samples, horizon=args.trace,
                                       drift_tolerance=args.drift_tolerance,
                                       lag_tolerance=args.lag_tolerance)
        escalate = drift.escalate & ~before & ~verified
        after = np.where(escalate, real, before)
        t_drift = time.perf_counter() - t0
        for scale in scales:
            bad = ((drift.predicted_drift > scale * args.drift_tolerance)
                   | (drift.predicted_lag > scale * args.lag_tolerance)).any(axis=0)
            esc = bad & ~before & ~verified
            row = sweep_rows.setdefault(scale, {"fs": 0, "fu": 0, "esc": 0})
            row["fs"] += int((~np.where(esc, real, before) & real).sum())
            row["fu"] += int((np.where(esc, real, before) & ~real).sum())
            row["esc"] += int(esc.sum())
        # the trivial alternative: roll out every sample predicted safe
        everyone = ~before & ~verified
        trivial["esc"] += int(everyone.sum())
        # chained segments: every sample predicted safe carried on its own state from the
        # first moment through the later ones; a chained failure predicts a failure
        t0 = time.perf_counter()
        chained_pred = before.copy()
        if everyone.any():
            chain = history.chained_failures(ev, steps, samples[everyone])
            chained_pred[everyone] = chain.failed
            chained["stepped"] += chain.stepped * int(everyone.sum())
        chained["s"] += time.perf_counter() - t0
        chained["fs"] += int((~chained_pred & real).sum())
        chained["fu"] += int((chained_pred & ~real).sum())
        chained["seeds_fs"] += int((~chained_pred & real).any())
        chained["n_chained"] += int(everyone.sum())
        chained["full_steps"] += int(everyone.sum()) * rec.n_steps
        entry = {
            "seed": seed, "real_failures": int(real.sum()),
            "false_safe_before": int((~before & real).sum()),
            "false_safe_after": int((~after & real).sum()),
            "false_unsafe_before": int((before & ~real).sum()),
            "false_unsafe_after": int((after & ~real).sum()),
            "verify_rollouts": int(verified.sum()), "escalated": int(escalate.sum()),
            "max_predicted_drift_mm": float(drift.predicted_drift.max(initial=0) * 1e3),
            "sparse_s": t_sparse, "drift_s": t_drift, "brute_s": t_brute}
        detail.append(entry)
        print(json.dumps(entry), flush=True)
        total["n"] += samples.shape[0]
        total["real"] += entry["real_failures"]
        for a, b in (("fs_before", "false_safe_before"), ("fs_after", "false_safe_after"),
                     ("fu_before", "false_unsafe_before"), ("fu_after", "false_unsafe_after"),
                     ("verify_rollouts", "verify_rollouts"), ("escalated", "escalated"),
                     ("sparse_s", "sparse_s"), ("drift_s", "drift_s"), ("brute_s", "brute_s")):
            total[a] += entry[b]
        total["seeds_fs_before"] += int(entry["false_safe_before"] > 0)
        total["seeds_fs_after"] += int(entry["false_safe_after"] > 0)
    per_rollout = total["brute_s"] / total["n"]
    cost_before = total["sparse_s"] + total["verify_rollouts"] * per_rollout
    cost_after = cost_before + total["drift_s"] + total["escalated"] * per_rollout
    print()
    print("| | false safes | false-safe rate | false unsafes | agreement | seeds with a false "
          "safe | full rollouts | compute / brute force |")
    print("|---|---|---|---|---|---|---|---|")
    for name, fs, fu, seeds, rolls, cost in (
            ("sparse + verification", total["fs_before"], total["fu_before"],
             total["seeds_fs_before"], total["verify_rollouts"], cost_before),
            ("+ drift escalation", total["fs_after"], total["fu_after"],
             total["seeds_fs_after"], total["verify_rollouts"] + total["escalated"],
             cost_after)):
        print(f"| {name} | {fs} of {total['real']} | {fs / max(1, total['real']):.3f} | {fu} | "
              f"{1 - (fs + fu) / total['n']:.3f} | {seeds} | {rolls} | "
              f"{cost / total['brute_s']:.3f} |")
    print()
    print("| drift / lag tolerance | false safes | false unsafes | escalated rollouts | "
          "compute / brute force |")
    print("|---|---|---|---|---|")
    for scale, row in sweep_rows.items():
        cost = cost_before + total["drift_s"] + row["esc"] * per_rollout
        print(f"| {scale * args.drift_tolerance * 1e3:.3g} mm / {scale * args.lag_tolerance:.3g} "
              f"rad | {row['fs']} | {row['fu']} | {row['esc']} | {cost / total['brute_s']:.3f} |")
    cost = cost_before + trivial["esc"] * per_rollout
    print(f"| every predicted safe sample rolled out | 0 | {total['fu_before']} | "
          f"{trivial['esc']} | {cost / total['brute_s']:.3f} |")
    print()
    cost = cost_before + chained["s"]
    print("| chained segments (history.chained_failures) on the samples predicted safe | "
          "false safes | false unsafes | agreement | seeds with a false safe | samples chained "
          "| steps per chained sample / full rollout | compute / brute force |")
    print("|---|---|---|---|---|---|---|---|")
    print(f"| sparse + verification + chained | {chained['fs']} of {total['real']} | "
          f"{chained['fu']} | {1 - (chained['fs'] + chained['fu']) / total['n']:.3f} | "
          f"{chained['seeds_fs']} | {chained['n_chained']} | "
          f"{chained['stepped'] / max(1, chained['full_steps']):.3f} | "
          f"{cost / total['brute_s']:.3f} |")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({"total": total, "detail": detail, "args": vars(args),
                       "scales": {str(k): v for k, v in sweep_rows.items()},
                       "trivial": trivial, "chained": chained}, fh, indent=1)


if __name__ == "__main__":
    main()
