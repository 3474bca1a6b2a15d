import os
import sys

sys.path.insert(0, os.path.dirname(__file__)); from harness import run
D = "/tmp/r28/cli/in/pq"
for n in sorted(os.listdir(D)):
    p = os.path.join(D, n)
    run(["episodes", p, "--json"], name="episodes " + n, json_out=True)
    run(["rollout", p], name="rollout " + n)
for ep in ["0", "1", "5", "7", "-1", "abc", "1e3", "0.5", " 1"]:
    run(["rollout", os.path.join(D, "multi.parquet"), "--episode", ep], name="rollout multi --episode " + repr(ep))
run(["rollout", os.path.join(D, "ds_ok"), "--episode", "2"], name="rollout ds_ok --episode 2")
run(["rollout", os.path.join(D, "ds_ok/data/chunk-000/episode_000001.parquet")], name="rollout ds_ok inner file ep1")
run(["rollout", os.path.join(D, "ds_ok/data/chunk-000/episode_000001.parquet"), "--episode", "0"], name="rollout ds_ok inner file --episode 0")
run(["rollout", os.path.join(D, "ds_v3"), "--episode", "1"], name="rollout ds_v3 --episode 1")
run(["rollout", os.path.join(D, "ep_noidx.parquet"), "--episode", "0"], name="rollout ep_noidx --episode 0")
run(["rollout", "/tmp/r28/cli/readme/traj.npz", "--episode", "0"], name="rollout npz --episode 0")
run(["episodes", "/tmp/r28/cli/readme/traj.npz", "--json"], name="episodes npz", json_out=True)
run(["episodes", "/tmp/r28/cli/in/act_ok.hdf5", "--json"], name="episodes hdf5", json_out=True)
run(["episodes", "/tmp/r28/cli/in/T1.npz", "--json"], name="episodes T1.npz", json_out=True)
run(["episodes", "/tmp/r28/cli/in/qpos0_wrong.npz"], name="episodes qpos0_wrong.npz")
