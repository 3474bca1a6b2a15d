"""Four small robots authored here to probe critmoment on models unlike the bundled ones.

    python benchmarks/probe_robots/run.py [--samples 32] [--only s1/scenario.toml ...]

* ``s1``: a 4-DoF arm in ``<compiler angle="degree">``, position servos geared 2:1 (the
  scenario's ``scales = [2]``), one hinge jaw closing on a fixed jaw; ``scene_motor.xml``
  the same arm on geared torque motors through ``[servos]``;
* ``s2``: a 5-DoF arm with a Menagerie-style hand (two slide fingers on one tendon servo and
  a joint equality), a cylinder;
* ``s3``: torque motors through ``[servos]``, implicitfast at 1 ms, armature, damping and
  frictionloss, filtered finger servos, a sphere held (pick_hold); ``scene_filt_rk4.xml``
  general filterexact servos, RK4 at 5 ms;
* ``s4``: the arm in its own folder pulled in by ``<include>``, a mesh block, a distractor,
  hinge fingers coupled by an equality.

Each folder's ``mk.py`` writes its ``traj.npz`` (damped-least-squares IK waypoints, checked in
plain MuJoCo); then ``critmoment validate`` runs each case and its false safes and agreement
are printed. About 1-2 minutes per case on 2 cores.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
CASES = ("s1/scenario.toml", "s1/scen_nolim.toml", "s1/scen_ell.toml", "s1/scen_motor.toml",
         "s2/scenario.toml", "s2/scen_ell.toml", "s3/scenario.toml", "s3/scen_ell.toml",
         "s3/scen_nm.toml", "s3/scen_filt.toml", "s3/scen_filt_narrow.toml",
         "s4/scenario.toml", "s4/scen_ell.toml")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--samples", type=int, default=32)
    parser.add_argument("--only", nargs="*", default=None)
    args = parser.parse_args()
    cases = args.only or CASES
    made = set()
    for case in cases:
        folder = HERE / Path(case).parent
        if folder not in made:
            subprocess.run([sys.executable, "mk.py"], cwd=folder, check=True,
                           capture_output=True)
            made.add(folder)
        proc = subprocess.run(["critmoment", "validate", "traj.npz", "--scenario",
                               Path(case).name, "--samples", str(args.samples), "--json"],
                              cwd=folder, capture_output=True, text=True)
        if proc.returncode == 2:
            print(f"{case}: error: {proc.stderr.strip().splitlines()[-1]}")
            continue
        doc = json.loads(proc.stdout)
        print(f"{case}: false-safe rate {doc['false_safe_rate']}, vacuous {doc['vacuous']}, agreement "
              f"{doc['agreement']:.3f}, exit {proc.returncode}")


if __name__ == "__main__":
    main()
