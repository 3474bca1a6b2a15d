"""Column types a parquet writer may produce (pandas, polars, datasets) through load_trajectory:
looks for exceptions other than CritmomentError (run from /tmp/r35/inputs)."""
import sys, warnings, decimal
import numpy as np, pyarrow as pa, pyarrow.parquet as pq
import critmoment
assert critmoment.__file__.startswith("/tmp/r35/src"), critmoment.__file__
from critmoment import load_trajectory

A0 = np.load("traj.npz")["actions"][:50]
T = len(A0)
vec = pa.FixedSizeListArray.from_arrays(pa.array(A0.reshape(-1), pa.float64()), 14)
ts = np.arange(T) / 50.0
base = {"action": vec, "episode_index": pa.array(np.zeros(T, np.int64)), "timestamp": pa.array(ts)}
def with_(**kw):
    d = dict(base); d.update(kw); return {k: v for k, v in d.items() if v is not None}
cases = {
    "ts_null": with_(timestamp=pa.array([None] + list(ts[1:]), pa.float64())),
    "ts_string": with_(timestamp=pa.array([f"{t:.2f}" for t in ts])),
    "ts_list": with_(timestamp=pa.FixedSizeListArray.from_arrays(pa.array(ts), 1)),
    "ts_decimal": with_(timestamp=pa.array([decimal.Decimal(f"{t:.2f}") for t in ts], pa.decimal128(10, 2))),
    "ts_f16": with_(timestamp=pa.array(ts.astype(np.float16))),
    "ep_dictionary": with_(episode_index=pa.array(np.zeros(T, np.int64)).dictionary_encode()),
    "ep_string": with_(episode_index=pa.array(["0"] * T)),
    "action_decimal": with_(action=pa.FixedSizeListArray.from_arrays(
        pa.array([decimal.Decimal(str(round(x, 4))) for x in A0.reshape(-1)], pa.decimal128(12, 6)), 14)),
    "action_struct": with_(action=pa.StructArray.from_arrays([pa.array(A0[:, i]) for i in range(14)],
                                                             names=[f"j{i}" for i in range(14)])),
    "action_binary": with_(action=pa.array([r.astype(np.float32).tobytes() for r in A0])),
    "state_string": with_(**{"observation.state": pa.array(["x"] * T)}),
    "state_null_first": with_(**{"observation.state": pa.array([None] + [list(r) for r in A0[1:]],
                                                               pa.list_(pa.float64()))}),
    "frame_uint64_big": with_(frame_index=pa.array(np.arange(T, dtype=np.uint64) + np.uint64(2**63))),
    "action_list_of_list": with_(action=pa.array([[list(r)] for r in A0])),
    "zero_rows": {k: v.slice(0, 0) for k, v in base.items()},
    "action_list_view": with_(action=pa.ListViewArray.from_arrays(
        pa.array(np.arange(0, 14 * T, 14, dtype=np.int32)), pa.array(np.full(T, 14, np.int32)),
        pa.array(A0.reshape(-1)))) if hasattr(pa, "ListViewArray") else None,
}
bad = 0
for name, cols in cases.items():
    if cols is None:
        continue
    path = f"pqt_{name}.parquet"
    try:
        pq.write_table(pa.table(cols), path)
    except Exception as e:  # noqa: BLE001
        print(f"== {name}: cannot write ({type(e).__name__}: {e})"); continue
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            tr = load_trajectory(path)
            res = f"OK fps={tr.fps:g} shape={tr.actions.shape} start={'set' if tr.start is not None else None}"
        except critmoment.CritmomentError as e:
            res = f"CMERR {type(e).__name__}: {str(e)[:250]}"
        except Exception as e:  # noqa: BLE001
            bad += 1
            res = f"OTHER (not a CritmomentError) {type(e).__name__}: {str(e)[:250]}"
    print(f"== {name}: {res}")
print("non-CritmomentError exceptions:", bad)
