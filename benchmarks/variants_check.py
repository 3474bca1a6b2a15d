"""The bundled twins under contact models, object shapes and parameters they were not tuned
for: ``validate`` (the audit's own decision path against brute-force full rollouts) per
variant, each a copy of the bundled scene with one change.

1. ALOHA transfer cube (demo seed ``--seed``, mass 0.05..``--mass-high`` kg, friction
   0.2..1.5): the cube's condim 3 or 6, a softer solref (0.03 s), noslip (10 iterations), a
   pyramidal cone with impratio 1, an elliptic cone with impratio 1, a 2 mm contact margin,
   the Euler and RK4 integrators.
2. Panda pick-and-place (seed 0, mass 0.05..1.5 kg): the object a cylinder, a sphere, a
   capsule lying down, an ellipsoid instead of the cube.
3. Panda pick-and-place with a five-parameter box: mass, friction, the cube's centre-of-mass
   offset (±15 mm), the left finger's force limit (2..20 N) and the shoulder's (20..87 N·m);
   seeds 0 and 3, 64 samples.

Usage::

    PYTHONPATH=. python benchmarks/variants_check.py [--seed 0] [--samples 32] [--mass-high 0.6]

Prints one line per case: the confusion counts (false_safe must be 0) and the real
failures. See docs/validation.md (twentieth round).
"""

from __future__ import annotations

import argparse
import shutil
import tempfile
import time
import warnings
from pathlib import Path

import critmoment as cm
from critmoment import demos, panda_demo

MODELS = Path(__file__).resolve().parent.parent / "models"

ALOHA = {
    "condim 3": ('condim="4" priority="1"', 'condim="3" priority="1"'),
    "condim 6": ('condim="4" priority="1"', 'condim="6" priority="1"'),
    "solref 0.03": ('solref="0.01 1"/>', 'solref="0.03 1"/>'),
    "noslip 10": ('impratio="10"/>', 'impratio="10" noslip_iterations="10"/>'),
    "pyramidal, impratio 1": ('cone="elliptic" impratio="10"', 'cone="pyramidal" impratio="1"'),
    "elliptic, impratio 1": ('impratio="10"', 'impratio="1"'),
    "margin 2 mm": ('solref="0.01 1"/>', 'solref="0.01 1" margin="0.002"/>'),
    "Euler": ('integrator="implicitfast"', 'integrator="Euler"'),
    "RK4": ('integrator="implicitfast"', 'integrator="RK4"'),
}
CUBE = 'type="box" size="0.02 0.02 0.02" mass="0.1"'
SHAPES = {
    "cylinder": (CUBE, 'type="cylinder" size="0.02 0.02" mass="0.1"'),
    "sphere": (CUBE, 'type="sphere" size="0.02" mass="0.1"'),
    "capsule lying": (CUBE, 'type="capsule" size="0.02 0.02" euler="1.5708 0 0" mass="0.1"'),
    "ellipsoid": (CUBE, 'type="ellipsoid" size="0.02 0.025 0.02" mass="0.1"'),
}
EXTRA = """
[uncertainty.com]
kind = "com_offset"
body = "cube"
range = [-0.015, 0.015]
nominal = 0.0

[uncertainty.grip]
kind = "force_limit"
actuator = "finger_left"
range = [2.0, 20.0]
nominal = 20.0

[uncertainty.shoulder]
kind = "force_limit"
actuator = "joint2"
range = [20.0, 87.0]
nominal = 87.0
"""


def _copy(src: Path, work: Path, name: str, old: str, new: str, extra: str = "") -> Path:
    out = work / name.replace(" ", "_").replace(",", "")
    shutil.copytree(src, out)
    scene = out / "scene.xml"
    text = scene.read_text()
    if old not in text:
        raise SystemExit(f"{name}: {old!r} not in {src / 'scene.xml'}")
    scene.write_text(text.replace(old, new))
    if extra:
        with (out / "scenario.toml").open("a") as f:
            f.write(extra)
    return out


def _validate(label: str, folder: Path, make, mass_high: float, samples: int) -> int:
    t0 = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sc = cm.load_scenario(folder)
        twin = cm.Twin(sc.replace(box=sc.box.with_range("mass", 0.05, mass_high)))
        traj = make(twin)
        result = cm.validate(traj, twin=twin, n_samples=samples, seed=0)
    c = result.confusion
    print(f"{label}: {c}, real failures {int(result.real_failed.sum())}/{samples}, "
          f"agreement {(c['true_safe'] + c['true_unsafe']) / samples:.3f} "
          f"({time.perf_counter() - t0:.0f} s)", flush=True)
    return c["false_safe"]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--samples", type=int, default=32)
    parser.add_argument("--mass-high", type=float, default=0.6)
    args = parser.parse_args()
    false_safes = 0
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        for name, (old, new) in ALOHA.items():
            folder = _copy(MODELS / "aloha_transfer_cube", work, f"aloha {name}", old, new)
            false_safes += _validate(
                f"ALOHA seed {args.seed}, {name}", folder,
                lambda twin: demos.scripted_transfer(args.seed, twin=twin), args.mass_high,
                args.samples)
        for name, (old, new) in SHAPES.items():
            folder = _copy(MODELS / "panda_pick_place", work, f"panda {name}", old, new)
            false_safes += _validate(
                f"Panda seed 0, {name}", folder,
                lambda twin: panda_demo.make_pick_place(0, model=twin.model), 1.5, args.samples)
        folder = _copy(MODELS / "panda_pick_place", work, "panda five", CUBE, CUBE, EXTRA)
        for seed in (0, 3):
            false_safes += _validate(
                f"Panda seed {seed}, mass, friction, com offset, finger and shoulder limits",
                folder, lambda twin, s=seed: panda_demo.make_pick_place(s, model=twin.model),
                1.5, 2 * args.samples)
    print(f"false safes in all: {false_safes}")
    raise SystemExit(1 if false_safes else 0)


if __name__ == "__main__":
    main()
