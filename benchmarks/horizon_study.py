"""Horizon study: sparse verdicts against brute-force full rollouts over the trajectory suite.

For every family of :mod:`critmoment.suite` (trajectory seed 0) the same Sobol samples of the
uncertainty box are rolled out in full once (the brute force, shared by every configuration),
and the audit's sparse prediction is made for each configuration: horizons 1, 5, 10, 25 (STEP)
and one solve (SOLVE, horizon 1), each with the audit's 4 moments, with the envelope check
(sparse evaluations every ``--envelope`` seconds of the phase where the nominal run carries
the object), with ``--moments`` moments, and with those moments plus the verification of
near-threshold safes by their own full rollout (``--verify``), and with the samples that fail
only where the object is squeezed off its support without a lift re-run in full too ("+
unlifted", the audit's default). Prints markdown tables: per
configuration over the suite, per family at ``--default``, and every missed failure;
``--json`` writes every number.

Reproduce (about 3 min on 2 CPUs)::

    PYTHONPATH=. python benchmarks/horizon_study.py --json /tmp/horizon_study.json

``--mass-high 1.5`` samples a box whose mass range ends at 1.5 kg (where the outcome changes,
a harder test of the boundary than the whole box); ``--sample-seed`` changes the Sobol seed.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import sys
import time
import warnings

import numpy as np

from critmoment import sparse as sp
from critmoment import suite
from critmoment import validation as val
from critmoment.scenario import load_scenario
from critmoment.twin import Twin


@dataclasses.dataclass(frozen=True)
class Config:
    """One way of making the sparse prediction."""

    name: str
    horizon: int
    mode: sp.SparseMode = sp.SparseMode.STEP
    envelope: float | None = None
    max_moments: int = 4
    verify: float | None = None
    verify_unlifted: bool = False


def configs(horizons: list[int], envelope: float, moments: int,
            verify: float | None) -> list[Config]:
    """Per horizon (and one solve): the audit's 4 moments, with the envelope check, with
    ``moments`` moments, and with ``moments`` moments and the verification."""
    base = [Config(f"h={h}", h) for h in horizons]
    base.append(Config("one solve", 1, sp.SparseMode.SOLVE))
    out = []
    for c in base:
        out.append(c)
        out.append(dataclasses.replace(c, name=f"{c.name} + envelope", envelope=envelope))
        if moments:
            more = dataclasses.replace(c, name=f"{c.name}, {moments} moments",
                                       max_moments=moments)
            out.append(more)
            if verify:
                checked = dataclasses.replace(more, name=f"{more.name} + verify {verify:g}",
                                              verify=verify)
                out.append(checked)
                out.append(dataclasses.replace(checked, name=f"{checked.name} + unlifted",
                                               verify_unlifted=True))
    return out


@dataclasses.dataclass(frozen=True)
class StudyOptions:
    """What the study runs.

    Attributes:
        families: trajectory families of :mod:`critmoment.suite`.
        n_samples: Sobol samples of the box.
        seed: trajectory seed of every family.
        sample_seed: Sobol seed.
        horizons: sparse horizons [physics steps].
        envelope: spacing of the envelope check [s].
        moments: moments of the many-moment configurations (0: none).
        verify: verification margin of the many-moment configurations (0: none).
        mass_high: upper end of the sampled mass range [kg] (None: the box's).
        criteria: the outcome tolerances.
        only: configuration names to run (None: all).
    """

    families: tuple[str, ...]
    n_samples: int = 64
    seed: int = 0
    sample_seed: int = 0
    horizons: tuple[int, ...] = (1, 5, 10, 25)
    envelope: float = 0.1
    moments: int = 8
    verify: float = 0.8
    mass_high: float | None = None
    criteria: val.OutcomeCriteria = val.OutcomeCriteria()
    only: tuple[str, ...] | None = None


def run(opt: StudyOptions, say) -> dict:
    """Brute force once per family, then every configuration's prediction and comparison."""
    twin = Twin(load_scenario())
    box = twin.scenario.box
    if opt.mass_high is not None:
        box = box.with_range("mass", box.parameters[box.index("mass")].low, opt.mass_high)
    samples = sp.sweep_samples(box, n=opt.n_samples, seed=opt.sample_seed)
    cfgs = [c for c in configs(list(opt.horizons), opt.envelope, opt.moments, opt.verify)
            if not opt.only or c.name in opt.only]
    results: dict[str, dict[str, val.ValidationResult]] = {c.name: {} for c in cfgs}
    for fam in opt.families:
        traj = suite.make(fam, seed=opt.seed, twin=twin)
        brute = val.brute_force(traj, twin=twin, samples=samples, criteria=opt.criteria)
        say(f"{fam}: brute force {brute.seconds:.1f} s, outcomes "
            f"{ {k: v for k, v in brute.classification.counts().items() if v} }")
        for c in cfgs:
            pred = val.predict(traj, twin=twin, samples=samples, horizon=c.horizon, mode=c.mode,
                               max_moments=c.max_moments, envelope=c.envelope,
                               verify=c.verify, verify_unlifted=c.verify_unlifted)
            results[c.name][fam] = val.compare(brute, pred, trajectory=traj.source,
                                               seed=opt.sample_seed)
    return {"configs": cfgs, "results": results, "samples": samples}


def _pooled(per_family: dict[str, val.ValidationResult]) -> dict:
    conf = {k: sum(r.confusion[k] for r in per_family.values())
            for k in ("true_safe", "false_safe", "true_unsafe", "false_unsafe")}
    failures = conf["false_safe"] + conf["true_unsafe"]
    n = sum(conf.values())
    sparse_s = sum(r.sparse_seconds for r in per_family.values())
    brute_s = sum(r.brute_force_seconds for r in per_family.values())
    rate = conf["false_safe"] / failures if failures else None
    return {"confusion": conf, "false_safe_rate": rate,
            "agreement": (conf["true_safe"] + conf["true_unsafe"]) / n, "samples": n,
            "sparse_seconds": sparse_s, "brute_force_seconds": brute_s,
            "compute_ratio": sparse_s / brute_s,
            "families_with_false_safe": [f for f, r in per_family.items()
                                         if r.confusion["false_safe"]]}


def _fmt_rate(x):
    return "n/a" if x is None else f"{x:.3f}"


def horizon_table(study: dict) -> str:
    lines = ["| configuration | true safe | false safe | true unsafe | false unsafe | "
             "false-safe rate | agreement | sparse [s] | brute force [s] | ratio |",
             "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|"]
    for c in study["configs"]:
        p = _pooled(study["results"][c.name])
        k = p["confusion"]
        lines.append(f"| {c.name} | {k['true_safe']} | {k['false_safe']} | {k['true_unsafe']} | "
                     f"{k['false_unsafe']} | {_fmt_rate(p['false_safe_rate'])} | "
                     f"{p['agreement']:.3f} | {p['sparse_seconds']:.2f} | "
                     f"{p['brute_force_seconds']:.1f} | {p['compute_ratio']:.3f} |")
    return "\n".join(lines)


def family_table(study: dict, name: str) -> str:
    lines = [f"Configuration: {name}", "",
             "| family | samples | outcomes | TS | FS | TU | FU | false-safe rate | agreement | "
             "sparse [s] | brute force [s] | ratio |",
             "|---|--:|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|"]
    for fam, r in study["results"][name].items():
        k = r.confusion
        outcomes = ", ".join(f"{o} {v}" for o, v in r.outcome_counts().items() if v)
        lines.append(f"| {fam} | {r.n_samples} | {outcomes} | {k['true_safe']} | "
                     f"{k['false_safe']} | {k['true_unsafe']} | {k['false_unsafe']} | "
                     f"{_fmt_rate(r.false_safe_rate)} | {r.agreement:.3f} | "
                     f"{r.sparse_seconds:.2f} | {r.brute_force_seconds:.1f} | "
                     f"{r.compute_ratio:.3f} |")
    return "\n".join(lines)


def missed_table(study: dict, names: list[str]) -> str:
    lines = ["| configuration | family | sample (mass, friction) | outcome | max cost | "
             "first failure [s] | nearest moment [s] | offset [s] |",
             "|---|---|---|---|--:|--:|--:|--:|"]
    for name in names:
        for fam, r in study["results"][name].items():
            for m in r.missed:
                vals = ", ".join(f"{v:.3g}" for v in m.values.values())
                ff = "-" if m.first_failure_step < 0 else f"{m.first_failure_time:.2f}"
                nm = "-" if m.nearest_moment < 0 else f"{m.nearest_moment * r.dt:.2f}"
                off = "-" if m.first_failure_step < 0 else f"{m.offset:+.2f}"
                lines.append(f"| {name} | {fam} | ({vals}) | {m.outcome.value} | "
                             f"{m.max_cost:.3f} | {ff} | {nm} | {off} |")
    return "\n".join(lines)


def to_json(study: dict) -> dict:
    return {
        "samples": study["samples"].tolist(),
        "configs": [dataclasses.asdict(c) | {"mode": c.mode.value} for c in study["configs"]],
        "pooled": {c.name: _pooled(study["results"][c.name]) for c in study["configs"]},
        "results": {name: {fam: r.to_json() for fam, r in per.items()}
                    for name, per in study["results"].items()},
    }


def critical_masses(frictions: list[float], *, family: str = "nominal", seed: int = 0,
                    mass_max: float = 2.0, step: float = 0.025,
                    configs_: tuple[Config, ...] = (
                        Config("h=1", 1), Config("h=10", 10),
                        Config("h=10, 8 moments + verify 0.8", 10, max_moments=8,
                               verify=0.8))) -> str:
    """Critical mass along the mass axis at fixed frictions: brute force against sparse.

    For each friction, a grid of masses is rolled out in full; the brute-force critical mass
    is the lightest failing mass (and the heaviest success is given too: the boundary need not
    be sharp). The sparse critical mass of a configuration is the lightest mass it predicts to
    fail. Returns a markdown table.
    """
    twin = Twin(load_scenario())
    traj = suite.make(family, seed=seed, twin=twin)
    masses = np.arange(0.05, mass_max + 1e-9, step)
    lines = ["| friction | brute force: lightest failure [kg] | heaviest success [kg] | "
             "outcome at the lightest failure | "
             + " | ".join(f"sparse {c.name} [kg]" for c in configs_) + " |",
             "|--:|--:|--:|---|" + "--:|" * len(configs_)]
    for mu in frictions:
        samples = np.column_stack([masses, np.full_like(masses, mu)])
        brute = val.brute_force(traj, twin=twin, samples=samples)
        failed = brute.failed
        first = int(np.argmax(failed)) if failed.any() else None
        ok = np.flatnonzero(~failed)
        cells = []
        for c in configs_:
            pred = val.predict(traj, twin=twin, samples=samples, horizon=c.horizon,
                               mode=c.mode, max_moments=c.max_moments, verify=c.verify)
            cells.append(f"{masses[np.argmax(pred.failed)]:.3f}" if pred.failed.any() else "-")
        lines.append(
            f"| {mu:g} | {masses[first]:.3f} | {masses[ok[-1]]:.3f} | "
            f"{brute.outcome[first].value} | " + " | ".join(cells) + " |"
            if first is not None else f"| {mu:g} | - | - | - | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--samples", type=int, default=64)
    parser.add_argument("--seed", type=int, default=0, help="trajectory seed of every family")
    parser.add_argument("--sample-seed", type=int, default=0, help="Sobol seed of the samples")
    parser.add_argument("--only", nargs="*", default=None,
                        help="run only these configurations (names as in the table)")
    parser.add_argument("--families", nargs="*", default=list(suite.FAMILIES))
    parser.add_argument("--horizons", type=int, nargs="*", default=[1, 5, 10, 25],
                        help="sparse horizons [physics steps] (default 1 5 10 25)")
    parser.add_argument("--envelope", type=float, default=0.1,
                        help="spacing of the envelope check [s] (default 0.1)")
    parser.add_argument("--moments", type=int, default=8,
                        help="also audit this many moments (0: skip)")
    parser.add_argument("--verify", type=float, default=0.8,
                        help="verification margin of the many-moment configurations "
                             "(0: skip)")
    parser.add_argument("--default", default="h=10, 8 moments + verify 0.8 + unlifted",
                        help="configuration of the per-family table")
    parser.add_argument("--mass-high", type=float, default=None,
                        help="sample mass only up to this value [kg]")
    parser.add_argument("--slip-tolerance", type=float, default=0.01, help="[m]")
    parser.add_argument("--slip-not-failure", action="store_true",
                        help="a run that slips but completes the task is a success")
    parser.add_argument("--json", default=None, help="write every number to this file")
    parser.add_argument("--critical-mass", type=float, nargs="*", default=None,
                        metavar="FRICTION",
                        help="instead: critical masses of the nominal family at these "
                             "frictions, brute force against sparse")
    args = parser.parse_args(argv)
    warnings.simplefilter("ignore")

    def say(msg):
        print(msg, file=sys.stderr, flush=True)

    if args.critical_mass:
        print(critical_masses(args.critical_mass, seed=args.seed))
        return 0

    opt = StudyOptions(
        families=tuple(args.families), n_samples=args.samples, seed=args.seed,
        sample_seed=args.sample_seed, horizons=tuple(args.horizons), envelope=args.envelope,
        moments=args.moments, verify=args.verify, mass_high=args.mass_high,
        criteria=val.OutcomeCriteria(slip_tolerance=args.slip_tolerance,
                                     slip_is_failure=not args.slip_not_failure),
        only=tuple(args.only) if args.only else None)
    t0 = time.perf_counter()
    study = run(opt, say)
    print(f"## Horizon study ({len(args.families)} families x {args.samples} samples, "
          f"trajectory seed {args.seed}, Sobol seed {args.sample_seed}"
          + (f", mass <= {args.mass_high} kg" if args.mass_high else "") + ")\n")
    print(horizon_table(study))
    print()
    if args.default in study["results"]:
        print(family_table(study, args.default))
    print()
    print("## Missed failures (false safes)\n")
    print(missed_table(study, [c.name for c in study["configs"]]))
    say(f"study done in {time.perf_counter() - t0:.0f} s")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(to_json(study), fh, indent=1, default=float)
    return 0


if __name__ == "__main__":
    sys.exit(main())
