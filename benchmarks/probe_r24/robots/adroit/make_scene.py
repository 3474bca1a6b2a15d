"""gymnasium-robotics 1.4.2's Adroit relocate scene (adroit_relocate.xml, its hand and arm
slides unedited), with the ball's six 1-DoF joints (OBJTx..OBJRz) replaced by one free
joint (critmoment needs a free body). Written next to the shipped file (its meshdir is
relative) as critmoment_r24_adroit_<contact>.xml; the scenarios reach it through the
``assets`` link that fetch.sh makes in this folder.

Usage: python make_scene.py [shipped|elliptic10]   (prints the path; fetch.sh runs it)
Environment: R24W, the folder fetch.sh unzipped the wheels into (default /tmp/r24w).
"""
import os
import sys
from pathlib import Path

import mujoco

R24W = Path(os.environ.get("R24W", "/tmp/r24w"))
SRC = R24W / "grx/gymnasium_robotics/envs/assets/adroit_hand/adroit_relocate.xml"


def build(contact: str = "shipped") -> Path:
    spec = mujoco.MjSpec.from_file(str(SRC))
    body = spec.body("Object")
    for j in list(body.joints):
        spec.delete(j)
    body.add_freejoint(name="object_free")
    if contact == "elliptic10":
        spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
        spec.option.impratio = 10.0
    out = SRC.with_name(f"critmoment_r24_adroit_{contact}.xml")
    spec.compile()
    out.write_text(spec.to_xml())
    return out


if __name__ == "__main__":
    print(build(sys.argv[1] if len(sys.argv) > 1 else "shipped"))
