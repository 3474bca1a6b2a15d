"""Three more small robots authored here to probe critmoment on models unlike the bundled
ones and unlike ``benchmarks/probe_robots`` (s1..s4).

    python benchmarks/probe_robots2/run.py [--samples 32] [--only g1/scenario.toml ...]

* ``g1``: a Cartesian gantry (x, y, z slides and a yaw hinge) with an ``<adhesion>`` suction
  cup (hand-written scenario, from before ``critmoment init`` guessed suction grippers),
  a 0.01 kg box dropped
  into a bin; variants: hand-written ``<general>`` affine servos (``scene_gen``), 0.5 ms step
  with warm start off and a pyramidal cone (``scene_fine``), ``pick_hold`` (``scen_hold``);
  a pure three-slide gantry (``scene_3ax``, audited on its slides); refused: ``<velocity>``
  axes (``scene_vel``);
* ``scara``: a SCARA arm (two hinges, a quill slide, a wrist hinge) with two slide fingers
  on condim 6 pads, implicit integrator at 4 ms, gravity tilted by 0.4 m/s² in x, an
  ellipsoid carried onto a raised shelf; one-change variants: condim 3 / 4, pyramidal
  impratio 1, soft pad solref/solimp, pad margin/gap, noslip 5, warm start off;
* ``arm7``: a 7-DoF redundant arm on hand-written ``<general>`` affine servos (degree
  model), two independently driven hinge jaws with condim 4 pads, a capsule lying on a
  support tilted 12° on a post, placed on a tray; variants: a sphere on a flat post, a
  0.01 kg ellipsoid, one servo with gain 2·kp and a bias offset (init's scales/offsets), a
  0.5 ms step, a 20° ramp; refused: ``<intvelocity>`` arm (``scene_intvel``).

Each folder's ``mk.py`` (and ``variants.py`` / ``gen.py``, which write the variant XMLs)
writes its trajectories (scripted joint-space waypoints, checked in plain MuJoCo); then
``critmoment validate`` runs each case and its false safes, agreement and wall time are
printed. About 5-80 s per case on 2 cores. ``bf.py`` runs brute-force full rollouts at
chosen parameter points.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
MAKE = {
    "g1": [["variants.py"], ["mk.py"], ["mk_extra.py"]],
    "scara": [["variants.py"], ["mk.py"]] + [["mk.py", f"scene_{v}.xml", f"traj_{v}.npz"]
                                             for v in ("c3", "c4", "pyr", "soft", "margin", "noslip", "nows")],
    "arm7": [["gen.py"], ["mk.py"]] + [["mk.py", f"scene_{v}.xml", f"traj_{v}.npz"]
                                       for v in ("sphere", "light", "offset", "fine", "steep")],
}
CASES = (("g1/scenario.toml", "traj.npz"), ("g1/scen_wide.toml", "traj.npz"),
         ("g1/scen_gen.toml", "traj.npz"), ("g1/scen_fine.toml", "traj.npz"),
         ("g1/scen_hold.toml", "traj_hold.npz"), ("g1/scen_vel.toml", "traj.npz"),
         ("g1/scen_3ax.toml", "traj_3ax.npz"),
         ("scara/scenario.toml", "traj.npz"))
CASES += tuple((f"scara/scen_{v}.toml", f"traj_{v}.npz")
               for v in ("c3", "c4", "pyr", "soft", "margin", "noslip", "nows"))
CASES += (("arm7/scenario.toml", "traj.npz"), ("arm7/scen_tol.toml", "traj.npz"))
CASES += tuple((f"arm7/scen_{v}.toml", f"traj_{v}.npz")
               for v in ("sphere", "light", "offset", "fine", "steep"))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--samples", type=int, default=32)
    parser.add_argument("--only", nargs="*", default=None)
    args = parser.parse_args()
    cases = [c for c in CASES if not args.only or c[0] in args.only]
    made = set()
    for scen, traj in cases:
        folder = Path(scen).parent
        if folder not in made:
            for cmd in MAKE[str(folder)]:
                subprocess.run([sys.executable, *cmd], cwd=HERE / folder, check=True,
                               capture_output=True)
            made.add(folder)
        t0 = time.perf_counter()
        proc = subprocess.run(["critmoment", "validate", traj, "--scenario", Path(scen).name,
                               "--samples", str(args.samples), "--json"],
                              cwd=HERE / folder, capture_output=True, text=True)
        wall = time.perf_counter() - t0
        if proc.returncode == 2:
            print(f"{scen}: error ({wall:.1f} s): {proc.stderr.strip().splitlines()[-1]}")
            continue
        doc = json.loads(proc.stdout)
        c = doc["confusion"]
        print(f"{scen}: samples {doc['samples']}, false safes {c['false_safe']}, false unsafes "
              f"{c['false_unsafe']}, agreement {doc['agreement']:.3f}, vacuous {doc['vacuous']}, "
              f"exit {proc.returncode}, {wall:.1f} s")


if __name__ == "__main__":
    main()
