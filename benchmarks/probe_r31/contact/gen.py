"""Variant folders under /tmp/r31/contact/v: copies of the bundled models (/tmp/r31/src/models),
one edit each (r31 contact probe; adapted from probe_r29/physics/gen.py).
usage: python gen.py   (builds the missing folders; FORCE=1 rebuilds)"""
import os, re, shutil
from pathlib import Path

M = Path("/tmp/r31/src/models")
V = Path("/tmp/r31/contact/v")
OPT = '<option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>'
A, P = "aloha_transfer_cube", "panda_pick_place"
ABOX = 'condim="4" priority="1" friction="1 0.005 0.0001"\n            solref="0.01 1"/>'
PCUBE = 'condim="4" priority="2" friction="1 0.005 0.0001"\n            solref="0.01 1"/>'
APAD = ('<geom type="box" contype="1" conaffinity="1" rgba="0.85 0.85 0.85 1" condim="4"\n'
        '              solref="0.01 1" friction="1 0.005 0.0001"/>')
PPAD = ('<geom type="box" contype="1" conaffinity="1" condim="4" rgba="0.1 0.1 0.1 1"\n'
        '                friction="1.13 0.005 0.0001" solref="0.01 1"/>')
AMASS = ("range = [0.05, 10.0]     # [kg]", "range = [0.05, 1.5]     # [kg]")


def mk(name, base, edits=(), toml_edits=(), toml_append=""):
    out = V / name
    if out.exists():
        if os.environ.get("FORCE") != "1":
            return
        shutil.rmtree(out)
    shutil.copytree(M / base, out)
    for fname, old, new in edits:
        p = out / fname
        t = p.read_text()
        assert old in t, (name, old)
        p.write_text(t.replace(old, new, 1))
    p = out / "scenario.toml"
    t = p.read_text()
    for old, new in ([AMASS] if base == A else []) + list(toml_edits):
        assert old in t, (name, old)
        t = t.replace(old, new, 1)
    p.write_text(t + toml_append)


def opt(s="", **kw):
    o = OPT
    for k, v in kw.items():
        if f'{k}="' in o:
            o = re.sub(f'{k}="[^"]*"', f'{k}="{v}"', o)
        else:
            o = o.replace("/>", f' {k}="{v}"/>')
    return [("scene.xml", OPT, o + s)]


def _rep(s, pairs):
    for o, n in zip(pairs[::2], pairs[1::2]):
        assert o in s, o
        s = s.replace(o, n)
    return s


FLAG = lambda f: f"\n  <option><flag {f}/></option>"

for base, pre, BOX, PAD, padfile in ((A, "a", ABOX, APAD, "vx300s.xml"), (P, "p", PCUBE, PPAD, "panda.xml")):
    box = lambda *pairs: [("scene.xml", BOX, _rep(BOX, pairs))]
    pad = lambda *pairs: [(padfile, PAD, _rep(PAD, pairs))]
    mk(f"{pre}_base", base)
    # integrators
    mk(f"{pre}_Euler", base, opt(integrator="Euler"))
    mk(f"{pre}_implicit", base, opt(integrator="implicit"))
    mk(f"{pre}_RK4", base, opt(integrator="RK4"))
    # timesteps
    mk(f"{pre}_dt001", base, opt(timestep=0.001))
    mk(f"{pre}_dt004", base, opt(timestep=0.004))
    # solvers
    mk(f"{pre}_CG", base, opt(solver="CG"))
    mk(f"{pre}_PGS", base, opt(solver="PGS"))
    mk(f"{pre}_it3", base, opt(iterations=3))
    mk(f"{pre}_tol1e-2", base, opt(tolerance=0.01, ls_iterations=3))
    mk(f"{pre}_noslip5", base, opt(noslip_iterations=5))
    mk(f"{pre}_noslip20", base, opt(noslip_iterations=20))
    # cones
    mk(f"{pre}_ell1", base, opt(impratio=1))
    mk(f"{pre}_ell100", base, opt(impratio=100))
    mk(f"{pre}_pyr", base, opt(cone="pyramidal"))
    mk(f"{pre}_pyr1", base, opt(cone="pyramidal", impratio=1))
    # condim on object and pads
    mk(f"{pre}_obj_c6", base, box('condim="4"', 'condim="6"', "1 0.005 0.0001", "1 0.05 0.001"))
    mk(f"{pre}_obj_c3", base, box('condim="4"', 'condim="3"'))
    mk(f"{pre}_pad_c6", base, pad('condim="4"', 'condim="6"', "0.005 0.0001", "0.05 0.001"))
    # soft contacts
    mk(f"{pre}_pad_soft", base, pad('solref="0.01 1"', 'solref="0.05 1" solimp="0.5 0.9 0.005"'))
    mk(f"{pre}_obj_soft", base, box('solref="0.01 1"', 'solref="0.04 1" solimp="0.5 0.9 0.005"'))
    # margin / gap on pads
    mk(f"{pre}_pad_margin", base, pad('solref="0.01 1"', 'solref="0.01 1" margin="0.003"'))
    mk(f"{pre}_pad_gap", base, pad('solref="0.01 1"', 'solref="0.01 1" margin="0.005" gap="0.004"'))
    # ccd flags
    mk(f"{pre}_multiccd", base, opt(FLAG('multiccd="enable"')))
    mk(f"{pre}_nonativeccd", base, opt(FLAG('nativeccd="disable"')))
print("variants in", V)

# --- boxes: heavier inertia + com_offset as a second dimension; gripper force_limit ---
AFRIC = '''[uncertainty.friction]
geom = "box"
range = [0.2, 1.5]       # sliding friction coefficient of the cube's contacts
nominal = 1.0
prior = "uniform"'''
PFRIC = AFRIC.replace('geom = "box"', 'geom = "cube"')
COM = lambda b: f'''[uncertainty.com]
kind = "com_offset"
body = "{b}"
range = [-0.015, 0.015]
nominal = 0.0'''
AINERT = ('<freejoint name="box_joint"/>', '<freejoint name="box_joint"/>\n      <inertial pos="0 0 0" mass="0.05" diaginertia="1e-4 1e-4 1e-4"/>')
mk("a_inert_com", A, [("scene.xml",) + AINERT], [(AFRIC, COM("box"))])
mk("a_com", A, [], [(AFRIC, COM("box"))])
PINERT = ('<body name="cube" pos="0.5 -0.15 0.02">', '<body name="cube" pos="0.5 -0.15 0.02">\n      <inertial pos="0 0 0" mass="0.1" diaginertia="2e-4 2e-4 2e-4"/>')
mk("p_inert_com", P, [("scene.xml",) + PINERT], [(PFRIC, COM("cube"))])
mk("p_com", P, [], [(PFRIC, COM("cube"))])
GRIP = '''[uncertainty.grip_l]
kind = "force_limit"
actuator = "right/left_finger"
range = [1.0, 5.0]
nominal = 5.0

[uncertainty.grip_r]
kind = "force_limit"
actuator = "right/right_finger"
range = [1.0, 5.0]
nominal = 5.0'''
mk("a_grip", A, [], [(AFRIC, GRIP)])
# one finger only (asymmetric squeeze)
mk("a_grip1", A, [], [(AFRIC, GRIP.split("\n\n")[0])])

# --- divergence candidates ---
mk("a_dt01", A, opt(timestep=0.01))
mk("p_dt01", P, opt(timestep=0.01))
mk("p_dt02", P, opt(timestep=0.02))
mk("p_RK4_dt01", P, opt(integrator="RK4", timestep=0.01))
mk("p_Euler_dt01", P, opt(integrator="Euler", timestep=0.01))
mk("a_Euler_dt01", A, opt(integrator="Euler", timestep=0.01))
mk("a_RK4_dt02", A, opt(integrator="RK4", timestep=0.02))
# narrower mass range for the grip boxes (0.05-1.5 kg with 1-5 N fingers: 31 of 32 fail)
for nm in ("a_grip", "a_grip1"):
    mk(nm + "_n", A, [], [(AFRIC, GRIP if nm == "a_grip" else GRIP.split("\n\n")[0]),
                          ("range = [0.05, 1.5]     # [kg]", "range = [0.05, 0.4]     # [kg]")])
mk("a_grip1_nn", A, [], [(AFRIC, GRIP.split("\n\n")[0].replace("range = [1.0, 5.0]", "range = [4.5, 5.0]")),
                         ("range = [0.05, 1.5]     # [kg]", "range = [0.05, 0.4]     # [kg]")])
mk("p_tol1e-2only", P, opt(tolerance=0.01))
mk("p_ls3", P, opt(ls_iterations=3))
mk("p_ls1", P, opt(ls_iterations=1))
# a model that blows up: very stiff object contacts with refsafe off, explicit damping
mk("p_blowup", P, [("scene.xml", PCUBE, _rep(PCUBE, ('solref="0.01 1"', 'solref="0.0002 0.05"')))] + opt(FLAG('refsafe="disable"'), integrator="Euler", timestep=0.004))
mk("a_blowup", A, [("scene.xml", ABOX, _rep(ABOX, ('solref="0.01 1"', 'solref="0.0002 0.05"')))] + opt(FLAG('refsafe="disable"'), integrator="Euler", timestep=0.004))
