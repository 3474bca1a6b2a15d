"""Write the variants of scene.xml (string edits of the base scene)."""
from pathlib import Path
base = Path('scene.xml').read_text()
V = {}
# velocity actuators on the three axes (critmoment should refuse them clearly)
V['scene_vel.xml'] = (base.replace('<position name="ax" joint="x" kp="4000" kv="400"', '<velocity name="ax" joint="x" kv="400"')
                          .replace('<position name="ay" joint="y" kp="3000" kv="250"', '<velocity name="ay" joint="y" kv="250"')
                          .replace('<position name="az" joint="z" kp="3000" kv="150"', '<velocity name="az" joint="z" kv="150"')
                          .replace('ctrlrange="0 1" forcerange="-300 300"', 'ctrlrange="-1 1" forcerange="-300 300"')
                          .replace('ctrlrange="0 0.8" forcerange', 'ctrlrange="-1 1" forcerange')
                          .replace('ctrlrange="-0.5 0" forcerange', 'ctrlrange="-1 1" forcerange'))
# hand-written general affine servos: force = kp*ctrl - kp*q - kv*qdot
gen = base
for n, j, kp, kv, cr, fr in [('ax', 'x', 4000, 400, '0 1', '-300 300'), ('ay', 'y', 3000, 250, '0 0.8', '-200 200'),
                             ('az', 'z', 3000, 150, '-0.5 0', '-150 150')]:
    old = f'<position name="{n}" joint="{j}" kp="{kp}" kv="{kv}" ctrlrange="{cr}" forcerange="{fr}"/>'
    assert old in gen, old
    gen = gen.replace(old, f'<general name="{n}" joint="{j}" biastype="affine" gainprm="{kp} 0 0" biasprm="0 -{kp} -{kv}" ctrlrange="{cr}" forcerange="{fr}" forcelimited="true"/>')
V['scene_gen.xml'] = gen
# pure Cartesian gantry: no yaw hinge (tool rigid on the quill)
V['scene_3ax.xml'] = (base.replace('<joint name="yaw" type="hinge" axis="0 0 1" range="-3 3" damping="0.2" armature="0.01"/>', '')
                          .replace('<position name="ayaw" joint="yaw" kp="20" kv="1" ctrlrange="-3 3" forcerange="-5 5"/>', ''))
# 0.5 ms step, warmstart off, pyramidal impratio 1
V['scene_fine.xml'] = base.replace('<option timestep="0.002" cone="elliptic" impratio="10"/>',
                                   '<option timestep="0.0005" cone="pyramidal" impratio="1"><flag warmstart="disable"/></option>')
for k, v in V.items():
    Path(k).write_text(v)
