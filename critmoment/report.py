"""Figures, JSON, HTML and terminal summaries.

Figures use matplotlib's object-oriented API (no pyplot state), so they render
under any backend and in threads.
"""

from __future__ import annotations

import base64
import html
import io
import json
from collections.abc import Sequence
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from critmoment.moments import Moment, plot_moments

__all__ = ["plot_recording", "moment_json", "figure_png"]


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
    fig = Figure(figsize=(10, 9), layout="constrained")
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
    axes[0].set_title(f"Frequent rollout: {recording.source or recording.scenario_name}")
    if path is not None:
        fig.savefig(path, dpi=110)
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
            "reason": m.reason, "sensitivity": _num(m.score),
            "worst_case": {k: float(v) for k, v in mr.worst_case.items()},
            "max_cost": _num(mr.max_cost),
            "min_fos_contact": _num(mr.min_fos_contact),
            "min_fos_motor": _num(mr.min_fos_motor),
            "critical": {k: _num(v) for k, v in mr.critical.items()},
            "critical_side": dict(mr.critical_side),
            "dominant": mr.dominant,
            "limiting_actuator": mr.limiting_actuator,
            "fail_fraction": float(mr.fail_fraction),
            "reached": float(mr.reached),
            "squeeze": bool(mr.squeeze),
            "analytic": _jsonable(mr.analytic),
            "search": _jsonable(mr.search),
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
        "uncertainty": {p.name: {"kind": type(p).__name__.replace("Parameter", "").lower(),
                                 "target": p.target, "range": [p.low, p.high],
                                 "nominal": p.nominal, "prior": p.prior.value, "unit": p.unit}
                        for p in box.parameters},
        "cost": dataclasses_asdict(report.scenario.cost),
        "horizon": int(report.sweep.horizon) if report.sweep is not None else None,
        "verification": _jsonable(report.verification),
        "rollout": report.recording.summary(),
        "manifest": _jsonable(report.manifest),
    }
    if timings:
        doc["timings"] = {k: round(float(v), 4) for k, v in report.timings.items()}
    return doc


def dataclasses_asdict(obj) -> dict:
    import dataclasses

    return dataclasses.asdict(obj)


def _jsonable(obj):
    if obj is None or isinstance(obj, (str, bool, int)):
        return obj
    if isinstance(obj, float) or isinstance(obj, np.floating):
        return _num(obj)
    if isinstance(obj, np.integer):
        return int(obj)
    if isinstance(obj, np.ndarray):
        return [_jsonable(v) for v in obj.tolist()]
    if isinstance(obj, dict) or hasattr(obj, "items"):
        return {str(k): _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_jsonable(v) for v in obj]
    if hasattr(obj, "value"):  # enums
        return _jsonable(obj.value)
    return str(obj)


def plot_curves(report, step: int) -> Figure:
    """FOS and cost against each parameter at one moment (others nominal): thesis Figs. 5–6."""
    box = report.scenario.box
    curves = report.curves[step]
    # fixed margins: a constrained layout would draw each of these figures twice
    fig = Figure(figsize=(5.2 * box.ndim, 6.4))
    fig.subplots_adjust(left=0.09, right=0.98, top=0.95, bottom=0.08, hspace=0.25,
                        wspace=0.26)
    axes = fig.subplots(2, box.ndim, squeeze=False)
    thr = report.scenario.cost.threshold
    for j, p in enumerate(box.parameters):
        res = curves[p.name]
        x = res.samples[:, j]
        ax = axes[0, j]
        ax.plot(x, np.clip(res.fos_grasp[0], 0, 10), label="FOS contact (grasp)")
        ax.plot(x, np.clip(res.fos_motor[0], 0, 10), label="FOS motor")
        ax.axhline(1.0, color="k", lw=0.6, ls=":")
        ax.set_ylabel("factor of safety (clipped at 10)")
        ax.set_title(f"step {step}: FOS vs {p.name}")
        ax.legend(fontsize="small")
        ax = axes[1, j]
        ax.plot(x, res.cost[0], color="k", label="cost")
        ax.plot(x, res.cost_contact[0], ls="--", label="contact term")
        ax.plot(x, res.cost_motor[0], ls="--", label="motor term")
        ax.axhline(thr, color="tab:red", lw=0.8, label=f"threshold {thr:g}")
        ax.axvline(p.nominal, color="tab:green", lw=0.8, ls=":", label="nominal")
        ax.set_xlabel(f"{p.name} [{p.unit}]" if p.unit else p.name)
        ax.set_ylabel("cost")
        ax.legend(fontsize="small")
    return fig


def plot_cost_map(report) -> Figure | None:
    """Max cost over the moments on a grid of the first two parameters."""
    if report.cost_map is None:
        return None
    n0, a0, n1, a1, grid = report.cost_map
    fig = Figure(figsize=(6.4, 5.0), layout="constrained")
    ax = fig.subplots()
    mesh = ax.pcolormesh(a0, a1, grid.T, shading="nearest", cmap="RdYlGn_r",
                         vmin=0, vmax=max(1.5, float(np.nanmax(grid))))
    thr = report.scenario.cost.threshold
    if np.nanmin(grid) < thr < np.nanmax(grid):
        ax.contour(a0, a1, grid.T, levels=[thr], colors="k", linewidths=1.2)
    fig.colorbar(mesh, ax=ax, label="max cost over the moments (nearest Sobol sample)")
    box = report.scenario.box
    ax.plot(box.nominal[0], box.nominal[1], "w*", ms=12, mec="k", label="nominal")
    ax.set_xlabel(n0)
    ax.set_ylabel(n1)
    ax.set_title(f"cost map (black line: cost = {thr:g})")
    ax.legend(loc="upper right", fontsize="small")
    return fig


def summary_text(report) -> str:
    """The terminal summary of an audit."""
    lo, hi = report.p_success_interval
    lines = [f"critmoment: {report.verdict.value} — {report.safe_region_text}",
             f"P(success) = {report.p_success:.3f} ({report.options.confidence:.0%} interval "
             f"{lo:.3f}–{hi:.3f}) over {report.sweep.n_samples if report.sweep else 0} samples "
             f"of the box; nominal max cost {report.nominal_cost:.3f} "
             f"(threshold {report.scenario.cost.threshold:g})"]
    for i, mr in enumerate(report.moments, 1):
        m = mr.moment
        crit = ", ".join(f"{k} {mr.critical_side[k]} {v:.3g}" for k, v in mr.critical.items()
                         if v is not None) or "never crosses"
        worst = ", ".join(f"{k}={v:.3g}" for k, v in mr.worst_case.items())
        lines.append(f"  {i}. {m.label.value:12s} step {m.step:5d} (t = {m.time:.2f} s): max cost "
                     f"{mr.max_cost:.3f} at {worst}; min FOS contact {mr.min_fos_contact:.3g}, "
                     f"motor {mr.min_fos_motor:.3g}; fails {mr.fail_fraction:.0%} of the box "
                     f"(reached by {mr.reached:.0%}); critical: {crit}")
    v = report.verification
    if v is not None:
        lines.append(f"  verification: {_verification_text(v)}")
    for cause in report.failure_causes:
        lines.append(f"  ! {cause}")
    return "\n".join(lines)


def write_report(report, out: str | Path) -> dict[str, Path]:
    """Write report.json, the figures and a self-contained report.html into ``out``."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    paths: dict[str, Path] = {}
    doc = report.to_json()
    paths["json"] = out / "report.json"
    paths["json"].write_text(json.dumps(doc, indent=2, allow_nan=False))
    figs = {"signals": plot_recording(report.recording,
                                      moments=[mr.moment for mr in report.moments])}
    for mr in report.moments:
        figs[f"moment_{mr.moment.step}"] = plot_curves(report, int(mr.moment.step))
    cmap = plot_cost_map(report)
    if cmap is not None:
        figs["cost_map"] = cmap
    images = {}
    for name, fig in figs.items():
        path = out / f"{name}.png"
        fig.savefig(path, dpi=100)
        paths[name] = path
        images[name] = base64.b64encode(path.read_bytes()).decode("ascii")
    paths["html"] = out / "report.html"
    paths["html"].write_text(_html(report, doc, images))
    return paths


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


def _verification_text(v) -> str:
    text = (f"{v['near']} sample(s) passing with cost ≥ {v['cost_from']:.3g} re-run in full, "
            f"{v['near_failed']} of them fail")
    if v.get("unlifted"):
        text += (f"; {v['unlifted']} failing only where the object is squeezed off its "
                 f"support without a lift re-run in full, {v['unlifted_failed']} of them fail")
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
            f"{mr['reached']:.0%}</span></td><td>{fc}</td><td>{fm} "
            f"<span class=muted>({e(mr['limiting_actuator'])})</span></td>"
            f"<td>{e(crit)}</td><td>{e(str(mr['dominant'] or '—'))}</td><td>{an_txt}</td></tr>")
    unc = "".join(
        f"<tr><td>{e(k)}</td><td>{e(v['target'])}</td><td>{v['range'][0]:g} – {v['range'][1]:g} "
        f"{e(v['unit'])}</td><td>{v['nominal']:g}</td><td>{e(v['prior'])}</td></tr>"
        for k, v in doc["uncertainty"].items())
    causes = "".join(f"<li>{e(c)}</li>" for c in doc["failure_causes"]) or "<li>none</li>"
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
<h2>Failure causes and suggestions</h2><ul>{causes}</ul>
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
