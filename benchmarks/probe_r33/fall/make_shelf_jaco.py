"""The r32 Jaco scene (jaco_motor.xml, made by make_jaco.py) with the cube on a 6 cm shelf; the goal
stays on the table (r33 probe). usage: make_shelf_jaco.py IN.xml OUT.xml"""
import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r33/src"), _cm_check.__file__  # r33 snapshot
import sys
import mujoco, numpy as np
spec = mujoco.MjSpec.from_file(sys.argv[1])
m0 = spec.compile()
H = 0.06
sh = spec.worldbody.add_body(name="shelf", pos=[0.5, 0.15, 0.1 + H / 2])
sh.add_geom(name="shelf_top", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.06, 0.06, H / 2], rgba=[0.5, 0.5, 0.5, 1])
spec.body("cube").pos = [0.5, 0.15, 0.125 + H]
adr = m0.jnt_qposadr[m0.joint("cube_joint").id]
for k in spec.keys:
    q = np.array(k.qpos); q[adr + 2] += H; k.qpos = q.tolist()
spec.compile()
open(sys.argv[2], "w").write(spec.to_xml()); print("wrote", sys.argv[2])
