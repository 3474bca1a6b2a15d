"""One process: analyze/validate/rollout repeatedly, Scenario and Twin objects reused,
seeds, pickling, to_json round trip; compared with the CLI's report.json.

    PYTHONPATH=/tmp/r29/src python api_repeat.py
"""
import json
import pickle
import sys
import time

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from common import SCRATCH, check_src, cli, demo_traj, diff, strip  # noqa: E402

import critmoment as cm  # noqa: E402

check_src()
tp = demo_traj()
traj = cm.load_trajectory(tp)
OPTS = cm.AnalyzeOptions(n_samples=32, nthread=1)
sc = cm.load_scenario()
twin = cm.Twin(sc)
docs = {}


def run(name, fn):
    t = time.perf_counter()
    r = fn()
    print(f"{name}: {r.verdict.value} p={r.p_success:.4f} ({time.perf_counter() - t:.1f} s)")
    docs[name] = r.to_json(timings=False)
    return r


r_a = run("analyze(traj, sc)", lambda: cm.analyze(traj, sc, options=OPTS))
r_b = run("analyze(traj, twin=twin)", lambda: cm.analyze(traj, twin=twin, options=OPTS))
v1 = cm.validate(traj, twin=twin, n_samples=16, nthread=1)
rec = cm.rollout(traj, twin=twin)
r_c = run("analyze(twin) after validate+rollout", lambda: cm.analyze(traj, twin=twin, options=OPTS))
r_d = run("analyze(traj, sc) again", lambda: cm.analyze(traj, sc, options=OPTS))
v2 = cm.validate(traj, twin=twin, n_samples=16, nthread=1)
r_e = run("analyze(traj, twin) seed=1", lambda: cm.analyze(traj, twin=twin, options=OPTS, seed=1))
r_f = run("analyze(traj, twin) seed=0 after seed=1", lambda: cm.analyze(traj, twin=twin, options=OPTS))

base = docs["analyze(traj, sc)"]
for k, d in docs.items():
    print(f"  {k}: diff vs first: {diff(base, d) if 'seed=1' not in k else len(diff(base, d))}")
print("seed 0 vs seed 1 differing top-level keys:",
      sorted({p.split('/')[1].split('[')[0] for p in diff(base, docs['analyze(traj, twin) seed=1'])}))
print("validate twice identical:", v1.to_json(timings=False) == v2.to_json(timings=False))

# CLI report of the same trajectory, seed, samples
out = SCRATCH / "repeat_cli"
r = cli("analyze", tp, "--samples", 32, "--figures", "none", "--out", out)
print("CLI rc", r.returncode)
cdoc = json.loads((out / "report.json").read_text())
print("CLI vs API diff:", diff(strip(cdoc), base))

# to_json round trip
s = json.dumps(base, allow_nan=False)
print("to_json JSON round trip equal:", json.loads(s) == base)

# pickling (what multiprocessing needs)
for name, obj in [("Trajectory", traj), ("Scenario", sc), ("Twin", twin), ("AuditReport", r_a),
                  ("Recording", rec), ("ValidationResult", v1), ("AnalyzeOptions", OPTS)]:
    try:
        back = pickle.loads(pickle.dumps(obj))
        extra = ""
        if name == "AuditReport":
            extra = f" to_json equal after unpickle: {back.to_json(timings=False) == base}"
        if name == "Twin":
            r2 = cm.analyze(traj, twin=back, options=OPTS)
            extra = f" analyze on unpickled twin == base: {not diff(base, r2.to_json(timings=False))}"
        print(f"pickle {name}: ok ({len(pickle.dumps(obj))} bytes){extra}")
    except Exception as exc:  # noqa: BLE001
        print(f"pickle {name}: FAILS {type(exc).__name__}: {str(exc)[:200]}")

# exceptions through pickle (a ProcessPool worker's error comes back pickled)
from critmoment.exceptions import (  # noqa: E402
    InfeasibleTwinError,
    OutputError,
    ResourceLimitError,
    SimulationDivergedError,
)

for exc in [SimulationDivergedError("diverged", step=12), InfeasibleTwinError("lag", report="R"),
            OutputError("x"), ResourceLimitError("y")]:
    try:
        back = pickle.loads(pickle.dumps(exc))
        print(f"pickle {type(exc).__name__}: ok; attrs after: "
              f"{ {k: getattr(back, k, None) for k in ('step', 'report')} } "
              f"before: { {k: getattr(exc, k, None) for k in ('step', 'report')} }")
    except Exception as e:  # noqa: BLE001
        print(f"pickle {type(exc).__name__}: FAILS {type(e).__name__}: {e}")

print("top-level exports of OutputError/ResourceLimitError/CritmomentWarning:",
      [n for n in ("OutputError", "ResourceLimitError", "CritmomentWarning")
       if hasattr(cm, n) and n in cm.__all__])
