"""Is a sample's real outcome a function of its parameters? Re-run the ground truth with the
parameters perturbed by a tiny relative amount and list the samples whose outcome changes.

    python benchmarks/chaos_check.py RUN_DIR [--scenario scenario.toml] [--samples 64]
                                     [--seed 0] [--eps 1e-9,1e-6]

RUN_DIR holds ``nominal.npz`` and the scenario (``benchmarks/real_models.py`` writes them under
``~/.cache/critmoment-real-models/runs/CASE``). The samples are validate's (``sweep_samples``
of the scenario's box, ``--samples``, ``--seed``); the first parameter (mass) is scaled by
``1 + eps``. A sample whose failed/succeeded outcome flips under a perturbation far below any
physical uncertainty has no determined outcome on that model: the simulation is chaotic there,
and a prediction from its parameters can match the ground truth only by chance.
"""

import argparse
import warnings
from pathlib import Path

import numpy as np

import critmoment as cm
from critmoment import groundtruth
from critmoment import sparse as sp


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run_dir")
    parser.add_argument("--scenario", default="scenario.toml")
    parser.add_argument("--samples", type=int, default=64)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--eps", default="1e-9,1e-6")
    args = parser.parse_args(argv)
    warnings.simplefilter("ignore")
    run = Path(args.run_dir).expanduser()
    sc = cm.load_scenario(str(run / args.scenario))
    twin = cm.Twin(sc)
    traj = cm.load_trajectory(str(run / "nominal.npz"))
    samples = sp.sweep_samples(sc.box, n=args.samples, seed=args.seed)
    base = groundtruth.brute_force(traj, twin=twin, samples=samples).classification
    print(f"{run.name} ({args.scenario}): {args.samples} samples, real outcomes {base.counts()}")
    for eps in (float(e) for e in args.eps.split(",")):
        scale = np.ones(samples.shape[1])
        scale[0] = 1.0 + eps
        other = groundtruth.brute_force(traj, twin=twin, samples=samples * scale).classification
        flips = [i for i in range(len(samples)) if base.failed[i] != other.failed[i]]
        same = sum(a is b for a, b in zip(base.outcome, other.outcome, strict=True))
        print(f"{sc.box.names[0]} x (1 + {eps:g}): {len(flips)} samples flip failed/succeeded "
              f"{[(i, base.outcome[i].value, other.outcome[i].value) for i in flips]}; "
              f"{same}/{len(samples)} keep their outcome")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
