"""``validate`` (the audit's own decision path) over demo seeds on a mass ≤ 1.5 kg box, with or
without chained segments (``AnalyzeOptions.chain``), against brute-force full rollouts.

    PYTHONPATH=. python benchmarks/chained_check.py --seeds 0,3,6,9,12,15,18 --chain 1

``--no-verify``: the audit without its own full rollouts (``analyze --no-verify``).
"""

from __future__ import annotations

import argparse
import warnings

import critmoment as cm
from critmoment import demos


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seeds", default="0,3,6,9,12,15,18")
    parser.add_argument("--chain", type=int, choices=(0, 1), default=1)
    parser.add_argument("--samples", type=int, default=32)
    parser.add_argument("--mass-high", type=float, default=1.5)
    parser.add_argument("--no-verify", action="store_true")
    args = parser.parse_args()
    scenario = cm.load_scenario()
    scenario = scenario.replace(box=scenario.box.with_range("mass", 0.05, args.mass_high))
    twin = cm.Twin(scenario)
    fs = fu = n = real = 0
    sparse_s = brute_s = 0.0
    for seed in (int(s) for s in args.seeds.split(",")):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = cm.validate(demos.scripted_transfer(seed, twin=twin), twin=twin,
                                 n_samples=args.samples, seed=0, chain=bool(args.chain),
                                 **({"verify": None} if args.no_verify else {}))
        c = result.confusion
        fs += c["false_safe"]
        fu += c["false_unsafe"]
        n += result.n_samples
        real += int(result.real_failed.sum())
        sparse_s += result.sparse_seconds
        brute_s += result.brute_force_seconds
        print(f"seed {seed}: {c}", flush=True)
    print(f"chain {bool(args.chain)}: {n} samples, {real} real failures, false safes {fs}, "
          f"false unsafes {fu}, agreement {1 - (fs + fu) / n:.3f}, compute ratio "
          f"{sparse_s / brute_s:.3f}")


if __name__ == "__main__":
    main()
