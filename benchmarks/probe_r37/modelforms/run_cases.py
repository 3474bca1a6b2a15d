"""inspect -> init -> rollout -> analyze (32 samples) for each model variant of make_models.py.

Run: PYTHONPATH=/tmp/r37/src /work/venv/bin/python run_cases.py [CASE ...]
Writes /tmp/r37/modelforms/runs/<case>/ and appends one JSON line per case to results/cases.jsonl.
"""
import json
import subprocess
import sys
from pathlib import Path

import common  # noqa: F401

HERE = Path(__file__).resolve().parent
CM = str(HERE / "cm.sh")
M = Path("/tmp/r37/modelforms/models")
RUNS = Path("/tmp/r37/modelforms/runs")
TRAJ = "/tmp/r37/modelforms/panda.npz"
NOQ = "/tmp/r37/modelforms/panda_noq.npz"  # no qpos0: for models with more coordinates
GOAL = ["--goal", "0.5", "0.15", "0.02"]
# case: (scene, init args, trajectory)
CASES = {
    "base": ("/tmp/r37/modelforms/base/scene.xml", ["--object", "cube"], TRAJ),
    "inc_chain": (M / "inc_chain/scenes/pick/scene.xml", ["--object", "cube"], TRAJ),
    "inc_assetdir": (M / "inc_assetdir/scenes/pick/scene.xml", ["--object", "cube"], TRAJ),
    "inc_flat": (M / "inc_flat/scene.xml", ["--object", "cube"], TRAJ),
    "frame": (M / "frame/scene.xml", ["--object", "cube"], TRAJ),
    "replicate": (M / "replicate/scene.xml", ["--object", "cube0"], NOQ),
    "replicate_flat": (M / "replicate_flat/scene.xml", ["--object", "cube0"], NOQ),
    "replicate_c1": (M / "replicate/scene.xml", ["--object", "cube1"], NOQ),
    "base_noq": ("/tmp/r37/modelforms/base/scene.xml", ["--object", "cube"], NOQ),
    "urdf": ("/tmp/r37/modelforms/urdf/scene.xml", ["--object", "cube"], "/tmp/r37/modelforms/urdf/gantry.npz"),
    "attach": (M / "attach/scene.xml", ["--object", "cube"], TRAJ),
    "attach_obj": (M / "attach_obj/scene.xml", ["--object", "o_cube"], TRAJ),
    "visual": (M / "visual/scene.xml", ["--object", "cube"], TRAJ),
    "defaults": (M / "defaults/scene.xml", ["--object", "cube"], TRAJ),
    "degree": (M / "degree/scene.xml", ["--object", "cube"], TRAJ),
    "degree_ctrl": (M / "degree_ctrl/scene.xml", ["--object", "cube"], TRAJ),
    "noautolimits": (M / "noautolimits/scene.xml", ["--object", "cube"], TRAJ),
    "keyframe": (M / "keyframe/scene.xml", ["--object", "cube"], TRAJ),
    "flex": (M / "flex/scene.xml", ["--object", "cube"], NOQ),
    "plugin": (M / "plugin/scene.xml", ["--object", "cube"], TRAJ),
    "mocap": (M / "mocap/scene.xml", ["--object", "cube"], TRAJ),
    "weld": (M / "weld/scene.xml", ["--object", "cube"], TRAJ),
    "exclude": (M / "exclude/scene.xml", ["--object", "cube"], TRAJ),
    "slides": (M / "slides/scene.xml", ["--object", "cube"], TRAJ),
    "fixed": (M / "fixed/scene.xml", ["--object", "cube"], TRAJ),
    "twomesh": (M / "twomesh/scene.xml", ["--object", "cube_a"], NOQ),
    "nested": (M / "nested/scene.xml", ["--object", "cube"], TRAJ),
}


def run(args, out=None):
    p = subprocess.run([CM, *map(str, args)], capture_output=True, text=True)
    if out:
        Path(out).write_text(p.stdout)
    err = [ln for ln in p.stderr.splitlines() if ln.strip()]
    return p.returncode, p.stdout, err


def case(name, extra_init=()):
    scene, init_args, traj = CASES[name]
    d = RUNS / name
    d.mkdir(parents=True, exist_ok=True)
    rec = {"case": name, "scene": str(scene)}
    rc, out, err = run(["inspect", scene], d / "inspect.txt")
    rec["inspect"] = [rc, err[-1:] if rc else [ln for ln in out.splitlines() if "free bodies" in ln or "note" in ln.lower()][:4]]
    toml = d / "scenario.toml"
    rc, out, err = run(["init", scene, *init_args, "--task", "pick_place", *GOAL, *extra_init, "--out", toml, "--force"])
    rec["init"] = [rc, err if rc else [ln for ln in err if ln.startswith(("critmoment", "warning", "note"))]]
    if rc:
        print(json.dumps(rec, ensure_ascii=False))
        return rec
    rc, out, err = run(["rollout", traj, "--scenario", toml, "--json"], d / "rollout.json")
    try:
        r = json.loads(out)
        rec["rollout"] = [rc, {k: r.get(k) for k in ("completed", "max_stage", "shortfalls", "min_fos_motor", "fit_warnings")}, err]
    except ValueError:
        rec["rollout"] = [rc, None, err]
    rc, out, err = run(["analyze", traj, "--scenario", toml, "--samples", 32, "--figures", "none", "--json"], d / "report.json")
    try:
        r = json.loads(out)
        rec["analyze"] = [rc, r["verdict"], r["p_success"], r["safe_region_text"][:70],
                          r["manifest"]["model_sha256"][:12], r["warnings"]]
    except ValueError:
        rec["analyze"] = [rc, None, err[-3:]]
    print(json.dumps(rec, ensure_ascii=False))
    return rec


if __name__ == "__main__":
    names = sys.argv[1:] or list(CASES)
    (HERE / "results").mkdir(exist_ok=True)
    with open(HERE / "results/cases.jsonl", "a") as f:
        for n in names:
            f.write(json.dumps(case(n), ensure_ascii=False) + "\n")
            f.flush()
