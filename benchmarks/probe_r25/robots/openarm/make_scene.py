"""Write the OpenArm pick scenes next to the wheel's pedestal scenes (mesh paths resolve).

openarm-mujoco 2.3.0's ``v2/pedestal/openarm_pedestal.xml`` (both arms on the pedestal,
attached unedited through ``<model>``/``<attach>``, as the wheel's own scenes do), a table
in front of the right arm, a free 4 cm 0.1 kg cube and a goal site.

Usage (from this folder, after ``sh ../fetch.sh``): ``python make_scene.py shipped`` or
``python make_scene.py pyramidal1``; writes ``assets/pedestal/critmoment_r25_oa_<variant>.xml``.
"""
from __future__ import annotations

import sys
from pathlib import Path

OPTION = {
    "shipped": '<option timestep="0.001" cone="elliptic" impratio="10"/>',
    "pyramidal1": '<option timestep="0.001" cone="pyramidal" impratio="1"/>',
}

SCENE = """<!-- critmoment probe r25: openarm-mujoco 2.3.0 pedestal (unedited, attached), a table,
     a free 4 cm 0.1 kg cube in front of the right arm and a goal site. -->
<mujoco model="critmoment_r25_oa_{variant}">
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
    <site name="goal" pos="0.25 -0.16 0.33" size="0.01" rgba="0 1 0 0.5"/>
  </worldbody>
</mujoco>
"""


def main():
    variant = sys.argv[1]
    here = Path(__file__).absolute().parent
    out = here / "assets" / "pedestal" / f"critmoment_r25_oa_{variant}.xml"
    out.write_text(SCENE.format(variant=variant, option=OPTION[variant]))
    print("wrote", out)


if __name__ == "__main__":
    main()
