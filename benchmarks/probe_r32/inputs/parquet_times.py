"""LeRobot parquet episode files with odd timestamp / frame_index columns."""
import pyarrow as pa, pyarrow.parquet as pq
from common import *
z = np.load(TRAJ); A = z["actions"]; S = z["start"]
n = len(A); T0 = np.arange(n) / 50.0
def write(name, ts=None, fi=None, order=None, state=True, ts_type=pa.float32()):
    idx = np.arange(n) if order is None else order
    cols = {"action": pa.array([list(map(float, A[i])) for i in idx], type=pa.list_(pa.float32(), 14)),
            "episode_index": pa.array(np.zeros(n, np.int64))}
    if fi is not None: cols["frame_index"] = pa.array(np.asarray(fi)[idx])
    if ts is not None: cols["timestamp"] = pa.array(np.asarray(ts)[idx], type=ts_type)
    if state: cols["observation.state"] = pa.array([list(map(float, S))] * n, type=pa.list_(pa.float32(), 14))
    p = f"/tmp/r32/inputs/{name}.parquet"; pq.write_table(pa.table(cols), p); return p
def load(name, **kw):
    tr = t(name, lambda: cm.load_trajectory(write(name, **kw)))
    if tr is not None: print(f"      fps={tr.fps:.6g} assumed={tr.fps_assumed} same actions as float32: {np.array_equal(tr.actions, A.astype(np.float32).astype(np.float64))}")
load("ts from 0", ts=T0)
load("ts from 1000 s float32", ts=T0 + 1000)
load("ts from 1e5 s float32", ts=T0 + 1e5)
load("ts from 1e5 s float64", ts=T0 + 1e5, ts_type=pa.float64())
load("ts decreasing", ts=T0[::-1])
load("ts duplicate", ts=np.r_[T0[:10], T0[9], T0[11:]])
load("ts 30 Hz (data is 50 Hz)", ts=np.arange(n) / 30.0)
rng = np.random.default_rng(0); perm = rng.permutation(n)
load("rows shuffled, frame_index + ts", ts=T0, fi=np.arange(n), order=perm)
load("rows shuffled, frame_index only", fi=np.arange(n), order=perm)
load("rows shuffled, ts only (no frame_index)", ts=T0, order=perm)
load("frame_index from 100 (a chunk)", ts=T0 + 2, fi=np.arange(n) + 100)
load("frame_index decreasing vs ts increasing", ts=T0, fi=np.arange(n)[::-1])
load("ts int64 ns", ts=(T0 * 1e9).astype(np.int64), ts_type=pa.int64())
