"""CLI flags at boundary values (analyze/validate/rollout/moments), expected rc per doc."""
import os, sys
sys.path.insert(0, os.path.dirname(__file__)); from harness import run
T = "/tmp/r31/inputs/traj.npz"; S = "/tmp/r31/inputs/safe"
A = ["analyze", T, "--scenario", S, "--figures", "none"]
cases = [
  (A + ["--samples", "0"], 2), (A + ["--samples", "7"], 2), (A + ["--samples", "8"], 0), (A + ["--samples", "1e9"], 2),
  (A + ["--samples", "1.5e1"], 2), (A + ["--samples", "nan"], 2), (A + ["--samples", "0x10"], 2), (A + ["--samples", "1_000"], None),
  (A + ["--samples", " 16"], None), (A + ["--samples", "16", "--samples", "8"], 0),
  (A + ["--samples", "8", "--seed", "-1"], 2), (A + ["--samples", "8", "--seed", str(2**32)], 2), (A + ["--samples", "8", "--seed", str(2**32 - 1)], 0),
  (A + ["--samples", "8", "--seed", str(2**64)], 2), (A + ["--samples", "8", "--seed", "1e400"], 2), (A + ["--samples", "8", "--seed", "4294967295.0"], 0),
  (A + ["--samples", "8", "--horizon", "0"], 2), (A + ["--samples", "8", "--horizon", "1"], None), (A + ["--samples", "8", "--horizon", "2000"], None),
  (A + ["--samples", "8", "--horizon", "2001"], 2), (A + ["--samples", "8", "--horizon", "99999999999"], 2),
  (A + ["--samples", "8", "--nthread", "1"], 2),
  (A + ["--samples", "8", "--max-steps", "1"], 2), (A + ["--samples", "8", "--max-steps", "4000"], 0), (A + ["--samples", "8", "--max-steps", "3999"], 2),
  (A + ["--samples", "8", "--max-batch-steps", "1"], 2), (A + ["--samples", "8", "--max-input-bytes", "1"], 2),
  (A + ["--samples", "8", "--max-moments", "0"], 2), (A + ["--samples", "8", "--max-moments", "1"], None), (A + ["--samples", "8", "--max-moments", "100000"], None),
  (A + ["--samples", "8", "--min-success", "1.1"], 2), (A + ["--samples", "8", "--min-success", "-0"], None), (A + ["--samples", "8", "--min-success", "nan"], 2),
  (A + ["--samples", "8", "--verify", "0"], 2), (A + ["--samples", "8", "--verify", "1"], None), (A + ["--samples", "8", "--verify", "0.5", "--no-verify"], 2),
  (A + ["--samples", "8", "--object-pose", "0.127", "0.454", "0.02", "1", "0", "0", "nan"], 2),
  (A + ["--samples", "8", "--object-pose", "0.127", "0.454", "0.02", "2", "0", "0", "0"], 2),
  (A + ["--samples", "8", "--object-pose", "0.127", "0.454", "0.02", "1.005", "0", "0", "0"], 0),
  (A + ["--samples", "8", "--object-pose", "0.127", "0.454", "0.02", "1", "0", "0"], 2),
  (A + ["--samples", "8", "--episode", "0"], 2), (A + ["--samples", "8", "--episode", "-1"], 2),
  (A + ["--samples", "8", "--figures", "some"], 2), (A + ["--samples", "8", "--exhaustive"], 0),
  (["validate", T, "--scenario", S, "--samples", "0"], 2), (["validate", T, "--scenario", S, "--samples", "1"], None),
  (["validate", T, "--scenario", S, "--samples", "1e9"], 2), (["validate", T, "--scenario", S, "--samples", "2", "--min-agreement", "1.5"], 2),
  (["moments", T, "--max-moments", "0"], 2), (["moments", T, "--max-moments", "1", "--json"], 0),
  (["rollout", T, "--max-steps", "3999"], 2), (["rollout", T, "--max-steps", "4000"], 0),
  (["rollout", T, "--scenario", "nope_bundled"], 2), (["rollout", T, "--scenario", ""], 2), (["rollout", ""], 2),
  (["analyze"], 2), (["--version"], 0), (["bogus"], 2),
]
env_cases = [({"CRITMOMENT_MAX_STEPS": "0"}, ["rollout", T], 2), ({"CRITMOMENT_MAX_STEPS": "abc"}, ["rollout", T], 2),
             ({"CRITMOMENT_MAX_STEPS": "-5"}, ["rollout", T], 2), ({"CRITMOMENT_MAX_STEPS": "1e3"}, ["rollout", T], 2),
             ({"CRITMOMENT_MAX_STEPS": "4000"}, ["rollout", T], 0), ({"CRITMOMENT_MAX_INPUT_BYTES": "10"}, ["rollout", T], 2)]
start = int(os.environ.get("START", "0"))
for args, exp in cases[start:]: run(args, expect=exp)
for env, args, exp in env_cases: run(args, name=f"{env} {' '.join(args)}", env=env, expect=exp)
