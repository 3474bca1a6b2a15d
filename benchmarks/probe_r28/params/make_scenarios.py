"""Write scenario variants (bundled scenario with its [uncertainty.*] tables replaced)."""
import re
from pathlib import Path

SRC = Path("/tmp/r28/src/models")
OUT = Path(__file__).parent / "scen"

def base(name):
    text = (SRC / name / "scenario.toml").read_text()
    text = text.replace('mjcf = "scene.xml"', f'mjcf = "{SRC / name / "scene.xml"}"')
    # drop the uncertainty tables (up to the [cost] table)
    text = re.sub(r"\[uncertainty\.[^\n]*\n(?:(?!\[cost\]).*\n)*?(?=\[uncertainty|\[cost\]|# Cost)", "", text)
    return text

def unc(name, kind, target_key, target, lo, hi, nom, prior="uniform"):
    return (f"[uncertainty.{name}]\nkind = \"{kind}\"\n{target_key} = \"{target}\"\n"
            f"range = [{lo}, {hi}]\nnominal = {nom}\nprior = \"{prior}\"\n\n")

M = lambda body, lo, hi, nom: unc("mass", "mass", "body", body, lo, hi, nom)
F = lambda geom, lo, hi, nom: unc("friction", "friction", "geom", geom, lo, hi, nom)
C = lambda body, lo, hi, nom, n="com": unc(n, "com_offset", "body", body, lo, hi, nom)
L = lambda n, act, lo, hi, nom: unc(n, "force_limit", "actuator", act, lo, hi, nom)

BOXES = {
  "aloha": {
    "com_narrow": C("box", -0.005, 0.005, 0.0),
    "com_wide": C("box", -0.018, 0.018, 0.0),
    "mass_com": M("box", 0.05, 1.5, 0.05) + C("box", -0.018, 0.018, 0.0),
    "grip_lim": L("grip", "right/right_finger", 0.2, 5.0, 5.0),
    "grip_lim_narrow": L("grip", "right/right_finger", 4.6, 5.0, 5.0),
    "shoulder_narrow": L("shoulder", "right/shoulder", 3.0, 7.0, 7.0),
    "shoulder_lim": L("shoulder", "right/shoulder", 2.0, 20.0, 20.0),
    "mass_shoulder": M("box", 0.05, 3.0, 0.05) + L("shoulder", "right/shoulder", 5.0, 20.0, 20.0),
    "mass_fric_grip": M("box", 0.05, 1.5, 0.05) + F("box", 0.3, 1.5, 1.0) + L("grip", "right/right_finger", 0.5, 5.0, 5.0),
    "mass_fric_com_grip": M("box", 0.05, 1.5, 0.05) + F("box", 0.3, 1.5, 1.0) + C("box", -0.015, 0.015, 0.0) + L("grip", "right/right_finger", 0.5, 5.0, 5.0),
  },
  "panda": {
    "com_narrow": C("cube", -0.005, 0.005, 0.0),
    "com_wide": C("cube", -0.018, 0.018, 0.0),
    "mass_com": M("cube", 0.05, 3.0, 0.1) + C("cube", -0.018, 0.018, 0.0),
    "grip_lim": L("grip", "finger_left", 0.5, 35.0, 35.0),
    "grip_lim_narrow": L("grip", "finger_left", 0.5, 6.0, 6.0),
    "shoulder_narrow": L("shoulder", "joint2", 30.0, 50.0, 50.0),
    "shoulder_lim": L("shoulder", "joint2", 5.0, 87.0, 87.0),
    "mass_shoulder": M("cube", 0.05, 3.0, 0.1) + L("shoulder", "joint2", 10.0, 87.0, 87.0),
    "mass_fric_grip": M("cube", 0.05, 3.0, 0.1) + F("cube", 0.3, 1.5, 1.0) + L("grip", "finger_left", 2.0, 35.0, 35.0),
    "mass_fric_com_grip": M("cube", 0.05, 3.0, 0.1) + F("cube", 0.3, 1.5, 1.0) + C("cube", -0.015, 0.015, 0.0) + L("grip", "finger_left", 2.0, 35.0, 35.0),
  },
}
NAMES = {"aloha": "aloha_transfer_cube", "panda": "panda_pick_place"}

if __name__ == "__main__":
    OUT.mkdir(exist_ok=True)
    for twin, boxes in BOXES.items():
        b = base(NAMES[twin])
        for box, tables in boxes.items():
            text = b.replace("[cost]", tables + "[cost]", 1) if "# Cost" not in b else b.replace("# Cost", tables + "# Cost", 1)
            (OUT / f"{twin}_{box}.toml").write_text(text)
    print("wrote", sorted(p.name for p in OUT.glob("*.toml")))

# variants whose force-limit actuator is NOT rated in [limits]: the sample is the actuator's limit
NOLIM = {
  "aloha_shoulder_narrow_nolim": ("aloha_shoulder_narrow", ["shoulder = 20.0"]),
  "aloha_grip_lim_narrow_nolim": ("aloha_grip_lim_narrow", ["right_finger = 5.0"]),
  "panda_shoulder_narrow_nolim": ("panda_shoulder_narrow", ["joint2 = 87.0"]),
  "panda_mass_shoulder_nolim": ("panda_mass_shoulder", ["joint2 = 87.0"]),
  "panda_mass_fric_com_grip_nolim": ("panda_mass_fric_com_grip", ["finger_left = 35.0"]),
}
if __name__ == "__main__":
    for new, (old, drop) in NOLIM.items():
        text = (OUT / f"{old}.toml").read_text()
        for line in drop:
            assert line in text, (old, line)
            text = text.replace(line + "\n", "")
        (OUT / f"{new}.toml").write_text(text)
