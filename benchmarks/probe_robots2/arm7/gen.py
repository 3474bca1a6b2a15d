"""Write the 7-DoF arm scenes: hand-written <general> affine servos, hinge jaws, a capsule
lying on a raised support tilted by TILT degrees (variants: a sphere, an intvelocity arm, an
offset/scaled servo, a 0.5 ms step)."""
from pathlib import Path

def scene(tilt=12.0, obj='capsule', act='general', timestep='0.002', extra_opt=''):
    if obj == 'capsule':
        og = '<geom name="obj" type="capsule" size="0.018 0.04" euler="0 90 0" mass="0.15" rgba=".9 .3 .3 1"/>'
        oz = 0.018
    elif obj == 'sphere':
        og = '<geom name="obj" type="sphere" size="0.025" mass="0.15" rgba=".9 .3 .3 1"/>'
        oz = 0.025
    else:  # light ellipsoid
        og = '<geom name="obj" type="ellipsoid" size="0.04 0.022 0.018" mass="0.01" rgba=".9 .3 .3 1"/>'
        oz = 0.018
    arm = [('j1', 'z', 150, 15, 120), ('j2', 'y', 300, 30, 120), ('j3', 'z', 100, 10, 60),
           ('j4', 'y', 200, 20, 60), ('j5', 'z', 100, 5, 20), ('j6', 'y', 100, 5, 20), ('j7', 'z', 60, 3, 10)]
    acts = []
    for j, _, kp, kv, fr in arm:
        if act == 'general':
            acts.append(f'<general name="m_{j}" joint="{j}" gainprm="{kp}" biastype="affine" biasprm="0 -{kp} -{kv}" '
                        f'ctrlrange="-3 3" forcerange="-{fr} {fr}"/>')
        elif act == 'offset' and j == 'j2':
            # force = 2 kp ctrl + 0.3 kp - kp q  ->  q = 2 ctrl + 0.3
            acts.append(f'<general name="m_{j}" joint="{j}" gainprm="{2*kp}" biastype="affine" biasprm="{0.3*kp} -{kp} -{kv}" '
                        f'ctrlrange="-1.6 1.4" forcerange="-{fr} {fr}"/>')
        elif act == 'offset':
            acts.append(f'<general name="m_{j}" joint="{j}" gainprm="{kp}" biastype="affine" biasprm="0 -{kp} -{kv}" '
                        f'ctrlrange="-3 3" forcerange="-{fr} {fr}"/>')
        elif act == 'intvelocity':
            acts.append(f'<intvelocity name="m_{j}" joint="{j}" kp="{kp}" kv="{kv}" ctrlrange="-2 2" actrange="-3 3" forcerange="-{fr} {fr}"/>')
    # jaws: each its own general servo, closes toward 0
    acts.append('<general name="jaw_l" joint="jaw_l" gainprm="8" biastype="affine" biasprm="0 -8 -0.2" ctrlrange="-0.1 0.6" forcerange="-1.5 1.5"/>')
    acts.append('<general name="jaw_r" joint="jaw_r" gainprm="8" biastype="affine" biasprm="0 -8 -0.2" ctrlrange="-0.1 0.6" forcerange="-1.5 1.5"/>')
    ax = {'z': '0 0 1', 'y': '0 1 0'}
    L = [0.2, 0.0, 0.3, 0.0, 0.28, 0.0, 0.08]
    body = ''
    close = ''
    for i, (j, a, *_r) in enumerate(arm):
        body += (f'<body name="l{i+1}" pos="0 0 {L[i-1] if i else 0.05}">'
                 f'<joint name="{j}" axis="{ax[a]}" range="-166 166"/>'
                 f'<geom type="capsule" fromto="0 0 0 0 0 {max(L[i], 0.04)}" size="{0.04 - 0.003*i}" contype="2" conaffinity="1" mass="{2.0 - 0.25*i}"/>\n')
        close += '</body>'
    hand = f'''<body name="hand" pos="0 0 0.08">
      <geom name="palm" type="box" pos="0 0 0.01" size="0.02 0.05 0.01" mass="0.3"/>
      <site name="tcp" pos="0 0 0.085"/>
      <body name="jl" pos="0 0.045 0.02"><joint name="jaw_l" axis="1 0 0" range="-5.7 34.4" damping="0.05"/>
        <geom name="pad_l" type="box" pos="0 -0.012 0.05" size="0.012 0.004 0.045" condim="4" friction="1 0.01 0.001" mass="0.03"/></body>
      <body name="jr" pos="0 -0.045 0.02"><joint name="jaw_r" axis="-1 0 0" range="-5.7 34.4" damping="0.05"/>
        <geom name="pad_r" type="box" pos="0 0.012 0.05" size="0.012 0.004 0.045" condim="4" friction="1 0.01 0.001" mass="0.03"/></body>
    </body>'''
    import math
    t = math.radians(tilt)
    # support top centre at (0.45, 0.15, 0.55); tilted about the y axis
    sx, sy, sz = 0.45, 0.15, 0.55
    ox = sx - oz * math.sin(t) * 1.0
    ozc = sz + oz * math.cos(t)
    obj_pos = f'{ox:.4f} {sy} {ozc + 0.001:.4f}'
    return f'''<mujoco model="arm7_{obj}_{act}">
  <compiler angle="degree" autolimits="true"/>
  <option timestep="{timestep}" cone="elliptic" impratio="10" {extra_opt}/>
  <default><joint damping="0.5" armature="0.05"/><geom friction="0.8 0.005 0.0001"/></default>
  <worldbody>
    <light pos="0 0 3" dir="0 0 -1"/>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <geom name="table" type="box" pos="0.3 0 0.2" size="0.5 0.5 0.2" rgba=".6 .5 .4 1"/>
    <geom name="post" type="cylinder" pos="{sx} {sy} 0.47" size="0.02 0.07" rgba=".4 .4 .4 1"/>
    <geom name="ramp" type="box" pos="{sx} {sy} {sz - 0.005:.4f}" euler="0 {tilt} 0" size="0.05 0.05 0.005" rgba=".3 .3 .8 1"/>
    <geom name="tray" type="box" pos="0.2 -0.35 0.41" size="0.08 0.08 0.01" rgba=".3 .8 .3 1"/>
    <body name="base" pos="0 0 0.4"><geom type="cylinder" size="0.07 0.025" pos="0 0 0.025" contype="2" conaffinity="1" mass="4"/>
{body}{hand}
{close}</body>
    <body name="item" pos="{obj_pos}" euler="0 {tilt} 0"><freejoint/>{og}</body>
  </worldbody>
  <actuator>
    {chr(10).join(acts)}
  </actuator>
</mujoco>
'''

V = {'scene.xml': {}, 'scene_sphere.xml': dict(obj='sphere', tilt=0.0), 'scene_light.xml': dict(obj='light', tilt=0.0),
     'scene_intvel.xml': dict(act='intvelocity'), 'scene_offset.xml': dict(act='offset'),
     'scene_fine.xml': dict(timestep='0.0005'), 'scene_flat.xml': dict(tilt=0.0)}
for k, kw in V.items():
    Path(k).write_text(scene(**kw))
Path('scene_steep.xml').write_text(scene(tilt=20.0))
