"""gymnasium-robotics 1.4.2's Franka kitchen Panda (``kitchen_franka/franka_assets``: chain.xml,
actuator.xml, assets.xml, basic_scene.xml; vikashplus' franka: position servos kp 870/120,
forcerange 87/12, joint damping 100/10, two finger servos kp 500 ±70 N, condim-6 capsule
fingertips) included unedited as the kitchen model includes them, on the floor at the
origin instead of the kitchen's 1.8 m pedestal, with a table (top z 0.3), a free 4 cm
0.1 kg cube (condim 4 as the robosuite scenes of real_models.py) and a goal site.

Writes ``kitchen_franka/probe3_franka_scene.xml`` next to the shipped files (its includes
and meshdir are relative to that folder) and ``probe3_franka_scene_elliptic10.xml``.
"""
from pathlib import Path

import mujoco

DIR = Path("/root/.cache/critmoment-real-models/gymnasium-robotics/gymnasium_robotics/envs/"
           "assets/kitchen_franka")
TEMPLATE = """<mujoco model="probe3_franka{tag}">
  <include file="franka_assets/assets.xml"/>
  <include file="franka_assets/actuator.xml"/>
  <include file="franka_assets/basic_scene.xml"/>
  {option}
  <worldbody>
    <body name="robot_base" pos="0 0 0">
      <include file="franka_assets/chain.xml"/>
    </body>
    <geom name="table" type="box" pos="0.5 0 0.15" size="0.3 0.4 0.15" rgba=".6 .5 .4 1"/>
    <body name="cube" pos="0.5 -0.1 0.32">
      <freejoint name="cube_joint"/>
      <geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1" condim="4" friction="1 0.005 0.0001" rgba=".8 .2 .2 1"/>
    </body>
    <site name="goal" pos="0.5 0.1 0.32" size="0.01"/>
  </worldbody>
</mujoco>
"""


def main():
    for tag, option in (("", ""), ("_elliptic10", '<option cone="elliptic" impratio="10"/>')):
        out = DIR / f"probe3_franka_scene{tag}.xml"
        out.write_text(TEMPLATE.format(tag=tag, option=option))
        m = mujoco.MjModel.from_xml_path(str(out))
        print("wrote", out, "nu", m.nu, "cone", m.opt.cone, "impratio", m.opt.impratio)


if __name__ == "__main__":
    main()
