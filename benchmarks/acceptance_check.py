"""The acceptance suite and the bundled Panda rows of the validity table, in one run.

    PYTHONPATH=. python benchmarks/acceptance_check.py [--samples 64] [--no-verify]
                                                       [--out results.json]

Validates (``critmoment.validation.validate``: the audit's decision path against brute-force
full rollouts of the same Sobol samples) the six trajectory families of
``critmoment.suite`` on the bundled ALOHA twin (family seed 0, Sobol seed 0) and the bundled
Panda's scripted pick and place for seeds 0, 1 and 2 (Sobol seed = the trajectory's seed).
Prints one line per case (confusion counts, false-safe rate, agreement, whether the
validation is vacuous: no real success or no real failure) and ends with the worst case.
About 1.5 minutes on 2 cores. ``--no-verify`` measures the audit without its own full
rollouts (``analyze --no-verify``).
"""

import argparse
import json
import time
import warnings

import critmoment as cm
from critmoment import panda_demo, suite, validation


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--samples", type=int, default=64)
    parser.add_argument("--out", default=None, help="write the results as JSON here")
    parser.add_argument("--no-verify", action="store_true",
                        help="the audit without its own full rollouts (analyze --no-verify)")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    cases = []
    aloha = cm.Twin(cm.load_scenario())
    for family in ("nominal", "fast", "shallow_grasp", "early_open", "jitter", "no_grasp"):
        cases.append((f"aloha {family}", aloha, lambda f=family: suite.make(f, seed=0), 0))
    panda = cm.Twin(cm.load_scenario("panda_pick_place"))
    for seed in (0, 1, 2):
        cases.append((f"panda nominal seed {seed}", panda,
                      lambda s=seed: panda_demo.make_pick_place(s), seed))
    results = {}
    for name, twin, make, seed in cases:
        t0 = time.perf_counter()
        extra = {"verify": None} if args.no_verify else {}
        r = validation.validate(make(), twin=twin, n_samples=args.samples, seed=seed, **extra)
        results[name] = {"confusion": r.confusion, "false_safe_rate": r.false_safe_rate,
                         "agreement": r.agreement, "vacuous": r.vacuous,
                         "seconds": time.perf_counter() - t0}
        print(f"{name:26s} {r.confusion} false-safe rate {r.false_safe_rate} agreement "
              f"{r.agreement:.3f}{' VACUOUS' if r.vacuous else ''} "
              f"({time.perf_counter() - t0:.0f} s)", flush=True)
    worst = min(results.values(), key=lambda v: v["agreement"])
    print(f"false safes in all: {sum(v['confusion']['false_safe'] for v in results.values())}; "
          f"lowest agreement {worst['agreement']:.3f}")
    if args.out:
        with open(args.out, "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
