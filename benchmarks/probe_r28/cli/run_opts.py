import os
import sys

sys.path.insert(0, os.path.dirname(__file__)); from harness import run
T = "/tmp/r28/cli/readme/traj.npz"
A = ["analyze", T, "--figures", "none"]
cases = [
 (A + ["--samples", "7"], 2), (A + ["--samples", "abc"], 2), (A + ["--samples", "nan"], 2), (A + ["--samples", "1e9"], 2),
 (A + ["--samples", "8.5"], 2), (A + ["--samples", "-8"], 2), (A + ["--samples", "inf"], 2),
 (A + ["--min-success", "-0.1"], 2), (A + ["--min-success", "1.1"], 2), (A + ["--min-success", "nan"], 2), (A + ["--min-success", "abc"], 2),
 (A + ["--seed", "-1"], 2), (A + ["--seed", "4294967296"], 2), (A + ["--seed", "1.5"], 2), (A + ["--seed", "0x10"], None),
 (A + ["--horizon", "0"], 2), (A + ["--horizon", "-1"], 2), (A + ["--horizon", "3000"], 2), (A + ["--horizon", "1e2"], None),
 (A + ["--max-moments", "0"], 2), (A + ["--verify", "-1"], 2), (A + ["--verify", "nan"], 2), (A + ["--verify", "0"], None),
 (A + ["--verify", "0.5", "--no-verify"], 2),
 (A + ["--object-pose", "0", "0", "0"], 2), (A + ["--object-pose", "0.1", "0.5", "0.02", "2", "0", "0", "0"], 2),
 (A + ["--object-pose", "a", "0.5", "0.02", "1", "0", "0", "0"], 2), (A + ["--object-pose", "nan", "0.5", "0.02", "1", "0", "0", "0"], 2),
 (A + ["--object-pose", "0.127", "0.454", "0.0125", "1.005", "0", "0", "0"], None),
 (A + ["--figures", "some"], 2), (A + ["--bogus"], 2), (["analyze"], 2), (["analyze", T, T], 2), ([], 2), (["bogus"], 2),
 (A + ["--max-steps", "0"], 2), (A + ["--max-steps", "100"], 2), (A + ["--max-batch-steps", "1000"], 2), (A + ["--max-input-bytes", "10"], 2),
 (A + ["--max-steps", "abc"], 2),
 (["-v", "analyze", T, "--samples", "7"], 2), (["analyze", "-v", T, "--samples", "7"], 2),
 (["validate", T, "--samples", "0"], 2), (["validate", T, "--min-agreement", "2"], 2), (["validate", T, "--min-agreement", "nan"], 2),
 (["moments", T, "--max-moments", "0"], 2), (["moments", T, "--max-moments", "abc"], 2),
 (["demo", "--seed", "-1", "--out", "/tmp/r28/cli/work/x.npz"], 2), (["demo", "--seed", "abc"], 2),
 (["demo", "--scenario", "panda_pick_place", "--family", "early_open", "--out", "/tmp/r28/cli/work/pe.npz"], None),
 (["demo", "--scenario", "aloha_transfer_cube", "--family", "faster", "--out", "/tmp/r28/cli/work/af.npz"], None),
 (["demo", "--out", "/tmp/r28/cli/work/noext"], None),
 (["demo", "--out", "/tmp/r28/cli/work/x.hdf5"], None),
 (["demo", "--out", "/tmp/r28/cli/readme/report"], 2),
 (["demo", "--out", "/tmp/r28/cli/in/with space ü é.npz"], 2),
 (["inspect", "/nonexistent.xml"], 2), (["inspect", "/tmp/r28/cli/scn/broken.xml"], 2), (["inspect", "/tmp/r28/cli/readme/traj.npz"], 2),
 (["inspect", "/tmp/r28/cli/scn/scenario_dir_not_xml"], 2),
 (["init", "/tmp/r28/src/models/aloha_transfer_cube/scene.xml", "--object", "nope", "--task", "handover"], 2),
 (["init", "/tmp/r28/src/models/aloha_transfer_cube/scene.xml", "--object", "box", "--task", "pick_place"], 2),
 (["init", "/tmp/r28/src/models/aloha_transfer_cube/scene.xml", "--object", "box", "--task", "pick_place", "--goal", "0", "0.5", "nan"], 2),
 (["init", "/tmp/r28/src/models/aloha_transfer_cube/scene.xml", "--object", "box", "--task", "pick_place", "--goal", "500", "200", "20"], 2),
 (["init", "/tmp/r28/src/models/aloha_transfer_cube/scene.xml", "--object", "box", "--task", "handover", "--picker", "nope"], 2),
 (["init", "/tmp/r28/src/models/aloha_transfer_cube/scene.xml", "--object", "box", "--task", "handover", "--out", "/tmp/r28/cli/readme/traj.npz"], 2),
 (["init", "/tmp/r28/src/models/aloha_transfer_cube/scene.xml", "--object", "box", "--task", "handover", "--out", "/tmp/r28/cli/work/newdir/"], 2),
 (["init", "/tmp/r28/src/models/aloha_transfer_cube/scene.xml", "--object", "box", "--task", "handover", "--support", "nope"], 2),
 (["init", "/tmp/r28/src/models/aloha_transfer_cube/scene.xml", "--object", "box", "--task", "handover", "--gripper", "nope"], 2),
]
for args, exp in cases: run(args, expect=exp)
