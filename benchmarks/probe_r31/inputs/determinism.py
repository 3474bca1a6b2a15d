"""Same seed twice (CLI, different path spellings) and nthread 1 vs 2 vs 0 (library): report.json identical but timings."""
import json, os, subprocess, sys
sys.path.insert(0, "/tmp/r31/src")
import critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src"), cm.__file__
from critmoment.analysis import AnalyzeOptions
CM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cm.sh")
W = "/tmp/r31/inputs/det"; os.makedirs(W, exist_ok=True)
if not os.path.lexists(f"{W}/lnk.npz"): os.symlink("/tmp/r31/inputs/traj.npz", f"{W}/lnk.npz")
def strip(d):
    if isinstance(d, dict): return {k: strip(v) for k, v in d.items() if k not in ("timings",) and "seconds" not in k}
    if isinstance(d, list): return [strip(v) for v in d]
    return d
def diff(a, b, path=""):
    out = []
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)): out += diff(a.get(k), b.get(k), f"{path}.{k}")
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)): out += diff(x, y, f"{path}[{i}]")
    elif a != b: out.append((path, str(a)[:80], str(b)[:80]))
    return out
reps = {}
for name, traj, cwd in (("abs", "/tmp/r31/inputs/traj.npz", W), ("rel", "../traj.npz", W), ("link", "lnk.npz", W)):
    p = subprocess.run([CM, "analyze", traj, "--samples", "8", "--json"], cwd=cwd, capture_output=True, text=True)
    reps[name] = strip(json.loads(p.stdout)); print(name, "rc", p.returncode, flush=True)
for n in ("rel", "link"): print(f"CLI abs vs {n}: {len(diff(reps['abs'], reps[n]))} differences", diff(reps["abs"], reps[n])[:5])
traj = cm.load_trajectory("/tmp/r31/inputs/traj.npz"); sc = cm.load_scenario()
lib = {}
for nt in (1, 2, 0):
    r = cm.analyze(traj, sc, options=AnalyzeOptions(n_samples=8, nthread=nt))
    lib[nt] = strip(json.loads(json.dumps(cm.report.jsonable(r.to_json())) if hasattr(cm, "report") else r.to_json()))
for nt in (2, 0): print(f"lib nthread 1 vs {nt}: {len(diff(lib[1], lib[nt]))} differences", diff(lib[1], lib[nt])[:5])
print("lib nthread=1 vs CLI:", len(diff(lib[1], reps["abs"])), diff(lib[1], reps["abs"])[:8])
