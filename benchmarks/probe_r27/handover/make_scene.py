"""Write the OpenArm hand-over scenes next to the wheel's pedestal scenes (mesh paths resolve).

The approach of probe_r25's ``openarm/make_scene.py``: openarm-mujoco 2.3.0's
``v2/pedestal/openarm_pedestal.xml`` (both arms) attached unedited through
``<model>``/``<attach prefix="">``, a table in front of the right arm and a free 4 cm
0.1 kg cube on it, in reach of the right arm. No goal site (the task is a hand-over).

Usage (from a folder whose ``assets`` links to the wheel's ``v2`` folder):
``python make_scene.py shipped`` or ``python make_scene.py pyramidal1``; writes
``assets/pedestal/critmoment_r27_oa_ho_<variant>.xml``.
"""
from __future__ import annotations

import sys
from pathlib import Path

OPTION = {
    "shipped": '<option timestep="0.001" cone="elliptic" impratio="10"/>',
    "pyramidal1": '<option timestep="0.001" cone="pyramidal" impratio="1"/>',
}

SCENE = """<!-- critmoment probe r27: openarm-mujoco 2.3.0 pedestal (unedited, attached), a table
     and a free 4 cm 0.1 kg cube in front of the right arm, for a right-to-left hand-over. -->
<mujoco model="critmoment_r27_oa_ho_{variant}">
  <compiler meshdir="../assets" angle="radian"/>
  {option}
  <asset>
    <model name="arm_pedestal" file="openarm_pedestal.xml"/>
  </asset>
  <worldbody>
    <light pos="0 0 2" dir="0 0 -1" directional="true"/>
    <geom name="floor" size="0 0 0.05" type="plane"/>
    <attach model="arm_pedestal" prefix=""/>
    <body name="table" pos="0.25 -0.22 0.29">
      <geom name="table_top" type="box" size="0.12 0.14 0.02" rgba="0.82 0.71 0.55 1"
            friction="1 0.005 0.0001"/>
    </body>
    <body name="cube" pos="0.25 -0.28 0.33">
      <freejoint name="cube_joint"/>
      <geom name="cube_geom" type="box" size="0.02 0.02 0.02" mass="0.1" condim="4"
            friction="1 0.005 0.0001" rgba="0.8 0.2 0.2 1"/>
    </body>
  </worldbody>
</mujoco>
"""


def main():
    variant = sys.argv[1]
    out = Path("assets") / "pedestal" / f"critmoment_r27_oa_ho_{variant}.xml"
    out.write_text(SCENE.format(variant=variant, option=OPTION[variant]))
    print("wrote", out)


if __name__ == "__main__":
    main()
