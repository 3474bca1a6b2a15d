"""Command-line interface: ``critmoment demo|rollout|moments|analyze|validate``.

Exit codes: 0 success (for ``analyze``: SAFE, or P(success) ≥ ``--min-success``),
1 not safe, 2 bad input or error. Errors are printed as one line, never a traceback.
"""

from __future__ import annotations

import argparse
import json
import logging
import sys
import warnings
from pathlib import Path

import numpy as np

from critmoment.exceptions import CritmomentError

__all__ = ["main", "build_parser"]

EXIT_OK, EXIT_UNSAFE, EXIT_ERROR = 0, 1, 2


def _json_default(obj):
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, Path):
        return str(obj)
    raise TypeError(f"not JSON serialisable: {type(obj).__name__}")


def _dump(obj) -> str:
    return json.dumps(obj, indent=2, default=_json_default, allow_nan=False)


def _load(args):
    from critmoment.scenario import load_scenario
    from critmoment.trajectory import load_trajectory
    from critmoment.twin import Twin

    scenario = load_scenario(args.scenario)
    traj = load_trajectory(args.trajectory)
    return Twin(scenario), traj


def _out_dir(path: str | None) -> Path | None:
    if path is None:
        return None
    out = Path(path)
    out.mkdir(parents=True, exist_ok=True)
    return out


def cmd_demo(args) -> int:
    from critmoment import suite
    from critmoment.trajectory import save_trajectory

    traj = suite.make(args.family, seed=args.seed)
    out = Path(args.out)
    if out.suffix != ".npz":
        raise CritmomentError(f"--out: expected a path ending in .npz, got {out}")
    out.parent.mkdir(parents=True, exist_ok=True)
    save_trajectory(traj, out)
    box = traj.object_pose
    print(f"wrote {out}: {traj.n_steps} actions at {traj.fps:g} Hz ({traj.duration:g} s), "
          f"family {args.family!r}, seed {args.seed}, cube at x={box[0]:.3f} y={box[1]:.3f} m")
    return EXIT_OK


def cmd_rollout(args) -> int:
    from critmoment import report
    from critmoment.recording import rollout

    twin, traj = _load(args)
    rec = rollout(traj, twin=twin)
    summary = rec.summary()
    out = _out_dir(args.out)
    if out is not None:
        rec.save(out / "recording.npz")
        report.plot_recording(rec, path=out / "signals.png")
        (out / "rollout.json").write_text(_dump(summary))
    if args.json:
        print(_dump(summary))
    else:
        firsts = ", ".join(f"{k}: {v if v is not None else '-'}"
                           for k, v in summary["stage_first_step"].items())
        print(f"{summary['steps']} steps of {summary['dt'] * 1e3:g} ms; max stage "
              f"{summary['max_stage']}, final stage {summary['final_stage']} "
              f"({'completed' if summary['completed'] else 'NOT completed'}); first step per "
              f"stage {{{firsts}}}")
        print(f"min FOS contact {summary['min_fos_contact']}, min FOS motor "
              f"{summary['min_fos_motor']:.3f} ({summary['limiting_actuator']}), max cost "
              f"{summary['max_cost']:.3f}")
        if out is not None:
            print(f"wrote {out / 'recording.npz'}, {out / 'signals.png'}, {out / 'rollout.json'}")
    return EXIT_OK


def cmd_moments(args) -> int:
    from critmoment import report
    from critmoment.analysis import detect_moments
    from critmoment.recording import rollout

    twin, traj = _load(args)
    rec = rollout(traj, twin=twin)
    moments = detect_moments(rec, twin, max_moments=args.max_moments)
    payload = {"moments": [report.moment_json(m) for m in moments]}
    out = _out_dir(args.out)
    if out is not None:
        report.plot_recording(rec, moments=moments, path=out / "moments.png")
        (out / "moments.json").write_text(_dump(payload))
    if args.json:
        print(_dump(payload))
    else:
        for rank, m in enumerate(moments, 1):
            print(f"{rank}. step {m.step} (t = {m.time:.3f} s) {m.label.value}: score "
                  f"{m.score:.3f} — {m.reason}")
    return EXIT_OK


def _method(args) -> dict:
    """The sparse method's options shared by ``analyze`` and ``validate``."""
    from critmoment.analysis import AnalyzeOptions

    default = AnalyzeOptions()
    return {"horizon": args.horizon,
            "max_moments": default.max_moments if args.max_moments is None else args.max_moments,
            "verify": None if args.no_verify else (
                default.verify if args.verify is None else args.verify)}


def _add_method(p) -> None:
    from critmoment.analysis import AnalyzeOptions

    default = AnalyzeOptions()
    p.add_argument("--horizon", type=int, default=None,
                   help="physics steps per sparse evaluation (default: the scenario's)")
    p.add_argument("--max-moments", type=int, default=None,
                   help=f"critical moments audited (default {default.max_moments})")
    p.add_argument("--verify", type=float, default=None, metavar="FRACTION",
                   help="re-run in full the samples that pass with a cost >= FRACTION x "
                        f"threshold (default {default.verify})")
    p.add_argument("--no-verify", action="store_true", help="skip the verification rollouts")


def cmd_analyze(args) -> int:
    from critmoment import report
    from critmoment.analysis import AnalyzeOptions, analyze

    twin, traj = _load(args)
    options = AnalyzeOptions(seed=args.seed, n_samples=args.samples, min_success=args.min_success,
                             exhaustive=args.exhaustive, **_method(args))
    result = analyze(traj, twin.scenario, twin=twin, options=options,
                     progress=not args.json and sys.stderr.isatty())
    out = _out_dir(args.out)
    if out is not None:
        report.write_report(result, out)
    if args.json:
        print(_dump(result.to_json()))
    else:
        print(report.summary_text(result))
        if out is not None:
            print(f"report: {out / 'report.html'} and {out / 'report.json'}")
    return EXIT_OK if result.passes(args.min_success) else EXIT_UNSAFE


def cmd_validate(args) -> int:
    from critmoment.validation import validate

    twin, traj = _load(args)
    result = validate(traj, twin=twin, n_samples=args.samples, seed=args.seed, **_method(args))
    out = _out_dir(args.out)
    payload = result.to_json()
    if out is not None:
        (out / "validation.json").write_text(_dump(payload))
    if args.json:
        print(_dump(payload))
    else:
        print(result.summary_text())
    return EXIT_OK if result.confusion["false_safe"] == 0 else EXIT_UNSAFE


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="critmoment",
        description="Audit a robot trajectory for physical safety in a MuJoCo digital twin.")
    parser.add_argument("-v", "--verbose", action="store_true", help="log progress details")
    sub = parser.add_subparsers(dest="command", required=True)

    def add_traj(p):
        p.add_argument("trajectory", help="trajectory: .npz, ACT .hdf5, LeRobot .parquet or dataset folder")
        p.add_argument("--scenario", default=None,
                       help="scenario.toml, a folder with one, or a bundled name "
                            "(default: aloha_transfer_cube)")
        p.add_argument("--out", default=None, help="folder for outputs")
        p.add_argument("--json", action="store_true", help="print JSON to stdout")

    from critmoment.suite import FAMILIES

    p = sub.add_parser("demo", help="write a scripted pick-and-transfer trajectory")
    p.add_argument("--seed", type=int, default=0, help="seeds the cube's spawn pose")
    p.add_argument("--out", default="traj.npz", help="output .npz (default traj.npz)")
    p.add_argument("--family", default="nominal", choices=sorted(FAMILIES),
                   help="trajectory family (default nominal)")
    p.set_defaults(func=cmd_demo)

    p = sub.add_parser("rollout", help="frequent rollout: replay at nominal parameters, record signals")
    add_traj(p)
    p.set_defaults(func=cmd_rollout)

    p = sub.add_parser("moments", help="find the critical moments of a trajectory")
    add_traj(p)
    p.add_argument("--max-moments", type=int, default=8)
    p.set_defaults(func=cmd_moments)

    p = sub.add_parser("analyze", help="full audit: verdict, P(success), report")
    add_traj(p)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--samples", type=int, default=256, help="Sobol samples of the box")
    p.add_argument("--min-success", type=float, default=None,
                   help="exit 0 when P(success) >= this even if not SAFE")
    _add_method(p)
    p.add_argument("--exhaustive", action="store_true",
                   help="evaluate every sample at every moment (default: each sample stops at "
                        "its first failure; same verdict, per-moment figures over the samples "
                        "that reach the moment)")
    p.set_defaults(func=cmd_analyze)

    p = sub.add_parser("validate", help="check sparse verdicts against brute-force full rollouts")
    add_traj(p)
    p.add_argument("--samples", type=int, default=64, help="Sobol samples of the box")
    p.add_argument("--seed", type=int, default=0, help="Sobol seed")
    _add_method(p)
    p.set_defaults(func=cmd_validate)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO if args.verbose else logging.WARNING,
                        format="%(levelname)s %(name)s: %(message)s")
    if not args.verbose:
        warnings.simplefilter("default")
    try:
        return args.func(args)
    except CritmomentError as exc:
        print(f"critmoment {args.command}: error: {exc}", file=sys.stderr)
        return EXIT_ERROR
    except KeyboardInterrupt:
        return EXIT_ERROR
    except BrokenPipeError:  # e.g. `critmoment ... --json | head`
        sys.stderr.close()
        return EXIT_OK


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
