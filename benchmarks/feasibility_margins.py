"""Tracking lag and saturation of the bundled scenario's trajectory families, seeds 0–19.

    python benchmarks/feasibility_margins.py [--seeds 20] [--families nominal fast ...]

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
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    twin = cm.Twin(cm.load_scenario())
    print("family         arm lag max [rad] (joint)   arm lag>tol [s]  arm sat [s] (actuator)"
          "   grip lag max [m]  grip sat [s]  infeasible  fit warnings")
    for family in args.families:
        arm_lag, arm_joint, arm_run, arm_sat, sat_act = 0.0, "", 0.0, 0.0, ""
        grip_lag, grip_sat, bad, fits = 0.0, 0.0, 0, 0
        for seed in range(args.seeds):
            traj = suite.make(family, seed=seed, twin=twin)
            rec = cm.rollout(traj, twin=twin)
            rep = feasibility.check_feasibility(rec, twin, raise_on_failure=False)
            bad += not rep.feasible
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
              f"      {bad:3d}/{args.seeds}     {fits:3d}/{args.seeds}")


if __name__ == "__main__":
    main()
