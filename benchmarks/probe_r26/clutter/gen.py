"""Round-26 probe: clutter, supports, multi-parameter boxes and unusual objects.

Builds variant folders OUT/v/<name>/ (OUT = $R26_OUT or /tmp/r26/clutter), each a copy of a
bundled model (read from $R26_MODELS or /tmp/r26/src/models) with one edit, and for every
Panda variant a trajectory OUT/v/<name>/traj.npz planned on the variant's own model
(critmoment.panda_demo.make_pick_place, demo seed 0 spawn unless the variant names a seed, with the object's height, the goal
and the grasp offset the variant needs). ALOHA variants use the demo trajectory
(`critmoment demo --seed 0`, OUT/aloha_s0.npz): it has no qpos0, so extra bodies take their
keyframe pose.

usage: python gen.py [NAME ...]     (no names: every variant)
"""
import os
import shutil
import sys
from pathlib import Path

M = Path(os.environ.get("R26_MODELS", "/tmp/r26/src/models"))
OUT = Path(os.environ.get("R26_OUT", "/tmp/r26/clutter")) / "v"

P, A = "panda_pick_place", "aloha_transfer_cube"
# demo seed 0's spawn (critmoment demo --scenario panda_pick_place --seed 0)
X0, Y0 = 0.51369617, -0.17302133
CUBE_BODY = '<body name="cube" pos="0.5 -0.15 0.02">'
CUBE_GEOM = '<geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1"'
CUBE_END = '''            solref="0.01 1"/>
    </body>'''
KEY_TAIL = "0.5 -0.15 0.02 1 0 0 0"
WB_END = "  </worldbody>"
FREE = 'contype="1" conaffinity="1" condim="4" friction="1 0.005 0.0001"'

VARIANTS = {}


def variant(name, base=P, xml=(), toml=(), append="", traj=None):
    """xml: (file, old, new) replacements; toml: (old, new); traj: make_pick_place kwargs
    (z: object height, goal, grasp_offset, transport_height) or None for the demo's."""
    VARIANTS[name] = dict(base=base, xml=list(xml), toml=list(toml), append=append, traj=traj)


def free_box(name, pos, size, mass, rgba="0.2 0.4 0.9 1", extra=""):
    """A free box body (appended before </worldbody>) and its keyframe qpos."""
    body = (f'    <body name="{name}" pos="{pos[0]} {pos[1]} {pos[2]}">\n'
            f'      <freejoint name="{name}_joint"/>\n'
            f'      <geom name="{name}" type="box" size="{size[0]} {size[1]} {size[2]}" '
            f'mass="{mass}" rgba="{rgba}" {FREE} {extra}/>\n    </body>\n')
    return body, f"{pos[0]} {pos[1]} {pos[2]} 1 0 0 0"


def with_free_bodies(bodies, key_tail=KEY_TAIL, scene="scene.xml"):
    xml_body = "".join(b for b, _ in bodies)
    key = " ".join(k for _, k in bodies)
    return [(scene, WB_END, xml_body + WB_END), (scene, key_tail, key_tail + "\n               " + key)]


# ---------------------------------------------------------------- 1. clutter (Panda)
# a second 4 cm, 0.1 kg cube 10 cm from the object along x: never touched
variant("c_distractor_side", xml=with_free_bodies([free_box("d1", (X0 + 0.10, Y0, 0.02), (0.02, 0.02, 0.02), 0.1)]))
# a cube beside the object along the fingers' closing axis (world y): its near face at
# 0.054 m from the object's centre, 1 mm inside the open pad's outer face (0.055 m): the
# descending finger brushes it
variant("c_distractor_brush", xml=with_free_bodies([free_box("d1", (X0, Y0 - 0.074, 0.02), (0.02, 0.02, 0.02), 0.1)]))
# the same, 5 mm inside: the pad lands on the distractor's edge
variant("c_distractor_pad_lands", xml=with_free_bodies([free_box("d1", (X0, Y0 - 0.07, 0.02), (0.02, 0.02, 0.02), 0.1)]))
# the same under the other pad (+y), and with a 0.5 kg distractor
variant("c_distractor_pad_lands_other", xml=with_free_bodies([free_box("d1", (X0, Y0 + 0.07, 0.02), (0.02, 0.02, 0.02), 0.1)]))
variant("c_distractor_pad_lands_heavy", xml=with_free_bodies([free_box("d1", (X0, Y0 - 0.07, 0.02), (0.02, 0.02, 0.02), 0.5)]))
# the same on demo seeds 2 and 3's spawns (the plan uses that seed)
X2, Y2 = 0.47616121, -0.17015089
X3, Y3 = 0.45856492, -0.17631895
variant("c_distractor_pad_lands_s2", xml=with_free_bodies([free_box("d1", (X2, Y2 - 0.07, 0.02), (0.02, 0.02, 0.02), 0.1)]), traj=dict(seed=2))
variant("c_distractor_pad_lands_s3", xml=with_free_bodies([free_box("d1", (X3, Y3 - 0.07, 0.02), (0.02, 0.02, 0.02), 0.1)]), traj=dict(seed=3))
# a cube resting against the object at the start (face to face along x, touching)
variant("c_distractor_touching", xml=with_free_bodies([free_box("d1", (X0 + 0.04, Y0, 0.02), (0.02, 0.02, 0.02), 0.1)]))
# the same, 0.5 mm into the object (so that MuJoCo makes the contact at the start)
variant("c_distractor_pressed", xml=with_free_bodies([free_box("d1", (X0 + 0.0395, Y0, 0.02), (0.02, 0.02, 0.02), 0.1)]))
# a 14 cm tall, 0.2 kg free block on the carry path (mid-way, y = 0): the carried object
# (bottom at ~0.12 m) hits its top 2 cm
variant("c_obstacle_on_path", xml=with_free_bodies([free_box("d1", (0.507, 0.0, 0.07), (0.02, 0.02, 0.07), 0.2)]))
# the same block, 1 kg: the carried object is stopped harder
variant("c_obstacle_on_path_heavy", xml=with_free_bodies([free_box("d1", (0.507, 0.0, 0.07), (0.02, 0.02, 0.07), 1.0)]))
# a free 4 cm, 0.1 kg cube on a static 10 cm post beside the carry path: the carried object
# (bottom at ~0.12 m) knocks it off
POST = ('    <body name="post" pos="0.507 -0.05 0">\n'
        '      <geom name="post" type="box" size="0.015 0.015 0.05" pos="0 0 0.05"/>\n    </body>\n')
variant("c_knock_off_post", xml=[("scene.xml", WB_END, POST + WB_END)] + with_free_bodies([free_box("d1", (0.507, -0.05, 0.12), (0.02, 0.02, 0.02), 0.1)]))
# a light (30 g) 10 x 10 x 1 cm box lying on the table under the goal: the object is put
# down 8 mm into it, and rests on it (1 cm above the goal)
variant("c_lid_under_goal", xml=with_free_bodies([free_box("lid", (0.5, 0.15, 0.005), (0.05, 0.05, 0.005), 0.03)]))
# the same light box half under the goal: the object lands with one edge on it
variant("c_lid_half_goal", xml=with_free_bodies([free_box("lid", (0.5, 0.15 + 0.06, 0.005), (0.05, 0.05, 0.005), 0.03)]))
# a light (30 g) 10 x 10 x 6 cm box on the table on the path, with a low carry (transport
# height 0.08 m): the carried object (bottom at ~0.05 m) hits its top 1 cm
variant("c_lid_on_low_path", xml=with_free_bodies([free_box("lid", (0.507, 0.0, 0.03), (0.05, 0.05, 0.03), 0.03)]),
        traj=dict(transport_height=0.08))

# ---------------------------------------------------------------- 2. supports (Panda)
PED = (f'    <body name="pedestal" pos="{X0} {Y0} 0">\n'
       '      <geom name="ped_base" type="box" size="0.04 0.04 0.01" pos="0 0 0.01" friction="1 0.005 0.0001"/>\n'
       '      <geom name="ped_top" type="box" size="0.03 0.03 0.01" pos="0 0 0.03" friction="1 0.005 0.0001"/>\n'
       '    </body>\n')
variant("s_pedestal2", xml=[("scene.xml", WB_END, PED + WB_END), ("scene.xml", CUBE_BODY, f'<body name="cube" pos="{X0} {Y0} 0.06">')],
        toml=[('geoms = ["table"]', 'geoms = ["table", "ped_base", "ped_top"]')], traj=dict(z=0.06))
# the same pedestal, its top geom left out of [support]
variant("s_pedestal2_top_unlisted", xml=[("scene.xml", WB_END, PED + WB_END), ("scene.xml", CUBE_BODY, f'<body name="cube" pos="{X0} {Y0} 0.06">')],
        toml=[('geoms = ["table"]', 'geoms = ["table", "ped_base"]')], traj=dict(z=0.06))
# the pedestal given as [support] bodies
variant("s_pedestal2_body", xml=[("scene.xml", WB_END, PED + WB_END), ("scene.xml", CUBE_BODY, f'<body name="cube" pos="{X0} {Y0} 0.06">')],
        toml=[('geoms = ["table"]', 'geoms = ["table"]\nbodies = ["pedestal"]')], traj=dict(z=0.06))
TRAY = (f'    <body name="tray" pos="{X0} {Y0} 0">\n'
        '      <geom name="tray_floor" type="box" size="0.06 0.085 0.002" pos="0 0 0.002" friction="1 0.005 0.0001"/>\n'
        '      <geom name="tray_wall_xp" type="box" size="0.003 0.085 0.0075" pos="0.063 0 0.0115"/>\n'
        '      <geom name="tray_wall_xm" type="box" size="0.003 0.085 0.0075" pos="-0.063 0 0.0115"/>\n'
        '      <geom name="tray_wall_yp" type="box" size="0.066 0.003 0.0075" pos="0 0.088 0.0115"/>\n'
        '      <geom name="tray_wall_ym" type="box" size="0.066 0.003 0.0075" pos="0 -0.088 0.0115"/>\n'
        '    </body>\n')
TRAY_GEOMS = '"tray_floor", "tray_wall_xp", "tray_wall_xm", "tray_wall_yp", "tray_wall_ym"'
variant("s_tray", xml=[("scene.xml", WB_END, TRAY + WB_END), ("scene.xml", CUBE_BODY, f'<body name="cube" pos="{X0} {Y0} 0.024">')],
        toml=[('geoms = ["table"]', f'geoms = ["table", {TRAY_GEOMS}]')], traj=dict(z=0.024))
# the object starts touching a tray wall (the tray shifted 3.95 cm along -x: its +x wall 0.5 mm into the object)
variant("s_tray_against_wall", xml=[("scene.xml", WB_END, TRAY.replace(f'pos="{X0} {Y0} 0"', f'pos="{X0 - 0.0395} {Y0} 0"') + WB_END),
                                    ("scene.xml", CUBE_BODY, f'<body name="cube" pos="{X0} {Y0} 0.024">')],
        toml=[('geoms = ["table"]', f'geoms = ["table", {TRAY_GEOMS}]')], traj=dict(z=0.024))
BIN = ('    <body name="bin" pos="0.5 0.15 0">\n'
       '      <geom name="bin_floor" type="box" size="0.07 0.07 0.005" pos="0 0 0.005" friction="1 0.005 0.0001"/>\n'
       '      <geom name="bin_wall_xp" type="box" size="0.004 0.07 0.035" pos="0.074 0 0.035"/>\n'
       '      <geom name="bin_wall_xm" type="box" size="0.004 0.07 0.035" pos="-0.074 0 0.035"/>\n'
       '      <geom name="bin_wall_yp" type="box" size="0.078 0.004 0.035" pos="0 0.074 0.035"/>\n'
       '      <geom name="bin_wall_ym" type="box" size="0.078 0.004 0.035" pos="0 -0.074 0.035"/>\n'
       '    </body>\n')
BIN_GEOMS = '"bin_floor", "bin_wall_xp", "bin_wall_xm", "bin_wall_yp", "bin_wall_ym"'
variant("s_bin_goal", xml=[("scene.xml", WB_END, BIN + WB_END)],
        toml=[('geoms = ["table"]', f'geoms = ["table", {BIN_GEOMS}]'), ("goal = [0.5, 0.15, 0.02]", "goal = [0.5, 0.15, 0.03]")],
        traj=dict(goal=(0.5, 0.15, 0.03)))
# the bin left out of [support]
variant("s_bin_goal_unlisted", xml=[("scene.xml", WB_END, BIN + WB_END)],
        toml=[("goal = [0.5, 0.15, 0.02]", "goal = [0.5, 0.15, 0.03]")], traj=dict(goal=(0.5, 0.15, 0.03)))
# the bin's goal 4 cm off centre, 3 cm from a wall's inner face: the released cube is 1 cm
# from the wall (same trajectory target as the scenario goal)
variant("s_bin_goal_near_wall", xml=[("scene.xml", WB_END, BIN + WB_END)],
        toml=[('geoms = ["table"]', f'geoms = ["table", {BIN_GEOMS}]'), ("goal = [0.5, 0.15, 0.02]", "goal = [0.5, 0.19, 0.03]")],
        traj=dict(goal=(0.5, 0.19, 0.03)))

# ---------------------------------------------------------------- 3. boxes (bundled Panda)
MASS_T = 'range = [0.05, 3.0]      # [kg]; 3 kg is the Panda\'s quoted payload\nnominal = 0.1\nprior = "uniform"'
FRIC_T = 'range = [0.2, 1.5]       # sliding friction coefficient of the cube\'s contacts\nnominal = 1.0\nprior = "uniform"'
COM = '\n[uncertainty.com]\nkind = "com_offset"\nbody = "cube"\nrange = [{lo}, {hi}]\nnominal = {nom}\n'
GRIP = '\n[uncertainty.grip]\nkind = "force_limit"\nactuator = "finger_left"\nrange = [{lo}, {hi}]\nnominal = {nom}\n'
GRIP2 = '\n[uncertainty.grip2]\nkind = "force_limit"\nactuator = "finger_right"\nrange = [{lo}, {hi}]\nnominal = {nom}\n'


def mass(lo, hi, nom, prior="uniform"):
    return (MASS_T, f"range = [{lo}, {hi}]\nnominal = {nom}\nprior = \"{prior}\"")


def fric(lo, hi, nom):
    return (FRIC_T, f"range = [{lo}, {hi}]\nnominal = {nom}\nprior = \"uniform\"")


variant("b4_m_f_com_grip", toml=[], append=COM.format(lo=-0.02, hi=0.02, nom=0.0) + GRIP.format(lo=5.0, hi=35.0, nom=35.0))
variant("b4_log_m_f_com_grip", toml=[mass(0.02, 3.0, 0.1, "loguniform")],
        append=COM.format(lo=-0.02, hi=0.02, nom=0.0) + GRIP.format(lo=5.0, hi=35.0, nom=35.0))
variant("b4_m_f_com_both_grips", toml=[mass(0.05, 2.0, 0.1)],
        append=COM.format(lo=-0.02, hi=0.02, nom=0.0) + GRIP.format(lo=8.0, hi=35.0, nom=35.0) + GRIP2.format(lo=8.0, hi=35.0, nom=35.0))
# only the heavy, slippery corner fails (~2 % of the box)
variant("b_thin_corner", toml=[mass(0.05, 2.1, 0.1), fric(0.85, 1.5, 1.0)])
variant("b_thin_corner_4d", toml=[mass(0.05, 2.1, 0.1), fric(0.85, 1.5, 1.0)],
        append=COM.format(lo=-0.01, hi=0.01, nom=0.0) + GRIP.format(lo=25.0, hi=35.0, nom=35.0))
# narrow: the outcome flips inside on the centre of mass and grip force
variant("b_flip_com_grip", toml=[mass(1.3, 1.6, 1.4), fric(0.75, 0.8, 0.8)],
        append=COM.format(lo=-0.02, hi=0.02, nom=0.0) + GRIP.format(lo=20.0, hi=35.0, nom=35.0))
variant("b_flip_grip_only", toml=[mass(1.0, 1.0001, 1.0), fric(1.0, 1.0001, 1.0)],
        append=GRIP.format(lo=2.0, hi=12.0, nom=12.0))

# ---------------------------------------------------------------- 4. objects (Panda)
variant("o_tall_thin", xml=[("scene.xml", CUBE_GEOM, '<geom name="cube" type="box" size="0.012 0.012 0.06" mass="0.1"'),
                            ("scene.xml", CUBE_BODY, f'<body name="cube" pos="{X0} {Y0} 0.06">')],
        toml=[("goal = [0.5, 0.15, 0.02]", "goal = [0.5, 0.15, 0.06]")], traj=dict(z=0.06, goal=(0.5, 0.15, 0.06)))
# gripped 4.5 cm above its centre (near its top): it hangs and swings
variant("o_tall_thin_high_grip", xml=[("scene.xml", CUBE_GEOM, '<geom name="cube" type="box" size="0.012 0.012 0.06" mass="0.1"'),
                                      ("scene.xml", CUBE_BODY, f'<body name="cube" pos="{X0} {Y0} 0.06">')],
         toml=[("goal = [0.5, 0.15, 0.02]", "goal = [0.5, 0.15, 0.06]")], traj=dict(z=0.06 + 0.035, goal=(0.5, 0.15, 0.06 + 0.035), object_z=0.06))
variant("o_heavy_slippery_sphere", xml=[("scene.xml", CUBE_GEOM, '<geom name="cube" type="sphere" size="0.02" mass="1.0"'),
                                        ("scene.xml", 'condim="4" priority="2" friction="1 0.005 0.0001"', 'condim="4" priority="2" friction="0.4 0.005 0.0001"')],
        toml=[mass(0.5, 2.5, 1.0), fric(0.2, 0.8, 0.4)])
# the same sphere light enough to lift at nominal: 0.3 kg at friction 0.5
variant("o_sphere_slippery_liftable", xml=[("scene.xml", CUBE_GEOM, '<geom name="cube" type="sphere" size="0.02" mass="0.3"'),
                                           ("scene.xml", 'condim="4" priority="2" friction="1 0.005 0.0001"', 'condim="4" priority="2" friction="0.5 0.005 0.0001"')],
        toml=[mass(0.1, 2.0, 0.3), fric(0.2, 0.8, 0.5)])
DENS = ('<geom name="cube" type="box" size="0.02 0.02 0.02" density="1500" rgba="0.9 0.1 0.1 1"\n'
        '            contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001"\n'
        '            solref="0.01 1"/>\n'
        '      <geom name="cap" type="box" size="0.015 0.015 0.01" pos="0 0 0.03" density="500" '
        'contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001"/>\n'
        '      <geom name="lug" type="cylinder" size="0.008 0.01" pos="0.028 0 0" euler="0 1.5708 0" density="7800" '
        'contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001"/>\n    </body>')
# mass by density on three geoms: 0.096 + 0.0045 + 0.0157 = 0.116 kg
variant("o_density_3geoms", xml=[("scene.xml", '<geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1" rgba="0.9 0.1 0.1 1"\n'
                                  '            contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001"\n'
                                  '            solref="0.01 1"/>\n    </body>', DENS)],
        toml=[mass(0.05, 3.0, 0.116)])
variant("o_density_nominal_off", xml=[("scene.xml", '<geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1" rgba="0.9 0.1 0.1 1"\n'
                                       '            contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001"\n'
                                       '            solref="0.01 1"/>\n    </body>', DENS)])

# ---------------------------------------------------------------- ALOHA clutter
AX, AY = 0.12737593, 0.45367029   # demo seed 0's spawn (approx.)
AKEY = "0.1 0.5 0.02 1 0 0 0"
variant("a_distractor_side", base=A, xml=with_free_bodies([free_box("d1", (AX - 0.1, AY, 0.02), (0.02, 0.02, 0.02), 0.05)], key_tail=AKEY))
variant("a_distractor_touching_y", base=A, xml=with_free_bodies([free_box("d1", (AX, AY + 0.04, 0.02), (0.02, 0.02, 0.02), 0.05)], key_tail=AKEY))
variant("a_distractor_touching_x", base=A, xml=with_free_bodies([free_box("d1", (AX - 0.04, AY, 0.02), (0.02, 0.02, 0.02), 0.05)], key_tail=AKEY))

# the ALOHA picker closes on both cubes (touching along x) and carries them together; the
# box's mass parameter moved onto the distractor, then on both
D1M = '\n[uncertainty.d1mass]\nkind = "mass"\nbody = "d1"\nrange = [0.05, 2.0]\nnominal = 0.05\n'
variant("a_two_cubes_d1_mass", base=A, xml=with_free_bodies([free_box("d1", (AX - 0.04, AY, 0.02), (0.02, 0.02, 0.02), 0.05)], key_tail=AKEY),
        toml=[("range = [0.05, 10.0]     # [kg]", "range = [0.05, 1.5]     # [kg]")], append=D1M)
variant("a_two_cubes_m15", base=A, xml=with_free_bodies([free_box("d1", (AX - 0.04, AY, 0.02), (0.02, 0.02, 0.02), 0.05)], key_tail=AKEY),
        toml=[("range = [0.05, 10.0]     # [kg]", "range = [0.05, 1.5]     # [kg]")])
variant("a_base_m15", base=A, toml=[("range = [0.05, 10.0]     # [kg]", "range = [0.05, 1.5]     # [kg]")])
# Panda: the distractor pressed against the object carries the mass parameter
variant("c_pressed_d1_mass", xml=with_free_bodies([free_box("d1", (X0 + 0.0395, Y0, 0.02), (0.02, 0.02, 0.02), 0.1)]),
        append=D1M.replace("[0.05, 2.0]", "[0.05, 3.0]").replace("nominal = 0.05", "nominal = 0.1"))

# a second 4 cm, 0.1 kg cube stacked on the object (clutter resting on it)
variant("c_cube_on_top", xml=with_free_bodies([free_box("d1", (X0, Y0, 0.06), (0.02, 0.02, 0.02), 0.1)]))
# a static post under the carry path, its top 4.5 mm under the carried object's bottom
# (the object rides at z = 0.14 m, bottom 0.12 m, at y = 0): an object that sags in the grip grazes it
GRAZE = ('    <body name="post" pos="0.505 0.0 0">\n'
         '      <geom name="post" type="box" size="0.03 0.015 0.05775" pos="0 0 0.05775"/>\n    </body>\n')
variant("c_post_grazing", xml=[("scene.xml", WB_END, GRAZE + WB_END)])
# pick the object from inside a walled bin (the bin of s_bin_goal, under the object)
variant("s_pick_from_bin", xml=[("scene.xml", WB_END, BIN.replace('pos="0.5 0.15 0"', f'pos="{X0} {Y0} 0"') + WB_END),
                                ("scene.xml", CUBE_BODY, f'<body name="cube" pos="{X0} {Y0} 0.03">')],
        toml=[('geoms = ["table"]', f'geoms = ["table", {BIN_GEOMS}]')], traj=dict(z=0.03))

# log-uniform friction (and mass): the slippery end gets most of the prior
variant("b_log_friction_mass", toml=[mass(0.05, 3.0, 0.1, "loguniform"),
                                     (FRIC_T, 'range = [0.05, 1.5]\nnominal = 1.0\nprior = "loguniform"')])
# a friction parameter on the distractor pressed against the object (its contacts with the
# object are won by the object's priority 2, so it should be refused)
variant("c_pressed_d1_friction", xml=with_free_bodies([free_box("d1", (X0 + 0.0395, Y0, 0.02), (0.02, 0.02, 0.02), 0.1)]),
        append='\n[uncertainty.d1fric]\nkind = "friction"\ngeom = "d1"\nrange = [0.2, 1.5]\nnominal = 1.0\n')


def build(name):
    spec = VARIANTS[name]
    out = OUT / name
    if out.exists():
        shutil.rmtree(out)
    shutil.copytree(M / spec["base"], out)
    for fname, old, new in spec["xml"]:
        p = out / fname
        t = p.read_text()
        assert old in t, (name, old)
        p.write_text(t.replace(old, new, 1))
    p = out / "scenario.toml"
    t = p.read_text()
    for old, new in spec["toml"]:
        assert old in t, (name, old)
        t = t.replace(old, new, 1)
    p.write_text(t + spec["append"])
    if spec["base"] == P:
        make_traj(name, out, spec["traj"] or {})


def make_traj(name, out, kw):
    import mujoco
    import numpy as np

    import critmoment.panda_demo as pd
    from critmoment.trajectory import save_trajectory

    kw = dict(kw)
    seed = kw.pop("seed", 0)
    z = kw.pop("z", 0.02)
    object_z = kw.pop("object_z", z)
    goal = kw.pop("goal", None)
    opt = pd.PickPlaceOptions(**({"goal": goal} if goal else {}), **kw)
    orig = pd.sample_cube_pose

    def pose(seed):
        p = orig(seed)
        p[2] = z          # where the plan grasps (grasp_offset above this)
        return p
    pd.sample_cube_pose = pose
    try:
        m = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
        t = pd.make_pick_place(seed, model=m, options=opt)
    finally:
        pd.sample_cube_pose = orig
    if object_z != z:   # the object's real centre (the plan grasps above it)
        import dataclasses
        adr = m.jnt_qposadr[m.joint("cube_joint").id]
        q0, op = t.qpos0.copy(), t.object_pose.copy()
        q0[adr + 2] = object_z
        op[2] = object_z
        t = dataclasses.replace(t, qpos0=q0, object_pose=op)
    save_trajectory(t, str(out / "traj.npz"))
    print(name, "traj", np.round(t.object_pose[:3], 4).tolist(), "goal", opt.goal)


if __name__ == "__main__":
    names = sys.argv[1:] or list(VARIANTS)
    for n in names:
        build(n)
        print("built", n)
