"""Generate variant folders under v/: each a copy of a bundled scene with edits.
usage: python gen.py   (idempotent: rewrites folders)
The bundled models are read from $R24_MODELS_DIR if set, else from the installed
`critmoment.models` package folder. The *_m15 copies need v/base_aloha (a plain copy of
aloha_transfer_cube) to exist."""
import os
import shutil
from importlib import resources
from pathlib import Path

M = Path(os.environ.get("R24_MODELS_DIR") or str(resources.files("critmoment.models")))
V = Path(__file__).resolve().parent / "v"
CUBE = '<geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1"'
OPT = '<option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>'
PAD = 'friction="1.13 0.005 0.0001" solref="0.01 1"/>'

def mk(name, base, edits=(), toml_edits=(), toml_append="", files=None):
    out = V / name
    if out.exists():
        shutil.rmtree(out)
    shutil.copytree(M / base, out)
    for fname, old, new in edits:
        p = out / fname
        t = p.read_text()
        assert old in t, (name, old)
        p.write_text(t.replace(old, new, 1))
    p = out / "scenario.toml"
    t = p.read_text()
    for old, new in toml_edits:
        assert old in t, (name, old)
        t = t.replace(old, new, 1)
    p.write_text(t + toml_append)
    for fn, content in (files or {}).items():
        (out / fn).write_text(content)

P = "panda_pick_place"
A = "aloha_transfer_cube"
def popt(new): return [("scene.xml", OPT, new)]
def pcube(new): return [("scene.xml", CUBE, new)]
CUBE_TAIL = 'contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001"\n            solref="0.01 1"/>'
def ptail(new): return [("scene.xml", CUBE_TAIL, new)]

# --- contact / solver variants, Panda ---
mk("p_condim1", P, ptail(CUBE_TAIL.replace('condim="4"', 'condim="1"')))
mk("p_condim3", P, ptail(CUBE_TAIL.replace('condim="4"', 'condim="3"')))
mk("p_condim6_roll", P, ptail(CUBE_TAIL.replace('condim="4"', 'condim="6"').replace('1 0.005 0.0001', '1 0.05 0.01')))
mk("p_condim4_torsion", P, ptail(CUBE_TAIL.replace('1 0.005 0.0001', '1 0.05 0.0001')))
mk("p_pads_condim1", P, [("panda.xml", 'condim="4" rgba="0.1 0.1 0.1 1"', 'condim="1" rgba="0.1 0.1 0.1 1"')])
mk("p_soft", P, ptail(CUBE_TAIL.replace('solref="0.01 1"', 'solref="0.02 1" solimp="0.8 0.9 0.01"')))
mk("p_pad_margin_gap", P, [("panda.xml", PAD, 'friction="1.13 0.005 0.0001" solref="0.01 1" margin="0.003" gap="0.001"/>')])
mk("p_noslip5", P, popt(OPT.replace('/>', ' noslip_iterations="5"/>')))
mk("p_PGS", P, popt(OPT.replace('/>', ' solver="PGS"/>')))
mk("p_CG", P, popt(OPT.replace('/>', ' solver="CG"/>')))
mk("p_Euler", P, popt(OPT.replace('implicitfast', 'Euler')))
mk("p_RK4", P, popt(OPT.replace('implicitfast', 'RK4')))
mk("p_implicit", P, popt(OPT.replace('implicitfast', 'implicit')))
mk("p_dt001", P, popt(OPT.replace('0.002', '0.001')))
mk("p_dt004", P, popt(OPT.replace('0.002', '0.004')))
mk("p_multiccd", P, popt(OPT + '\n  <option><flag multiccd="enable"/></option>'))
mk("p_nonativeccd", P, popt(OPT + '\n  <option><flag nativeccd="disable"/></option>'))
mk("p_pyr1", P, popt(OPT.replace('elliptic" impratio="10', 'pyramidal" impratio="1')))
mk("p_pyr10", P, popt(OPT.replace('elliptic', 'pyramidal')))
mk("p_pyr100", P, popt(OPT.replace('elliptic" impratio="10', 'pyramidal" impratio="100')))
mk("p_ell1", P, popt(OPT.replace('impratio="10', 'impratio="1')))
mk("p_ell100", P, popt(OPT.replace('impratio="10', 'impratio="100')))
# --- objects, Panda ---
mk("p_cyl_lying", P, pcube('<geom name="cube" type="cylinder" size="0.02 0.025" euler="1.5708 0 0" mass="0.1"'))
X0, Y0 = 0.51369617, -0.17302133
CB = '<body name="cube" pos="0.5 -0.15 0.02">'
def zpos(z): return [("scene.xml", CB, f'<body name="cube" pos="{X0} {Y0} {z}">')]
mk("p_capsule_up", P, pcube('<geom name="cube" type="capsule" size="0.02 0.01" mass="0.1"') + zpos(0.03))
mk("p_cyl_up", P, pcube('<geom name="cube" type="cylinder" size="0.02 0.02" mass="0.1"'))
mk("p_sphere", P, pcube('<geom name="cube" type="sphere" size="0.02" mass="0.1"'))
MESH = """<asset><mesh name="hexprism" vertex="0.02 0 -0.02  0.01 0.0173 -0.02  -0.01 0.0173 -0.02  -0.02 0 -0.02  -0.01 -0.0173 -0.02  0.01 -0.0173 -0.02  0.02 0 0.02  0.01 0.0173 0.02  -0.01 0.0173 0.02  -0.02 0 0.02  -0.01 -0.0173 0.02  0.01 -0.0173 0.02"/></asset>
  <worldbody>"""
mk("p_mesh", P, [("scene.xml", CUBE, '<geom name="cube" type="mesh" mesh="hexprism" mass="0.1"'), ("scene.xml", "  <worldbody>", MESH)])
mk("p_compound", P, ptail(CUBE_TAIL + '\n      <geom name="cap" type="box" size="0.015 0.015 0.01" pos="0 0 0.03" mass="0.05" contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001"/>\n      <geom name="knob" type="sphere" size="0.01" pos="0 0.03 0" mass="0.05" contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001"/>'))
mk("p_com_offset", P, ptail(CUBE_TAIL + '\n      <inertial pos="0.012 0.0 0.012" mass="0.1" diaginertia="3e-5 3e-5 3e-5"/>'))
mk("p_big_heavy", P, pcube('<geom name="cube" type="box" size="0.03 0.03 0.03" mass="1.5"') + zpos(0.03),
   [("nominal = 0.1", "nominal = 1.5"), ("range = [0.05, 3.0]", "range = [1.0, 3.0]")])
SLOPE = f'<body name="ramp" pos="{X0} {Y0} 0.0"><geom name="ramp" type="box" size="0.05 0.05 0.01" euler="0.1745 0 0" contype="1" conaffinity="1" friction="1 0.005 0.0001"/></body>\n    <body name="cube" pos="{X0} {Y0} 0.04" euler="0.1745 0 0">'
mk("p_slope", P, [("scene.xml", CB, SLOPE)], [('geoms = ["table"]', 'geoms = ["table", "ramp"]')])
STACK = f'<body name="block" pos="{X0} {Y0} 0.01"><geom name="block" type="box" size="0.03 0.03 0.01" contype="1" conaffinity="1" friction="1 0.005 0.0001"/></body>\n    <body name="cube" pos="{X0} {Y0} 0.04">'
mk("p_on_block", P, [("scene.xml", CB, STACK)], [('geoms = ["table"]', 'geoms = ["table", "block"]')])
STACK2 = f'<body name="block" pos="{X0} {Y0} 0.01"><freejoint/><geom name="block" type="box" size="0.03 0.03 0.01" mass="0.3" contype="1" conaffinity="1" friction="1 0.005 0.0001"/></body>\n    <body name="cube" pos="{X0} {Y0} 0.04">'
mk("p_on_freeblock", P, [("scene.xml", CB, STACK2), ("scene.xml", "0.04 0.04\n               0.5 -0.15 0.02 1 0 0 0", f"0.04 0.04\n               {X0} {Y0} 0.01 1 0 0 0 {X0} {Y0} 0.04 1 0 0 0")],
   [('geoms = ["table"]', 'geoms = ["table", "block"]')])

# ---------------- ALOHA contact variants ----------------
AOPT = '<option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>'
ABOX = 'condim="4" priority="1" friction="1 0.005 0.0001"\n            solref="0.01 1"/>'
def aopt(new): return [("scene.xml", AOPT, new)]
def abox(new): return [("scene.xml", ABOX, new)]
mk("a_PGS", A, aopt(AOPT.replace('/>', ' solver="PGS"/>')))
mk("a_dt004", A, aopt(AOPT.replace('0.002', '0.004')))
mk("a_dt001", A, aopt(AOPT.replace('0.002', '0.001')))
mk("a_pyr100", A, aopt(AOPT.replace('elliptic" impratio="10', 'pyramidal" impratio="100')))
mk("a_ell100", A, aopt(AOPT.replace('impratio="10', 'impratio="100')))
mk("a_soft", A, abox(ABOX.replace('solref="0.01 1"', 'solref="0.02 1" solimp="0.8 0.9 0.01"')))
mk("a_condim6_roll", A, abox(ABOX.replace('condim="4"', 'condim="6"').replace('1 0.005 0.0001', '1 0.05 0.01')))
mk("a_condim1", A, abox(ABOX.replace('condim="4"', 'condim="1"')))
mk("a_implicit", A, aopt(AOPT.replace('implicitfast', 'implicit')))
mk("a_multiccd", A, aopt(AOPT + '\n  <option><flag multiccd="enable"/></option>'))
mk("a_PGS_pyr1_noslip", A, aopt(AOPT.replace('elliptic" impratio="10', 'pyramidal" impratio="1" solver="PGS" noslip_iterations="3"')))
mk("a_margin_gap", A, abox(ABOX.replace('solref="0.01 1"', 'solref="0.01 1" margin="0.003" gap="0.002"')))

# ---------------- box variants ----------------
MASS_T = '''[uncertainty.mass]
body = "cube"
range = [0.05, 3.0]      # [kg]; 3 kg is the Panda's quoted payload
nominal = 0.1
prior = "uniform"
'''
FRIC_T = '''[uncertainty.friction]
geom = "cube"
range = [0.2, 1.5]       # sliding friction coefficient of the cube's contacts
nominal = 1.0
prior = "uniform"
'''
def box(mass=None, fric=None, mass_nom=None, fric_nom=None):
    e = []
    e.append((MASS_T, "" if mass is None else MASS_T.replace("[0.05, 3.0]", str(list(mass))).replace("nominal = 0.1", f"nominal = {mass_nom if mass_nom is not None else mass[0]}")))
    e.append((FRIC_T, "" if fric is None else FRIC_T.replace("[0.2, 1.5]", str(list(fric))).replace("nominal = 1.0", f"nominal = {fric_nom if fric_nom is not None else fric[1]}")))
    return e
mk("b_mass_only", P, toml_edits=box(mass=(0.05, 3.0), mass_nom=0.1))
mk("b_fric_only", P, toml_edits=box(fric=(0.05, 1.5), fric_nom=1.0))
mk("b_com_only", P, toml_edits=box(), toml_append='\n[uncertainty.com]\nkind = "com_offset"\nbody = "cube"\nrange = [-0.03, 0.03]\nnominal = 0.0\n')
mk("b_finger_limit", P, toml_edits=box(mass=(0.05, 3.0), mass_nom=0.1), toml_append='\n[uncertainty.grip]\nkind = "force_limit"\nactuator = "finger_left"\nrange = [1.0, 35.0]\nnominal = 35.0\n')
mk("b_pad_friction_refused", P, toml_edits=box(mass=(0.05, 3.0), mass_nom=0.1), toml_append='\n[uncertainty.padf]\nkind = "friction"\ngeom = "left_pad"\nrange = [0.2, 1.5]\nnominal = 1.13\n')
# pad friction that wins: pads priority 3, object priority 0
mk("b_pad_friction_prio", P, [("panda.xml", 'condim="4" rgba="0.1 0.1 0.1 1"', 'condim="4" priority="3" rgba="0.1 0.1 0.1 1"')],
   toml_edits=box(mass=(0.05, 3.0), mass_nom=0.1), toml_append='\n[uncertainty.padf]\nkind = "friction"\ngeom = "left_pad"\nrange = [0.2, 1.5]\nnominal = 1.13\n\n[uncertainty.padf2]\nkind = "friction"\ngeom = "right_pad"\nrange = [0.2, 1.5]\nnominal = 1.13\n')
mk("b_narrow_flip", P, toml_edits=box(mass=(1.6, 2.2), fric=(0.9, 1.1), mass_nom=1.6, fric_nom=1.0))
mk("b_all_safe", P, toml_edits=box(mass=(0.05, 0.5), fric=(0.8, 1.5), mass_nom=0.1, fric_nom=1.0))
mk("b_all_fail", P, toml_edits=box(mass=(2.6, 3.0), fric=(0.2, 0.3), mass_nom=2.6, fric_nom=0.3))
mk("b_loguniform", P, toml_edits=[(MASS_T, MASS_T.replace('"uniform"', '"loguniform"'))])
mk("b_point_box", P, toml_edits=box(mass=(0.1, 0.1), fric=(1.0, 1.0), mass_nom=0.1, fric_nom=1.0))
mk("b_table_friction", P, toml_edits=box(mass=(0.05, 3.0), mass_nom=0.1), toml_append='\n[uncertainty.tablef]\nkind = "friction"\ngeom = "table"\nrange = [0.2, 1.5]\nnominal = 1.0\n')
mk("b_shoulder_limit_narrow", P, toml_edits=box(mass=(0.05, 3.0), mass_nom=0.1), toml_append='\n[uncertainty.j2]\nkind = "force_limit"\nactuator = "joint2"\nrange = [5.0, 87.0]\nnominal = 87.0\n')
mk("b_damping_unsupported", P, toml_append='\n[uncertainty.damp]\nkind = "damping"\nbody = "cube"\nrange = [0.0, 1.0]\nnominal = 0.0\n')

mk("b_pad_friction_left_only", P, [("panda.xml", 'name="left_pad" class="pad"', 'name="left_pad" class="pad" priority="3"')],
   toml_edits=box(mass=(0.05, 3.0), mass_nom=0.1), toml_append='\n[uncertainty.padf]\nkind = "friction"\ngeom = "left_pad"\nrange = [0.2, 1.5]\nnominal = 1.13\n')

mk("a_PGS_pyr1_noslip", A, aopt(AOPT.replace('elliptic" impratio="10"', 'pyramidal" impratio="1" solver="PGS" noslip_iterations="3"')))
for n in ["base_aloha", "a_pyr100", "a_soft", "a_PGS", "a_dt004", "a_margin_gap", "a_PGS_pyr1_noslip", "a_condim6_roll"]:
    dst = V / (n.replace("base_aloha", "a_base") + "_m15")
    if dst.exists():
        shutil.rmtree(dst)
    shutil.copytree(V / n, dst, ignore=shutil.ignore_patterns("report", "*.json", "*.err"))
    p = dst / "scenario.toml"
    t = p.read_text()
    assert "range = [0.05, 10.0]" in t
    p.write_text(t.replace("range = [0.05, 10.0]", "range = [0.05, 1.5]"))

# ---------------- round 2: combined stresses ----------------
mk("p_soft_pyr1", P, ptail(CUBE_TAIL.replace('solref="0.01 1"', 'solref="0.02 1" solimp="0.8 0.9 0.01"')) + popt(OPT.replace('elliptic" impratio="10', 'pyramidal" impratio="1')))
mk("p_verysoft", P, ptail(CUBE_TAIL.replace('solref="0.01 1"', 'solref="0.05 1" solimp="0.4 0.8 0.01"')))
mk("p_dt004_pyr1", P, popt(OPT.replace('0.002', '0.004').replace('elliptic" impratio="10', 'pyramidal" impratio="1')))
mk("p_compound_com", P, ptail(CUBE_TAIL + '\n      <geom name="cap" type="box" size="0.015 0.015 0.01" pos="0 0 0.03" mass="0.05" contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001"/>\n      <geom name="knob" type="sphere" size="0.01" pos="0 0.03 0" mass="0.05" contype="1" conaffinity="1" condim="4" priority="2" friction="1 0.005 0.0001"/>'),
   toml_append='\n[uncertainty.com]\nkind = "com_offset"\nbody = "cube"\nrange = [-0.02, 0.02]\nnominal = 0.0\n')
mk("p_heavy_motor", P, pcube('<geom name="cube" type="box" size="0.03 0.03 0.03" mass="1.5"') + zpos(0.03),
   [("nominal = 0.1", "nominal = 1.5"), ("range = [0.05, 3.0]", "range = [1.0, 8.0]")],
   toml_append='\n[uncertainty.j4]\nkind = "force_limit"\nactuator = "joint4"\nrange = [20.0, 87.0]\nnominal = 87.0\n')

mk("b_fric_sliver", P, toml_edits=box(fric=(0.04, 0.08), fric_nom=0.08))
mk("b_mass_sliver", P, toml_edits=box(mass=(1.35, 1.5), fric=(0.74, 0.76), mass_nom=1.35, fric_nom=0.76))
