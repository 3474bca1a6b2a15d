"""Synthetic check of the two-sided region logic (verdict.fail_sides / safe_subbox /
candidate_region / shrink_region), no simulation: a known failure function on a box, Sobol
samples decided exactly, then (1) is any failing SAMPLE strictly inside the stated region,
(2) is any failing point of a dense grid inside it (what full rollouts would find), and how
much of the truly safe set the region keeps.
usage: PYTHONPATH=/tmp/r29b/src python region_synth.py"""
import itertools
import numpy as np
import critmoment as cm
from critmoment import verdict as vd
from critmoment.params import FrictionParameter, MassParameter, UncertaintyBox, ComOffsetParameter, ForceLimitParameter
from critmoment.sparse import sweep_samples
print("critmoment", cm.__file__)

def P(cls, name, lo, hi, nom):
    return cls(name=name, target="obj", low=lo, high=hi, nominal=nom)

def run(title, box, fails, n=256, margin=0.0):
    s = sweep_samples(box, n=n, seed=0)
    f = np.array([fails(x) for x in s])
    sides = vd.fail_sides(s, f, box)
    reg = vd.candidate_region(s, f, box, sides, margin=margin)
    line = f"{title}: fail {f.sum()}/{n} sides {sides} region " + (
        "None" if reg is None else "{" + ", ".join(f"{k}: [{a:.3g}, {b:.3g}]" for k, (a, b) in reg.items()) + "}")
    if reg is not None:
        lo = np.array([reg[k][0] for k in box.names]); hi = np.array([reg[k][1] for k in box.names])
        strict = ((s > lo + 1e-12) & (s < hi - 1e-12)).all(axis=1) & f
        g = np.array(list(itertools.product(*[np.linspace(a, b, 21) for a, b in zip(lo, hi)])))
        gf = np.array([fails(x) for x in g])
        full = np.array(list(itertools.product(*[np.linspace(p.low, p.high, 21) for p in box.parameters])))
        safe_full = ~np.array([fails(x) for x in full])
        in_reg = ((full >= lo) & (full <= hi)).all(axis=1)
        line += (f"\n    failing samples strictly inside: {int(strict.sum())}; failing grid points in region: "
                 f"{int(gf.sum())}/{len(g)}; region keeps {int((in_reg & safe_full).sum())}/{int(safe_full.sum())} safe grid points; nominal inside: "
                 f"{bool(((box.nominal >= lo) & (box.nominal <= hi)).all())}")
        if gf.any():
            line += f"\n    e.g. failing {g[np.flatnonzero(gf)[0]].round(4)}"
    print(line)
    return s, f, sides, reg

com = lambda lo=-0.015, hi=0.015, nom=0.0: P(ComOffsetParameter, "com", lo, hi, nom)  # a plain scalar axis
m = P(MassParameter, "mass", 0.05, 3.0, 1.0)
mu = P(FrictionParameter, "friction", 0.2, 1.5, 0.8)
# 1. symmetric two-sided com, one-sided mass
run("1 |com|>1cm or mass>2", UncertaintyBox((m, com())), lambda x: abs(x[1]) > 0.01 or x[0] > 2.0)
# 2. asymmetric: fails below -0.5 cm, above +1.2 cm
run("2 com<-5mm or com>12mm", UncertaintyBox((m, com())), lambda x: x[1] < -0.005 or x[1] > 0.012 or x[0] > 2.5)
# 3. interaction: tolerance to |com| shrinks with mass (a cone: the heavier, the narrower)
run("3 |com| > 1.5cm*(1-mass/3.2)", UncertaintyBox((m, com())), lambda x: abs(x[1]) > 0.015 * (1 - x[0] / 3.2))
# 4. friction both ends fail (too slippery, and too grippy to release), mass one-sided
run("4 mu<0.4 or mu>1.2 or mass>2", UncertaintyBox((m, mu)), lambda x: x[1] < 0.4 or x[1] > 1.2 or x[0] > 2.0)
# 5. three params: com two-sided whose width depends on friction
run("5 3-D |com|>0.01*mu/1.5+0.003", UncertaintyBox((m, mu, com())),
    lambda x: abs(x[2]) > 0.01 * x[1] / 1.5 + 0.003 or x[0] > 2.5)
# 6. four params, two two-sided (com and force), mass one-sided
f = P(ForceLimitParameter, "force", 4.0, 100.0, 35.0)
run("6 4-D |com|>1cm or force<15 or force>80 or mass>2 (mu<0.3)", UncertaintyBox((m, mu, com(), f)),
    lambda x: abs(x[2]) > 0.01 or x[3] < 15 or x[3] > 80 or x[0] > 2.0 or x[1] < 0.3)
# 7. two-sided failure only in a corner: com fails both ways but only when heavy
run("7 |com|>5mm and mass>1.5", UncertaintyBox((m, com())), lambda x: abs(x[1]) > 0.005 and x[0] > 1.5)
# 8. an island of failure around the nominal's side (non-monotone band inside)
run("8 band 0.4<mu<0.5 fails + mass>2.5", UncertaintyBox((m, mu)), lambda x: 0.4 < x[1] < 0.5 or x[0] > 2.5)
# 9. one-sided failure but the nominal mid-box: must not become "both" by chance
run("9 com>8mm only", UncertaintyBox((m, com())), lambda x: x[1] > 0.008)
# 10. 64 samples only (validate-sized): two-sided com
run("10 n=64 |com|>1cm or mass>2", UncertaintyBox((m, com())), lambda x: abs(x[1]) > 0.01 or x[0] > 2.0, n=64)
