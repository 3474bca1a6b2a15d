"""Force-limit scenario variants of the bundled twins (mjcf points at /tmp/r28b/src/models)."""
import re
from pathlib import Path
SRC = Path("/tmp/r28b/src/models"); OUT = Path(__file__).parent / "scen"
def base(name):
    t = (SRC / name / "scenario.toml").read_text()
    t = t.replace('mjcf = "scene.xml"', f'mjcf = "{SRC / name / "scene.xml"}"')
    return re.sub(r"\[uncertainty\.[^\n]*\n(?:(?!\[cost\]).*\n)*?(?=\[uncertainty|\[cost\]|# Cost)", "", t)
def unc(n, kind, key, tgt, lo, hi, nom):
    return f'[uncertainty.{n}]\nkind = "{kind}"\n{key} = "{tgt}"\nrange = [{lo}, {hi}]\nnominal = {nom}\nprior = "uniform"\n\n'
M = lambda b, lo, hi, nom: unc("mass", "mass", "body", b, lo, hi, nom)
L = lambda n, a, lo, hi, nom: unc(n, "force_limit", "actuator", a, lo, hi, nom)
B = {
 "aloha_elbow": ("aloha_transfer_cube", L("elbow", "right/elbow", 1, 15, 15), "elbow = 15.0"),
 "aloha_wrist": ("aloha_transfer_cube", L("wrist", "right/wrist_angle", 0.3, 5, 5), "wrist_angle = 5.0"),
 "aloha_mass_elbow": ("aloha_transfer_cube", M("box", 0.05, 3, 0.05) + L("elbow", "right/elbow", 3, 15, 15), "elbow = 15.0"),
 "aloha_mass10_shoulder": ("aloha_transfer_cube", M("box", 0.05, 10, 0.05) + L("shoulder", "right/shoulder", 5, 20, 20), "shoulder = 20.0"),
 "aloha_left_shoulder": ("aloha_transfer_cube", M("box", 0.05, 3, 0.05) + L("shoulder", "left/shoulder", 3, 20, 20), "shoulder = 20.0"),
 "aloha_elbow_band": ("aloha_transfer_cube", L("elbow", "right/elbow", 2.5, 3.6, 3.6), "elbow = 15.0"),
 "aloha_mass_elbow_band": ("aloha_transfer_cube", M("box", 0.05, 0.6, 0.05) + L("elbow", "right/elbow", 2.5, 6, 6), "elbow = 15.0"),
 "panda_j4_band": ("panda_pick_place", L("elbow", "joint4", 18, 25, 25), "joint4 = 87.0"),
 "panda_j6_band": ("panda_pick_place", L("wrist", "joint6", 2.5, 3.6, 3.6), "joint6 = 12.0"),
 "panda_mass_j6_band": ("panda_pick_place", M("cube", 0.05, 1.0, 0.1) + L("wrist", "joint6", 2.5, 6, 6), "joint6 = 12.0"),
 "panda_j4": ("panda_pick_place", L("elbow", "joint4", 5, 87, 87), "joint4 = 87.0"),
 "panda_j6": ("panda_pick_place", L("wrist", "joint6", 0.5, 12, 12), "joint6 = 12.0"),
 "panda_mass10_j2": ("panda_pick_place", M("cube", 0.05, 10, 0.1) + L("shoulder", "joint2", 10, 87, 87), "joint2 = 87.0"),
 "panda_mass_j4": ("panda_pick_place", M("cube", 0.05, 3, 0.1) + L("elbow", "joint4", 10, 87, 87), "joint4 = 87.0"),
}
OUT.mkdir(exist_ok=True)
for name, (tw, tables, rating) in B.items():
    b = base(tw)
    t = b.replace("[cost]", tables + "[cost]", 1) if "# Cost" not in b else b.replace("# Cost", tables + "# Cost", 1)
    (OUT / f"{name}.toml").write_text(t)
    assert rating + "\n" in t, (name, rating)
    (OUT / f"{name}_nolim.toml").write_text(t.replace(rating + "\n", "", 1))
print(sorted(p.name for p in OUT.glob("*.toml")))
