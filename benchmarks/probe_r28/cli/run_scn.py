import os
import sys

sys.path.insert(0, os.path.dirname(__file__)); from harness import run
D = "/tmp/r28/cli/scn"
for n in sorted(os.listdir(D)):
    if n.endswith(".toml"):
        run(["rollout", "/tmp/r28/cli/readme/traj.npz", "--scenario", os.path.join(D, n)], name="rollout scn " + n)
