"""Trajectory forms (case 5) built from the ALOHA demo (aloha.npz) and the Panda demo (panda.npz).

Run from /tmp/r37/modelforms: PYTHONPATH=/tmp/r37/src /work/venv/bin/python make_trajs.py
"""
import json
from pathlib import Path

import h5py
import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq

import common  # noqa: F401

T = Path("/tmp/r37/modelforms/trajs")
T.mkdir(exist_ok=True)
a = np.load("/tmp/r37/modelforms/aloha.npz")
p = np.load("/tmp/r37/modelforms/panda.npz")
A, pose = a["actions"], a["object_pose"]
PA = p["actions"]

# npz: one row; two rows; panda with extra keys; float32 / int actions; non-uniform time
np.savez(T / "one_row.npz", actions=PA[:1], fps=50.0, object_pose=p["object_pose"])
np.savez(T / "extra_keys.npz", actions=PA, fps=50.0, object_pose=p["object_pose"], qpos0=p["qpos0"],
         observations=np.zeros((500, 8)), episode_id=np.int64(3), success=np.bool_(True))
np.savez(T / "f32.npz", actions=PA.astype(np.float32), fps=np.float32(50), object_pose=p["object_pose"].astype(np.float32),
         qpos0=p["qpos0"].astype(np.float32))
t = np.arange(500) / 50.0
t_nonuni = t.copy(); t_nonuni[250:] += 0.01   # one 30 ms gap (a dropped-ish frame) in the middle
np.savez(T / "time_gap.npz", actions=PA, time=t_nonuni, object_pose=p["object_pose"], qpos0=p["qpos0"])
# longer (a 10 s still hold at the end) and shorter (cut at 60 %, mid-carry)
np.savez(T / "longer.npz", actions=np.vstack([PA, np.repeat(PA[-1:], 500, 0)]), fps=50.0,
         object_pose=p["object_pose"], qpos0=p["qpos0"])
np.savez(T / "shorter.npz", actions=PA[:300], fps=50.0, object_pose=p["object_pose"], qpos0=p["qpos0"])

# ACT hdf5 with an extra dataset (and the cube pose under /observations/env_state)
with h5py.File(T / "act_extra.hdf5", "w") as f:
    f.attrs["sim"] = True
    f["action"] = A
    f["observations/qpos"] = np.vstack([a["start"][None], A[:-1]])
    f["observations/qvel"] = np.zeros_like(A)
    f["observations/env_state"] = np.repeat(pose[None], len(A), 0)
    f["observations/images/top"] = np.zeros((len(A), 4, 4, 3), np.uint8)
    f["language_instruction"] = np.bytes_("transfer the cube")
    f["reward"] = np.zeros(len(A))
# ACT hdf5 with /action stored as float32 and an extra top-level dataset named like a rate
with h5py.File(T / "act_f32.hdf5", "w") as f:
    f["action"] = A.astype(np.float32)
    f["observations/qpos"] = np.vstack([a["start"][None], A[:-1]]).astype(np.float32)
    f["observations/env_state"] = np.repeat(pose[None], len(A), 0).astype(np.float32)

# LeRobot dataset folder at 30 fps (the scenario says 50): actions resampled to 30 Hz
def lerobot(root, fps, acts):
    root = Path(root)
    (root / "meta").mkdir(parents=True, exist_ok=True)
    (root / "data/chunk-000").mkdir(parents=True, exist_ok=True)
    n = len(acts)
    (root / "meta/info.json").write_text(json.dumps({"codebase_version": "v2.1", "robot_type": "aloha", "fps": fps,
        "features": {"action": {"dtype": "float32", "shape": [14]}}}))
    tbl = pa.table({"action": pa.array([list(map(float, r)) for r in acts], type=pa.list_(pa.float32(), 14)),
                    "episode_index": pa.array(np.zeros(n, np.int64)), "frame_index": pa.array(np.arange(n)),
                    "timestamp": pa.array((np.arange(n) / fps).astype(np.float32))})
    pq.write_table(tbl, root / "data/chunk-000/episode_000000.parquet")

t50 = np.arange(len(A)) / 50.0
t30 = np.arange(0, t50[-1] + 1e-9, 1 / 30.0)
A30 = np.stack([np.interp(t30, t50, A[:, j]) for j in range(14)], 1)
lerobot(T / "lr30", 30, A30)
lerobot(T / "lr50", 50, A)
print(sorted(x.name for x in T.iterdir()))
