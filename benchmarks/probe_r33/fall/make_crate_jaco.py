"""The r32 Jaco scene (jaco_motor.xml) with a low fixed crate (6 x 6 x 2 cm) on the table under the
'--loosen-dy 0.09' hover point (r33 probe): a cube that falls there lands on the crate, a surface
init does not declare a support. usage: make_crate_jaco.py IN.xml OUT.xml"""
import sys
import critmoment as _cm_check; assert _cm_check.__file__.startswith("/tmp/r33/src"), _cm_check.__file__  # r33 snapshot
import mujoco
spec = mujoco.MjSpec.from_file(sys.argv[1])
spec.worldbody.add_geom(name="crate", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.03, 0.03, 0.01],
                        pos=[0.5, -0.06, 0.11], rgba=[0.3, 0.3, 0.3, 1])
spec.compile()
open(sys.argv[2], "w").write(spec.to_xml()); print("wrote", sys.argv[2])
