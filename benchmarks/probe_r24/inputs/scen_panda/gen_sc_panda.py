"""Scenario TOML variants of the bundled Panda scenario (panda_pick_place), written next to this
script: `python scen_panda/gen_sc_panda.py` (from any folder).

The variants point `mjcf` at the bundled model by absolute path, found at run time: the folder
named by $R24_MODELS_DIR if set, else the installed `critmoment.models` package folder.
The .toml files are generated (git-ignored); rerun this script to get them back."""
import os
from importlib import resources
from pathlib import Path

MODELS = os.environ.get("R24_MODELS_DIR") or str(resources.files("critmoment.models"))
M = os.path.join(MODELS, "panda_pick_place")
HERE = Path(__file__).resolve().parent
base = (Path(M) / "scenario.toml").read_text().replace('mjcf = "scene.xml"', f'mjcf = "{M}/scene.xml"')

GOAL = "goal = [0.5, 0.15, 0.02]  #"
TOL = "tolerance = 0.03          # [m]"
SCALES = "scales = [0.04, 0.04]"


def w(name, s):
    (HERE / f"{name}.toml").write_text(s)


def sub(name, *pairs):
    s = base
    for a, b in pairs:
        assert a in s, a
        s = s.replace(a, b, 1)
    w(name, s)


w("ok", base)
sub("channel_missing", ('[[actions.channel]]\nactuators = ["joint7"]\nlabel = "joint7"\n', ""))
sub("dup_actuator", ('actuators = ["joint7"]', 'actuators = ["joint6"]'))
sub("unknown_actuator", ('actuators = ["joint7"]', 'actuators = ["joint77"]'))
sub("label_dup", ('label = "joint7"', 'label = "joint6"'))
sub("fps_mismatch", ("fps = 50.0", "fps = 25.0"))
sub("goal_2", (GOAL, "goal = [0.5, 0.15]  #"))
sub("goal_in_air", (GOAL, "goal = [0.5, 0.15, 0.5]  #"))
sub("goal_mm", (GOAL, "goal = [500, 150, 20]  #"))
sub("goal_underground", (GOAL, "goal = [0.5, 0.15, -0.5]  #"))
sub("grip_never_closes", ("scales = [0.04, 0.04]\noffsets = [0.0, 0.0]", "scales = [0.03, 0.03]\noffsets = [0.041, 0.041]"))
sub("gripper_unknown", ('gripper = "hand"', 'gripper = "hnd"'))
sub("receiver_on_pp", ('gripper = "hand"\n', 'gripper = "hand"\nreceiver = "hand"\n'))
sub("normalised_str", ("normalised = true", 'normalised = "yes"'))
sub("scale_len", (SCALES, "scales = [0.04]"))
sub("scale_neg", (SCALES, "scales = [-0.04, -0.04]"))
sub("scale_neg05", (SCALES, "scales = [-0.05, -0.05]"))
sub("scale_zero", (SCALES, "scales = [0.0, 0.0]"))
sub("tol_huge", (TOL, "tolerance = 100.0          # [m]"))
sub("tol_zero", (TOL, "tolerance = 0.0          # [m]"))
