"""Odd-but-real parquet/info.json inputs through load_trajectory and the CLI's rollout
(run from /tmp/r35/inputs after make_inputs.py)."""
import json, shutil, subprocess, sys, warnings
from pathlib import Path
import numpy as np, pyarrow as pa, pyarrow.parquet as pq
sys.path.insert(0, "/work/main/benchmarks/probe_r35/inputs")
import critmoment
assert critmoment.__file__.startswith("/tmp/r35/src"), critmoment.__file__
from critmoment import load_trajectory

A0 = np.load("traj.npz")["actions"]
T = len(A0)
def vec(a):
    return pa.FixedSizeListArray.from_arrays(pa.array(a.reshape(-1), pa.float32()), a.shape[1])
base = {"action": vec(A0), "episode_index": pa.array(np.zeros(T, np.int64)),
        "frame_index": pa.array(np.arange(T))}
cases = {}
# wall-clock timestamps as an arrow timestamp type (a recorder logging datetimes)
t0 = np.datetime64("2026-01-01T00:00:00", "ns")
cases["ts_datetime"] = dict(base, timestamp=pa.array(t0 + (np.arange(T) * 20_000_000).astype("timedelta64[ns]")))
cases["ts_duration"] = dict(base, timestamp=pa.array((np.arange(T) * 20_000_000).astype("timedelta64[ns]")))
cases["ts_int_ms"] = dict(base, timestamp=pa.array(np.arange(T) * 20, pa.int64()))
cases["ts_30hz_nofps"] = dict(base, timestamp=pa.array(np.arange(T) / 30.0))
for name, cols in cases.items():
    pq.write_table(pa.table(cols), f"pq_{name}.parquet")
# duplicate 'action' column names (pyarrow allows it)
tab = pa.Table.from_arrays([vec(A0), vec(A0 * 0), base["episode_index"]],
                           names=["action", "action", "episode_index"])
pq.write_table(tab, "pq_dup_action.parquet")
# info.json written with a UTF-8 BOM (Windows editors / PowerShell Out-File)
src = Path("lr_v30"); dst = Path("lr_bom")
shutil.rmtree(dst, ignore_errors=True); shutil.copytree(src, dst)
(dst / "meta" / "info.json").write_bytes(b"\xef\xbb\xbf" + (src / "meta" / "info.json").read_bytes())
# info.json fps as a bool / as 50.0 in a nested 'fps': {"action": 50}
for nm, fps in (("lr_fps_bool", True), ("lr_fps_dict", {"action": 50})):
    d = Path(nm); shutil.rmtree(d, ignore_errors=True); shutil.copytree(src, d)
    inf = json.loads((d / "meta" / "info.json").read_text()); inf["fps"] = fps
    (d / "meta" / "info.json").write_text(json.dumps(inf))

for path, kw in [("pq_ts_datetime.parquet", {}), ("pq_ts_duration.parquet", {}),
                 ("pq_ts_int_ms.parquet", {}), ("pq_ts_30hz_nofps.parquet", {}),
                 ("pq_dup_action.parquet", {}), ("lr_bom", {"episode": 1}),
                 ("lr_fps_bool", {"episode": 1}), ("lr_fps_dict", {"episode": 1})]:
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        try:
            tr = load_trajectory(path, object_pose=np.load("traj.npz")["object_pose"], **kw)
            res = f"OK fps={tr.fps:g} shape={tr.actions.shape} assumed={tr.fps_assumed}"
        except critmoment.CritmomentError as e:
            res = f"CMERR {type(e).__name__}: {str(e)[:300]}"
        except Exception as e:  # noqa: BLE001
            res = f"OTHER {type(e).__name__}: {str(e)[:300]}"
    print(f"== {path}: {res}")
    for x in w:
        print("   warning:", str(x.message)[:200])
    args = [path] + (["--episode", str(kw["episode"])] if kw else [])
    p = subprocess.run(["/work/main/benchmarks/probe_r35/inputs/cm.sh", "rollout", *args, "--json"],
                       capture_output=True, text=True)
    print(f"   CLI rollout rc={p.returncode}", (p.stderr.strip().splitlines() or [""])[-1][:300])
