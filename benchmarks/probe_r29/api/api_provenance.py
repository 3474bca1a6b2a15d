"""What report.json's manifest says about the trajectory that was audited.

    cd /tmp/r29/api && PYTHONPATH=/tmp/r29/src python api_provenance.py
"""
import dataclasses
import hashlib
import os
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from common import SCRATCH, check_src, demo_traj  # noqa: E402

import critmoment as cm  # noqa: E402

check_src()
os.chdir(SCRATCH)
tp = demo_traj()
file_hash = hashlib.sha256(tp.read_bytes()).hexdigest()
OPTS = cm.AnalyzeOptions(n_samples=16, nthread=1, search=False)
traj = cm.load_trajectory(tp)


def show(label, t):
    r = cm.analyze(t, options=OPTS)
    m = r.manifest
    print(f"{label}: verdict {r.verdict.value} p={r.p_success:.3f}; manifest trajectory="
          f"{m['trajectory']!r} sha256={'<the file>' if m['trajectory_sha256'] == file_hash else m['trajectory_sha256']}")


show("1 loaded from traj.npz", traj)
# 2: the actions edited in code (a service that perturbs or trims a loaded trajectory)
edited = dataclasses.replace(traj, actions=traj.actions * np.r_[np.ones(13), 0.0])
show("2 replace(traj, actions=right gripper forced closed)", edited)
# 3: the object pose replaced in code
moved = dataclasses.replace(traj, object_pose=np.r_[0.20, traj.object_pose[1:]])
show("3 replace(traj, object_pose x=0.20)", moved)
# 4: built in code with no source
built = cm.Trajectory(actions=traj.actions, fps=traj.fps, start=traj.start,
                      object_pose=traj.object_pose)
show("4 Trajectory(...) built in code", built)
# 5: built in code, source a description that happens to name a file in the cwd
other = cm.Trajectory(actions=traj.actions * np.r_[np.ones(13), 0.0], fps=traj.fps,
                      start=traj.start, object_pose=traj.object_pose, source="traj.npz")
show("5 Trajectory(edited actions, source='traj.npz') in a cwd holding traj.npz", other)
