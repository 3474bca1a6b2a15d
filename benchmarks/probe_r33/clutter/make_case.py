"""Build a cluttered variant of the bundled Panda pick-place scene + its scenario + a scripted
trajectory (critmoment.panda_demo.make_pick_place on the edited model, seed 0).
usage: make_case.py CASE OUTDIR   (OUTDIR gets scene.xml, panda.xml, scenario.toml, traj.npz)"""
import shutil, sys, re, tomllib
from pathlib import Path
import mujoco, numpy as np
import critmoment as cm; assert cm.__file__.startswith("/tmp/r33/src2"), cm.__file__
from critmoment import panda_demo as pd
from critmoment.trajectory import save_trajectory
SRC = Path("/tmp/r33/src2/models/panda_pick_place")
case, out = sys.argv[1], Path(sys.argv[2]); out.mkdir(parents=True, exist_ok=True)
shutil.copy(SRC / "panda.xml", out / "panda.xml")
xml = (SRC / "scene.xml").read_text(); scen = (SRC / "scenario.toml").read_text()
def fixed(name, size, pos, euler="0 0 0", rgba="0.4 0.4 0.6 1"):
    return (f'<body name="{name}" pos="{pos}" euler="{euler}"><geom name="{name}" type="box" size="{size}" '
            f'rgba="{rgba}" contype="1" conaffinity="1" friction="1 0.005 0.0001"/></body>\n')
def free(name, size, pos, mass, typ="box"):
    return (f'<body name="{name}" pos="{pos}"><freejoint name="{name}_joint"/><geom name="{name}" type="{typ}" size="{size}" '
            f'mass="{mass}" rgba="0.2 0.6 0.9 1" contype="1" conaffinity="1" condim="4" friction="1 0.005 0.0001"/></body>\n')
opts = {}; extra = ""; free_q = []; goal = None; support = None; tol = None
# carried cube (seed 0): spawn (0.514, -0.173, 0.02); carry at TCP z 0.15 (cube bottom ~0.12) to (0.5, 0.15)
if case == "post":        # fixed post under the carry path, top 4 mm below the nominal cube's bottom
    extra = fixed("post", "0.02 0.02 0.058", "0.507 0.0 0.058")
elif case == "post_hit":  # same post, 12 mm higher: the nominal cube hits it too
    extra = fixed("post", "0.02 0.02 0.064", "0.507 0.0 0.064")
elif case == "bottle":    # a free, light, tall box ("bottle") standing under the carry path, top 4 mm below
    extra = free("bottle", "0.02 0.02 0.058", "0.507 0.0 0.058", 0.05); free_q = [0.507, 0.0, 0.058, 1, 0, 0, 0]
elif case == "bottle_hit":  # the same bottle 12 mm taller: the nominal carried cube knocks it over
    extra = free("bottle", "0.02 0.02 0.064", "0.507 0.0 0.064", 0.05); free_q = [0.507, 0.0, 0.064, 1, 0, 0, 0]
elif case == "post2":     # fixed post, top at 0.118: the nominal cube clears it by 1.8 mm, samples that sag > 1.8 mm in the grip (mass > ~1 kg) hit it
    extra = fixed("post", "0.02 0.02 0.059", "0.507 0.0 0.059")
elif case == "bottle2":   # free light 'bottle' (4 x 4 x 11.8 cm, 50 g) with its top at 0.118: heavier samples brush it
    extra = free("bottle", "0.02 0.02 0.059", "0.507 0.0 0.059", 0.05); free_q = [0.507, 0.0, 0.059, 1, 0, 0, 0]
elif case == "bottle3":   # the same bottle with its top at 0.1215: the nominal carried cube (bottom 0.1198) brushes it too
    extra = free("bottle", "0.02 0.02 0.06075", "0.507 0.0 0.06075", 0.05); free_q = [0.507, 0.0, 0.06075, 1, 0, 0, 0]
elif case == "overlap":   # a free 4 cm box whose edge reaches 5 mm under the goal footprint (x): the placed cube lands on its edge
    extra = free("box2", "0.02 0.02 0.02", "0.535 0.15 0.02", 0.1); free_q = [0.535, 0.15, 0.02, 1, 0, 0, 0]
elif case == "ledge":     # a fixed 1 cm tall strip under the +x 1.5 cm of the goal footprint (not a support): the cube ends tilted
    extra = fixed("ledge", "0.02 0.04 0.005", "0.525 0.15 0.005")
elif case == "double":    # a free 1.5 x 4 x 4 cm, 50 g slab touching the cube along the fingers' closing axis (y): the hand closes on both
    y = -0.17302133 + 0.0275 + 0.0005
    extra = free("slab", "0.02 0.0075 0.02", f"0.5137 {y:.5f} 0.02", 0.05); free_q = [0.5137, round(y, 5), 0.02, 1, 0, 0, 0]
elif case == "stack":     # the goal is on top of a free 5 cm box (stacking); box2 not a support
    extra = free("box2", "0.025 0.025 0.025", "0.5 0.15 0.025", 0.2); free_q = [0.5, 0.15, 0.025, 1, 0, 0, 0]
    goal = [0.5, 0.15, 0.07]
elif case == "beside":    # a free 4 cm box 5 mm beside the goal along x (the carried cube lands next to it)
    extra = free("box2", "0.02 0.02 0.02", "0.545 0.15 0.02", 0.1); free_q = [0.545, 0.15, 0.02, 1, 0, 0, 0]
elif case == "neighbour": # a free 4 cm box under the descending left finger at the pick (y -0.173 - 0.055)
    extra = free("box2", "0.02 0.02 0.02", "0.514 -0.228 0.02", 0.1); free_q = [0.514, -0.228, 0.02, 1, 0, 0, 0]
elif case.startswith("ramp"):  # goal on a fixed plate tilted about world y by DEG degrees (the pick-place goal on it)
    deg = float(case[4:]); th = np.radians(deg)
    # plate centre at the goal, 5 cm thick box raised so the goal point is on its surface
    zc = 0.05; extra = fixed("ramp", "0.08 0.08 0.005", f"0.5 0.15 {zc}", euler=f"0 {th} 0")  # the scene compiles angles in radians
    # the cube resting on the plate at the goal: centre 0.02 + 0.005 along the plate normal from the plate centre
    n = np.array([np.sin(th), 0, np.cos(th)]); g = np.array([0.5, 0.15, zc]) + 0.025 * n
    goal = g.round(4).tolist(); support = ["table", "ramp"]
elif case == "edge":      # goal on a fixed 4 cm pedestal whose edge is 1 cm past the cube centre (+x)
    extra = fixed("pedestal", "0.03 0.03 0.02", "0.48 0.15 0.02"); goal = [0.5, 0.15, 0.06]; support = ["table", "pedestal"]
elif case == "bin":       # goal inside a fixed bin (walls 6 cm tall, inner 14 x 14 cm); bin walls not listed
    w = ""
    for nm, sz, p in (("bin_n", "0.075 0.005 0.03", "0.5 0.225 0.03"), ("bin_s", "0.075 0.005 0.03", "0.5 0.075 0.03"),
                      ("bin_e", "0.005 0.075 0.03", "0.575 0.15 0.03"), ("bin_w", "0.005 0.075 0.03", "0.425 0.15 0.03")):
        w += fixed(nm, sz, p)
    extra = w
else:
    raise SystemExit("unknown case " + case)
xml = xml.replace("  </worldbody>", extra + "  </worldbody>", 1)
if free_q:
    xml = re.sub(r'(qpos="[^"]*0\.5 -0\.15 0\.02 1 0 0 0)', lambda m: m.group(1) + " " + " ".join(map(str, free_q)), xml, count=1)
(out / "scene.xml").write_text(xml)
if goal is not None:
    scen = re.sub(r"goal = \[0\.5, 0\.15, 0\.02\]", f"goal = {goal}", scen)
if support is not None:
    scen = scen.replace('geoms = ["table"]', "geoms = " + str(support).replace("'", '"'))
(out / "scenario.toml").write_text(scen)
model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
g = tomllib.loads(scen)["task"]["goal"]
opt = pd.PickPlaceOptions(goal=tuple(g), transport_height=max(0.15, g[2] + 0.13),
                          place_clearance=0.012 if case.startswith('ramp') else 0.002)
tr = pd.make_pick_place(0, options=opt, model=model)
save_trajectory(tr, out / "traj.npz")
print(out, "goal", g, "transport", opt.transport_height)
