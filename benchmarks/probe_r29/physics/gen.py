"""Build the variant folders under $R29_V (default /tmp/r29/physics/v): copies of the bundled
models (from $R29_MODELS, default /tmp/r29/src/models) with one or a few edits each.
usage: python gen.py   (builds the missing folders; R29_FORCE=1 rebuilds all, R29_ALL=0 only the second batch)"""
import os
import shutil
from pathlib import Path

M = Path(os.environ.get("R29_MODELS", "/tmp/r29/src/models"))
V = Path(os.environ.get("R29_V", "/tmp/r29/physics/v"))
OPT = '<option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>'
A, P = "aloha_transfer_cube", "panda_pick_place"
ABOX = 'condim="4" priority="1" friction="1 0.005 0.0001"\n            solref="0.01 1"/>'
PCUBE = 'condim="4" priority="2" friction="1 0.005 0.0001"\n            solref="0.01 1"/>'
AGEOM = '<geom name="box" type="box" size="0.02 0.02 0.02" mass="0.05"'
PGEOM = '<geom name="cube" type="box" size="0.02 0.02 0.02" mass="0.1"'
AFING = '<joint type="slide" axis="0 1 0" armature="0.01" damping="1" frictionloss="0.1"/>'
PFING = '<joint type="slide" axis="0 1 0" range="0 0.04" armature="0.1" damping="1"/>'
# ALOHA: the mass <= 1.5 kg box of the earlier rounds
AMASS = ("range = [0.05, 10.0]     # [kg]", "range = [0.05, 1.5]     # [kg]")


def mk(name, base, edits=(), toml_edits=(), toml_append=""):
    out = V / name
    if out.exists():
        if os.environ.get("R29_FORCE") != "1":
            return  # keep an existing folder (and its results); R29_FORCE=1 rebuilds
        shutil.rmtree(out)
    shutil.copytree(M / base, out)
    for fname, old, new in edits:
        p = out / fname
        t = p.read_text()
        assert old in t, (name, old)
        p.write_text(t.replace(old, new, 1))
    p = out / "scenario.toml"
    t = p.read_text()
    for old, new in list(toml_edits) + ([AMASS] if base == A else []):
        assert old in t, (name, old)
        t = t.replace(old, new, 1)
    p.write_text(t + toml_append)


def opt(s, **kw):
    o = OPT
    for k, v in kw.items():
        if f'{k}="' in o:
            import re
            o = re.sub(f'{k}="[^"]*"', f'{k}="{v}"', o)
        else:
            o = o.replace("/>", f' {k}="{v}"/>')
    return [("scene.xml", OPT, o + s)]


def _rep(s, pairs):
    for o, n in zip(pairs[::2], pairs[1::2]):
        s = s.replace(o, n)
    return s


def abox(*pairs):
    return [("scene.xml", ABOX, _rep(ABOX, pairs))]


def pcube(*pairs):
    return [("scene.xml", PCUBE, _rep(PCUBE, pairs))]


FLAG = lambda f: f"\n  <option><flag {f}/></option>"
OVR = lambda mu: f'\n  <option o_friction="{mu} {mu} 0.005 0.0001 0.0001" o_solref="0.01 1"><flag override="enable"/></option>'

if os.environ.get("R29_ALL", "1") == "1":
  for base, pre, box, fing in ((A, "a", abox, AFING), (P, "p", pcube, PFING)):
      g = "scene.xml" if base == A else "scene.xml"
      fingfile = "vx300s.xml" if base == A else "panda.xml"
      mk(f"{pre}_base", base)
      mk(f"{pre}_noslip5", base, opt("", noslip_iterations=5))
      mk(f"{pre}_noslip_pyr1", base, opt("", cone="pyramidal", impratio=1, noslip_iterations=10))
      mk(f"{pre}_CG", base, opt("", solver="CG"))
      mk(f"{pre}_PGS_ell100", base, opt("", solver="PGS", impratio=100))
      mk(f"{pre}_RK4", base, opt("", integrator="RK4"))
      mk(f"{pre}_dt0005", base, opt("", timestep=0.0005))
      mk(f"{pre}_dt005", base, opt("", timestep=0.005))
      mk(f"{pre}_torsion", base, box('condim="4"', 'condim="6"', "1 0.005 0.0001", "1 0.3 0.01"))
      mk(f"{pre}_soft05", base, box('solref="0.01 1"', 'solref="0.05 1"'))
      mk(f"{pre}_solimp_wide", base, box('solref="0.01 1"', 'solref="0.01 1" solimp="0.5 0.95 0.02 0.5 2"'))
      mk(f"{pre}_stiff", base, box('solref="0.01 1"', 'solref="-100000 -500" solimp="0.99 0.999 0.0005"'))
      mk(f"{pre}_margin", base, box('solref="0.01 1"', 'solref="0.01 1" margin="0.004"'))
      mk(f"{pre}_fingers", base, [(fingfile, fing, fing.replace('armature="0.01"' if base == A else 'armature="0.1"', 'armature="0.5"')
                                    .replace('damping="1"', 'damping="20"').replace(' frictionloss="0.1"', '').replace('/>', ' frictionloss="3"/>'))])
      mk(f"{pre}_multiccd_ell100", base, opt(FLAG('multiccd="enable"'), impratio=100))
      mk(f"{pre}_override", base, opt(OVR(0.6)))
      # shapes
      G = AGEOM if base == A else PGEOM
      m0 = G.split('mass="')[1].rstrip('"')
      nm = G.split('name="')[1].split('"')[0]
      mk(f"{pre}_sphere", base, [("scene.xml", G, f'<geom name="{nm}" type="sphere" size="0.02" mass="{m0}"')])
      mk(f"{pre}_cyl_up", base, [("scene.xml", G, f'<geom name="{nm}" type="cylinder" size="0.02 0.02" mass="{m0}"')])
      mk(f"{pre}_capsule_x", base, [("scene.xml", G, f'<geom name="{nm}" type="capsule" size="0.02 0.03" euler="0 1.5708 0" mass="{m0}"')])
      MESH = ('<asset><mesh name="oct" vertex="0.02 0 0  -0.02 0 0  0 0.02 0  0 -0.02 0  0 0 0.02  0 0 -0.02'
              '  0.014 0.014 0.014  -0.014 0.014 0.014  0.014 -0.014 0.014  -0.014 -0.014 0.014'
              '  0.014 0.014 -0.014  -0.014 0.014 -0.014  0.014 -0.014 -0.014  -0.014 -0.014 -0.014"/></asset>\n  <worldbody>')
      mk(f"{pre}_mesh", base, [("scene.xml", G, f'<geom name="{nm}" type="mesh" mesh="oct" mass="{m0}"'),
                               ("scene.xml", "  <worldbody>", MESH)])
print("variants in", V)

# second batch
mk("a_Euler", A, opt("", integrator="Euler"))
mk("p_Euler", P, opt("", integrator="Euler"))
mk("a_dt003", A, opt("", timestep=0.003))
mk("a_refsafe", A, abox('solref="0.01 1"', 'solref="0.001 1"') + opt(FLAG('refsafe="disable"')))
mk("a_gap", A, abox('solref="0.01 1"', 'solref="0.01 1" margin="0.004" gap="0.004"'))
mk("p_gap", P, pcube('solref="0.01 1"', 'solref="0.01 1" margin="0.004" gap="0.004"'))
mk("p_gap2", P, pcube('solref="0.01 1"', 'solref="0.01 1" margin="0.01" gap="0.009"'))

# third batch: under-damped (bouncy) object contacts; pads much softer than the object
mk("a_bouncy", A, abox('solref="0.01 1"', 'solref="0.01 0.1"'))
mk("p_bouncy", P, pcube('solref="0.01 1"', 'solref="0.01 0.1"'))
mk("p_dampratio_neg", P, pcube('solref="0.01 1"', 'solref="-20000 -5"'))
