"""Physics-breaking inputs through the library: CritmomentError or not, and the message.

    cd /tmp/r29/api && PYTHONPATH=/tmp/r29/src python api_physics_errors.py
(needs /tmp/r29/api/scwarn: the bundled ALOHA scenario copied with range_policy = "warn")
"""
import dataclasses
import sys
import warnings

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from common import SCRATCH, check_src, demo_traj  # noqa: E402

import critmoment as cm  # noqa: E402

check_src()
traj = cm.load_trajectory(demo_traj())
OPTS = cm.AnalyzeOptions(n_samples=8, nthread=1, search=False)
warn = str(SCRATCH / "scwarn")


def case(label, fn):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        try:
            r = fn()
            res = f"returned {type(r).__name__} " + (r.verdict.value if hasattr(r, "verdict") else
                                                     str(r.summary().get("completed")))
        except cm.CritmomentError as exc:
            res = f"CritmomentError/{type(exc).__name__}: {str(exc)[:300]}"
        except Exception as exc:  # noqa: BLE001
            res = f"NOT CritmomentError: {type(exc).__name__}: {str(exc)[:300]}"
    print(f"- {label}\n    {res}" + "".join(f"\n    warning {x.category.__name__}: {str(x.message)[:200]}"
                                            for x in w))


A = np.array(traj.actions)
big = A.copy()
big[150:160, 1] = 1e3
case("rollout, range_policy warn, shoulder target 1e3 rad", lambda: cm.rollout(
    dataclasses.replace(traj, actions=big), warn))
case("analyze, range_policy warn, shoulder target 1e3 rad", lambda: cm.analyze(
    dataclasses.replace(traj, actions=big), warn, options=OPTS))
pose = np.array(traj.object_pose)
pose[2] = -0.5
case("rollout, object 0.5 m below the table", lambda: cm.rollout(dataclasses.replace(traj, object_pose=pose)))
pose2 = np.array(traj.object_pose)
pose2[:3] = [5.0, 5.0, 0.02]
case("analyze, object 7 m away (never touched)", lambda: cm.analyze(dataclasses.replace(traj, object_pose=pose2), options=OPTS))
rec = None
m = cm.Twin(cm.load_scenario()).model
q0 = np.array(m.qpos0)
v0 = np.full(m.nv, 1e6)
case("rollout, qvel0 = 1e6 everywhere", lambda: cm.rollout(
    cm.Trajectory(actions=A, fps=50, qpos0=q0, qvel0=v0)))
case("analyze, qvel0 = 1e6 everywhere", lambda: cm.analyze(
    cm.Trajectory(actions=A, fps=50, qpos0=q0, qvel0=v0), options=OPTS))
case("analyze, constant actions (robot never moves)", lambda: cm.analyze(
    cm.Trajectory(actions=np.repeat(A[:1], 400, 0), fps=50, start=traj.start,
                  object_pose=traj.object_pose), options=OPTS))
