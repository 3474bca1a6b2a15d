"""Round 38 second batch: tight bin (the opening fingers hit its walls), pick_hold lowered just above an
unlisted block. usage: gen2.py OUTDIR  (appends to OUTDIR/cases2.tsv)"""
import sys, pathlib, runpy, numpy as np
sys.argv = [sys.argv[0], sys.argv[1]]
g = runpy.run_path(str(pathlib.Path(__file__).parent / "gen.py"))   # re-runs gen.py (same files), then adds
scene, traj, pose, pd, OUT, WP0 = g["scene"], g["traj"], g["pose"], g["pd"], g["OUT"], g["WP0"]
g["cases"].clear()
cases = g["cases"]
# tight bin: inner 8 cm (x) x 6 cm (y): the pads (open to 8 cm + 2 x 1.5 cm) touch the walls when opening
walls = [(0.005, 0.04, 0.045, 0), (0.005, 0.04, -0.045, 0), (0.05, 0.005, 0, 0.035), (0.05, 0.005, 0, -0.035)]
binw = "".join(f'      <geom name="bin{i}" type="box" size="{sx} {sy} 0.025" pos="{px} {py} 0.025" rgba="0.3 0.3 0.6 1" '
               f'contype="1" conaffinity="1" friction="1 0.005 0.0001"/>\n' for i, (sx, sy, px, py) in enumerate(walls))
scene("bintight", extra_world=f'    <body name="bin" pos="0.5 0.15 0">\n{binw}    </body>\n', support='["table"]\nbodies = ["bin"]')
traj("P_bintight", "bintight", pose(0.02), pd.PickPlaceOptions(place_clearance=0.005, transport_height=0.2))
# pick_hold: lift 2.5 cm, move to (0.5, 0.0) over a block whose top is 1 mm under the cube's bottom; block NOT a support
import re
hold_t = lambda t: re.sub(r'\[task\]\n.*?\n\n', '[task]\nkind = "pick_hold"\ngripper = "hand"\nlift_height = 0.02\n\n', t, flags=re.S)
blk = ('    <body name="block" pos="0.5 0.0 0.012">\n      <geom name="block" type="box" size="0.05 0.05 0.012" '
       'rgba="0.5 0.5 0.5 1" contype="1" conaffinity="1" friction="1 0.005 0.0001"/>\n    </body>\n')
scene("hold_block", extra_world=blk, toml_edit=hold_t)
scene("hold_block_sup", extra_world=blk, toml_edit=hold_t, support='["table", "block"]')
def wp_lowhold(cube, opt):
    w = WP0(cube, opt)
    z = cube[2] + 0.025 + opt.grasp_offset          # cube bottom 0.025 above the table, block top 0.024
    up = np.array([cube[0], cube[1], z]); over = np.array([0.5, 0.0, z])
    out = [(s, p, gr) for s, p, gr in w[:5]]
    out += [(230, up, 0.0), (305, over, 0.0), (355, over, 0.0), (370, over, 0.0), (395, over, 0.0), (445, over, 0.0), (500, over, 0.0)]
    return out
traj("H_block", "hold_block", pose(0.02), wp=wp_lowhold)
traj("H_block_sup", "hold_block_sup", pose(0.02), wp=wp_lowhold)
(OUT / "cases2.tsv").write_text("".join(f"{c}\t{s}\n" for c, s in cases))
