"""Tiny harness: run a critmoment command, classify the result."""
import json
import os
import subprocess
import time

CM = "/tmp/r28/cli/venv/bin/critmoment"
LOG = os.environ.get("PROBE_LOG", "/tmp/r28/cli/probe_log.jsonl")

def run(args, name=None, cwd="/tmp/r28/cli/work", env=None, timeout=300, expect=None, json_out=False):
    os.makedirs(cwd, exist_ok=True)
    e = dict(os.environ); e.update(env or {})
    t = time.time()
    p = subprocess.run([CM] + args, cwd=cwd, env=e, capture_output=True, text=True, timeout=timeout)
    dt = time.time() - t
    err = p.stderr
    flags = []
    if p.returncode not in (0, 1, 2): flags.append(f"RC{p.returncode}")
    if "Traceback" in err: flags.append("TRACEBACK")
    errlines = [l for l in err.splitlines() if ": error:" in l]
    if p.returncode == 2 and len(errlines) != 1: flags.append(f"ERRLINES={len(errlines)}")
    if p.returncode == 2 and err.strip() and len(err.strip().splitlines()) != 1: flags.append("MULTILINE_STDERR")
    if json_out:
        try: json.loads(p.stdout)
        except Exception as ex: flags.append(f"BADJSON:{ex}"[:80])
    if expect is not None and p.returncode != expect: flags.append(f"EXPECTED{expect}")
    rec = dict(name=name or " ".join(args), rc=p.returncode, dt=round(dt, 1), flags=flags,
               stderr_tail=err.strip().splitlines()[-3:] if err.strip() else [], stdout_head=p.stdout[:300])
    with open(LOG, "a") as f: f.write(json.dumps(rec) + "\n")
    print(f"[{p.returncode}] {dt:5.1f}s {' '.join(flags)} :: {rec['name']}\n    " + "\n    ".join(rec['stderr_tail'])[:600], flush=True)
    return p
