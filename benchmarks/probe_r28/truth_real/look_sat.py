"""Longest stretch an arm actuator spends at >= 0.99 / 0.999 / 0.9999 of its limit in one
sample's own rollout (truth.Setup), and the force, limit and where.
usage: look_sat.py SCENARIO TRAJ MASS FRICTION"""
import sys

sys.path.insert(0, "/work/main/benchmarks/probe_r28/truth_real")
import truth

s = truth.Setup(sys.argv[1], sys.argv[2])
vals = [float(sys.argv[3]) if n == "mass" else float(sys.argv[4]) for n in s.names]
rec = s.rollout(vals)
dt = s.model.opt.timestep
def longest(mask):
    best = cur = 0; end = -1
    for i, v in enumerate(mask):
        cur = cur + 1 if v else 0
        if cur > best: best, end = cur, i
    return best, end
for a in s.arm_act:
    f = rec["frac"][:, a]
    if f.max() < 0.99: continue
    out = [f"{s.model.actuator(a).name} limit {s.limits[a]:.3g} max frac {f.max():.5f}"]
    for th in (0.99, 0.999, 0.9999):
        n, e = longest(f >= th)
        out.append(f">= {th}: longest {n} steps ({n*dt*1000:.0f} ms) ending step {e}")
    print("; ".join(out))
