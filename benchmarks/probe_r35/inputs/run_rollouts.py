"""Runs `critmoment rollout --json` on every input of make_inputs.py and compares it with
traj.npz's (run from /tmp/r35/inputs). Prints one block per case: rc, stderr lines, and the
fields that differ from the npz baseline. Usage: run_rollouts.py [CASE-SUBSTRING ...]"""
import json
import subprocess
import sys

import numpy as np

CM = "/work/main/benchmarks/probe_r35/inputs/cm.sh"
POSE = [repr(float(x)) for x in np.load("traj.npz")["object_pose"]]
FIELDS = ("steps", "duration", "max_stage", "final_stage", "completed", "stage_first_step",
          "min_fos_contact", "min_fos_motor", "max_cost", "max_cost_step")

CASES = [  # (name, args)
    ("npz", ["traj.npz"]),
    ("lr_v30 ep1", ["lr_v30", "--episode", "1"]),
    ("lr_v30 file ep1", ["lr_v30/data/chunk-000/file-000.parquet", "--episode", "1"]),
    ("lr_v30 no ep", ["lr_v30"]),
    ("lr_v30_ids ep1 (position)", ["lr_v30_ids", "--episode", "1"]),
    ("lr_v30_ids ep3", ["lr_v30_ids", "--episode", "3"]),
    ("lr_v21 ep1", ["lr_v21", "--episode", "1"]),
    ("lr_v21 file", ["lr_v21/data/chunk-000/episode_000001.parquet"]),
    ("lr_names_swapped", ["lr_names_swapped"]),
    ("lr_names_dict", ["lr_names_dict"]),
    ("lr_width16", ["lr_width16"]),
    ("lr_fps30", ["lr_fps30"]),
    ("lr_fps_conflict", ["lr_fps_conflict"]),
    ("lr_f16", ["lr_f16"]),
    ("lr_f64_list", ["lr_f64_list"]),
    ("lr_large_list", ["lr_large_list"]),
    ("lr_frame100", ["lr_frame100"]),
    ("lr_split ep1", ["lr_split", "--episode", "1"]),
    ("lr_split ep0", ["lr_split", "--episode", "0"]),
    ("lr_state28", ["lr_state28"]),
    ("lr_drift", ["lr_drift"]),
    ("lr_global_ts ep1", ["lr_global_ts", "--episode", "1"]),
    ("lr_appledouble", ["lr_appledouble"]),
    ("panda_ep (aloha scn)", ["panda_ep.parquet"]),
    ("panda_ep (panda scn)", ["panda_ep.parquet", "--scenario", "panda_pick_place"]),
    ("ep_alone", ["ep_alone.parquet"]),
    ("ep_alone_nots", ["ep_alone_nots.parquet"]),
    ("act", ["act.hdf5"]),
    ("act_actions", ["act_actions.hdf5"]),
    ("act_30hz_attr", ["act_30hz_attr.hdf5"]),
    ("act_fps_array", ["act_fps_array.hdf5"]),
    ("act_qpos16", ["act_qpos16.hdf5"]),
    ("act_f16", ["act_f16.hdf5"]),
    ("act_3d", ["act_3d.hdf5"]),
    ("act_extra", ["act_extra.hdf5"]),
    ("act_qpos_rows", ["act_qpos_rows.hdf5"]),
    ("act_envstate (no pose arg)", ["act_envstate.hdf5", "NOPOSE"]),
    ("act_rates3", ["act_rates3.hdf5"]),
    ("act_rate_neg", ["act_rate_neg.hdf5"]),
    ("robomimic", ["robomimic.hdf5"]),
    ("npz_1TD", ["npz_1TD.npz"]),
    ("npz_T1D", ["npz_T1D.npz"]),
    ("npz_f16", ["npz_f16.npz"]),
    ("npz_chunks", ["npz_chunks.npz"]),
    ("npz_qpos", ["npz_qpos.npz"]),
    ("npz_int64", ["npz_int64.npz"]),
    ("npz_object", ["npz_object.npz"]),
    ("npz_pickle", ["npz_pickle.npz"]),
    ("npz_action_singular", ["npz_action_singular.npz"]),
    ("npz_dt", ["npz_dt.npz"]),
    ("npz_dt --fps", ["npz_dt.npz", "--fps", "25"]),
    ("npz_fps_str", ["npz_fps_str.npz"]),
    ("npz_fps_int", ["npz_fps_int.npz"]),
    ("npz_time_int_ms", ["npz_time_int_ms.npz"]),
    ("npz_start_transposed", ["npz_start_transposed.npz"]),
    ("npz_meta_bytes", ["npz_meta_bytes.npz"]),
    ("npz_meta_other_scn", ["npz_meta_other_scn.npz"]),
    ("npz_compressed", ["npz_compressed.npz"]),
]


def run(args):
    if "NOPOSE" in args:
        args = [a for a in args if a != "NOPOSE"]
    elif "panda" not in args[0]:
        args = args + ["--object-pose", *POSE]
    p = subprocess.run([CM, "rollout", *args, "--json"], capture_output=True, text=True, timeout=300)
    try:
        out = json.loads(p.stdout) if p.stdout.strip() else None
    except ValueError:
        out = {"_stdout": p.stdout[:300]}
    return p.returncode, out, p.stderr.strip().splitlines()


def close(a, b):
    if isinstance(a, float) and isinstance(b, float):
        return abs(a - b) <= 1e-3 * max(1.0, abs(a), abs(b))
    return a == b


if __name__ == "__main__":
    want = sys.argv[1:]
    base = None
    for name, args in CASES:
        if want and name != "npz" and not any(w in name for w in want):
            continue
        rc, out, err = run(args)
        if name == "npz":
            base = out
        print(f"== {name}: rollout {' '.join(args)} -> rc {rc}")
        for line in err:
            print("   stderr:", line[:400])
        if out and base and name != "npz":
            diff = {k: (base.get(k), out.get(k)) for k in FIELDS if not close(base.get(k), out.get(k))}
            print("   same as npz" if not diff else f"   DIFFERS: {diff}")
        sys.stdout.flush()
