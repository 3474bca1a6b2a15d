"""dm_control 1.0.50's planar manipulator (suite/manipulator.xml: torque motors with gears,
a tendon-driven two-finger hand with a tendon equality coupling; arm unedited), the ball's
three planar joints (ball_x, ball_z, ball_y) replaced by one free joint and the ball put
on the floor at x = 0.25. Written next to the shipped file (its includes are relative) as
critmoment_r24_manip_<contact>.xml; the scenarios reach it through the ``assets`` link that
fetch.sh makes in this folder.

Usage: python make_scene.py [shipped|pyramidal1]   (prints the path; fetch.sh runs it)
Environment: R24W, the folder fetch.sh unzipped the wheels into (default /tmp/r24w).
"""
import os
import sys
from pathlib import Path

import mujoco

R24W = Path(os.environ.get("R24W", "/tmp/r24w"))
SRC = R24W / "dmcx/dm_control/suite/manipulator.xml"


def build(contact="shipped"):
    spec = mujoco.MjSpec.from_file(str(SRC))
    ball = spec.body("ball")
    for j in list(ball.joints):
        spec.delete(j)
    ball.add_freejoint(name="ball_free")
    ball.pos = [0.25, 0.0, 0.022]
    if contact == "pyramidal1":
        spec.option.cone = mujoco.mjtCone.mjCONE_PYRAMIDAL
        spec.option.impratio = 1.0
    out = SRC.with_name(f"critmoment_r24_manip_{contact}.xml")
    spec.compile()
    out.write_text(spec.to_xml())
    return out


if __name__ == "__main__":
    print(build(sys.argv[1] if len(sys.argv) > 1 else "shipped"))
