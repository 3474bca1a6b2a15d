"""Author the probe's robots (own MJCF, primitives only): a 6-DoF position-servo arm with a
two-finger slide gripper on a base that is not welded to the world, a table and a 4 cm cube.

usage: make_robot.py KIND OUT.xml [--cart-mass M] [--tray]
KIND:
  free        base = box cart with a <freejoint/>, standing on 4 foot spheres on the floor
  free_weld   same, plus <equality><weld body1="base"/></equality> (a common way to fix a free base)
  planar      base on slide x, slide y, hinge z (a mobile base), position servos on the three
  planar_vel  same, velocity actuators on the three (TidyBot/Stretch-like)
  planar_iv   same, intvelocity actuators on the three
--tray: the cube starts on a tray on the robot's own base (a moving support), not on the table.
The keyframe "home" holds the arm's home pose; for the free base it is the settled base pose
(simulated 2 s with the arm held), so the run starts at rest.
"""
import argparse
import sys

import mujoco
import numpy as np

ARM = """
      <body name="shoulder" pos="0.10 0 {top}">
        <joint name="j1" axis="0 0 1" range="-2.8 2.8" armature="0.1" damping="1"/>
        <geom type="cylinder" size="0.05 0.04" mass="1.0" rgba=".3 .3 .3 1"/>
        <body name="upper" pos="0 0 0.06">
          <joint name="j2" axis="0 1 0" range="-2 2" armature="0.1" damping="1"/>
          <geom type="capsule" fromto="0 0 0 0 0 0.30" size="0.035" mass="2.0" rgba=".5 .5 .7 1"/>
          <body name="fore" pos="0 0 0.30">
            <joint name="j3" axis="0 1 0" range="-2.6 2.6" armature="0.05" damping="0.5"/>
            <geom type="capsule" fromto="0 0 0 0.28 0 0" size="0.03" mass="1.2" rgba=".5 .5 .7 1"/>
            <body name="wrist1" pos="0.28 0 0">
              <joint name="j4" axis="1 0 0" range="-3 3" armature="0.02" damping="0.2"/>
              <geom type="cylinder" fromto="0 0 0 0.05 0 0" size="0.03" mass="0.4" rgba=".3 .3 .3 1"/>
              <body name="wrist2" pos="0.05 0 0">
                <joint name="j5" axis="0 1 0" range="-2.2 2.2" armature="0.02" damping="0.2"/>
                <geom type="sphere" size="0.03" mass="0.3" rgba=".3 .3 .3 1"/>
                <body name="hand" pos="0.05 0 0">
                  <joint name="j6" axis="1 0 0" range="-3 3" armature="0.01" damping="0.1"/>
                  <geom name="palm" type="box" size="0.02 0.05 0.025" pos="0.01 0 0" mass="0.4" rgba=".2 .2 .2 1"/>
                  <body name="finger_l" pos="0.06 0 0">
                    <joint name="fl" type="slide" axis="0 1 0" range="0 0.04" armature="0.01" damping="2"/>
                    <geom name="pad_l" type="box" size="0.03 0.005 0.012" pos="0 0.005 0" mass="0.05" friction="1 0.005 0.0001" rgba=".8 .2 .2 1"/>
                  </body>
                  <body name="finger_r" pos="0.06 0 0">
                    <joint name="fr" type="slide" axis="0 -1 0" range="0 0.04" armature="0.01" damping="2"/>
                    <geom name="pad_r" type="box" size="0.03 0.005 0.012" pos="0 -0.005 0" mass="0.05" friction="1 0.005 0.0001" rgba=".8 .2 .2 1"/>
                  </body>
                </body>
              </body>
            </body>
          </body>
        </body>
      </body>"""

ARM_ACT = """
    <position name="a1" joint="j1" kp="3000" kv="150" forcerange="-150 150" ctrlrange="-2.8 2.8"/>
    <position name="a2" joint="j2" kp="3000" kv="150" forcerange="-150 150" ctrlrange="-2 2"/>
    <position name="a3" joint="j3" kp="2000" kv="100" forcerange="-80 80" ctrlrange="-2.6 2.6"/>
    <position name="a4" joint="j4" kp="300" kv="15" forcerange="-20 20" ctrlrange="-3 3"/>
    <position name="a5" joint="j5" kp="300" kv="15" forcerange="-20 20" ctrlrange="-2.2 2.2"/>
    <position name="a6" joint="j6" kp="100" kv="5" forcerange="-10 10" ctrlrange="-3 3"/>
    <position name="grip_l" joint="fl" kp="{gkp}" kv="10" forcerange="-{gf} {gf}" ctrlrange="0 0.04"/>
    <position name="grip_r" joint="fr" kp="{gkp}" kv="10" forcerange="-{gf} {gf}" ctrlrange="0 0.04"/>"""


def build(kind: str, cart_mass: float, tray: bool, gkp: float = 300.0, hip_force: float = 6.0) -> str:
    legged = kind == "legged"
    free = kind.startswith("free") or legged
    # cart: box half (0.25, 0.20, 0.06), body origin 0.17 above the floor (feet reach z = 0)
    base_joint = {
        "free": '<freejoint name="base_free"/>',
        "free_weld": '<freejoint name="base_free"/>',
        "legged": '<freejoint name="base_free"/>',
    }.get(kind, '<joint name="base_x" type="slide" axis="1 0 0" range="-1 1" damping="5"/>\n'
                '      <joint name="base_y" type="slide" axis="0 1 0" range="-1 1" damping="5"/>\n'
                '      <joint name="base_yaw" axis="0 0 1" range="-3.14 3.14" damping="5"/>')
    feet = "".join(
        f'<geom name="foot{i}" type="sphere" size="0.04" pos="{sx * 0.2} {sy * 0.15} -0.13" '
        f'mass="0.2" friction="1 0.005 0.0001" rgba=".1 .1 .1 1"/>'
        for i, (sx, sy) in enumerate([(1, 1), (1, -1), (-1, 1), (-1, -1)])) if free and not legged else ""
    if legged:  # four one-joint legs: hip hinge about y, shank 5 cm forward and 8 cm down, foot sphere
        feet = "".join(
            f'<body name="leg{i}" pos="{sx * 0.2} {sy * 0.15} -0.06"><joint name="hip{i}" axis="0 1 0" range="-0.8 0.8" armature="0.01" damping="0.5"/>'
            f'<geom type="capsule" fromto="0 0 0 0.05 0 -0.08" size="0.015" mass="0.2" rgba=".1 .1 .1 1"/>'
            f'<geom name="foot{i}" type="sphere" size="0.03" pos="0.05 0 -0.08" mass="0.1" friction="1 0.005 0.0001" rgba=".1 .1 .1 1"/></body>'
            for i, (sx, sy) in enumerate([(1, 1), (1, -1), (-1, 1), (-1, -1)]))
    tray_geom = ('<geom name="tray" type="box" size="0.08 0.08 0.005" pos="0.0 0.15 0.065" '
                 'rgba=".6 .6 .3 1"/>' if tray else "")
    cube_pos = "0.05 0.12 0.265" if tray else "0.55 0 0.32"  # tray: relative to... world, below
    if tray:
        cube_pos = "0.0 0.15 0.26"  # world, base at origin: tray top 0.17+0.065+0.005=0.24, +0.02
    base_act = ""
    if kind == "planar":
        base_act = """
    <position name="bx" joint="base_x" kp="20000" kv="2000" forcerange="-600 600" ctrlrange="-1 1"/>
    <position name="by" joint="base_y" kp="20000" kv="2000" forcerange="-600 600" ctrlrange="-1 1"/>
    <position name="byaw" joint="base_yaw" kp="5000" kv="500" forcerange="-300 300" ctrlrange="-3.14 3.14"/>"""
    elif kind == "planar_vel":
        base_act = """
    <velocity name="bx" joint="base_x" kv="2000" forcerange="-600 600" ctrlrange="-0.5 0.5"/>
    <velocity name="by" joint="base_y" kv="2000" forcerange="-600 600" ctrlrange="-0.5 0.5"/>
    <velocity name="byaw" joint="base_yaw" kv="500" forcerange="-300 300" ctrlrange="-1 1"/>"""
    elif kind == "planar_iv":
        base_act = """
    <intvelocity name="bx" joint="base_x" kp="20000" kv="2000" forcerange="-600 600" ctrlrange="-0.5 0.5" actrange="-1 1"/>
    <intvelocity name="by" joint="base_y" kp="20000" kv="2000" forcerange="-600 600" ctrlrange="-0.5 0.5" actrange="-1 1"/>
    <intvelocity name="byaw" joint="base_yaw" kp="5000" kv="500" forcerange="-300 300" ctrlrange="-1 1" actrange="-3.14 3.14"/>"""
    if legged:
        base_act = "".join(f'\n    <position name="h{i}" joint="hip{i}" kp="300" kv="10" forcerange="-{hip_force} {hip_force}" ctrlrange="-0.8 0.8"/>' for i in range(4))
    weld = '<equality><weld name="fix_base" body1="base"/></equality>' if kind == "free_weld" else ""
    return f"""<mujoco model="probe_r34_{kind}">
  <compiler angle="radian" autolimits="true"/>
  <option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>
  <worldbody>
    <light pos="0 0 3"/>
    <geom name="floor" type="plane" size="3 3 0.1" rgba=".8 .8 .8 1"/>
    <body name="table" pos="0.65 0.3 0.15">
      <geom name="table_top" type="box" size="0.25 0.6 0.15" rgba=".6 .4 .2 1"/>
    </body>
    <body name="base" pos="0 0 0.17">
      {base_joint}
      <geom name="chassis" type="box" size="0.25 0.2 0.06" mass="{cart_mass}" rgba=".2 .4 .7 1"/>
      {feet}
      {tray_geom}
{ARM.format(top=0.06 + 0.04)}
    </body>
    <body name="cube" pos="{cube_pos}">
      <freejoint name="cube_joint"/>
      <geom name="cube_geom" type="box" size="0.02 0.02 0.02" mass="0.2" friction="0.8 0.005 0.0001" rgba=".9 .1 .1 1"/>
    </body>
    <site name="goal" pos="0.55 0.35 0.32" size="0.01" rgba="0 1 0 1"/>
  </worldbody>
  {weld}
  <contact><exclude body1="shoulder" body2="fore"/><exclude body1="upper" body2="wrist1"/><exclude body1="upper" body2="wrist2"/><exclude body1="fore" body2="wrist2"/><exclude body1="fore" body2="hand"/><exclude body1="wrist1" body2="hand"/><exclude body1="wrist1" body2="finger_l"/><exclude body1="wrist1" body2="finger_r"/><exclude body1="wrist2" body2="finger_l"/><exclude body1="wrist2" body2="finger_r"/><exclude body1="fore" body2="finger_l"/><exclude body1="fore" body2="finger_r"/><exclude body1="finger_l" body2="finger_r"/></contact>
  <actuator>{ARM_ACT.format(gkp=gkp, gf=max(20.0, gkp * 0.04))}{base_act}
  </actuator>
</mujoco>"""


HOME = {"j1": 0.0, "j2": 0.0, "j3": 0.3, "j4": 0.0, "j5": 1.2, "j6": 0.0, "fl": 0.04, "fr": 0.04}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("kind", choices=["free", "free_weld", "planar", "planar_vel", "planar_iv", "legged"])
    ap.add_argument("--hip-force", type=float, default=6.0, help="legged: the hip servos' forcerange [N m]")
    ap.add_argument("out")
    ap.add_argument("--cart-mass", type=float, default=15.0)
    ap.add_argument("--tray", action="store_true")
    ap.add_argument("--grip-kp", type=float, default=300.0)
    a = ap.parse_args()
    xml = build(a.kind, a.cart_mass, a.tray, a.grip_kp, a.hip_force)
    m = mujoco.MjModel.from_xml_string(xml)
    d = mujoco.MjData(m)
    for j, v in HOME.items():
        d.qpos[m.jnt_qposadr[m.joint(j).id]] = v
    for i in range(m.nu):
        jn = m.joint(m.actuator_trnid[i, 0]).name
        if m.actuator_dyntype[i] == mujoco.mjtDyn.mjDYN_NONE and m.actuator_biastype[i] != 0:
            d.ctrl[i] = HOME.get(jn, 0.0)
    # settle 2 s with the arm held: the base (free) sinks onto its feet, the cube onto its support
    for _ in range(1000):
        mujoco.mj_step(m, d)
    q = d.qpos.copy()
    # keep the arm exactly at home (its servo sag is the trajectory's business), base/cube settled
    for j, v in HOME.items():
        q[m.jnt_qposadr[m.joint(j).id]] = v
    key = " ".join(f"{v:.9g}" for v in q)
    ctrl = " ".join(f"{v:.9g}" for v in d.ctrl)
    xml = xml.replace("</mujoco>", f'  <keyframe><key name="home" qpos="{key}" ctrl="{ctrl}"/></keyframe>\n</mujoco>')
    mujoco.MjModel.from_xml_string(xml)
    open(a.out, "w").write(xml)
    base = q[:7] if a.kind.startswith("free") else q[:3]
    print("wrote", a.out, "base settled:", np.round(base, 4), "cube:",
          np.round(q[m.jnt_qposadr[m.joint('cube_joint').id]:][:7], 4), file=sys.stderr)


if __name__ == "__main__":
    main()
