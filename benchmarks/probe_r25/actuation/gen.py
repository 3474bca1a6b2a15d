"""Build the actuation/model-feature variants under v/<name>/ (copies of the bundled twins
with one edit each).  usage: python gen.py [NAME ...]   (idempotent; all when no NAME)
The bundled models are read from $R25_MODELS_DIR (default /tmp/r25/src/models)."""
import os
import re
import shutil
import sys
from pathlib import Path

M = Path(os.environ.get("R25_MODELS_DIR", "/tmp/r25/src/models"))
V = Path(__file__).resolve().parent / "v"
P, A = "panda_pick_place", "aloha_transfer_cube"
VARIANTS = {}


def variant(name, base):
    def deco(fn):
        VARIANTS[name] = (base, fn)
        return fn
    return deco


class Files:
    def __init__(self, root):
        self.root = root

    def sub(self, fname, old, new, count=1, regex=False):
        p = self.root / fname
        t = p.read_text()
        if regex:
            t2, n = re.subn(old, new, t, count=0 if count is None else count)
        else:
            n = t.count(old)
            t2 = t.replace(old, new, -1 if count is None else count)
        assert n, (self.root.name, fname, old)
        p.write_text(t2)

    def append_toml(self, text):
        p = self.root / "scenario.toml"
        p.write_text(p.read_text() + text)


PANDA_ARM = [("joint1", 4500, 450, 87), ("joint2", 4500, 450, 87), ("joint3", 3500, 350, 87),
             ("joint4", 3500, 350, 87), ("joint5", 2000, 200, 12), ("joint6", 2000, 200, 12),
             ("joint7", 2000, 200, 12)]


def panda_act_line(name):
    return rf'(<position name="{name}" joint="{name}"[^/]*)/>'


def drop_limits(f, names):
    for n in names:
        f.sub("scenario.toml", rf"\n{n} = [0-9.]+", "", regex=True)


# ---------------- 1. actuator dynamics -------------------------------------------------
for tc in (0.01, 0.03, 0.05):
    @variant(f"p_filtexact_arm_{tc}", P)
    def _(f, tc=tc):
        for n, *_ in PANDA_ARM:
            f.sub("panda.xml", panda_act_line(n), rf'\1 timeconst="{tc}"/>', regex=True)


@variant("p_filtexact_grip_0.05", P)
def _(f):
    for n in ("finger_left", "finger_right"):
        f.sub("panda.xml", rf'(<position name="{n}"[^/]*)/>', r'\1 timeconst="0.05"/>', regex=True)


@variant("p_filter_arm_0.03", P)  # dyntype="filter" (Euler-integrated) through <general>
def _(f):
    for n, kp, kv, _fr in PANDA_ARM:
        f.sub("panda.xml", rf'<position name="{n}" joint="{n}" kp="{kp}" kv="{kv}"',
              f'<general name="{n}" joint="{n}" dyntype="filter" dynprm="0.03" gainprm="{kp}" '
              f'biastype="affine" biasprm="0 -{kp} -{kv}"')


@variant("a_filtexact_arm_0.03", A)
def _(f):
    for n in ("waist", "shoulder", "elbow", "forearm_roll", "wrist_angle", "wrist_rotate"):
        f.sub("vx300s.xml", rf'(<position name="{n}"[^/]*)/>', r'\1 timeconst="0.03"/>', regex=True)


@variant("a_filtexact_grip_0.05", A)
def _(f):
    for n in ("left_finger", "right_finger"):
        f.sub("vx300s.xml", rf'(<position name="{n}"[^/]*)/>', r'\1 timeconst="0.05"/>', regex=True)


# ---------------- 2. gear ratios ----------------------------------------------------------
def gear_arm(f, g, keep_limits):
    for n, kp, kv, fr in PANDA_ARM:
        m = re.search(rf'<position name="{n}" joint="{n}" [^/]*ctrlrange="([-0-9.]+) ([-0-9.]+)"/>',
                      (f.root / "panda.xml").read_text())
        lo, hi = float(m.group(1)), float(m.group(2))
        f.sub("panda.xml", m.group(0),
              f'<position name="{n}" joint="{n}" gear="{g}" kp="{kp / g**2:.6g}" kv="{kv / g**2:.6g}" '
              f'forcerange="{-fr / g:.6g} {fr / g:.6g}" ctrlrange="{lo * g:.6g} {hi * g:.6g}"/>')
        f.sub("scenario.toml", f'actuators = ["{n}"]\n', f'actuators = ["{n}"]\nscales = [{g}]\noffsets = [0.0]\n')
    f.sub("scene.xml", 'ctrl="0 -0.78539816 0 -2.35619449 0 1.57079633 0.78539816',
          'ctrl="' + " ".join(f"{v * g:.8g}" for v in (0, -0.78539816, 0, -2.35619449, 0, 1.57079633, 0.78539816)))
    if not keep_limits:
        drop_limits(f, [n for n, *_ in PANDA_ARM])


@variant("p_gear50_nolimits", P)
def _(f):
    gear_arm(f, 50, keep_limits=False)


@variant("p_gear50_jointlimits", P)  # [limits] still in joint torque (87 N·m) = 50x the actuator's
def _(f):
    gear_arm(f, 50, keep_limits=True)


@variant("p_gear50_rescaledlimits", P)  # [limits] in actuator units (87/50)
def _(f):
    gear_arm(f, 50, keep_limits=False)
    f.sub("scenario.toml", "[limits]\n", "[limits]\n" + "".join(f"{n} = {fr / 50:.6g}\n" for n, _, _, fr in PANDA_ARM))


@variant("p_gear10_grip", P)
def _(f):
    for n in ("finger_left", "finger_right"):
        f.sub("panda.xml", rf'<position name="{n}" joint="(finger_joint\d)" kp="500" kv="10" forcerange="-35 35" ctrlrange="0 0.04"/>',
              rf'<position name="{n}" joint="\1" gear="10" kp="5" kv="0.1" forcerange="-3.5 3.5" ctrlrange="0 0.4"/>', regex=True)
    f.sub("scenario.toml", "scales = [0.04, 0.04]", "scales = [0.4, 0.4]")
    f.sub("scene.xml", "0.78539816 0.04 0.04\"", "0.78539816 0.4 0.4\"")
    drop_limits(f, ["finger_left", "finger_right"])


# ---------------- 3. joint-level force limits ---------------------------------------------
J2 = '<joint name="joint2" axis="0 0 1" range="-1.7628 1.7628"'


@variant("p_j2_forcerange50", P)  # reference: actuator forcerange 50 on joint2
def _(f):
    f.sub("panda.xml", '<position name="joint2" joint="joint2" kp="4500" kv="450" forcerange="-87 87"',
          '<position name="joint2" joint="joint2" kp="4500" kv="450" forcerange="-50 50"')
    drop_limits(f, ["joint2"])


@variant("p_j2_jointfrc50", P)  # same limit as the joint's actuatorfrcrange only
def _(f):
    f.sub("panda.xml", '<position name="joint2" joint="joint2" kp="4500" kv="450" forcerange="-87 87"',
          '<position name="joint2" joint="joint2" kp="4500" kv="450"')
    f.sub("panda.xml", J2, J2 + ' actuatorfrcrange="-50 50"')
    drop_limits(f, ["joint2"])


@variant("p_j2_both87_50", P)  # actuator forcerange 87, joint actuatorfrcrange 50 (the tighter)
def _(f):
    f.sub("panda.xml", J2, J2 + ' actuatorfrcrange="-50 50"')
    drop_limits(f, ["joint2"])


@variant("p_j2_jointfrc50_limits87", P)  # [limits] says 87, the joint clamps at 50
def _(f):
    f.sub("panda.xml", J2, J2 + ' actuatorfrcrange="-50 50"')


@variant("p_arm_jointfrc_only", P)  # every arm limit moved to actuatorfrcrange, no [limits]
def _(f):
    for n, kp, kv, fr in PANDA_ARM:
        f.sub("panda.xml", f'<position name="{n}" joint="{n}" kp="{kp}" kv="{kv}" forcerange="-{fr} {fr}"',
              f'<position name="{n}" joint="{n}" kp="{kp}" kv="{kv}"')
        f.sub("panda.xml", rf'(<joint name="{n}" axis="0 0 1" range="[-0-9. ]+")', rf'\1 actuatorfrcrange="-{fr} {fr}"', regex=True)
    drop_limits(f, [n for n, *_ in PANDA_ARM])


@variant("a_jointfrc_only", A)
def _(f):
    for n, fr in (("waist", 10), ("shoulder", 20), ("elbow", 15), ("forearm_roll", 2), ("wrist_angle", 5), ("wrist_rotate", 1)):
        f.sub("vx300s.xml", rf'(<position name="{n}" [^/]*) forcerange="-{fr} {fr}"', r"\1", regex=True)
        f.sub("vx300s.xml", rf'(<joint name="{n}" [^/]*)/>', rf'\1 actuatorfrcrange="-{fr} {fr}"/>', regex=True)
        drop_limits(f, [n])


@variant("p_gear50_jointfrc", P)  # gear 50 with the joint-side limit as actuatorfrcrange only
def _(f):
    gear_arm(f, 50, keep_limits=False)
    for n, _kp, _kv, fr in PANDA_ARM:
        f.sub("panda.xml", rf'(<position name="{n}" joint="{n}" gear="50" kp="[0-9.e-]+" kv="[0-9.e-]+") forcerange="[-0-9. ]+"', r"\1", regex=True)
        f.sub("panda.xml", rf'(<joint name="{n}" axis="0 0 1" range="[-0-9. ]+")', rf'\1 actuatorfrcrange="-{fr} {fr}"', regex=True)


# ---------------- 4. joint passive properties ---------------------------------------------
@variant("p_armature0.5", P)
def _(f):
    f.sub("panda.xml", '<joint armature="0.1" damping="1"/>', '<joint armature="0.5" damping="1"/>')


@variant("p_frictionloss2", P)
def _(f):
    f.sub("panda.xml", '<joint armature="0.1" damping="1"/>', '<joint armature="0.1" damping="1" frictionloss="2"/>')


@variant("p_damping20", P)
def _(f):
    f.sub("panda.xml", '<joint armature="0.1" damping="1"/>', '<joint armature="0.1" damping="20"/>')


@variant("p_stiffness20", P)  # springs towards 0 (springref default): a static load the servo fights
def _(f):
    f.sub("panda.xml", '<joint armature="0.1" damping="1"/>', '<joint armature="0.1" damping="1" stiffness="20"/>')


@variant("p_stiffness20_springref", P)  # springs at the home pose
def _(f):
    f.sub("panda.xml", '<joint armature="0.1" damping="1"/>', '<joint armature="0.1" damping="1" stiffness="20"/>')
    for n, ref in (("joint2", -0.785), ("joint4", -2.356), ("joint6", 1.571), ("joint7", 0.785)):
        f.sub("panda.xml", rf'(<joint name="{n}" axis="0 0 1" range="[-0-9. ]+")', rf'\1 springref="{ref}"', regex=True)


@variant("a_frictionloss0.5", A)
def _(f):
    f.sub("vx300s.xml", '<joint frictionloss="0.1" damping="0.1"/>', '<joint frictionloss="0.5" damping="0.1"/>')


@variant("a_stiffness1", A)
def _(f):
    f.sub("vx300s.xml", '<joint frictionloss="0.1" damping="0.1"/>', '<joint frictionloss="0.1" damping="0.1" stiffness="1"/>')


# ---------------- 5. coupled / tendon / adhesion grippers ---------------------------------
FINGERS = ('    <position name="finger_left" joint="finger_joint1" kp="500" kv="10" forcerange="-35 35" ctrlrange="0 0.04"/>\n'
           '    <position name="finger_right" joint="finger_joint2" kp="500" kv="10" forcerange="-35 35" ctrlrange="0 0.04"/>\n')
GRIP_CH = 'actuators = ["finger_left", "finger_right"]\nnormalised = true\nscales = [0.04, 0.04]\noffsets = [0.0, 0.0]'


@variant("p_tendon_grip", P)
def _(f):
    f.sub("panda.xml", FINGERS,
          '    <position name="grip" tendon="grip" kp="1000" kv="20" forcerange="-70 70" ctrlrange="0 0.04"/>\n')
    f.sub("panda.xml", "  <contact>", '  <tendon>\n    <fixed name="grip">\n      <joint joint="finger_joint1" coef="0.5"/>\n'
          '      <joint joint="finger_joint2" coef="0.5"/>\n    </fixed>\n  </tendon>\n\n  <contact>')
    f.sub("scenario.toml", GRIP_CH, 'actuators = ["grip"]\nnormalised = true\nscales = [0.04]\noffsets = [0.0]')
    f.sub("scene.xml", "0.78539816 0.04 0.04\"", "0.78539816 0.04\"")
    drop_limits(f, ["finger_left", "finger_right"])
    f.sub("scenario.toml", "[limits]\n", "[limits]\ngrip = 70.0\n")


@variant("p_equality_grip", P)
def _(f):
    f.sub("panda.xml", FINGERS,
          '    <position name="finger_left" joint="finger_joint1" kp="1000" kv="20" forcerange="-70 70" ctrlrange="0 0.04"/>\n')
    f.sub("panda.xml", "  <contact>", '  <equality>\n    <joint joint1="finger_joint2" joint2="finger_joint1" polycoef="0 1 0 0 0"/>\n'
          '  </equality>\n\n  <contact>')
    f.sub("scenario.toml", GRIP_CH, 'actuators = ["finger_left"]\nnormalised = true\nscales = [0.04]\noffsets = [0.0]')
    f.sub("scene.xml", "0.78539816 0.04 0.04\"", "0.78539816 0.04\"")
    drop_limits(f, ["finger_left", "finger_right"])
    f.sub("scenario.toml", "[limits]\n", "[limits]\nfinger_left = 70.0\n")


ADH = ('    <adhesion name="suck_left" body="left_finger" ctrlrange="0 1" gain="{g}"/>\n'
       '    <adhesion name="suck_right" body="right_finger" ctrlrange="0 1" gain="{g}"/>\n')


@variant("p_adhesion_assist", P)  # the fingers plus adhesion on both finger bodies
def _(f):
    f.sub("panda.xml", FINGERS, FINGERS + ADH.format(g=20))
    f.sub("scenario.toml", GRIP_CH, 'actuators = ["finger_left", "finger_right", "suck_left", "suck_right"]\n'
          'normalised = true\nscales = [0.04, 0.04, -1.0, -1.0]\noffsets = [0.0, 0.0, 1.0, 1.0]')
    f.sub("scene.xml", "0.78539816 0.04 0.04\"", "0.78539816 0.04 0.04 0 0\"")


@variant("p_adhesion_weakfingers", P)  # fingers squeeze 1 N; adhesion (20 N per pad) holds
def _(f):
    f.sub("panda.xml", FINGERS, FINGERS.replace('kp="500" kv="10"', 'kp="50" kv="2"') + ADH.format(g=20))
    f.sub("scenario.toml", GRIP_CH, 'actuators = ["finger_left", "finger_right", "suck_left", "suck_right"]\n'
          'normalised = true\nscales = [0.04, 0.04, -1.0, -1.0]\noffsets = [0.0, 0.0, 1.0, 1.0]')
    f.sub("scene.xml", "0.78539816 0.04 0.04\"", "0.78539816 0.04 0.04 0 0\"")


# ---------------- 6. velocity actuators ---------------------------------------------------
@variant("p_velocity_arm", P)
def _(f):
    for n, kp, kv, _fr in PANDA_ARM:
        f.sub("panda.xml", f'<position name="{n}" joint="{n}" kp="{kp}" kv="{kv}"', f'<velocity name="{n}" joint="{n}" kv="{kv}"')


@variant("p_intvelocity_arm", P)
def _(f):
    for n, kp, kv, fr in PANDA_ARM:
        m = re.search(rf'<position name="{n}" joint="{n}" [^/]*ctrlrange="([-0-9.]+) ([-0-9.]+)"/>', (f.root / "panda.xml").read_text())
        f.sub("panda.xml", m.group(0), f'<intvelocity name="{n}" joint="{n}" kp="{kp}" kv="{kv}" forcerange="-{fr} {fr}" '
              f'ctrlrange="-2 2" actrange="{m.group(1)} {m.group(2)}"/>')


# ---------------- 7. fluid, wind, gravity -------------------------------------------------
OPT = '<option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"'
CUBE = '<geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1"'


@variant("p_fluid_air", P)
def _(f):
    f.sub("scene.xml", OPT, OPT + ' density="1.2" viscosity="1.8e-5"')
    f.sub("scene.xml", CUBE, CUBE + ' fluidshape="ellipsoid"')


@variant("p_fluid_water", P)
def _(f):
    f.sub("scene.xml", OPT, OPT + ' density="1000" viscosity="1e-3"')
    f.sub("scene.xml", CUBE, CUBE + ' fluidshape="ellipsoid"')


@variant("p_wind30", P)
def _(f):
    f.sub("scene.xml", OPT, OPT + ' density="1.2" viscosity="1.8e-5" wind="0 30 0"')
    f.sub("scene.xml", CUBE, CUBE + ' fluidshape="ellipsoid"')


@variant("p_moon", P)
def _(f):
    f.sub("scene.xml", OPT, OPT + ' gravity="0 0 -1.62"')


@variant("p_tilted_g", P)  # 12 degrees tilt towards +x
def _(f):
    f.sub("scene.xml", OPT, OPT + ' gravity="2.04 0 -9.595"')


@variant("a_moon", A)
def _(f):
    f.sub("scene.xml", OPT, OPT + ' gravity="0 0 -1.62"')


@variant("a_tilted_g", A)
def _(f):
    f.sub("scene.xml", OPT, OPT + ' gravity="0 2.04 -9.595"')


# ---------------- 8. contact overrides ----------------------------------------------------
@variant("p_exclude_leftpad", P)
def _(f):
    f.sub("scene.xml", "  </worldbody>", '  </worldbody>\n  <contact>\n    <exclude body1="left_finger" body2="cube"/>\n  </contact>')


@variant("p_pair_pads", P)  # explicit pairs pads-cube with friction 1.0 (the friction parameter cannot reach them)
def _(f):
    f.sub("scene.xml", "  </worldbody>", '  </worldbody>\n  <contact>\n'
          '    <pair geom1="left_pad" geom2="cube" condim="4" friction="1 1 0.005 0.0001 0.0001"/>\n'
          '    <pair geom1="right_pad" geom2="cube" condim="4" friction="1 1 0.005 0.0001 0.0001"/>\n  </contact>')


@variant("p_pair_pads_lowfric", P)  # the same with friction 0.3 in the pairs
def _(f):
    f.sub("scene.xml", "  </worldbody>", '  </worldbody>\n  <contact>\n'
          '    <pair geom1="left_pad" geom2="cube" condim="4" friction="0.3 0.3 0.005 0.0001 0.0001"/>\n'
          '    <pair geom1="right_pad" geom2="cube" condim="4" friction="0.3 0.3 0.005 0.0001 0.0001"/>\n  </contact>')


@variant("p_override_friction", P)
def _(f):
    f.sub("scene.xml", OPT + "/>", OPT + ' o_friction="0.5 0.5 0.005 0.0001 0.0001">\n    <flag override="enable"/>\n  </option>')


@variant("p_override_solref", P)
def _(f):
    f.sub("scene.xml", OPT + "/>", OPT + ' o_solref="0.02 1" o_friction="1 1 0.005 0.0001 0.0001">\n    <flag override="enable"/>\n  </option>')


@variant("a_override_friction", A)
def _(f):
    f.sub("scene.xml", OPT + "/>", OPT + ' o_friction="0.5 0.5 0.005 0.0001 0.0001">\n    <flag override="enable"/>\n  </option>')


# ---------------- 9. payloads and parameter kinds -----------------------------------------
HAND = '<inertial pos="-0.01 0 0.03" mass="0.73" diaginertia="0.001 0.0025 0.0017"/>'


@variant("p_tool2kg", P)  # a 2 kg tool rigidly on the hand (no collision)
def _(f):
    f.sub("panda.xml", HAND, HAND + '\n                      <body name="tool"><inertial pos="0.08 0 0.02" mass="2" diaginertia="0.004 0.004 0.004"/></body>')


@variant("p_tool_weld", P)  # a 0.5 kg free body welded to the hand by an <equality weld>
def _(f):
    f.sub("scene.xml", "  </worldbody>", '    <body name="tool" pos="0.3 0 0.59">\n      <freejoint name="tool_joint"/>\n'
          '      <inertial pos="0 0 0" mass="0.5" diaginertia="0.001 0.001 0.001"/>\n    </body>\n  </worldbody>\n'
          '  <equality>\n    <weld body1="tool" body2="hand"/>\n  </equality>')
    f.sub("scene.xml", '0.5 -0.15 0.02 1 0 0 0"', '0.5 -0.15 0.02 1 0 0 0 0.3 0 0.59 1 0 0 0"')


@variant("a_tool0.3kg", A)
def _(f):
    f.sub("scene.xml", '<attach model="vx300s" body="base_link" prefix="right/"/>',
          '<attach model="vx300s" body="base_link" prefix="right/"/>')
    f.sub("vx300s.xml", '<site name="tcp"', '<body name="tool"><inertial pos="0.03 0 0" mass="0.3" diaginertia="3e-4 3e-4 3e-4"/></body>\n                  <site name="tcp"')


@variant("p_param_com", P)
def _(f):
    f.append_toml('\n[uncertainty.com]\nkind = "com_offset"\nbody = "cube"\nrange = [-0.015, 0.015]\nnominal = 0.0\nprior = "uniform"\n')


@variant("p_param_gripforce", P)
def _(f):
    f.append_toml('\n[uncertainty.grip]\nkind = "force_limit"\nactuator = "finger_left"\nrange = [2.0, 35.0]\nnominal = 35.0\nprior = "uniform"\n')


@variant("p_param_forcelimit_j2", P)
def _(f):
    f.append_toml('\n[uncertainty.j2]\nkind = "force_limit"\nactuator = "joint2"\nrange = [40.0, 87.0]\nnominal = 87.0\nprior = "uniform"\n')
    drop_limits(f, ["joint2"])


@variant("p_param_forcelimit_j2_jointfrc", P)  # force_limit on an actuator limited only at the joint
def _(f):
    f.sub("panda.xml", '<position name="joint2" joint="joint2" kp="4500" kv="450" forcerange="-87 87"',
          '<position name="joint2" joint="joint2" kp="4500" kv="450"')
    f.sub("panda.xml", J2, J2 + ' actuatorfrcrange="-87 87"')
    f.append_toml('\n[uncertainty.j2]\nkind = "force_limit"\nactuator = "joint2"\nrange = [40.0, 87.0]\nnominal = 87.0\nprior = "uniform"\n')
    drop_limits(f, ["joint2"])


@variant("p_param_forcelimit_gear50", P)  # force_limit on a gear-50 actuator: in actuator units
def _(f):
    gear_arm(f, 50, keep_limits=False)
    f.append_toml('\n[uncertainty.j2]\nkind = "force_limit"\nactuator = "joint2"\nrange = [0.8, 1.74]\nnominal = 1.74\nprior = "uniform"\n')


@variant("base_panda", P)
def _(f):
    pass


@variant("base_aloha", A)
def _(f):
    pass


def build(name):
    base, fn = VARIANTS[name]
    out = V / name
    if out.exists():
        shutil.rmtree(out)
    shutil.copytree(M / base, out, ignore=shutil.ignore_patterns("__pycache__", "__init__.py"))
    fn(Files(out))


if __name__ == "__main__":
    for n in sys.argv[1:] or VARIANTS:
        build(n)
    print("\n".join(sys.argv[1:] or VARIANTS))
