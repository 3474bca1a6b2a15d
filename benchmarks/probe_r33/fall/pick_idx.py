"""Sample indices for the (slow) independent truth: every sample either validate run predicted safe,
plus every k-th other one (so that some predicted failures are cross-checked too).
usage: pick_idx.py VAL.json VALNV.json [K]"""
import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r33/src"), _cm_check.__file__  # r33 snapshot
import json, sys
a = json.load(open(sys.argv[1]))["per_sample"]; b = json.load(open(sys.argv[2]))["per_sample"]
k = int(sys.argv[3]) if len(sys.argv) > 3 else 4
idx = [i for i in range(len(a)) if not a[i]["predicted_failed"] or not b[i]["predicted_failed"] or i % k == 0]
print(" ".join(map(str, idx)))
