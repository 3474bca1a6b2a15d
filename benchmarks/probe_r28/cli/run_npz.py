import os
import sys

sys.path.insert(0, os.path.dirname(__file__)); from harness import run
D = "/tmp/r28/cli/in"
for n in sorted(os.listdir(D.encode())):
    n = n.decode(errors="surrogateescape")
    if n.endswith(('.parquet', '.hdf5', '.h5', '.json', '.csv')) or os.path.isdir(os.path.join(D, n)) and n != "dir.npz": continue
    run(["rollout", os.path.join(D, n), "--json"], name="rollout " + n, json_out=False)
