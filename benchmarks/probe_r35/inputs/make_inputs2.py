"""Second batch of inputs (run from /tmp/r35/inputs after make_inputs.py)."""
import json
import sys

import h5py
import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq

sys.path.insert(0, "/work/main/benchmarks/probe_r35/inputs")
from make_inputs import A0, NAMES, episode_table, fresh, h5, v21, v30  # noqa: E402  (re-runs batch 1)

qpos = A0.copy()
# --- HDF5 time bases under other names (npz refuses these since r33 F5; HDF5?) ---
A30 = A0  # the same rows, recorded at 30 Hz
h5("act_dt_attr.hdf5", {"action": A30, "observations/qpos": qpos}, attrs={"dt": 1 / 30})
h5("act_control_dt.hdf5", {"action": A30, "observations/qpos": qpos}, attrs={"control_dt": 1 / 30})
h5("act_hz_attr.hdf5", {"action": A30, "observations/qpos": qpos}, attrs={"hz": 30})
h5("act_timestamps.hdf5", {"action": A30, "observations/qpos": qpos,
                           "timestamps": np.arange(400) / 30.0})
h5("act_obs_timestamp.hdf5", {"action": A30, "observations/qpos": qpos,
                              "observations/timestamp": np.arange(400) / 30.0})
h5("act_FPS_attr.hdf5", {"action": A30, "observations/qpos": qpos}, attrs={"FPS": 30})
h5("act_fps_f32.hdf5", {"action": A30, "observations/qpos": qpos}, attrs={"fps": np.float32(30)})
# rate on the /action dataset's own attributes rather than the root
p = h5("act_dset_fps.hdf5", {"action": A30, "observations/qpos": qpos})
with h5py.File(p, "a") as f:
    f["action"].attrs["fps"] = 30
# --- names: a subtle permutation inside one arm (wrist_angle <-> wrist_rotate) ---
perm = list(range(14))
perm[4], perm[5] = 5, 4
v30("lr_names_wrist", [A0[:, perm]], info_kw={"names": [NAMES[i] for i in perm]})
# --- LeRobot info.json variations ---
v30("lr_info_fps_str", [A0], info_kw={"extra": {"fps": "50"}})
r = v30("lr_info_nofps", [A0], table_kw={"fps": 30})
info = json.loads((r / "meta" / "info.json").read_text()); del info["fps"]
(r / "meta" / "info.json").write_text(json.dumps(info))
# v3.0 episode of one row / an empty episode selection
v30("lr_one_row", [A0[:1]])
# v3.0 where the dataset's episode 1 is a 30 Hz timestamp episode but info says 50 (mixed)
r = v30("lr_mixed_rates", [A0, A0])
t0 = episode_table(A0, 0)
t1 = episode_table(A0, 1, fps=30)
pq.write_table(pa.concat_tables([t0, t1]), r / "data" / "chunk-000" / "file-000.parquet")
# LeRobot action chunk per row (a policy output: H=4 steps of 14 per frame)
chunk = A0.reshape(100, 4, 14)
inner = pa.FixedSizeListArray.from_arrays(pa.array(chunk.reshape(-1), pa.float32()), 14)
outer = pa.FixedSizeListArray.from_arrays(inner, 4)
pq.write_table(pa.table({"action": outer, "episode_index": pa.array(np.zeros(100, np.int64))}),
               fresh("lr_chunk_rows.parquet"))
# v3.0 with the rows of the file in reverse order and no frame_index (written newest first)
t = episode_table(A0, 0).drop(["frame_index"])
r = v30("lr_rev_noframe", [A0])
pq.write_table(t.take(pa.array(np.arange(399, -1, -1))), r / "data" / "chunk-000" / "file-000.parquet")
# frame_index global across the file (v3.0 'index'-like) for episode 1: starts at 400
t = pa.concat_tables([episode_table(A0, 0), episode_table(A0, 1, frame0=400)])
r = v30("lr_frame_global", [A0, A0])
pq.write_table(t, r / "data" / "chunk-000" / "file-000.parquet")
print("batch 2 written")
# observation.state named in another order than action (info.json says so); the data follow
# their names: the start state is read in the action's order without a look at the names
r = v30("lr_state_names", [A0], table_kw={"state": A0[:, perm]})
inf = json.loads((r / "meta" / "info.json").read_text())
inf["features"]["observation.state"]["names"] = [NAMES[i] for i in perm]
(r / "meta" / "info.json").write_text(json.dumps(inf, indent=2))
# degrees (a LeRobot so100/koch-style export) with the gripper in percent
v30("lr_degrees", [np.concatenate([np.degrees(A0[:, :6]), A0[:, 6:7] * 100,
                                   np.degrees(A0[:, 7:13]), A0[:, 13:] * 100], 1)])
print("batch 2b written")
# the same motion at 30 Hz as float64 / float32 npz (the float32 observation), and a 1-row npz
d = dict(np.load("traj.npz"))
np.savez("npz30_f64.npz", actions=d["actions"], fps=30.0, start=d["start"], object_pose=d["object_pose"])
np.savez("npz30_f32.npz", actions=d["actions"].astype(np.float32), fps=30.0,
         start=d["start"].astype(np.float32), object_pose=d["object_pose"])
np.savez("npz_one_row.npz", actions=d["actions"][:1], fps=50.0)
print("batch 2c written")
