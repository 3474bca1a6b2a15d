"""Writes scenario_<contact>.toml for the Adroit scene by hand (init finds no gripper on a
dexterous hand and writes nothing): every actuator its own channel in ctrl units (the
trajectory is in ctrl units), the hand = the palm's subtree, pick_hold of the ball.

Usage: python make_scenario.py [CONTACT [MASS_RANGE [FRICTION_RANGE [OUT.toml]]]] [--hand] [--limits]
e.g. python make_scenario.py elliptic10 "0.05, 2.0" "0.2, 1.5" scenario_30ch_elliptic10_limits.toml --limits
CONTACT is shipped or elliptic10 (the scene make_scene.py wrote, reached through the
``assets`` link fetch.sh makes next to this file); --hand puts the 17 moving finger
actuators on one normalised channel; --limits adds finite [limits]. The scenario's mjcf
path is written relative to OUT's folder.
"""
import os
import sys
from pathlib import Path

import mujoco

argv = [x for x in sys.argv[1:] if not x.startswith("--")]
contact = argv[0] if argv else "shipped"
mass = argv[1] if len(argv) > 1 else "0.05, 2.0"
fric = argv[2] if len(argv) > 2 else "0.2, 1.5"
out = argv[3] if len(argv) > 3 else f"scenario_{contact}.toml"
scene = Path(__file__).absolute().parent / "assets" / f"critmoment_r24_adroit_{contact}.xml"
m = mujoco.MjModel.from_xml_path(str(scene))
path = os.path.relpath(scene, Path(out).absolute().parent)
lines = [f'name = "adroit_{contact}"', f'description = "Adroit relocate ball, pick_hold ({contact})"',
         "", "[model]", f'mjcf = "{path}"', "", "[object]", 'body = "Object"', 'geom = "sphere"', "",
         "[grippers.hand]", 'body = "palm"', "", "[support]", 'bodies = ["table"]', "",
         "[actions]", 'convention = "explicit"', "fps = 50.0", 'range_policy = "warn"', ""]
hand = "--hand" in sys.argv
allf = [m.actuator(i).name for i in range(m.nu) if m.actuator(i).name[2:4] in ("FF", "MF", "RF", "LF", "TH")]
ALLC = [0.0, 1.0, 1.0, 0.6, 0.0, 1.0, 1.0, 0.6, 0.0, 1.0, 1.0, 0.6, 0.0, 0.0, 1.0, 1.0, 0.6, 0.4, 1.2, 0.2, 0.3, -0.6]
# closed == open is refused per actuator: the joints that stay at 0 get their own channels
fingers = [f for f, c in zip(allf, ALLC, strict=True) if c != 0.0]
CLOSED = [c for c in ALLC if c != 0.0]
for i in range(m.nu):
    if hand and m.actuator(i).name in fingers:
        continue
    lines += ["[[actions.channel]]", f'actuators = ["{m.actuator(i).name}"]', ""]
if hand:
    lines += ["[[actions.channel]]", f"actuators = {fingers!r}".replace("'", '"'), "normalised = true",
              f"closed = {CLOSED!r}", f"open = {[0.0] * len(fingers)!r}", 'label = "hand"', ""]
if "--limits" in sys.argv:  # finite force limits (none in the MJCF: finding 1)
    lines += ["[limits]"]
    for i in range(m.nu):
        n = m.actuator(i).name
        lim = 300.0 if n.startswith("A_ART") else 100.0 if n.startswith("A_ARR") else 20.0 if n.startswith("A_WR") else 5.0
        lines += [f"{n} = {lim}"]
    lines += [""]
lines += ["[task]", 'kind = "pick_hold"', 'gripper = "hand"', "lift_height = 0.02", "",
          "[uncertainty.mass]", 'body = "Object"', f"range = [{mass}]", "nominal = 0.18", "",
          "[uncertainty.friction]", 'geom = "sphere"', f"range = [{fric}]", "nominal = 1.0", "",
          "[sparse]", "horizon = 10", ""]
open(out, "w").write("\n".join(lines))
print("wrote", out)
