#!/bin/bash
# make_fixture.sh DIR: bundled Panda scene + a hinged flap (world-rooted body with a range-limited hinge: a
# fixture such as a lid or drawer front) whose plate touches the fingers' pads at the start (2 mm), and the
# r30 tasks' P_nominal with qpos0 extended by the hinge. Then: cm_{old,new}.sh analyze DIR/traj.npz --scenario DIR/scenario.toml
set -e; D=$1; mkdir -p $D; cp /tmp/r30b/src/models/panda_pick_place/* $D
python3 - $D <<'PY'
import sys
p=sys.argv[1]+'/scene.xml'; s=open(p).read()
flap='''    <body name="flap" pos="0.307 0 0.477">
      <joint name="flap_hinge" type="hinge" axis="0 1 0" pos="-0.08 0 0" range="-0.01 0.01" limited="true" damping="50"/>
      <geom name="flap_plate" type="box" size="0.08 0.08 0.005" mass="0.5" rgba="0.6 0.4 0.2 1"/>
    </body>
  </worldbody>'''
open(p,'w').write(s.replace('  </worldbody>', flap, 1))
PY
/work/venv/bin/python -c "
import numpy as np
d=dict(np.load('/tmp/r30/tasks/gen/P_nominal.npz',allow_pickle=True)); d['qpos0']=np.append(d['qpos0'],0.0); np.savez('$D/traj.npz',**d)"
