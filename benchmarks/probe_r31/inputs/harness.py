"""Run one critmoment command (snapshot /tmp/r31/src), classify the result, log it."""
import json, os, subprocess, time
CM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cm.sh")
LOG = os.environ.get("PROBE_LOG", "/tmp/r31/inputs/log.jsonl")
def run(args, name=None, cwd="/tmp/r31/inputs/work", env=None, timeout=600, expect=None, json_out=False, quiet=False):
    os.makedirs(cwd, exist_ok=True)
    e = dict(os.environ); e.update(env or {})
    t = time.time()
    p = subprocess.run([CM] + args, cwd=cwd, env=e, capture_output=True, text=True, timeout=timeout)
    dt = time.time() - t
    err = p.stderr; flags = []
    if p.returncode not in (0, 1, 2): flags.append(f"RC{p.returncode}")
    if "Traceback" in err: flags.append("TRACEBACK")
    if "a bug in critmoment" in err: flags.append("BUG")
    errlines = [l for l in err.splitlines() if ": error:" in l]
    if p.returncode == 2 and len(errlines) != 1: flags.append(f"ERRLINES={len(errlines)}")
    if json_out and p.returncode in (0, 1):
        try: json.loads(p.stdout)
        except Exception as ex: flags.append(f"BADJSON:{ex}"[:80])
    if expect is not None and p.returncode != expect: flags.append(f"EXPECTED{expect}")
    rec = dict(name=name or " ".join(args), args=args, rc=p.returncode, dt=round(dt, 1), flags=flags,
               stderr=err.strip().splitlines()[:4], stdout_head=p.stdout[:300])
    with open(LOG, "a") as f: f.write(json.dumps(rec) + "\n")
    if not quiet:
        print(f"[{p.returncode}] {dt:5.1f}s {' '.join(flags)} :: {rec['name']}\n    " + "\n    ".join(rec['stderr'])[:700], flush=True)
    return p
