"""Shared helpers of the probe_r29/api scripts (run with PYTHONPATH=/tmp/r29/src)."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

SCRATCH = Path(os.environ.get("R29_SCRATCH", "/tmp/r29/api"))
SRC = os.environ.get("R29_SRC", "/tmp/r29/src")
PY = os.environ.get("R29_PY", "/work/venv/bin/python")
CLI = [PY, "-c", "import sys; from critmoment.cli import run; sys.argv[0]='critmoment'; "
       "sys.exit(run())"]


def env(**extra):
    e = dict(os.environ, PYTHONPATH=SRC)
    e.update(extra)
    return e


def cli(*args, cwd=None, timeout=600, **kw):
    """Runs the critmoment CLI from the snapshot; returns CompletedProcess."""
    return subprocess.run([*CLI, *map(str, args)], cwd=cwd, env=env(**kw.pop("env", {})),
                          capture_output=True, text=True, timeout=timeout, **kw)


def demo_traj(seed=0, name="traj.npz", family="nominal", scenario=None):
    p = SCRATCH / name
    if not p.exists():
        args = ["demo", "--seed", seed, "--out", p, "--family", family]
        if scenario:
            args += ["--scenario", scenario]
        r = cli(*args)
        assert r.returncode == 0, r.stderr
    return p


def strip(doc, drop=("timings",)):
    doc = dict(doc)
    for k in drop:
        doc.pop(k, None)
    return doc


def diff(a, b, path=""):
    """Paths where two JSON documents differ (first 20)."""
    out = []
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                out.append(f"{path}/{k}: only in {'b' if k not in a else 'a'}")
            else:
                out += diff(a[k], b[k], f"{path}/{k}")
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            out += diff(x, y, f"{path}[{i}]")
    elif a != b:
        out.append(f"{path}: {json.dumps(a)[:80]} != {json.dumps(b)[:80]}")
    return out[:40]


def check_src():
    import critmoment
    assert critmoment.__file__.startswith(SRC), critmoment.__file__
    print("critmoment from", critmoment.__file__, file=sys.stderr)
