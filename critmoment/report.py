"""Figures, JSON, HTML and terminal summaries.

Figures use matplotlib's object-oriented API (no pyplot state), so they render
under any backend and in threads.
"""

from __future__ import annotations

import base64
import html
import io
import json
from pathlib import Path
from typing import Sequence

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
