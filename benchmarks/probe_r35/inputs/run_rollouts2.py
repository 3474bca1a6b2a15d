"""rollout --json on make_inputs2.py's inputs, compared with traj.npz (run from /tmp/r35/inputs)."""
import sys
sys.path.insert(0, "/work/main/benchmarks/probe_r35/inputs")
from run_rollouts import FIELDS, close, run  # noqa: E402

CASES = [("npz", ["traj.npz"])] + [(n, [n]) for n in (
    "act_dt_attr.hdf5", "act_control_dt.hdf5", "act_hz_attr.hdf5", "act_timestamps.hdf5",
    "act_obs_timestamp.hdf5", "act_FPS_attr.hdf5", "act_fps_f32.hdf5", "act_dset_fps.hdf5",
    "lr_names_wrist", "lr_info_fps_str", "lr_info_nofps", "lr_one_row", "lr_chunk_rows.parquet",
    "lr_rev_noframe")] + [
    ("lr_mixed_rates ep0", ["lr_mixed_rates", "--episode", "0"]),
    ("lr_mixed_rates ep1", ["lr_mixed_rates", "--episode", "1"]),
    ("lr_frame_global ep1", ["lr_frame_global", "--episode", "1"]),
]
base = None
for name, args in CASES:
    rc, out, err = run(args)
    base = out if name == "npz" else base
    print(f"== {name}: rollout {' '.join(args)} -> rc {rc}")
    for line in err:
        print("   stderr:", line[:400])
    if out and name != "npz":
        diff = {k: (base.get(k), out.get(k)) for k in FIELDS if not close(base.get(k), out.get(k))}
        print("   same as npz" if not diff else f"   DIFFERS: {diff}")
    sys.stdout.flush()
