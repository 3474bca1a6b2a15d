"""second batch (uses gen.py's helpers: exec of its head). usage: gen2.py OUTDIR -> cases2.tsv"""
import sys
src = open(__file__.replace("gen2.py", "gen.py")).read()
exec(src.split("# --- objects")[0])
# tall box 9 cm (the 12 cm one is hit by the palm at 2.1 s, before the grasp)
obj("tall9", G('type="box" size="0.02 0.02 0.045"'), 0.045, grasp=0.015)
# tall box 9 cm released 4 cm above its goal (may tip over when it lands)
pd._waypoints_orig = pd._waypoints
def wp_drop(h):
    def f(cube, opt):
        w = pd._waypoints_orig(cube, opt)
        return [(s, p + np.array([0, 0, h]) if s in (355, 370, 395) else p, g) for s, p, g in w]
    return f
traj("O_tall9_drop4", "tall9", pose(0.045), pd.PickPlaceOptions(goal=(0.5, 0.15, 0.045), grasp_offset=0.015), wp=wp_drop(0.04))
# com offset on the 9 cm tall box, along x
scene("com_tall9", body(G('type="box" size="0.02 0.02 0.045"'), 0.045), z=0.045, goal=(0.5, 0.15, 0.045),
      toml_edit=lambda t: t + '\n[uncertainty.com]\nkind = "com_offset"\nbody = "cube"\n'
      'range = [-0.019, 0.019]\nnominal = 0.0\nprior = "uniform"\n')
traj("P_com_tall9", "com_tall9", pose(0.045), pd.PickPlaceOptions(goal=(0.5, 0.15, 0.045), grasp_offset=0.015))
(OUT / "cases2.tsv").write_text("".join(f"{c}\t{s}\n" for c, s in cases))
