import os, sys
sys.path.insert(0, os.path.dirname(__file__)); from harness import run
D = "/tmp/r31/inputs/scn"
names = sys.argv[1:] or sorted(n for n in os.listdir(D) if n.endswith(".toml"))
for n in names:
    run(["rollout", "/tmp/r31/inputs/traj.npz", "--scenario", os.path.join(D, n), "--json"], name="scn " + n, json_out=True, quiet=True)
