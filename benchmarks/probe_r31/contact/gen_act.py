"""ACT's gym-aloha scene (copy of /tmp/r28/truth_real/rm/gym_aloha assets) with one option edit each,
scenario from /tmp/r28/truth_real/act/scenario_shipped.toml -> /tmp/r31/contact/v/act_*"""
import shutil
from pathlib import Path
SRC = Path("/tmp/r28/truth_real/rm/gym_aloha/gym_aloha/assets"); V = Path("/tmp/r31/contact/v")
SC = Path("/tmp/r28/truth_real/act/scenario_shipped.toml").read_text().replace(
    "../rm/gym_aloha/gym_aloha/assets/bimanual_viperx_transfer_cube.xml", "assets/bimanual_viperx_transfer_cube.xml")
BOX = '<geom condim="4" solimp="2 1 0.01" solref="0.01 1" friction="1 0.005 0.0001"'
VARS = {"act_shipped": ("", None), "act_implicitfast": ('<option integrator="implicitfast"/>', None),
        "act_noslip20": ('<option noslip_iterations="20"/>', None),
        "act_ell100": ('<option cone="elliptic" impratio="100"/>', None),
        "act_obj_c6": ("", BOX.replace('condim="4"', 'condim="6"').replace("0.005 0.0001", "0.05 0.001")),
        "act_dt004": ('<option timestep="0.004"/>', None)}
for name, (opt, box) in VARS.items():
    out = V / name
    if out.exists():
        continue
    shutil.copytree(SRC, out / "assets")
    x = out / "assets" / "bimanual_viperx_transfer_cube.xml"; t = x.read_text()
    assert t.count("<mujoco") == 1
    i = t.index(">", t.index("<mujoco")) + 1
    t = t[:i] + "\n    " + opt + t[i:]
    if box:
        assert BOX in t; t = t.replace(BOX, box)
    x.write_text(t)
    (out / "scenario.toml").write_text(SC)
    shutil.copy("/tmp/r28/truth_real/act/traj_shipped.npz", out / "traj.npz")
print("ok")
