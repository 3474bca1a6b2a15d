"""Tracking lag and saturation of the bundled scenarios' trajectories, seeds 0–19.

    python benchmarks/feasibility_margins.py [--seeds 20] [--families nominal fast ...]
        [--delay 0.1] [--panda]

The ALOHA families of :mod:`critmoment.suite` and, with ``--panda``, the Panda
pick-and-place demo (:func:`critmoment.panda_demo.make_pick_place`).

Runs the nominal frequent rollout of each family and seed, then
:func:`critmoment.feasibility.check_feasibility` without raising, and prints per family the
largest arm lag [rad], the longest arm lag above tolerance [s], the longest arm and gripper
saturation [s], the largest gripper lag [m] and the fit warnings. The default tolerances of
:class:`~critmoment.feasibility.FeasibilityOptions` are set from these numbers with margin
(``docs/method.md``, "Feasibility and fit checks").
"""

import argparse
import warnings

import numpy as np

import critmoment as cm
from critmoment import feasibility, suite


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seeds", type=int, default=20)
    parser.add_argument("--families", nargs="*", default=list(suite.FAMILIES))
    parser.add_argument("--delay", type=float, default=feasibility.FeasibilityOptions().delay,
                        help="delay allowance of the lag [s] (0: the plain |q - target|)")
    parser.add_argument("--panda", action="store_true", help="the Panda scenario instead")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    options = feasibility.FeasibilityOptions(delay=args.delay)
    if args.panda:
        from critmoment import panda_demo

        twin = cm.Twin(cm.load_scenario("panda_pick_place"))
        families = {"panda": lambda seed: panda_demo.make_pick_place(seed)}
    else:
        twin = cm.Twin(cm.load_scenario())
        families = {f: (lambda seed, f=f: suite.make(f, seed=seed, twin=twin))
                    for f in args.families}
    print("family         arm lag max [rad] (joint)   arm lag>tol [s]  arm sat [s] (actuator)"
          "   grip lag max [m]  grip sat [s]  infeasible  held back  fit warnings")
    for family, make in families.items():
        arm_lag, arm_joint, arm_run, arm_sat, sat_act = 0.0, "", 0.0, 0.0, ""
        grip_lag, grip_sat, bad, fits, held = 0.0, 0.0, 0, 0, 0
        for seed in range(args.seeds):
            traj = make(seed)
            rec = cm.rollout(traj, twin=twin)
            rep = feasibility.check_feasibility(rec, twin, options=options,
                                                raise_on_failure=False)
            bad += not rep.feasible
            held += bool(rep.warnings)
            fits += bool(feasibility.check_fit(traj, rec, twin))
            for j in rep.joints:
                if j.gripper:
                    grip_lag = max(grip_lag, np.nan_to_num(j.max_lag))
                    grip_sat = max(grip_sat, j.saturation_duration)
                    continue
                if j.max_lag > arm_lag:
                    arm_lag, arm_joint = j.max_lag, f"{j.joint}, seed {seed}"
                arm_run = max(arm_run, j.lag_duration)
                if j.saturation_duration > arm_sat:
                    arm_sat, sat_act = j.saturation_duration, f"{j.actuator}, seed {seed}"
        print(f"{family:14s} {arm_lag:8.4f} ({arm_joint:24s}) {arm_run:8.3f}       "
              f"{arm_sat:8.3f} ({sat_act or '-':24s}) {grip_lag:8.4f}        {grip_sat:8.3f}"
              f"      {bad:3d}/{args.seeds}     {held:3d}/{args.seeds}    {fits:3d}/{args.seeds}")


if __name__ == "__main__":
    main()
