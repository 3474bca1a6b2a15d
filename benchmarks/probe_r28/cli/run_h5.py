import os
import sys

sys.path.insert(0, os.path.dirname(__file__)); from harness import run
D = "/tmp/r28/cli/in"
for n in sorted(os.listdir(D)):
    if n.endswith((".hdf5", ".h5")): run(["rollout", os.path.join(D, n)], name="rollout " + n)
