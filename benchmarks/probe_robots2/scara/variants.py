"""Write the one-change variants of scene.xml."""
from pathlib import Path
base = Path('scene.xml').read_text()
pad = '<geom type="box" size="0.005 0.012 0.025" condim="6" friction="1.2 0.02 0.002" rgba=".1 .1 .1 1"/>'
opt = '<option timestep="0.004" integrator="implicit" gravity="0.4 0 -9.8" cone="elliptic" impratio="10"/>'
assert pad in base and opt in base
V = {
    'scene_c3.xml': base.replace(pad, pad.replace('condim="6"', 'condim="3"')),
    'scene_c4.xml': base.replace(pad, pad.replace('condim="6"', 'condim="4"')),
    'scene_pyr.xml': base.replace(opt, opt.replace('cone="elliptic" impratio="10"', 'cone="pyramidal" impratio="1"')),
    'scene_soft.xml': base.replace(pad, pad.replace('condim="6"', 'condim="6" solref="0.03 1" solimp="0.8 0.9 0.005"')),
    'scene_margin.xml': base.replace(pad, pad.replace('condim="6"', 'condim="6" margin="0.003" gap="0.001"')),
    'scene_noslip.xml': base.replace(opt, opt.replace('impratio="10"', 'impratio="10" noslip_iterations="5"')),
    'scene_nows.xml': base.replace(opt, opt.replace('/>', '><flag warmstart="disable"/></option>')),
}
for k, v in V.items():
    Path(k).write_text(v)
