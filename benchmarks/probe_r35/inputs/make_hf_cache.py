"""A LeRobot v3.0 dataset as the Hugging Face hub cache stores it: snapshots/<rev>/... are
symlinks into blobs/ (run from /tmp/r35/inputs after make_inputs.py). info.json says 30 Hz;
the data file has no 'timestamp' column (as exports that drop it, or as a 30 Hz dataset
converted without one)."""
import json, os, shutil, hashlib
from pathlib import Path
import numpy as np, pyarrow as pa, pyarrow.parquet as pq

A0 = np.load("traj.npz")["actions"]
root = Path("hf_cache/datasets--lab--aloha30")
shutil.rmtree("hf_cache", ignore_errors=True)
(root / "blobs").mkdir(parents=True)
snap = root / "snapshots" / "0123abcd"
def blob(data: bytes, rel: str):
    h = hashlib.sha256(data).hexdigest()
    (root / "blobs" / h).write_bytes(data)
    link = snap / rel
    link.parent.mkdir(parents=True, exist_ok=True)
    os.symlink(os.path.relpath(root / "blobs" / h, link.parent), link)
vec = pa.FixedSizeListArray.from_arrays(pa.array(A0.reshape(-1), pa.float32()), 14)
t = pa.table({"action": vec, "observation.state": vec,
              "episode_index": pa.array(np.zeros(400, np.int64)),
              "frame_index": pa.array(np.arange(400))})
import io
buf = io.BytesIO(); pq.write_table(t, buf)
blob(buf.getvalue(), "data/chunk-000/file-000.parquet")
blob(json.dumps({"codebase_version": "v3.0", "fps": 30, "robot_type": "aloha"}).encode(), "meta/info.json")
print("snapshot at", snap)
