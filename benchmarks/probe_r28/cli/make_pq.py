import json
import os
import shutil

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq

D = "/tmp/r28/cli/in/pq"; shutil.rmtree(D, ignore_errors=True); os.makedirs(D)
z = np.load("/tmp/r28/cli/readme/traj.npz"); A = z["actions"]; S = z["start"]
T = len(A); Q = np.vstack([S, A[:-1]])
def tbl(ep=0, actions=A, ts=True, fi=True, state=True, dtype=pa.float32(), fixed=False, extra=None):
    n = len(actions)
    cols = {}
    typ = pa.list_(dtype, actions.shape[1]) if fixed else pa.list_(dtype)
    cols["action"] = pa.array([list(map(float, r)) for r in actions], type=typ)
    if state: cols["observation.state"] = pa.array([list(map(float, r)) for r in Q[:n]], type=typ)
    if ts: cols["timestamp"] = pa.array(np.arange(n) / 50.0, type=pa.float32())
    if fi: cols["frame_index"] = pa.array(np.arange(n), type=pa.int64())
    if ep is not None: cols["episode_index"] = pa.array(np.full(n, ep), type=pa.int64())
    cols["index"] = pa.array(np.arange(n), type=pa.int64())
    if extra: cols.update(extra)
    return pa.table(cols)
def w(name, t): pq.write_table(t, os.path.join(D, name))
w("ep_ok.parquet", tbl())
w("ep_fixed.parquet", tbl(fixed=True))
w("ep_f64.parquet", tbl(dtype=pa.float64()))
w("ep_noidx.parquet", tbl(ep=None))
w("ep_nots.parquet", tbl(ts=False))
w("ep_nots_nofi.parquet", tbl(ts=False, fi=False))
w("multi.parquet", pa.concat_tables([tbl(0), tbl(1), tbl(5)]))
t = tbl(); perm = np.random.default_rng(0).permutation(T)
w("shuffled_fi.parquet", t.take(pa.array(perm)))
t2 = tbl(fi=False); w("shuffled_ts.parquet", t2.take(pa.array(perm)))
ts = np.arange(T) / 50.0; ts[100], ts[101] = ts[101], ts[100]
w("ts_swap.parquet", tbl(fi=False).set_column(tbl(fi=False).schema.get_field_index("timestamp"), "timestamp", pa.array(ts)))
w("ts_ms.parquet", tbl(fi=False).set_column(tbl(fi=False).schema.get_field_index("timestamp"), "timestamp", pa.array(np.arange(T) * 20.0)))
w("ts_int.parquet", tbl(fi=False).set_column(tbl(fi=False).schema.get_field_index("timestamp"), "timestamp", pa.array(np.arange(T), type=pa.int64())))
w("ts_null.parquet", tbl(fi=False).set_column(tbl(fi=False).schema.get_field_index("timestamp"), "timestamp", pa.array([None] + list(np.arange(1, T) / 50.0))))
w("fi_gap.parquet", tbl().filter(pa.array(np.arange(T) != 200)))
w("fi_dup.parquet", tbl().set_column(tbl().schema.get_field_index("frame_index"), "frame_index", pa.array(np.r_[0, np.arange(T - 1)])))
# varying-length list column
rows = [list(map(float, r)) for r in A]; rows[10] = rows[10][:13]
t = tbl(); w("ragged.parquet", t.set_column(t.schema.get_field_index("action"), "action", pa.array(rows, type=pa.list_(pa.float32()))))
rows = [list(map(float, r)) for r in A]; rows[10] = None
w("null_row.parquet", t.set_column(t.schema.get_field_index("action"), "action", pa.array(rows, type=pa.list_(pa.float32()))))
rows = [list(map(float, r)) for r in A]; rows[10][3] = None
w("null_elem.parquet", t.set_column(t.schema.get_field_index("action"), "action", pa.array(rows, type=pa.list_(pa.float32()))))
w("action_str.parquet", t.set_column(t.schema.get_field_index("action"), "action", pa.array([str(r) for r in A])))
w("action_scalar.parquet", t.set_column(t.schema.get_field_index("action"), "action", pa.array(A[:, 0])))
w("action_struct.parquet", t.set_column(t.schema.get_field_index("action"), "action", pa.array([{"a": float(r[0])} for r in A])))
w("action_nested.parquet", t.set_column(t.schema.get_field_index("action"), "action", pa.array([[list(map(float, r))] for r in A])))
w("action_int.parquet", t.set_column(t.schema.get_field_index("action"), "action", pa.array([[int(x) for x in np.round(r)] for r in A], type=pa.list_(pa.int64()))))
w("action_bool.parquet", t.set_column(t.schema.get_field_index("action"), "action", pa.array([[bool(x > 0) for x in r] for r in A])))
w("no_action.parquet", t.drop_columns(["action"]))
w("empty.parquet", tbl().slice(0, 0))
w("ep_float.parquet", t.set_column(t.schema.get_field_index("episode_index"), "episode_index", pa.array(np.zeros(T) + 0.5)))
w("ep_str.parquet", t.set_column(t.schema.get_field_index("episode_index"), "episode_index", pa.array(["0"] * T)))
w("ep_neg.parquet", tbl(ep=-3))
w("ep_null.parquet", t.set_column(t.schema.get_field_index("episode_index"), "episode_index", pa.array([None] * T, type=pa.int64())))
w("ep_huge.parquet", tbl(ep=2**62))
w("state_short.parquet", tbl().set_column(tbl().schema.get_field_index("observation.state"), "observation.state", pa.array([list(map(float, r[:5])) for r in Q])))
w("state_far.parquet", tbl().set_column(tbl().schema.get_field_index("observation.state"), "observation.state", pa.array([list(map(float, r + 50)) for r in Q])))
w("nan_action.parquet", tbl(actions=np.where(np.arange(A.size).reshape(A.shape) == 30, np.nan, A)))
w("wide.parquet", tbl(actions=np.hstack([A, A[:, :1]]), state=False))
open(os.path.join(D, "corrupt.parquet"), "wb").write(open(os.path.join(D, "ep_ok.parquet"), "rb").read()[:3000])
open(os.path.join(D, "text.parquet"), "w").write("x")
# datasets
def ds(name, info, files):
    r = os.path.join(D, name); os.makedirs(os.path.join(r, "meta"), exist_ok=True)
    if info is not None:
        open(os.path.join(r, "meta", "info.json"), "w").write(info if isinstance(info, str) else json.dumps(info))
    for rel, t in files.items():
        p = os.path.join(r, "data", rel); os.makedirs(os.path.dirname(p), exist_ok=True); pq.write_table(t, p)
ok3 = {"chunk-000/episode_000000.parquet": tbl(0), "chunk-000/episode_000001.parquet": tbl(1), "chunk-000/episode_000002.parquet": tbl(2)}
ds("ds_ok", {"fps": 50, "codebase_version": "v2.1", "robot_type": "aloha"}, ok3)
ds("ds_one", {"fps": 50}, {"chunk-000/episode_000000.parquet": tbl(0)})
ds("ds_nofps", {"codebase_version": "v2.1"}, {"chunk-000/episode_000000.parquet": tbl(0, ts=False)})
ds("ds_nofps_ts", {"codebase_version": "v2.1"}, {"chunk-000/episode_000000.parquet": tbl(0)})
ds("ds_fps_str", {"fps": "50"}, {"chunk-000/episode_000000.parquet": tbl(0)})
ds("ds_fps_30", {"fps": 30}, {"chunk-000/episode_000000.parquet": tbl(0)})
ds("ds_fps_30_nots", {"fps": 30}, {"chunk-000/episode_000000.parquet": tbl(0, ts=False)})
ds("ds_badjson", "{fps: 50", {"chunk-000/episode_000000.parquet": tbl(0)})
ds("ds_list", "[1]", {"chunk-000/episode_000000.parquet": tbl(0)})
ds("ds_nodata", {"fps": 50}, {})
ds("ds_split", {"fps": 50}, {"chunk-000/a.parquet": tbl(0).slice(0, 200), "chunk-000/b.parquet": tbl(0).slice(200)})
ds("ds_mixed", {"fps": 50}, {"chunk-000/a.parquet": tbl(0), "chunk-000/b.parquet": tbl(None)})
ds("ds_v3", {"fps": 50, "codebase_version": "v3.0"}, {"chunk-000/file-000.parquet": pa.concat_tables([tbl(0), tbl(1)])})
# a parquet file inside a dataset (finds root)
print("ok", len(os.listdir(D)))
