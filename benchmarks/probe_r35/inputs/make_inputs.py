"""Generates the probe's inputs under /tmp/r35/inputs (run from there).

Needs traj.npz (demo --seed 0), s1.npz, s2.npz (demo --seed 1/2), panda.npz (demo --scenario
panda_pick_place --seed 0). Every input carries seed 0's actions somewhere, so its audit can be
compared with traj.npz's (give --object-pose of traj.npz: LeRobot/ACT files carry no pose).
"""
import json
import os
import pickle
import shutil
from pathlib import Path

import h5py
import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq

HERE = Path.cwd()
A0 = np.load("traj.npz")["actions"]
A1 = np.load("s1.npz")["actions"]
A2 = np.load("s2.npz")["actions"]
P0 = np.load("panda.npz")["actions"]
FPS = 50.0
NAMES = [f"{s}_{j}" for s in ("left", "right") for j in
         ("waist", "shoulder", "elbow", "forearm_roll", "wrist_angle", "wrist_rotate", "gripper")]


def fresh(path):
    p = HERE / path
    if p.is_dir():
        shutil.rmtree(p)
    elif p.exists():
        p.unlink()
    return p


def vec_col(a, typ="fixed", dtype=pa.float32()):
    a = np.asarray(a)
    flat = pa.array(a.reshape(-1), type=dtype)
    if typ == "fixed":
        return pa.FixedSizeListArray.from_arrays(flat, a.shape[1])
    offs = pa.array(np.arange(0, a.size + 1, a.shape[1], dtype=np.int32 if typ == "list" else np.int64))
    return (pa.ListArray if typ == "list" else pa.LargeListArray).from_arrays(offs, flat)


def episode_table(actions, ep, start_index=0, frame0=0, typ="fixed", dtype=pa.float32(),
                  state=None, fps=FPS, ts=None):
    T = len(actions)
    state = actions if state is None else state
    frame = np.arange(frame0, frame0 + T)
    cols = {
        "action": vec_col(actions, typ, dtype),
        "observation.state": vec_col(state, typ, dtype),
        "timestamp": pa.array((frame / fps if ts is None else ts).astype(np.float32)),
        "frame_index": pa.array(frame, pa.int64()),
        "episode_index": pa.array(np.full(T, ep), pa.int64()),
        "index": pa.array(np.arange(start_index, start_index + T), pa.int64()),
        "task_index": pa.array(np.zeros(T), pa.int64()),
    }
    return pa.table(cols)


def info(version, fps=FPS, names=NAMES, width=14, n_eps=3, n_frames=1200, extra=None):
    feats = {
        "action": {"dtype": "float32", "shape": [width], "names": names},
        "observation.state": {"dtype": "float32", "shape": [width], "names": names},
        "observation.images.top": {"dtype": "video", "shape": [480, 640, 3],
                                   "names": ["height", "width", "channel"]},
        "timestamp": {"dtype": "float32", "shape": [1], "names": None},
        "frame_index": {"dtype": "int64", "shape": [1], "names": None},
        "episode_index": {"dtype": "int64", "shape": [1], "names": None},
        "index": {"dtype": "int64", "shape": [1], "names": None},
        "task_index": {"dtype": "int64", "shape": [1], "names": None},
    }
    d = {"codebase_version": version, "robot_type": "aloha", "total_episodes": n_eps,
         "total_frames": n_frames, "total_tasks": 1, "chunks_size": 1000, "fps": fps,
         "splits": {"train": f"0:{n_eps}"}, "features": feats}
    if version == "v3.0":
        d.update(data_path="data/chunk-{chunk_index:03d}/file-{file_index:03d}.parquet",
                 video_path="videos/{video_key}/chunk-{chunk_index:03d}/file-{file_index:03d}.mp4",
                 data_files_size_in_mb=100, video_files_size_in_mb=500)
    else:
        d.update(data_path="data/chunk-{episode_chunk:03d}/episode_{episode_index:06d}.parquet",
                 video_path="videos/chunk-{episode_chunk:03d}/{video_key}/episode_{episode_index:06d}.mp4",
                 total_chunks=1, total_videos=n_eps)
    if extra:
        d.update(extra)
    return d


def v30(name, episodes, *, ep_ids=None, info_kw=None, table_kw=None, files=None):
    """LeRobot v3.0: one data file holding several episodes + meta/episodes parquet."""
    root = fresh(name)
    (root / "meta" / "episodes" / "chunk-000").mkdir(parents=True)
    (root / "data" / "chunk-000").mkdir(parents=True)
    ep_ids = list(range(len(episodes))) if ep_ids is None else ep_ids
    tables, rows, start = [], [], 0
    for ep, acts in zip(ep_ids, episodes):
        tables.append(episode_table(acts, ep, start_index=start, **(table_kw or {})))
        rows.append({"episode_index": ep, "length": len(acts), "data/chunk_index": 0,
                     "data/file_index": 0, "dataset_from_index": start,
                     "dataset_to_index": start + len(acts), "tasks": ["transfer the cube"]})
        start += len(acts)
    table = pa.concat_tables(tables)
    files = files or [slice(None)]
    if len(files) == 1:
        pq.write_table(table, root / "data" / "chunk-000" / "file-000.parquet")
    else:
        for k, (a, b) in enumerate(files):
            pq.write_table(table.slice(a, b - a), root / "data" / "chunk-000" / f"file-{k:03d}.parquet")
    pq.write_table(pa.Table.from_pylist(rows), root / "meta" / "episodes" / "chunk-000" / "file-000.parquet")
    (root / "meta" / "info.json").write_text(json.dumps(info("v3.0", n_eps=len(episodes), n_frames=start,
                                                             **(info_kw or {})), indent=2))
    (root / "meta" / "tasks.parquet").write_bytes(b"")  # present, not read
    return root


def v21(name, episodes, *, ep_ids=None, info_kw=None, table_kw=None):
    root = fresh(name)
    (root / "meta").mkdir(parents=True)
    (root / "data" / "chunk-000").mkdir(parents=True)
    ep_ids = list(range(len(episodes))) if ep_ids is None else ep_ids
    lines, start = [], 0
    for ep, acts in zip(ep_ids, episodes):
        pq.write_table(episode_table(acts, ep, start_index=start, **(table_kw or {})),
                       root / "data" / "chunk-000" / f"episode_{ep:06d}.parquet")
        lines.append(json.dumps({"episode_index": ep, "tasks": ["transfer"], "length": len(acts)}))
        start += len(acts)
    (root / "meta" / "episodes.jsonl").write_text("\n".join(lines) + "\n")
    (root / "meta" / "info.json").write_text(json.dumps(info("v2.1", n_eps=len(episodes), n_frames=start,
                                                             **(info_kw or {})), indent=2))
    return root


def h5(name, groups, attrs=None, compression=None):
    p = fresh(name)
    with h5py.File(p, "w") as f:
        for key, val in groups.items():
            f.create_dataset(key, data=val, compression=compression)
        for k, v in (attrs or {}).items():
            f.attrs[k] = v
    return p


# ---------------- LeRobot ----------------
v30("lr_v30", [A1, A0, A2])                                 # seed 0 is episode 1 of 3
v30("lr_v30_ids", [A1, A0, A2], ep_ids=[7, 3, 5])           # indices not in file order
v21("lr_v21", [A1, A0, A2])
# action names in another order than the scenario's channels (right arm first), data to match
perm = list(range(7, 14)) + list(range(0, 7))
v30("lr_names_swapped", [A0[:, perm]], info_kw={"names": [NAMES[i] for i in perm]})
# names in v2.x dict form {"motors": [...]} and in order
v21("lr_names_dict", [A0], info_kw={"names": {"motors": NAMES}})
# width declared 14 in info.json but the parquet holds 16 (gripper as two fingers)
A16 = np.concatenate([A0[:, :7], A0[:, 6:7], A0[:, 7:], A0[:, 13:14]], axis=1)
v30("lr_width16", [A16], info_kw={"width": 16, "names": None})
# fps in info.json differs from the scenario's (30 vs 50); timestamps agree with info
v30("lr_fps30", [A0], info_kw={"fps": 30}, table_kw={"fps": 30})
# info.json fps 30 but the timestamps were written at 50 (a relabelled dataset)
v30("lr_fps_conflict", [A0], info_kw={"fps": 30})
# float16 / float64 actions, list / large_list columns
v30("lr_f16", [A0], table_kw={"dtype": pa.float16()})
v30("lr_f64_list", [A0], table_kw={"dtype": pa.float64(), "typ": "list"})
v30("lr_large_list", [A0], table_kw={"typ": "large"})
# frame_index not from 0 (a clip cut from a longer episode), timestamps too
v30("lr_frame100", [A0], table_kw={"frame0": 100})
# v3.0 episode across two data files (a file-size rollover)
v30("lr_split", [A1, A0], files=[(0, 600), (600, 800)])
# v3.0: the data file holds 3 episodes but --episode is given as a position 0..2 while
# indices are 10, 11, 12 (the meta/episodes file maps them) -> covered by lr_v30_ids
# observation.state with the velocities appended (28 wide)
v30("lr_state28", [A0], table_kw={"state": np.concatenate([A0, np.zeros_like(A0)], 1)})
# timestamp drift: float32 timestamps of a 50 Hz clock that runs 0.5 % slow
v30("lr_drift", [A0], table_kw={"ts": np.arange(400) / 50.0 * 1.005})
# per-dataset timestamps (global time, not per episode) in a v3.0 file of several episodes
tab = [episode_table(a, e, ts=(np.arange(400) + 400 * e) / 50.0) for e, a in enumerate([A1, A0])]
r = v30("lr_global_ts", [A1, A0])
pq.write_table(pa.concat_tables(tab), r / "data" / "chunk-000" / "file-000.parquet")
# AppleDouble sidecar next to the data (a dataset copied from a Mac)
r = v30("lr_appledouble", [A0])
(r / "data" / "chunk-000" / "._file-000.parquet").write_bytes(b"\x00\x05\x16\x07" + b"\x00" * 60)
# Panda: 8-wide actions
pq.write_table(episode_table(P0, 0), fresh("panda_ep.parquet"))
# single episode file outside a dataset (no info.json), with and without timestamp
t = episode_table(A0, 0)
pq.write_table(t, fresh("ep_alone.parquet"))
pq.write_table(t.drop(["timestamp"]), fresh("ep_alone_nots.parquet"))

# ---------------- ACT HDF5 ----------------
qpos = A0.copy()
img = np.zeros((len(A0), 4, 4, 3), np.uint8)
h5("act.hdf5", {"action": A0, "observations/qpos": qpos, "observations/qvel": np.zeros_like(A0),
                "observations/images/top": img}, attrs={"sim": True}, compression="gzip")
h5("act_actions.hdf5", {"actions": A0, "observations/qpos": qpos})
h5("act_30hz_attr.hdf5", {"action": A0, "observations/qpos": qpos}, attrs={"fps": b"30"})
h5("act_fps_array.hdf5", {"action": A0, "observations/qpos": qpos}, attrs={"fps": np.array([30.0])})
h5("act_qpos16.hdf5", {"action": A0, "observations/qpos": A16})
h5("act_f16.hdf5", {"action": A0.astype(np.float16), "observations/qpos": qpos.astype(np.float16)})
h5("act_3d.hdf5", {"action": A0[:, None, :], "observations/qpos": qpos})
h5("act_extra.hdf5", {"action": A0, "observations/qpos": qpos, "observations/effort": np.zeros_like(A0),
                      "base_action": np.zeros((400, 2)), "compress_len": np.zeros((3, 400))},
   attrs={"sim": False, "compress": True, "camera_names": np.array([b"cam_high", b"cam_low"])})
# qpos rows that do not match the actions' rows (the recorder logged one more)
h5("act_qpos_rows.hdf5", {"action": A0, "observations/qpos": np.vstack([qpos[:1] + 0.3, qpos])})
# ACT start pose stored where ACT's sim stores it
h5("act_envstate.hdf5", {"action": A0, "observations/qpos": qpos,
                         "observations/env_state": np.tile(np.load("traj.npz")["object_pose"], (400, 1))})
# attrs frame_rate = 30 and control_freq = 30.0 (agree), fps = 50 (disagree)
h5("act_rates3.hdf5", {"action": A0, "observations/qpos": qpos},
   attrs={"frame_rate": 30, "control_freq": 30.0, "fps": 50})
h5("act_rate_neg.hdf5", {"action": A0, "observations/qpos": qpos}, attrs={"fps": -50})
# robomimic layout
h5("robomimic.hdf5", {"data/demo_0/actions": A0, "data/demo_0/obs/joint_pos": qpos})

# ---------------- npz ----------------
np.savez(fresh("npz_1TD.npz"), actions=A0[None], fps=FPS)
np.savez(fresh("npz_T1D.npz"), actions=A0[:, None], fps=FPS)
np.savez(fresh("npz_f16.npz"), actions=A0.astype(np.float16), fps=FPS)
np.savez(fresh("npz_chunks.npz"), actions=A0.reshape(4, 100, 14), fps=FPS)
np.savez(fresh("npz_qpos.npz"), qpos=A0, fps=FPS)
np.savez(fresh("npz_int64.npz"), actions=np.round(A0 * 1000).astype(np.int64), fps=FPS)
np.savez(fresh("npz_object.npz"), actions=A0.astype(object), fps=FPS)
with open(fresh("npz_pickle.npz"), "wb") as fh:
    pickle.dump({"actions": A0, "fps": FPS}, fh)
np.savez(fresh("npz_action_singular.npz"), action=A0, fps=FPS)
np.savez(fresh("npz_dt.npz"), actions=A0, dt=0.04)          # rate as dt (r33 F5's fix)
np.savez(fresh("npz_fps_str.npz"), actions=A0, fps=np.array("50"))
np.savez(fresh("npz_fps_int.npz"), actions=A0, fps=np.int64(50))
np.savez(fresh("npz_time_int_ms.npz"), actions=A0, time=np.arange(400) * 20)
np.savez(fresh("npz_start_transposed.npz"), actions=A0, fps=FPS, start=A0[0][:, None])
np.savez(fresh("npz_meta_bytes.npz"), actions=A0, fps=FPS, meta=np.array(b'{"scenario": "panda_pick_place"}'))
np.savez(fresh("npz_meta_other_scn.npz"), actions=A0, fps=FPS, meta=np.array('{"scenario": "panda_pick_place"}'))
np.savez_compressed(fresh("npz_compressed.npz"), actions=A0, fps=FPS)
print("inputs written to", HERE)
