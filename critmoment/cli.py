"""Command-line interface: ``critmoment demo|rollout|moments|analyze|validate|episodes``.

Exit codes (docs/cli.md): 0 success (for ``analyze``: SAFE, or CONDITIONAL with
P(success) ≥ ``--min-success``; for ``validate``: no false safe), 1 not safe, 2 bad input or
error. A closed output pipe (``critmoment analyze ... --json | head -1``) keeps
the verdict's code. Every error ends as one line on stderr,
``critmoment COMMAND: error: ...``, never a traceback (``-v`` adds one), and
outputs are written whole or not at all (:class:`critmoment.report.StagedOutput`).
"""

from __future__ import annotations

import argparse
import contextlib
import dataclasses
import json
import logging
import math
import os
import re
import sys
import traceback
import warnings
import zipfile
import zlib
from collections.abc import Iterator
from pathlib import Path

# only light modules here: NumPy, MuJoCo and the rest load inside main(), where an
# interruption is handled
from critmoment import budget
from critmoment._signals import signals_held, stop_signals
from critmoment.exceptions import CritmomentError, CritmomentWarning

__all__ = ["main", "build_parser", "EXIT_OK", "EXIT_UNSAFE", "EXIT_ERROR"]

EXIT_OK, EXIT_UNSAFE, EXIT_ERROR = 0, 1, 2


# -- output ------------------------------------------------------------------------
class _Stdout:
    """Prints to stdout; once the reader has gone (a closed pipe), prints nothing."""

    closed = False

    @classmethod
    def emit(cls, text: str) -> None:
        if cls.closed:
            return
        try:
            print(text, flush=True)  # flush here, so a closed pipe is seen here
        except BrokenPipeError:
            cls.silence()
        except OSError as exc:  # a full disk or a file-size limit behind a redirection
            from critmoment.exceptions import OutputError

            cls.silence()
            raise OutputError(f"writing to the standard output failed: "
                              f"{exc.strerror or exc}") from None

    @classmethod
    def silence(cls) -> None:
        cls.closed = True
        # Point the file descriptor at /dev/null so that Python's flush at exit
        # does not report the broken pipe a second time.
        with contextlib.suppress(OSError, ValueError, AttributeError):
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            os.close(devnull)


def _dump(obj) -> str:
    """JSON text of ``obj``; NaN and infinities (a motor FOS without a force limit) as null."""
    from critmoment.report import jsonable

    return json.dumps(jsonable(obj), indent=2, allow_nan=False)


@contextlib.contextmanager
def _staged(args, command: str, *, kind: str = "folder") -> Iterator[Path | None]:
    """The folder to write ``--out`` into: validated and staged before any work."""
    if getattr(args, "out", None) is None:
        yield None
        return
    from critmoment.report import StagedOutput

    with StagedOutput(args.out, command=command, kind=kind) as stage:
        yield stage.path
    args.out_written = stage.destination


# -- inputs ------------------------------------------------------------------------
def _scenario_for(given, traj):
    """The scenario to load: ``--scenario``, else the bundled one the trajectory names in its
    ``meta`` (``critmoment demo`` writes it), else the default bundled scenario."""
    from critmoment.scenario import BUNDLED_SCENARIOS

    if given is not None:
        return given
    named = traj.meta.get("scenario") if isinstance(traj.meta, dict) else None
    if named is not None and named not in BUNDLED_SCENARIOS:
        warnings.warn(f"the trajectory's meta names scenario {str(named)[:80]!r}, which is not "
                      f"a bundled one ({', '.join(BUNDLED_SCENARIOS)}); using the default "
                      f"{BUNDLED_SCENARIOS[0]!r}: pass --scenario to audit it on its own twin",
                      CritmomentWarning, stacklevel=2)
    return named if named in BUNDLED_SCENARIOS else None


def _load(args):
    from critmoment.recording import at_scenario_rate
    from critmoment.scenario import load_scenario
    from critmoment.trajectory import load_trajectory
    from critmoment.twin import Twin

    traj = load_trajectory(args.trajectory, episode=args.episode, object_pose=args.object_pose,
                           fps=getattr(args, "fps", None))
    scenario = load_scenario(_scenario_for(args.scenario, traj))
    twin = Twin(scenario)
    traj = at_scenario_rate(traj, twin)  # the action rate where the file records none
    budget.check_rollout(traj, twin)
    return twin, traj


# -- commands ----------------------------------------------------------------------
def cmd_demo(args) -> int:
    from critmoment import suite
    from critmoment.trajectory import save_trajectory

    if Path(args.out).suffix.lower() != ".npz":
        raise CritmomentError(f"--out: expected a path ending in .npz, got {args.out}")
    if not args.force and Path(args.out).is_file() and not _demo_written(Path(args.out)):
        raise CritmomentError(
            f"--out: {args.out} exists and is not a trajectory critmoment demo wrote; "
            f"expected a new path, or --force to replace it")
    with _staged(args, "demo", kind="file") as path:
        traj = suite.make(args.family, seed=args.seed, scenario=args.scenario)
        save_trajectory(traj, path)
    box = traj.object_pose
    _Stdout.emit(f"wrote {args.out}: {traj.n_steps} actions at {traj.fps:g} Hz "
                 f"({traj.duration:g} s), {args.scenario} family {args.family!r}, seed {args.seed}, "
                 f"object at "
                 f"x={box[0]:.3f} y={box[1]:.3f} m")
    return EXIT_OK


def _demo_written(path: Path) -> bool:
    """Whether the .npz at ``path`` is one ``critmoment demo`` wrote (its meta names a
    critmoment generator): that one may be replaced, a user's recorded episode may not."""
    import numpy as np

    try:
        with np.load(path, allow_pickle=False) as data:
            if "meta" not in data.files:
                return False
            meta = json.loads(str(data["meta"]))
    except (OSError, ValueError, zipfile.BadZipFile, EOFError):
        return False
    return isinstance(meta, dict) and str(meta.get("generator", "")).startswith("critmoment.")


def cmd_rollout(args) -> int:
    from critmoment import report
    from critmoment.feasibility import FitWarning, check_feasibility, check_fit
    from critmoment.recording import rollout

    with _staged(args, "rollout") as out:
        twin, traj = _load(args)
        check_fit(traj, None, twin)  # width and units, naming the likely mistake
        rec = rollout(traj, twin=twin)
        # the run's own fit (an object never touched, a gripper that never closes, a
        # start inside the table): the likely reason a run does not complete its task
        fit = check_fit(traj, rec, twin)
        # what analyze would refuse the run for (a joint that cannot follow, a force that
        # oscillates), said here as warnings: the run itself is what was asked for
        from critmoment.recording import observed_controls

        feasibility = check_feasibility(rec, twin, raise_on_failure=False,
                                        observed=observed_controls(twin, traj))
        infeasible = feasibility.problems
        # a run that completes its task can still fail the ground truth's other rules (a
        # joint held at its force limit for seconds by a bin's wall had read "(completed)"
        # without a word, while analyze said the nominal fails)
        from critmoment.analysis import nominal_run_failure
        from critmoment.groundtruth import reference_from_recording

        own = nominal_run_failure(reference_from_recording(rec, twin), twin, rec.dt)
        failing = (f"the run fails by the ground truth's rules: {own}",) if own else ()
        for msg in (*fit, *infeasible, *feasibility.warnings, *failing):
            warnings.warn(msg, FitWarning, stacklevel=1)
        # the contact model's check, as analyze and validate run it (it warns of a soft
        # model, and of a nominal grip whose own object shifts over 1 cm: a Jaco hand moved
        # its cube 3 cm, which rollout alone had called "completed" without a word)
        from critmoment.contactmodel import check_contact_model

        contact = check_contact_model(twin, rec)
        summary = {**rec.summary(), **rec.sustained(twin.scenario), "fit_warnings": list(fit),
                   "feasibility_problems": list(infeasible),
                   "feasibility_warnings": list(feasibility.warnings),
                   "ground_truth_failure": own, "contact_model": contact.summary()}
        if out is not None:
            rec.save(out / "recording.npz")
            fig = report.plot_recording(rec)
            fig.savefig(out / "signals.png", dpi=report.DPI)
            (out / "rollout.json").write_text(_dump(summary))
    if args.json:
        _Stdout.emit(_dump(summary))
        return EXIT_OK
    firsts = ", ".join(f"{k}: {v if v is not None else '-'}"
                       for k, v in summary["stage_first_step"].items())
    names = twin.task.stage_names

    def stage(n: int) -> str:
        return f"{n} ({names[n]})" if 0 <= n < len(names) else str(n)

    _Stdout.emit(f"{summary['steps']} steps of {summary['dt'] * 1e3:g} ms; max stage "
                 f"{stage(summary['max_stage'])}, final stage {stage(summary['final_stage'])} "
                 f"({'completed' if summary['completed'] else 'NOT completed'}); first step "
                 f"per stage {{{firsts}}}")
    if summary["shortfalls"]:
        _Stdout.emit(f"short of the task: {'; '.join(summary['shortfalls'])}")
    from critmoment.safety import format_fos

    limiting = summary["limiting_actuator"]
    _Stdout.emit(f"min FOS contact {format_fos(summary['min_fos_contact'], '.3f')}, min FOS "
                 f"motor {format_fos(summary['min_fos_motor'], '.3f')}"
                 f"{f' ({limiting})' if limiting else ' (no force limit)'}, max cost "
                 f"{summary['max_cost']:.3f}")
    ms = summary["persistence"] * 1e3
    _Stdout.emit(f"held for {ms:g} ms ([sparse] persistence, as the audit counts a contact "
                 f"excursion): min FOS contact "
                 f"{format_fos(summary['min_fos_contact_sustained'], '.3f')}, max cost "
                 f"{summary['max_cost_sustained']:.3f} (threshold {summary['threshold']:g})")
    if args.out is not None:
        out = args.out_written
        _Stdout.emit(f"wrote {out / 'recording.npz'}, {out / 'signals.png'}, "
                     f"{out / 'rollout.json'}")
    return EXIT_OK


def cmd_moments(args) -> int:
    from critmoment import report
    from critmoment.analysis import detect_moments
    from critmoment.recording import rollout

    with _staged(args, "moments") as out:
        twin, traj = _load(args)
        rec = rollout(traj, twin=twin)
        moments = detect_moments(rec, twin, max_moments=args.max_moments)
        payload = {"moments": [report.moment_json(m) for m in moments]}
        if out is not None:
            report.plot_recording(rec, moments=moments).savefig(out / "moments.png",
                                                                dpi=report.DPI)
            (out / "moments.json").write_text(_dump(payload))
    if args.json:
        _Stdout.emit(_dump(payload))
    else:
        for rank, m in enumerate(moments, 1):
            _Stdout.emit(f"{rank}. step {m.step} (t = {m.time:.3f} s) {m.label.value}: score "
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


def cmd_analyze(args) -> int:
    from critmoment import report
    from critmoment.analysis import AnalyzeOptions, analyze

    options = AnalyzeOptions(seed=args.seed, n_samples=args.samples, min_success=args.min_success,
                             exhaustive=args.exhaustive, **_method(args))
    with _staged(args, "analyze") as out:
        twin, traj = _load(args)
        budget.check_audit(traj, twin, options)
        result = analyze(traj, twin.scenario, twin=twin, options=options,
                         progress=args.verbose or (not args.json and sys.stderr.isatty()))
        # the run's warnings so far (reading the inputs, the audit) go on the record too
        result = _with_caught(result, args)
        if out is not None:
            report.write_report_files(result, out, figures=report.Figures.parse(args.figures),
                                      record_warnings=True)
            # the figures' warnings, which it recorded and issued again, in the printed
            # document too
            result = _with_caught(result, args)
    code = EXIT_OK if result.passes(args.min_success) else EXIT_UNSAFE
    if args.json:
        _Stdout.emit(_dump(result.to_json()))
    else:
        _Stdout.emit(report.summary_text(result))
        if args.out is not None:
            _Stdout.emit(f"report: {args.out_written / 'report.html'} and "
                         f"{args.out_written / 'report.json'}")
    return code


def _with_caught(result, args):
    """``result`` with the command's warnings caught so far as its ``warnings``."""
    return dataclasses.replace(result, warnings=tuple(dict.fromkeys(
        _one_line(str(w.message)) for w in getattr(args, "caught", ()))))


def cmd_validate(args) -> int:
    from critmoment.analysis import AnalyzeOptions
    from critmoment.validation import validate

    method = _method(args)
    with _staged(args, "validate") as out:
        twin, traj = _load(args)
        budget.check_audit(traj, twin, AnalyzeOptions(seed=args.seed, n_samples=max(
            args.samples, 8), **method))
        budget.check_validation(traj, twin, n_samples=args.samples)
        result = validate(traj, twin=twin, n_samples=args.samples, seed=args.seed, **method)
        payload = result.to_json()
        if out is not None:
            (out / "validation.json").write_text(_dump(payload))
    # a vacuous validation (no real success or no real failure) proves nothing: exit 1
    code = EXIT_OK if result.confusion["false_safe"] == 0 and not result.vacuous else EXIT_UNSAFE
    if args.min_agreement is not None and not result.agreement >= args.min_agreement:
        code = EXIT_UNSAFE  # too many conservative errors for the caller's purpose
    _Stdout.emit(_dump(payload) if args.json else result.summary_text())
    return code


def cmd_inspect(args) -> int:
    from critmoment.modelinfo import inspect_model

    info = inspect_model(args.model)
    _Stdout.emit(_dump(info.to_json()) if args.json else info.text())
    return EXIT_OK


def cmd_init(args) -> int:
    from critmoment.modelinfo import init_scenario

    result = init_scenario(args.model, object_body=args.object, task=args.task,
                           supports=args.support or (), out=args.out, goal=args.goal,
                           goal_site=args.goal_site, picker=args.picker,
                           receiver=args.receiver, overwrite=args.force,
                           grippers=args.gripper or ())
    if args.out is None:
        _Stdout.emit(result.text)
    lines = [f"wrote {result.path} (it loads as written)" if result.path else
             "scenario printed above (it loads as written; --out FILE to write it)"]
    lines += [f"guessed: {g}" for g in result.guesses]
    lines += [f"check:   {c}" for c in result.checks]
    if args.out is None:
        print("\n".join(lines), file=sys.stderr)
    else:
        _Stdout.emit("\n".join(lines))
    return EXIT_OK


def cmd_episodes(args) -> int:
    from critmoment.trajectory import list_episodes

    episodes = list_episodes(args.dataset)
    if args.json:
        _Stdout.emit(_dump({"episodes": [{"index": e.index, "frames": e.frames, "file": e.file}
                                         for e in episodes]}))
        return EXIT_OK
    _Stdout.emit(f"{len(episodes)} episode(s) in {args.dataset}")
    for e in episodes:
        name = "-" if e.index is None else str(e.index)
        _Stdout.emit(f"  episode {name}: {e.frames} frames in {e.file}")
    return EXIT_OK


# -- argument types ----------------------------------------------------------------
def _integer(text: str) -> int:
    """An integer, also written as an integral float (``1e3``)."""
    try:
        value = int(text, 10)
    except ValueError:
        try:
            number = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected an integer, got {text!r}") from None
        if not math.isfinite(number) or number != int(number):
            raise argparse.ArgumentTypeError(f"expected an integer, got {text!r}") from None
        value = int(number)
    return value


def _int_at_least(low: int):
    def parse(text: str) -> int:
        value = _integer(text)
        if value < low:
            raise argparse.ArgumentTypeError(f"expected an integer >= {low}, got {value}")
        return value

    parse.__name__ = f"integer >= {low}"
    return parse


def _seed(text: str) -> int:
    value = _integer(text)
    if not 0 <= value <= budget.SEED_MAX:
        raise argparse.ArgumentTypeError(
            f"expected an integer in [0, 2**32 - 1 = {budget.SEED_MAX}], got {value}")
    return value


def _real(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"expected a finite number, got {text!r}")
    return value


def _positive_rate(text: str) -> float:
    value = _real(text)
    if not value > 0:
        raise argparse.ArgumentTypeError(f"expected a rate > 0 Hz, got {value:g}")
    return value


def _fraction(*, open_low: bool):
    def parse(text: str) -> float:
        value = _real(text)
        ok = (0 < value <= 1) if open_low else (0 <= value <= 1)
        if not ok:
            interval = "(0, 1]" if open_low else "[0, 1]"
            raise argparse.ArgumentTypeError(f"expected a number in {interval}, got {value:g}")
        return value

    return parse


class _Parser(argparse.ArgumentParser):
    """argparse with errors as one line, ``PROG: error: message (see PROG --help)``."""

    def error(self, message):  # noqa: D401 - argparse's interface
        text = " ".join(str(message).split())
        self.exit(EXIT_ERROR, f"{self.prog}: error: {text} (see {self.prog} --help)\n")


def build_parser() -> argparse.ArgumentParser:
    from critmoment.report import Figures
    from critmoment.suite import SCENARIO_FAMILIES

    parser = _Parser(
        prog="critmoment",
        description="Audit a robot trajectory for physical safety in a MuJoCo digital twin.")
    from critmoment import __version__

    parser.add_argument("--version", action="version", version=f"critmoment {__version__}")
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="log details and the audit's progress (also when stderr is not a "
                             "terminal); on an error, also print the traceback")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    limits = budget.Budget()

    def add_traj(p):
        p.add_argument("trajectory", help="trajectory: .npz, ACT .hdf5, LeRobot .parquet or "
                                          "dataset folder")
        p.add_argument("--scenario", default=None,
                       help="scenario.toml, a folder with one, or a bundled name "
                            "(default: aloha_transfer_cube)")
        p.add_argument("--episode", type=_int_at_least(0), default=None, metavar="N",
                       help="LeRobot data: the episode_index to read (list them with "
                            "`critmoment episodes DATASET`)")
        p.add_argument("--fps", type=_positive_rate, default=None, metavar="HZ",
                       help="the trajectory's action rate [Hz], for a file that records none "
                            "or under another name (one that records a different rate is an "
                            "error)")
        p.add_argument("--object-pose", type=_real, nargs=7, default=None,
                       metavar=("X", "Y", "Z", "QW", "QX", "QY", "QZ"),
                       help="the object's start pose, position [m] and unit quaternion; "
                            "replaces the trajectory's")
        p.add_argument("--out", default=None, help="folder for outputs (created, or replaced "
                                                   "whole if it holds an earlier output)")
        p.add_argument("--json", action="store_true", help="print JSON to stdout")
        p.add_argument("--max-steps", type=_int_at_least(1), default=None, metavar="N",
                       help=f"most physics steps of one rollout (default {limits.max_steps:,}"
                            f"; env CRITMOMENT_MAX_STEPS)")
        p.add_argument("--max-batch-steps", type=_int_at_least(1), default=None, metavar="N",
                       help=f"most physics steps of the batched simulations (default "
                            f"{limits.max_batch_steps:,}; env CRITMOMENT_MAX_BATCH_STEPS)")
        p.add_argument("--max-input-bytes", type=_int_at_least(1), default=None, metavar="N",
                       help=f"most bytes of arrays an input file may declare (default "
                            f"{limits.max_input_bytes:,}; env CRITMOMENT_MAX_INPUT_BYTES)")

    def add_method(p):
        from critmoment.analysis import AnalyzeOptions

        default = AnalyzeOptions()
        p.add_argument("--horizon", type=_int_at_least(1), default=None,
                       help="physics steps per sparse evaluation (default: the scenario's)")
        p.add_argument("--max-moments", type=_int_at_least(1), default=None,
                       help=f"critical moments audited (default {default.max_moments})")
        verify = p.add_mutually_exclusive_group()
        verify.add_argument("--verify", type=_fraction(open_low=True), default=None,
                            metavar="FRACTION",
                            help="re-run in full the samples that pass with a cost >= "
                                 f"FRACTION x threshold (default {default.verify})")
        verify.add_argument("--no-verify", action="store_true",
                            help="skip the verification rollouts")

    p = sub.add_parser("demo", help="write a scripted pick-and-transfer trajectory")
    p.add_argument("--seed", type=_seed, default=0, help="seeds the cube's spawn pose")
    p.add_argument("--out", default="traj.npz", help="output .npz (default traj.npz)")
    p.add_argument("--family", default="nominal",
                   choices=sorted({f for fams in SCENARIO_FAMILIES.values() for f in fams}),
                   help="trajectory family (default nominal; see critmoment.suite)")
    p.add_argument("--scenario", default="aloha_transfer_cube",
                   choices=sorted(SCENARIO_FAMILIES),
                   help="bundled scenario to write a trajectory for (default aloha_transfer_cube)")
    p.add_argument("--force", action="store_true",
                   help="replace an existing --out that critmoment demo did not write")
    p.set_defaults(func=cmd_demo)

    p = sub.add_parser("rollout", help="frequent rollout: replay at nominal parameters, "
                                       "record signals")
    add_traj(p)
    p.set_defaults(func=cmd_rollout)

    p = sub.add_parser("moments", help="find the critical moments of a trajectory")
    add_traj(p)
    p.add_argument("--max-moments", type=_int_at_least(1), default=8)
    p.set_defaults(func=cmd_moments)

    p = sub.add_parser("analyze", help="full audit: verdict, P(success), report")
    add_traj(p)
    p.add_argument("--seed", type=_seed, default=0)
    p.add_argument("--samples", type=_int_at_least(8), default=256,
                   help="Sobol samples of the box")
    p.add_argument("--min-success", type=_fraction(open_low=False), default=None,
                   help="exit 0 when CONDITIONAL with P(success) >= this (UNSAFE, the "
                        "nominal parameters failing, always exits 1)")
    add_method(p)
    p.add_argument("--exhaustive", action="store_true",
                   help="evaluate every sample at every moment (default: each sample stops at "
                        "its first failure; same verdict, per-moment figures over the samples "
                        "that reach the moment)")
    p.add_argument("--figures", choices=[f.value for f in Figures], default="summary",
                   help="figures in the report: none, summary (signals, every moment's curves "
                        "in one figure, cost map; default) or all (plus one figure per moment)")
    p.set_defaults(func=cmd_analyze)

    p = sub.add_parser("validate", help="check sparse verdicts against brute-force full "
                                        "rollouts")
    add_traj(p)
    p.add_argument("--samples", type=_int_at_least(1), default=64, help="Sobol samples of the box")
    p.add_argument("--seed", type=_seed, default=0, help="Sobol seed")
    p.add_argument("--min-agreement", type=_fraction(open_low=False), default=None,
                   help="also exit 1 when the agreement (false unsafes count against it) is "
                        "below this, e.g. 0.95")
    add_method(p)
    p.set_defaults(func=cmd_validate)

    p = sub.add_parser("inspect", help="list a model's free bodies, actuators, grippers and "
                                       "contact settings")
    p.add_argument("model", help="MJCF scene file")
    p.add_argument("--json", action="store_true", help="print JSON to stdout")
    p.set_defaults(func=cmd_inspect)

    from critmoment.task import TASK_KINDS

    p = sub.add_parser("init", help="write a scenario.toml for a model as it ships")
    p.add_argument("model", help="MJCF scene file")
    p.add_argument("--object", required=True, metavar="BODY", help="the free body to audit")
    p.add_argument("--task", required=True, choices=list(TASK_KINDS), help="task kind")
    p.add_argument("--support", action="extend", nargs="+", metavar="GEOM",
                   help="support geoms (--support table shelf, or repeated; default: what "
                        "the object rests on, and at a pick_place goal what lies under it)")
    p.add_argument("--goal", nargs=3, type=_real, metavar=("X", "Y", "Z"),
                   help="pick_place: goal position of the object [m]")
    p.add_argument("--goal-site", default=None, help="pick_place: a site marking the goal")
    p.add_argument("--picker", default=None, help="handover: gripper that lifts first")
    p.add_argument("--receiver", default=None, help="handover: gripper that takes over")
    p.add_argument("--gripper", action="append", metavar="BODY", default=None,
                   help="a gripper's body, instead of the ones found (a hand whose fingers "
                        "the search does not recognise); repeat for several")
    p.add_argument("--out", default=None, help="scenario.toml to write (default: print it)")
    p.add_argument("--force", action="store_true", help="replace an existing --out")
    p.set_defaults(func=cmd_init)

    p = sub.add_parser("episodes", help="list the episodes of a LeRobot dataset")
    p.add_argument("dataset", help="LeRobot dataset folder or parquet file (an npz/HDF5 file "
                                   "is one episode)")
    p.add_argument("--json", action="store_true", help="print JSON to stdout")
    p.set_defaults(func=cmd_episodes)
    parser.commands = dict(sub.choices)
    for command in parser.commands.values():  # `critmoment analyze traj.npz -v` too
        command.add_argument("-v", "--verbose", action="store_true", default=argparse.SUPPRESS,
                             help="as critmoment -v")
        # argparse takes only -1 and -0.5 for negative numbers: a pose printed with %g
        # (--object-pose ... 1 -3.4e-05 0 0) was "expected 7 arguments" for 7 numbers
        command._negative_number_matcher = _NEGATIVE_NUMBER
    return parser


_NEGATIVE_NUMBER = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|infinity|nan)$",
                              re.IGNORECASE)


# -- errors ------------------------------------------------------------------------
def _one_line(text: str) -> str:
    return " ".join(str(text).split())


def _describe(exc: BaseException) -> str:
    """An exception that escaped the readers, as one message naming what and where."""
    from critmoment.trajectory import _short

    if isinstance(exc, CritmomentError):
        return str(exc)
    if isinstance(exc, MemoryError):
        return ("out of memory; lower --samples / --max-moments / --horizon, or the "
                "limits --max-steps / --max-batch-steps / --max-input-bytes")
    if isinstance(exc, OSError):
        where = exc.filename if exc.filename is not None else ""
        what = exc.strerror or str(exc)
        return f"{_short(where)!r}: {what}" if where else what
    if isinstance(exc, UnicodeDecodeError):
        return f"expected UTF-8 text, got bytes that are not: {exc}"
    if isinstance(exc, (zipfile.BadZipFile, zlib.error)):
        return f"corrupt compressed data: {exc}"
    text = str(exc).lower()
    if "size memory" in text or "mj_stackalloc" in text or "mjwarn_cnstrfull" in text:
        # MuJoCo's own arena, sized by the MJCF: more threads or memory would not help
        return (f"the model's arena is too small for this run ({type(exc).__name__}: "
                f"{_one_line(str(exc))}): raise <size memory=\"...\"/> in the MJCF (the arena "
                f"is per simulation; a heavier sample's contacts need more of it)")
    if any(sign in text for sign in _EXHAUSTED):
        # a memory or thread limit (ulimit -v, a container's): not a bug in critmoment
        return (f"out of resources ({type(exc).__name__}: {_one_line(str(exc))}): too little "
                f"memory or too few threads for the run (a limit such as ulimit -v or a "
                f"container's?); lower --samples / --max-moments, or raise the limit")
    if "plugin" in text and "not found" in text:
        return (f"a solver plugin could not load ({_one_line(str(exc))}): a broken install "
                f"(reinstall casadi) or too little memory to load it")
    return (f"unexpected {type(exc).__name__}: {exc} (a bug in critmoment; rerun with -v "
            f"for the traceback and report it)")


#: words of an error that says the process ran out of memory or threads
_EXHAUSTED = ("thread constructor failed", "can't start new thread", "cannot allocate memory",
              "could not allocate", "failed to map segment", "out of memory",
              "resource temporarily unavailable", "std::bad_alloc")


def _warning_lines(caught, command: str) -> list[str]:
    seen, lines = set(), []
    for w in caught:
        text = _one_line(str(w.message))
        if text not in seen:
            seen.add(text)
            lines.append(f"critmoment {command}: warning: {text}")
    return lines


def _stderr_sink() -> None:
    """With the standard error closed (``2>&-``) Python sets ``sys.stderr`` to None, and
    ``print(..., file=None)`` writes to standard output: the error line, the warnings and
    ``-v``'s progress had landed in ``--json``'s document. They go nowhere instead."""
    if sys.stderr is None:
        sys.stderr = open(os.devnull, "w")  # noqa: SIM115 - the process's own stream


def main(argv: list[str] | None = None) -> int:
    """Runs the command line; returns the exit code (0 ok, 1 not safe, 2 error)."""
    _stderr_sink()
    with _terminate_as_interrupt():
        try:
            # the libraries load here (about 1 s), whole: a Ctrl-C meanwhile is raised after
            # them (one cutting NumPy's initialisation short left an ImportError, exit 1)
            with signals_held():
                # what the parser reads (the figure choices, the scenario families): a
                # broken matplotlib or ruptures had raised from build_parser, a raw
                # traceback and exit 1, the "not safe" code
                import importlib

                from critmoment.twin import quiet_mujoco_log

                for module in ("critmoment.report", "critmoment.suite"):
                    importlib.import_module(module)
        except KeyboardInterrupt:
            print("critmoment: error: interrupted; no output was written", file=sys.stderr)
            return EXIT_ERROR
        except Exception as exc:  # ImportError, or whatever a broken library raises
            print(f"critmoment: error: {type(exc).__name__}: {_one_line(str(exc))} (a "
                  "dependency is missing or broken: reinstall critmoment)", file=sys.stderr)
            return EXIT_ERROR
        # MuJoCo's own log appends each warning (an unstable simulation) to MUJOCO_LOG.TXT in
        # the user's folder and prints it, besides the one line critmoment prints
        with quiet_mujoco_log():
            return _main(argv)


@contextlib.contextmanager
def _terminate_as_interrupt() -> Iterator[None]:
    """The stop signals (:func:`~critmoment._signals.stop_signals`) end the run as Ctrl-C
    does: the output being written is removed, the previous one kept, exit 2. Only in the
    main thread (where Python runs signal handlers), and only for a signal not ignored
    (``nohup`` ignores SIGHUP); the previous handlers come back after."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def stop(signum, frame):
        budget.request_stop()  # stands where a library swallows the interrupt
        raise KeyboardInterrupt

    previous = {}
    try:
        for sig in stop_signals():
            if signal.getsignal(sig) is not signal.SIG_IGN:
                previous[sig] = signal.signal(sig, stop)
    except (ValueError, OSError):  # no signals here (an embedded interpreter)
        for sig, handler in previous.items():
            signal.signal(sig, handler)
        yield
        return
    try:
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)


def _main(argv: list[str] | None) -> int:
    try:
        parser = build_parser()
    except KeyboardInterrupt:
        # the line names the command, as every other error line does
        words = [a for a in (sys.argv[1:] if argv is None else argv) if not a.startswith("-")]
        name = f"critmoment {words[0]}" if words else "critmoment"
        print(f"{name}: error: interrupted; no output was written", file=sys.stderr)
        return EXIT_ERROR
    try:
        args, extra = parser.parse_known_args(argv)
        if extra:  # reported by the command's parser, so the line names the command
            parser.commands[args.command].error(
                f"unrecognized arguments: {' '.join(extra)}")
    except SystemExit as exc:  # argparse: --help (0) or a usage error (2, one line)
        return exc.code if isinstance(exc.code, int) else EXIT_ERROR
    # a library log line reads as the command's own warnings do
    handler = logging.StreamHandler()
    handler.setFormatter(_CommandFormatter(args.command, verbose=args.verbose))
    logging.basicConfig(level=logging.INFO if args.verbose else logging.WARNING,
                        handlers=[handler])
    _Stdout.closed = False
    budget.clear_stop()
    command = args.command
    code = EXIT_ERROR
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        warnings.filterwarnings("ignore", category=DeprecationWarning)
        try:
            args.caught = caught
            with budget.limits(max_steps=getattr(args, "max_steps", None),
                               max_batch_steps=getattr(args, "max_batch_steps", None),
                               max_input_bytes=getattr(args, "max_input_bytes", None)):
                code = args.func(args)
                budget.check_stop()
            if sys.stdout is not None:  # None where stdout was closed (``>&-``)
                sys.stdout.flush()
        except BrokenPipeError:  # the reader went away: keep the verdict's code
            _Stdout.silence()
        except KeyboardInterrupt:
            written = getattr(args, "out_written", None)
            # the output is swapped in whole before the summary prints: an interrupt while
            # printing leaves it written (and the previous one replaced), say which
            _error(command, "interrupted; no output was written" if written is None else
                   f"interrupted after the output was written whole to {written} (the "
                   f"summary on stdout may be cut short)", args)
            return EXIT_ERROR
        except Exception as exc:  # noqa: BLE001 - the last resort: one line, exit 2
            _error(command, _describe(exc), args)
            return EXIT_ERROR
    try:
        for line in _warning_lines(caught, command):
            print(line, file=sys.stderr)
    except (BrokenPipeError, OSError, ValueError):
        pass
    return code


class _CommandFormatter(logging.Formatter):
    """``critmoment COMMAND: warning: message`` (the logger's name too with --verbose), as
    critmoment's own lines print; the record itself is left as it is for other handlers."""

    def __init__(self, command: str, *, verbose: bool):
        super().__init__()
        self.command, self.verbose = command, verbose

    def format(self, record: logging.LogRecord) -> str:
        name = f"{record.name}: " if self.verbose else ""
        return (f"critmoment {self.command}: {record.levelname.lower()}: {name}"
                f"{record.getMessage()}")


def _error(command: str, message: str, args) -> None:
    if getattr(args, "verbose", False):
        traceback.print_exc()
    try:
        print(f"critmoment {command}: error: {_one_line(message)}", file=sys.stderr)
    except (BrokenPipeError, OSError, ValueError):
        pass


def run() -> None:
    """The ``critmoment`` console command: :func:`main`, then exit with its code. Once
    ``main`` has returned, its outputs are whole and the code is decided: a Ctrl-C during
    the interpreter's shutdown is then ignored instead of ending the process by the signal
    (the verdict's exit code lost); one just before is exit 2, interrupted."""
    import signal

    _stderr_sink()
    # a console that cannot encode "≤" or "—" (PYTHONIOENCODING=ascii, a Windows code page)
    # gets them escaped: an audit whose report was written whole had exited 2 on its summary
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(AttributeError, ValueError, OSError):
            stream.reconfigure(errors="backslashreplace")
    code = EXIT_ERROR
    try:
        code = main()
    except KeyboardInterrupt:
        print("critmoment: error: interrupted", file=sys.stderr)
    try:
        for sig in (signal.SIGINT, *stop_signals()):
            signal.signal(sig, signal.SIG_IGN)
    except (ValueError, OSError):  # not the main thread, or no signals here
        pass
    sys.exit(code)


if __name__ == "__main__":  # pragma: no cover
    run()
