"""Shared helpers for probe r33: run the snapshot's CLI, compare reports."""
import json, os, subprocess, sys, time
SRC = "/tmp/r33/src"
sys.path.insert(0, SRC)
import critmoment  # noqa: E402
assert critmoment.__file__.startswith(SRC), critmoment.__file__
CM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cm.sh")
SCRATCH = "/tmp/r33/inputs"
RES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "results")
os.makedirs(RES, exist_ok=True)


def cm(*args, env=None, cwd=SCRATCH, timeout=900, cpu="0"):
    e = dict(os.environ)
    e.update(env or {})
    t = time.time()
    p = subprocess.run(["taskset", "-c", cpu, CM, *map(str, args)], capture_output=True,
                       text=True, env=e, cwd=cwd, timeout=timeout)
    return p.returncode, p.stdout, p.stderr, time.time() - t


def strip(doc):
    doc = dict(doc)
    doc.pop("timings", None)
    return doc


def diff(a, b, path=""):
    """List of paths where two JSON docs differ."""
    out = []
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                out.append(f"{path}/{k} missing on one side")
            else:
                out += diff(a[k], b[k], f"{path}/{k}")
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)):
            out += diff(x, y, f"{path}[{i}]")
    elif a != b:
        out.append(f"{path}: {str(a)[:80]} != {str(b)[:80]}")
    return out


def log(name, line):
    print(line, flush=True)
    with open(os.path.join(RES, name), "a") as f:
        f.write(line + "\n")
