"""Figures, JSON, HTML and terminal summaries, and the output folders they go to.

Figures use matplotlib's object-oriented API (no pyplot state), so they render
under any backend and in threads. Text that comes from the user (file names,
parameter names) is escaped for matplotlib's mathtext, so a ``$`` in a file
name is drawn as a dollar sign.

Outputs are written whole or not at all (:class:`StagedOutput`): everything goes
into a temporary folder beside the destination, which is then swapped into place
under a lock on the parent folder, so a failed or interrupted run leaves the
previous output intact, a folder holds the files of one run, and concurrent runs
cannot interleave.
"""

from __future__ import annotations

import base64
import contextlib
import dataclasses
import enum
import errno
import html
import io
import json
import math
import os
import re
import shutil
import tempfile
import warnings
import zipfile
from collections.abc import Iterator, Sequence
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from critmoment import budget
from critmoment.exceptions import CritmomentWarning, OutputError, ParameterError
from critmoment.moments import Moment, plot_moments
from critmoment.params import kind_of
from critmoment.safety import format_fos
from critmoment.trajectory import name_head as _head

__all__ = ["plot_recording", "moment_json", "figure_png", "Figures", "write_report",
           "StagedOutput", "check_output_path", "MARKER"]

#: Name of the file that marks a folder as one critmoment output.
MARKER = ".critmoment-output.json"

# Files earlier critmoment versions wrote without a marker.
_KNOWN_OUTPUTS = frozenset({"report.json", "report.html", "recording.npz", "rollout.json",
                            "moments.json", "validation.json"})
#: The figure files critmoment writes (report_figures' names; the CLI's signals/moments).
_FIGURE_FILE = re.compile(r"(signals|moments|cost_map|moment_\d+)\.png")

#: Resolution of the report's PNG figures [dots per inch].
DPI = 90


def _lighten(fig: Figure) -> Figure:
    """Fewer ticks: most of a figure's drawing time is spent making tick objects."""
    from matplotlib.ticker import FixedLocator, MaxNLocator

    for ax in fig.axes:
        for axis, bins in ((ax.xaxis, 5), (ax.yaxis, 4)):
            if not isinstance(axis.get_major_locator(), FixedLocator):
                axis.set_major_locator(MaxNLocator(nbins=bins))
    return fig


def _tex_safe(text) -> str:
    """``text`` with ``$`` escaped, so matplotlib never parses it as mathtext."""
    return str(text).replace("$", r"\$")


class Figures(enum.Enum):
    """Which figures :func:`write_report` draws."""

    NONE = "none"
    """No figures: report.json and report.html only (fastest)."""
    SUMMARY = "summary"
    """The signals, one overview of every moment's curves, and the cost map (default)."""
    ALL = "all"
    """The summary figures plus one figure of FOS and cost curves per moment."""

    @classmethod
    def parse(cls, value) -> Figures:
        if isinstance(value, cls):
            return value
        for member in cls:
            if str(value).lower() in (member.value, member.name.lower()):
                return member
        raise ParameterError(f"figures: expected one of {[m.value for m in cls]}, "
                             f"got {value!r}")


def moment_json(m: Moment) -> dict:
    """A moment as the JSON object of ``critmoment moments --json``."""
    score = None if not np.isfinite(m.score) else float(m.score)
    return {"step": int(m.step), "time": float(m.time), "label": m.label.value,
            "reason": m.reason, "score": score, "gripper": m.gripper}


def plot_recording(recording, *, moments: Sequence[Moment] = (), path: str | Path | None = None
                   ) -> Figure:
    """The frequent rollout's signals over time with stage changes (and moments) marked.

    Panels: object acceleration, normalised actuator forces, 1/FOS per gripper and motor,
    and the task stage (thesis Appendix A).

    Args:
        recording: a :class:`~critmoment.recording.Recording`.
        moments: moments to mark as labelled vertical lines.
        path: save the figure there when given (format from the extension).
    """
    # fixed margins: a constrained layout draws the figure twice
    fig = Figure(figsize=(10, 9))
    fig.subplots_adjust(left=0.08, right=0.98, top=0.96, bottom=0.06, hspace=0.12)
    axes = fig.subplots(4, 1, sharex=True, height_ratios=[1, 1, 1, 0.6])
    plot_moments(recording, list(moments), ax=list(axes[:3]))
    t = recording.time
    axes[3].step(t, recording.stage, where="post", color="tab:purple", lw=1.0)
    axes[3].set_ylabel("task stage")
    axes[3].set_yticks(range(5))
    axes[3].set_xlabel("time [s]")
    changes = np.flatnonzero(np.diff(recording.stage)) + 1
    for k in changes:
        for ax in axes:
            ax.axvline(t[k], color="tab:purple", lw=0.5, alpha=0.4, ls=":")
    axes[0].set_title(_tex_safe(
        f"Frequent rollout: {recording.source or recording.scenario_name}"))
    if path is not None:
        fig.savefig(path, dpi=DPI)
    return fig


def figure_png(fig: Figure) -> str:
    """A figure as a base64 PNG string, for embedding in HTML."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100)
    return base64.b64encode(buf.getvalue()).decode("ascii")


# -- the audit report --------------------------------------------------------------
def _num(x):
    """A JSON number, or None for NaN/inf (JSON has neither)."""
    if x is None:
        return None
    x = float(x)
    return x if np.isfinite(x) else None


def report_json(report, *, timings: bool = True) -> dict:
    """The ``report.json`` document of an :class:`~critmoment.analysis.AuditReport`."""
    from critmoment.analysis import REPORT_SCHEMA

    box = report.scenario.box
    moments = []
    for mr in report.moments:
        m = mr.moment
        moments.append({
            "step": int(m.step), "time": float(m.time), "label": m.label.value,
            "reason": m.reason, "sensitivity": _num(m.score), "audited_step": mr.step,
            "worst_case": {k: float(v) for k, v in mr.worst_case.items()},
            "max_cost": _num(mr.max_cost),
            "min_fos_contact": _num(mr.min_fos_contact),
            "min_fos_motor": _num(mr.min_fos_motor),
            "critical": {k: _num(v) for k, v in mr.critical.items()},
            "critical_side": dict(mr.critical_side),
            "critical_refuted": {k: {"side": side, "value": float(v)}
                                 for k, (side, v) in mr.critical_refuted.items()},
            "dominant": mr.dominant,
            "limiting_actuator": mr.limiting_actuator,
            "fail_fraction": float(mr.fail_fraction),
            "own_fail_fraction": float(mr.own_fail_fraction),
            "overturned": bool(mr.overturned),
            "worst_fails": mr.worst_fails,
            "worst_note": mr.worst_note,
            "reached": float(mr.reached),
            "squeeze": bool(mr.squeeze),
            "analytic": jsonable(mr.analytic),
            "search": jsonable(mr.search),
        })
    doc = {
        "schema": REPORT_SCHEMA,
        "verdict": report.verdict.value,
        "p_success": float(report.p_success),
        "p_success_interval": [float(v) for v in report.p_success_interval],
        "confidence": report.options.confidence,
        "n_samples": int(report.sweep.n_samples) if report.sweep is not None else 0,
        "nominal_cost": _num(report.nominal_cost),
        "threshold": report.scenario.cost.threshold,
        "safe_region": (None if report.safe_region is None else
                        {k: [float(a), float(b)] for k, (a, b) in report.safe_region.items()}),
        "safe_region_text": report.safe_region_text,
        "failure_causes": list(report.failure_causes),
        "moments": moments,
        "candidates": [moment_json(m) for m in report.candidates],
        "uncertainty": {p.name: {"kind": kind_of(p),
                                 "target": p.target, "range": [p.low, p.high],
                                 "nominal": p.nominal, "prior": p.prior.value, "unit": p.unit}
                        for p in box.parameters},
        "cost": dataclasses_asdict(report.scenario.cost),
        "horizon": int(report.sweep.horizon) if report.sweep is not None else None,
        "verification": jsonable(report.verification),
        "feasibility": (report.feasibility.to_json()
                        if getattr(report, "feasibility", None) is not None else None),
        "contact_model": _contact_json(getattr(report, "contact_model", None),
                                       getattr(report, "force_ratio_untrusted", ())),
        "load_bound": jsonable(getattr(report, "load_bound", None)),
        "rollout": jsonable(report.recording.summary()),  # inf: no force limit
        "manifest": jsonable(report.manifest),
        "warnings": list(getattr(report, "warnings", ())),
    }
    if timings:
        doc["timings"] = {k: round(float(v), 4) for k, v in report.timings.items()}
    return doc


def _contact_json(cm, untrusted=()) -> dict | None:
    """The contact-model check (critmoment.contactmodel) as JSON, or None; ``untrusted``:
    the moments where the force ratio does not decide (the nominal grip chatters)."""
    if cm is None:
        return None
    return {"force_ratio_untrusted_at": [int(k) for k in untrusted],
            "summary": cm.summary(), "cone": cm.cone, "impratio": _num(cm.impratio),
            "noslip_iterations": int(cm.noslip_iterations), "soft": bool(cm.soft),
            "probe_mass": _num(cm.probe_mass), "creep_rate": _num(cm.creep_rate),
            "carry_time": _num(cm.carry_time), "creep_horizon": int(cm.creep_horizon),
            "nominal_creep": _num(getattr(cm, "nominal_creep", math.nan)),
            "findings": [str(getattr(f, "message", f)) for f in cm.findings]}


def dataclasses_asdict(obj) -> dict:
    import dataclasses

    return dataclasses.asdict(obj)


def jsonable(obj):
    """``obj`` as plain JSON values: numbers (NaN and infinities as None: JSON has neither),
    strings, lists and dicts; enums by value, anything else by ``str``."""
    if obj is None or isinstance(obj, (str, bool, int)):
        return obj
    if isinstance(obj, np.bool_):
        return bool(obj)
    if isinstance(obj, float) or isinstance(obj, np.floating):
        return _num(obj)
    if isinstance(obj, np.integer):
        return int(obj)
    if isinstance(obj, np.ndarray):
        return [jsonable(v) for v in obj.tolist()]
    if isinstance(obj, dict) or hasattr(obj, "items"):
        return {str(k): jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [jsonable(v) for v in obj]
    if hasattr(obj, "value"):  # enums
        return jsonable(obj.value)
    return str(obj)


def plot_curves(report, step: int) -> Figure:
    """FOS and cost against each parameter at one moment (others nominal): thesis Figs. 5–6."""
    return _curves_figure(report, step)[0]


def _curve_data(report, step: int, j: int, name: str) -> tuple:
    res = report.curves[step][name]
    return (res.samples[:, j], np.clip(res.fos_grasp[0], 0, 10), np.clip(res.fos_motor[0], 0, 10),
            res.cost[0], res.cost_contact[0], res.cost_motor[0])


def _curves_figure(report, step: int) -> tuple[Figure, list]:
    """The curves figure of one moment, and per parameter its (axes, lines) to update."""
    box = report.scenario.box
    # fixed margins: a constrained layout would draw each of these figures twice
    fig = Figure(figsize=(5.2 * box.ndim, 6.4))
    fig.subplots_adjust(left=0.09, right=0.98, top=0.95, bottom=0.08, hspace=0.25,
                        wspace=0.26)
    axes = fig.subplots(2, box.ndim, squeeze=False)
    thr = report.scenario.cost.threshold
    artists = []
    for j, p in enumerate(box.parameters):
        x, fos_c, fos_m, cost, cost_c, cost_m = _curve_data(report, step, j, p.name)
        ax = axes[0, j]
        top = [ax.plot(x, fos_c, label="FOS contact (grasp)")[0],
               ax.plot(x, fos_m, label="FOS motor")[0]]
        ax.axhline(1.0, color="k", lw=0.6, ls=":")
        ax.set_ylabel("factor of safety (clipped at 10)")
        ax.set_title(_tex_safe(f"step {step}: FOS vs {p.name}"))
        ax.legend(fontsize="small")
        ax = axes[1, j]
        bottom = [ax.plot(x, cost, color="k", label="cost")[0],
                  ax.plot(x, cost_c, ls="--", label="contact term")[0],
                  ax.plot(x, cost_m, ls="--", label="motor term")[0]]
        ax.axhline(thr, color="tab:red", lw=0.8, label=f"threshold {thr:g}")
        ax.axvline(p.nominal, color="tab:green", lw=0.8, ls=":", label="nominal")
        ax.set_xlabel(_tex_safe(f"{p.name} [{p.unit}]" if p.unit else p.name))
        ax.set_ylabel("cost")
        ax.legend(fontsize="small")
        artists.append((axes[0, j], axes[1, j], top + bottom))
    return fig, artists


def _moment_pngs(report) -> Iterator[tuple[str, bytes]]:
    """One PNG per moment, drawn by updating a single figure (its axes, ticks and legends
    are made once)."""
    fig, artists = None, []
    box = report.scenario.box
    for mr in report.moments:
        step = mr.step
        if fig is None:
            fig, artists = _curves_figure(report, step)
            _lighten(fig)
        else:
            for j, (p, (top, bottom, lines)) in enumerate(
                    zip(box.parameters, artists, strict=True)):
                x, *ys = _curve_data(report, step, j, p.name)
                for line, y in zip(lines, ys, strict=True):
                    line.set_data(x, y)
                top.set_title(_tex_safe(f"step {step}: FOS vs {p.name}"))
                for ax in (top, bottom):
                    ax.relim()
                    ax.autoscale_view()
        yield f"moment_{mr.moment.step}", _png(fig)


def _png(fig: Figure) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=DPI)
    return buf.getvalue()


def plot_moment_overview(report) -> Figure | None:
    """Every audited moment's curves in one figure: the lower of the two FOS (top) and
    the cost (bottom) against each parameter, others nominal, one colour per moment."""
    if not report.moments:
        return None
    box = report.scenario.box
    fig = Figure(figsize=(5.2 * box.ndim, 6.4))
    fig.subplots_adjust(left=0.09, right=0.98, top=0.95, bottom=0.08, hspace=0.25,
                        wspace=0.26)
    axes = fig.subplots(2, box.ndim, squeeze=False)
    thr = report.scenario.cost.threshold
    colours = [f"C{i % 10}" for i in range(len(report.moments))]
    for j, p in enumerate(box.parameters):
        top, bottom = axes[0, j], axes[1, j]
        for mr, colour in zip(report.moments, colours, strict=True):
            step = mr.step
            res = report.curves[step][p.name]
            x = res.samples[:, j]
            fos = np.minimum(res.fos_grasp[0], res.fos_motor[0])
            label = _tex_safe(f"step {step} {mr.moment.label.value}")
            top.plot(x, np.clip(fos, 0, 10), color=colour, lw=1.0, label=label)
            bottom.plot(x, res.cost[0], color=colour, lw=1.0)
        top.axhline(1.0, color="k", lw=0.6, ls=":")
        top.set_title(_tex_safe(f"lower FOS vs {p.name} (clipped at 10)"))
        bottom.axhline(thr, color="tab:red", lw=0.8)
        bottom.axvline(p.nominal, color="tab:green", lw=0.8, ls=":")
        bottom.set_title(_tex_safe(f"cost vs {p.name} (red: threshold {thr:g})"))
        bottom.set_xlabel(_tex_safe(f"{p.name} [{p.unit}]" if p.unit else p.name))
    axes[0, 0].legend(fontsize="x-small", ncol=2)
    return fig


def plot_cost_map(report) -> Figure | None:
    """Max cost over the moments on a grid of the first two parameters."""
    if report.cost_map is None:
        return None
    n0, a0, n1, a1, grid = report.cost_map
    fig = Figure(figsize=(6.4, 5.0))
    fig.subplots_adjust(left=0.12, right=0.98, top=0.93, bottom=0.1)
    ax = fig.subplots()
    mesh = ax.pcolormesh(a0, a1, grid.T, shading="nearest", cmap="RdYlGn_r",
                         vmin=0, vmax=max(1.5, float(np.nanmax(grid))))
    thr = report.scenario.cost.threshold
    if np.nanmin(grid) < thr < np.nanmax(grid):
        ax.contour(a0, a1, grid.T, levels=[thr], colors="k", linewidths=1.2)
    fig.colorbar(mesh, ax=ax, label="max cost over the moments (nearest Sobol sample)")
    box = report.scenario.box
    ax.plot(box.nominal[0], box.nominal[1], "w*", ms=12, mec="k", label="nominal")
    ax.set_xlabel(_tex_safe(n0))
    ax.set_ylabel(_tex_safe(n1))
    ax.set_title(f"cost map (black line: cost = {thr:g})")
    ax.legend(loc="upper right", fontsize="small")
    return fig


def _whole_run_cost(report) -> str:
    """The nominal run's cost over every step, held over ``[sparse] persistence``, where it
    is above the moments' figure (``rollout`` prints it; a reader comparing the two should
    not find them contradict)."""
    rec = getattr(report, "recording", None)
    if rec is None:
        return ""
    held = rec.sustained(report.scenario)
    if not held["max_cost_sustained"] > report.nominal_cost + 0.01:
        return ""
    text = (f"; over the whole nominal run {held['max_cost_sustained']:.3f} (held "
            f"{held['persistence'] * 1e3:g} ms, at t = {held['max_cost_sustained_time']:.2f} s)")
    if held["max_cost_sustained"] >= report.scenario.cost.threshold and rec.completed:
        # a force ratio at its cone (chatter, a soft contact) on a run whose task succeeds
        text += ", by the force ratio alone: the nominal run completes its task, which decides it"
    return text


def summary_text(report) -> str:
    """The terminal summary of an audit."""
    lo, hi = report.p_success_interval
    lines = [f"critmoment: {report.verdict.value} — {report.safe_region_text}",
             f"P(success) = {report.p_success:.3f} ({report.options.confidence:.0%} interval "
             f"{lo:.3f}–{hi:.3f}) over {report.sweep.n_samples if report.sweep else 0} samples "
             f"of the box; nominal max cost {report.nominal_cost:.3f} at the audited "
             f"moments (threshold {report.scenario.cost.threshold:g})"
             + _whole_run_cost(report)]
    untrusted = set(getattr(report, "force_ratio_untrusted", ()))
    for i, mr in enumerate(report.moments, 1):
        m = mr.moment
        crit = (", ".join(f"{k} {mr.critical_side[k]} {v:.3g}" for k, v in mr.critical.items()
                          if v is not None)
                + (" (the others at nominal)" if len(mr.critical) > 1 else "")
                if any(v is not None for v in mr.critical.values()) else "") or (
                             "none: the worst case does not fail" if mr.worst_fails is False
                             else "none of one parameter alone (the others at nominal)"
                             if mr.max_cost >= report.scenario.cost.threshold else "never crosses")
        passing = f" (not a failure: {mr.worst_note})" if mr.worst_fails is False else ""
        worst = ", ".join(f"{k}={v:.3g}" for k, v in mr.worst_case.items())
        # a force ratio the cost does not use (contact chatter) is not shown bare beside it
        trust = " (not trusted here, not in the cost: contact chatter)" if int(m.step) in untrusted else ""
        lines.append(f"  {i}. {m.label.value:12s} step {m.step:5d} (t = {m.time:.2f} s): max cost "
                     f"{mr.max_cost:.3f} at {worst}{passing}; min FOS contact {format_fos(mr.min_fos_contact)}"
                     f"{trust}, motor {format_fos(mr.min_fos_motor)}; fails {mr.fail_fraction:.0%} "
                     f"of the box here (reached by {mr.reached:.0%})"
                     + (f", and {_share(mr.own_fail_fraction, report)} fail on their own "
                        f"runs after it, before the next moment"
                        if mr.own_fail_fraction > 0 else "")
                     + f"; critical: {crit}")
    v = report.verification
    if v is not None:
        lines.append(f"  verification: {_verification_text(v)}")
    lb = getattr(report, "load_bound", None)
    if lb and lb.get("masses"):
        parts = [f"{e['mass']:.3g} kg: {e['actuator']} saturates from t = "
                 f"{e['first_failing_time']:.2f} s" if e["first_failing_time"] is not None
                 else f"{e['mass']:.3g} kg: no motor saturates" for e in lb["masses"]]
        unbounded = lb.get("unbounded") or []
        if unbounded:
            parts.append(f"not bounded: {', '.join(unbounded)} (they stand the robot's "
                         f"free-floating base on its contacts; its weight is left out)")
        lines.append("  analytic motor bound over the whole motion: " + "; ".join(parts))
    if untrusted:
        lines.append(f"  contact force ratio not trusted at steps "
                     f"{', '.join(map(str, report.force_ratio_untrusted))}"
                     f": the nominal grip sits on the friction cone there although its run "
                     f"completes (contact chatter); measured slip and motor loads decide")
    unlimited = getattr(report, "unlimited_motors", ())
    if unlimited:
        lines.append(f"  no force limit (not in the scenario or the MJCF) on the arm's "
                     f"actuators {', '.join(unlimited)}: their motor FOS is not checked")
    for cause in report.failure_causes:
        lines.append(f"  ! {cause}")
    return "\n".join(lines)


def report_figures(report, figures: Figures | str = Figures.SUMMARY) -> dict[str, Figure]:
    """The report's figures by name (``signals``, ``moments``, ``cost_map``,
    ``moment_<step>``), as :class:`Figures` selects them."""
    which = Figures.parse(figures)
    figs: dict[str, Figure] = {}
    if which is Figures.NONE:
        return figs
    figs["signals"] = plot_recording(report.recording,
                                     moments=[mr.moment for mr in report.moments])
    overview = plot_moment_overview(report)
    if overview is not None:
        figs["moments"] = overview
    cmap = plot_cost_map(report)
    if cmap is not None:
        figs["cost_map"] = cmap
    if which is Figures.ALL:
        for mr in report.moments:
            figs[f"moment_{mr.moment.step}"] = plot_curves(report, mr.step)
    return figs


def write_report(report, out: str | Path, *, figures: Figures | str = Figures.SUMMARY
                 ) -> dict[str, Path]:
    """Writes report.json, the figures and a self-contained report.html into ``out``.

    The files are staged in a temporary folder and moved into ``out`` at the end
    (:class:`StagedOutput`): a failure leaves a previous report in ``out`` untouched, and
    ``out`` ends up holding this report's files and no file of an earlier one. Other files
    in ``out`` (e.g. the trajectory) are kept.

    Args:
        report: an :class:`~critmoment.analysis.AuditReport`.
        out: the folder; created, or replaced if it holds an earlier critmoment output.
        figures: which figures to draw (:class:`Figures`; default ``SUMMARY``).

    Returns:
        The written paths by name (``json``, ``html`` and one per figure).

    Raises:
        ParameterError: ``report`` is not an AuditReport, ``out`` is not a path, or
            ``figures`` names no :class:`Figures`.
        OutputError: ``out`` is a file, lies under a file, is not writable, or the disk
            fills.
    """
    from critmoment.analysis import AuditReport

    if not isinstance(report, AuditReport):
        raise ParameterError(f"report: expected an AuditReport (the result of "
                             f"critmoment.analyze(...)), got {type(report).__name__}")
    which = Figures.parse(figures)
    with StagedOutput(out, command="analyze", shared=True, option="output folder") as stage:
        names = write_report_files(report, stage.path, figures=which)
    return {k: stage.destination / v.name for k, v in names.items()}


def write_report_files(report, folder: Path, *, figures: Figures = Figures.SUMMARY,
                       record_warnings: bool = False) -> dict[str, Path]:
    """Writes the report's files into an existing ``folder`` (no staging). The figures are
    drawn first; with ``record_warnings`` the warnings drawing them raised (a glyph the font
    lacks for a parameter's name) join the report's ``warnings`` in the written documents,
    as the CLI's other warnings do (they had been printed but not recorded); they are
    issued again either way."""
    folder = Path(folder)
    paths: dict[str, Path] = {}
    which = Figures.parse(figures)
    with warnings.catch_warnings(record=True) as drawing:
        warnings.simplefilter("always")
        pngs = [(name, _png(_lighten(fig))) for name, fig in report_figures(
            report, Figures.SUMMARY if which is Figures.ALL else which).items()]
        if which is Figures.ALL:
            pngs += list(_moment_pngs(report))
    for w in drawing:
        warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    if record_warnings and drawing:
        said = (" ".join(str(w.message).split()) for w in drawing)
        report = dataclasses.replace(report, warnings=tuple(dict.fromkeys(
            [*getattr(report, "warnings", ()), *said])))
    doc = report.to_json()
    paths["json"] = folder / "report.json"
    paths["json"].write_text(json.dumps(jsonable(doc), indent=2, allow_nan=False))
    images = {}
    for name, data in pngs:
        path = folder / f"{name}.png"
        path.write_bytes(data)
        paths[name] = path
        images[name] = base64.b64encode(data).decode("ascii")
    paths["html"] = folder / "report.html"
    paths["html"].write_text(_html(report, doc, images), encoding="utf-8")
    return paths


# -- output folders ----------------------------------------------------------------
def _nearest_existing(path: Path) -> Path:
    """The deepest existing ancestor of ``path`` (``path`` itself excluded)."""
    for parent in path.parents:
        try:
            if parent.exists() or parent.is_symlink():
                return parent
        except OSError:
            continue
    return Path(path.anchor or ".")


def _foreign_entries(folder: Path) -> list[str]:
    """Entries of ``folder`` that are not part of its critmoment output."""
    names = {e.name for e in os.scandir(folder)}
    ours = _previous_files(folder) | {MARKER}
    return sorted(names - ours)


def check_output_path(path: str | os.PathLike, *, kind: str = "folder",
                      option: str = "--out", shared: bool = False) -> Path:
    """Validates an output path before any work starts.

    Args:
        path: the destination folder (``kind="folder"``) or file (``kind="file"``).
        kind: ``"folder"`` or ``"file"``.
        option: how the path was given, for messages.
        shared: a folder may hold other files (see :class:`StagedOutput`).

    Returns:
        The destination as an absolute path (symlinks resolved).

    Raises:
        ParameterError: ``path`` is not a str, bytes or os.PathLike.
        OutputError: the destination is of the other kind, lies under a file, cannot be
            created for lack of permission or because the file system is read-only, or
            (a folder) holds files that are not a critmoment output.
    """
    if not isinstance(path, (str, bytes, os.PathLike)):
        raise ParameterError(f"{option}: expected a {kind} path (str or os.PathLike), got "
                             f"{type(path).__name__} {path!r}")
    try:
        raw = os.fsdecode(path)
    except (TypeError, UnicodeDecodeError) as exc:  # a PathLike that returns no path
        raise ParameterError(f"{option}: expected a {kind} path (str or os.PathLike), got "
                             f"{type(path).__name__} ({exc})") from None
    if not raw:
        raise OutputError(f"{option}: expected a {kind} path, got an empty string")
    try:
        dest = Path(os.path.realpath(raw))
        exists = dest.exists()
        is_dir = dest.is_dir()
    except (OSError, ValueError) as exc:  # a name too long, an embedded NUL byte
        raise OutputError(f"{option} {_short(raw)!r}: cannot be used as a {kind}: "
                          f"{getattr(exc, 'strerror', None) or exc}") from None
    if exists and kind == "folder" and not is_dir:
        raise OutputError(f"{option} {_short(raw)!r}: expected a folder (or a path to create "
                          f"one), got an existing file")
    if exists and kind == "file" and is_dir:
        raise OutputError(f"{option} {_short(raw)!r}: expected a file path, got an existing "
                          f"folder")
    if exists and kind == "file" and not dest.is_file():
        raise OutputError(f"{option} {_short(raw)!r}: expected a file path, got an existing "
                          f"special file (a device, FIFO or socket), which is never replaced")
    anchor = _nearest_existing(dest)
    if not anchor.is_dir():
        raise OutputError(f"{option} {_short(raw)!r}: expected a path under a folder, but "
                          f"{_short(anchor)!r} is a file")
    try:
        name_max = os.pathconf(anchor, "PC_NAME_MAX")
    except (OSError, ValueError, AttributeError):
        name_max = 255
    long_parts = [part for part in dest.relative_to(anchor).parts
                  if len(os.fsencode(part)) > name_max]
    if long_parts:
        raise OutputError(f"{option} {_short(raw)!r}: expected names of at most {name_max} "
                          f"bytes, got one of {len(os.fsencode(long_parts[0]))} bytes")
    if exists and kind == "folder":
        cwd = Path(os.path.realpath(os.getcwd()))
        if cwd == dest or dest in cwd.parents:  # replacing it would pull the floor away
            raise OutputError(f"{option} {_short(raw)!r}: expected a folder other than the "
                              f"current working directory or one of its parents")
        try:
            foreign = _foreign_entries(dest)
        except OSError as exc:
            raise OutputError(f"{option} {_short(raw)!r}: cannot list the folder: "
                              f"{exc.strerror or exc}") from None
        if foreign and not shared:
            raise _foreign_error(option, raw, foreign)
    return dest


def _foreign_error(option: str, raw: str, foreign: Sequence[str]) -> OutputError:
    """The refusal of an output folder holding files that are not critmoment's."""
    shown = ", ".join(foreign[:5]) + (" ..." if len(foreign) > 5 else "")
    return OutputError(
        f"{option} {_short(raw)!r}: expected an empty folder or one holding an earlier "
        f"critmoment output (it is replaced whole), got a folder with other files "
        f"({shown}); choose a new folder")


def _unmovable(folder: Path) -> bool:
    """``folder`` exists and is a mount point, or on another device than its parent."""
    try:
        if not folder.is_dir():
            return False
        return os.path.ismount(folder) or folder.stat().st_dev != folder.parent.stat().st_dev
    except OSError:
        return False


def _short(path, limit: int = 120) -> str:
    text = str(path)
    return text if len(text) <= limit else f"{text[:60]}...{text[-40:]}"


@contextlib.contextmanager
def _locked(folder: Path) -> Iterator[None]:
    """An exclusive advisory lock on ``folder`` (POSIX flock; a no-op elsewhere)."""
    try:
        import fcntl
    except ImportError:  # pragma: no cover - Windows
        yield
        return
    fd = os.open(folder, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)  # closing releases the lock


def _exchange(a: Path, b: Path) -> bool:
    """Atomically swaps two paths (Linux renameat2 RENAME_EXCHANGE); False if unsupported."""
    import ctypes
    import ctypes.util
    import sys

    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
        renameat2 = libc.renameat2
    except (OSError, AttributeError):
        return False
    at_fdcwd, rename_exchange = -100, 2
    rc = renameat2(at_fdcwd, os.fsencode(a), at_fdcwd, os.fsencode(b), rename_exchange)
    if rc == 0:
        return True
    err = ctypes.get_errno()
    if err in (errno.ENOSYS, errno.EINVAL, errno.ENOTSUP, errno.EOPNOTSUPP):
        return False
    raise OSError(err, os.strerror(err), str(b))


def _marked_files(folder: Path) -> set[str] | None:
    """The files its marker lists as the critmoment output in ``folder``, or None (no
    readable marker)."""
    try:
        listed = json.loads((folder / MARKER).read_text())["files"]
        return {str(n) for n in listed if "/" not in str(n) and str(n) not in ("", ".", "..")}
    except (OSError, ValueError, KeyError, TypeError, RecursionError):
        return None


def _previous_files(folder: Path) -> set[str]:
    """The files of the critmoment output in ``folder`` (its marker's list, or known names)."""
    listed = _marked_files(folder)
    if listed is not None:
        return listed
    # only the figure names critmoment writes: a folder of the user's own pictures is
    # not an earlier output; and the reports and recordings by their content (report.html
    # is pytest-html's default name too: a CI folder of its reports had been replaced)
    # (a marker without its list still says the folder is critmoment's: names suffice)
    marked = (folder / MARKER).is_file()
    return {e.name for e in os.scandir(folder) if e.is_file() and (
        _FIGURE_FILE.fullmatch(e.name) or (e.name in _KNOWN_OUTPUTS
                                           and (marked or _written_by_us(e.path))))}


#: per unmarked JSON output, a key critmoment's document of that name holds
_JSON_KEYS = {"report.json": "verdict", "rollout.json": "stage_first_step",
              "moments.json": "moments", "validation.json": "confusion"}


def _written_by_us(path: str) -> bool:
    """An unmarked file named like a critmoment output holds one: a recording's arrays, a
    page that names critmoment near its start, or a JSON document with the key
    critmoment's of that name has."""
    name = os.path.basename(path)
    try:
        if name.endswith(".npz"):
            with zipfile.ZipFile(path) as archive:
                return {"states.npy", "sensordata.npy"} <= set(archive.namelist())
        if name.endswith(".html"):
            with open(path, "rb") as fh:
                return b"critmoment" in fh.read(1 << 16)
        if os.path.getsize(path) > 1 << 28:
            return False
        with open(path, "rb") as fh:
            doc = json.loads(fh.read())
        return isinstance(doc, dict) and _JSON_KEYS.get(name, "schema") in doc
    except (OSError, zipfile.BadZipFile, ValueError, RecursionError):
        return False


def _remove_tree(path: Path) -> None:
    """Removes a staged or replaced folder, read-only parts included (an earlier output made
    read-only stayed behind, whole, as ``.DIR.critmoment-tmp-*``, where a batch reading
    every ``report.json`` found it); warns where something still cannot be removed."""
    with contextlib.suppress(OSError):
        for root, _, _ in os.walk(path):
            os.chmod(root, os.stat(root).st_mode | 0o700)
    shutil.rmtree(path, ignore_errors=True)
    if os.path.lexists(path):
        warnings.warn(f"could not remove {str(path)!r} (an earlier output or a staged one); "
                      f"remove it by hand", CritmomentWarning, stacklevel=3)


class StagedOutput:
    """Builds an output folder (or file) in a temporary place and moves it into position.

    Usage::

        with StagedOutput("out", command="analyze") as stage:
            (stage.path / "report.json").write_text(...)

    Entering validates the destination (:func:`check_output_path`) and creates the
    temporary folder beside it, so an unusable destination fails before any work. On a
    normal exit the temporary folder replaces the destination: atomically where the OS
    can swap two paths (Linux), else by two renames, under an exclusive lock on the
    parent folder either way. On an exception it is removed and the destination is left
    as it was.

    With ``shared=True`` a destination folder may also hold files critmoment did not
    write (e.g. the trajectory beside its report). Those are never touched: the new
    files are renamed in one by one, replacing same-named ones atomically, then the
    files of the previous output that the new one lacks are removed, all under the lock
    on the folder, so concurrent runs still cannot interleave (an interruption during
    these renames, unlike the swap, can leave some previous files).

    Attributes:
        destination: the final path (absolute).
        path: the temporary folder (or, for ``kind="file"``, the temporary file) to
            write into.
    """

    def __init__(self, destination: str | os.PathLike, *, command: str, kind: str = "folder",
                 option: str = "--out", shared: bool = False):
        if kind not in ("folder", "file"):
            raise ParameterError(f"kind: expected 'folder' or 'file', got {kind!r}")
        self.option, self.kind, self.command, self.shared = option, kind, command, shared
        self.destination = check_output_path(destination, kind=kind, option=option,
                                             shared=shared)
        self._raw = os.fspath(destination)
        self._tmpdir: Path | None = None
        self._inside = False
        self.path: Path = self.destination

    def __enter__(self) -> StagedOutput:
        anchor = _nearest_existing(self.destination)
        if self.destination.parent.is_dir():
            anchor = self.destination.parent
        # a folder that is a mount point (a container's volume given as --out) cannot be
        # swapped or renamed (EBUSY), nor can files be renamed into it from beside it
        # (EXDEV): the output is staged inside it and its files renamed in one by one
        self._inside = self.kind == "folder" and _unmovable(self.destination)
        if self._inside:
            anchor = self.destination
        try:
            self._tmpdir = Path(tempfile.mkdtemp(
                prefix=f".{_head(self.destination.name)}.critmoment-tmp-", dir=anchor))
        except OSError as exc:
            raise OutputError(f"{self.option} {_short(self._raw)!r}: cannot write in "
                              f"{_short(anchor)!r} ({exc.strerror or exc}); expected a "
                              f"folder on a writable file system") from None
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(self._tmpdir, 0o777 & ~umask)  # mkdtemp's 0700 would outlive the rename
        self.path = (self._tmpdir if self.kind == "folder"
                     else self._tmpdir / self.destination.name)
        return self

    def __exit__(self, exc_type, exc, tb) -> bool:
        try:
            if exc_type is None:
                budget.check_stop()  # a stop signal a library swallowed: keep the old output
                self._commit()
            elif isinstance(exc, OSError) and not isinstance(exc, OutputError) and (
                    str(self._tmpdir) in str(getattr(exc, "filename", "") or "")
                    or exc.errno in (errno.ENOSPC, errno.EDQUOT, errno.EROFS, errno.EFBIG)):
                raise OutputError(f"{self.option} {_short(self._raw)!r}: writing failed, "
                                  f"nothing was changed: {exc.strerror or exc}") from None
        finally:
            if self._tmpdir is not None and self._tmpdir.exists():
                _remove_tree(self._tmpdir)
        return False

    def _merge_into(self, dest: Path, *, marked_only: bool = True) -> None:
        """Renames the staged files into a folder that also holds other files, and removes
        the earlier output's files the new one lacks: only those its marker lists
        (``marked_only``; a file of the user's named like a figure, ``signals.png``, in a
        folder without a marker is the user's), else also those named like critmoment's."""
        new = sorted(e.name for e in os.scandir(self.path) if e.name != MARKER)
        earlier = _marked_files(dest) if marked_only else _previous_files(dest)
        old = (earlier or set()) - set(new) - {MARKER}
        for name in new:
            os.replace(self.path / name, dest / name)
        for name in old:
            with contextlib.suppress(FileNotFoundError):
                (dest / name).unlink()
        os.replace(self.path / MARKER, dest / MARKER)

    def _commit(self) -> None:
        dest = self.destination
        try:
            if self.kind == "folder":
                files = sorted(e.name for e in os.scandir(self.path))
                (self.path / MARKER).write_text(json.dumps(
                    {"command": self.command, "files": files}) + "\n")
            dest.parent.mkdir(parents=True, exist_ok=True)
            with _locked(dest.parent):
                if self.kind == "file":
                    os.replace(self.path, dest)
                    return
                if self._inside:
                    foreign = [n for n in _foreign_entries(dest) if n != self._tmpdir.name]
                    if foreign and not self.shared:
                        raise _foreign_error(self.option, self._raw, foreign)
                    self._merge_into(dest, marked_only=self.shared)
                    return
                check_output_path(dest, kind="folder", option=self.option,
                                  shared=self.shared)
                if dest.exists() and _foreign_entries(dest):
                    self._merge_into(dest)
                elif not dest.exists():
                    os.rename(self.path, dest)
                elif not _exchange(self.path, dest):
                    aside = Path(tempfile.mkdtemp(prefix=f".{_head(dest.name)}.critmoment-old-",
                                                  dir=dest.parent))
                    os.rename(dest, aside / dest.name)
                    try:
                        os.rename(self.path, dest)
                    except OSError:
                        os.rename(aside / dest.name, dest)  # put the old output back
                        raise
                    finally:
                        _remove_tree(aside)
        except OutputError:
            raise
        except OSError as exc:
            raise OutputError(f"{self.option} {_short(self._raw)!r}: cannot move the output "
                              f"into place, nothing was changed: {exc.strerror or exc}"
                              ) from None


_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Roboto,sans-serif;max-width:1100px;margin:2em auto;
padding:0 1em;color:#222;line-height:1.45}
h1{font-size:1.6em;margin-bottom:.2em} h2{margin-top:1.6em;border-bottom:1px solid #ddd}
.verdict{display:inline-block;padding:.3em .8em;border-radius:.4em;color:#fff;font-weight:700}
.SAFE{background:#2e7d32}.CONDITIONAL{background:#ef6c00}.UNSAFE{background:#c62828}
table{border-collapse:collapse;margin:.6em 0;font-size:.92em}
td,th{border:1px solid #ccc;padding:.3em .6em;text-align:left;vertical-align:top}
th{background:#f4f4f4} img{max-width:100%;border:1px solid #eee;margin:.4em 0}
.muted{color:#666;font-size:.9em} code{background:#f4f4f4;padding:0 .2em}
"""


def _verification_html(doc) -> str:
    v = doc.get("verification")
    if not v:
        return ""
    return " · verification: " + _verification_text(v)


def _share(fraction: float, report) -> str:
    """A fraction of the sweep's samples as a percentage and a count: "94 % (241 of 256)";
    a small one reads as its count, not "0 %"."""
    n = report.sweep.n_samples if report.sweep is not None else 0
    count = int(round(fraction * n))
    return f"{fraction:.0%} ({count} of {n})" if n else f"{fraction:.0%}"


def _verification_text(v) -> str:
    text = (f"{v['near']} sample(s) passing with cost ≥ {v['cost_from']:.3g} re-run in full, "
            f"{v['near_failed']} of them fail")
    if v.get("unlifted"):
        text += (f"; {v['unlifted']} failing only where the object is squeezed off its "
                 f"support without a lift re-run in full, {v['unlifted_failed']} of them fail")
    if v.get("sticking"):
        text += (f"; {v['sticking']} failing only where the grip holds (inside its friction "
                 f"cone, or settled after a small shift) re-run in full, "
                 f"{v['sticking_failed']} of them fail")
    if v.get("slipping"):
        text += (f"; {v['slipping']} failing only by a slip under the ground truth's "
                 f"tolerance re-run in full, {v['slipping_failed']} of them fail")
    if v.get("margin"):
        text += (f"; {v['margin']} failing only by the cost's margin with every motor under "
                 f"its limit re-run in full, {v['margin_failed']} of them fail")
    if v.get("inherited"):
        text += (f"; {v['inherited']} failing only at moments where the nominal run fails too "
                 f"re-run in full, {v['inherited_failed']} of them fail")
    if v.get("chained"):
        text += (f"; {v['chained']} passing at every moment carried on their own state "
                 f"(chained segments), {v['chained_failed']} of them fail there")
        if v.get("chained_rolled_out"):
            # the chain's doubtful failures, decided by their own full rollout
            text += (f" ({v['chained_rolled_out']} of those re-run in full, "
                     f"{v['chained_confirmed']} confirmed: "
                     f"{v['chained_failed'] - v['chained_rolled_out'] + v['chained_confirmed']}"
                     f" fail)")
    return text


def _html(report, doc, images) -> str:
    e = html.escape
    lo, hi = doc["p_success_interval"]
    rows = []
    for mr in doc["moments"]:
        crit = ", ".join(f"{k} {mr['critical_side'][k]} {v:.3g}"
                         for k, v in mr["critical"].items() if v is not None) or "—"
        worst = ", ".join(f"{k} = {v:.3g}" for k, v in mr["worst_case"].items())
        fc = "—" if mr["min_fos_contact"] is None else f"{mr['min_fos_contact']:.3g}"
        fm = "—" if mr["min_fos_motor"] is None else f"{mr['min_fos_motor']:.3g}"
        mc = "—" if mr["max_cost"] is None else f"{mr['max_cost']:.3f}"
        if mr.get("worst_fails") is False:
            mc += f"<br><span class=muted>not a failure: {e(mr.get('worst_note', ''))}</span>"
        an = mr.get("analytic") or {}
        an_txt = ""
        if an:
            def fmt(v):
                return f"{v:.3g}" if isinstance(v, float) else str(v)

            an_txt = e(", ".join(f"{k.replace('_', ' ')}: {fmt(an[k])}" for k in (
                "limiting_joint", "motor_critical_mass", "contact_critical_mass_threshold")
                if an.get(k) is not None))
        rows.append(
            f"<tr><td>{mr['step']}<br><span class=muted>{mr['time']:.2f} s</span></td>"
            f"<td>{e(mr['label'])}</td><td>{e(mr['reason'])}</td><td>{e(worst)}</td>"
            f"<td>{mc}</td><td>{mr['fail_fraction']:.0%}<br><span class=muted>reached by "
            f"{mr['reached']:.0%}"
            + (f"; {_share(mr['own_fail_fraction'], report)} fail on their own runs "
               f"after it" if mr.get("own_fail_fraction") else "") + f"</span></td><td>{fc}</td><td>{fm} "
            f"<span class=muted>({e(mr['limiting_actuator'])})</span></td>"
            f"<td>{e(crit)}</td><td>{e(str(mr['dominant'] or '—'))}</td><td>{an_txt}</td></tr>")
    unc = "".join(
        f"<tr><td>{e(k)}</td><td>{e(v['target'])}</td><td>{v['range'][0]:g} – {v['range'][1]:g} "
        f"{e(v['unit'])}</td><td>{v['nominal']:g}</td><td>{e(v['prior'])}</td></tr>"
        for k, v in doc["uncertainty"].items())
    causes = "".join(f"<li>{e(c)}</li>" for c in doc["failure_causes"]) or "<li>none</li>"
    # what the run warned of (clipped actions, an assumed object pose, an object not at rest,
    # a creeping nominal grip): in the page too, not only in report.json
    warned = "".join(f"<li>{e(w)}</li>" for w in doc.get("warnings", []))
    warned = f"<h2>Warnings</h2><ul>{warned}</ul>" if warned else ""
    figs = "".join(
        f"<h3>{e(name.replace('_', ' '))}</h3><img alt='{e(name)}' src='data:image/png;base64,{b64}'>"
        for name, b64 in images.items())
    man = doc["manifest"]
    timing = ", ".join(f"{k} {v:.2f} s" for k, v in doc.get("timings", {}).items())
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>critmoment report: {e(doc['verdict'])}</title>
<style>{_CSS}</style></head><body>
<h1>critmoment audit <span class="verdict {e(doc['verdict'])}">{e(doc['verdict'])}</span></h1>
<p><b>{e(doc['safe_region_text'])}</b>. P(success) = <b>{doc['p_success']:.3f}</b>
({doc['confidence']:.0%} Wilson interval {lo:.3f}–{hi:.3f}, {doc['n_samples']} Sobol samples of the box);
nominal max cost {doc['nominal_cost']:.3f} against threshold {doc['threshold']:g}.</p>
<p class=muted>Trajectory {e(str(man['trajectory']))} · scenario {e(str(man['scenario']))} ·
model {e(str(man['model_sha256'])[:12])} · seed {man['seed']} · critmoment {e(man['critmoment'])},
MuJoCo {e(man['mujoco'])} · sparse horizon {doc['horizon']} step(s){_verification_html(doc)}</p>
<h2>Failure causes and suggestions</h2><ul>{causes}</ul>{warned}
<h2>Critical moments</h2>
<table><tr><th>step</th><th>label</th><th>why chosen</th><th>worst case</th><th>max cost</th>
<th>fails here</th><th>min FOS contact</th><th>min FOS motor</th><th>critical values</th><th>dominant</th><th>analytic</th></tr>
{''.join(rows)}</table>
<h2>Uncertainty box</h2>
<table><tr><th>parameter</th><th>acts on</th><th>range</th><th>nominal</th><th>prior</th></tr>{unc}</table>
<h2>Figures</h2>{figs}
<p class=muted>Timings: {e(timing)}</p>
</body></html>
"""
