import os, sys
sys.path.insert(0, os.path.dirname(__file__)); from harness import run
D = "/tmp/r31/inputs/in"
names = sorted(os.listdir(D.encode()))
if len(sys.argv) > 1: names = [n.encode() for n in sys.argv[1:]]
for n in names:
    n = n.decode(errors="surrogateescape")
    run(["rollout", os.path.join(D, n), "--json"], name="rollout " + n, json_out=True)
run(["rollout", "/tmp/r31/inputs/fifo.npz", "--json"], name="rollout fifo", timeout=30)
