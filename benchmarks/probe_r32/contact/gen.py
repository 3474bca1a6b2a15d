"""Variant folders under /tmp/r32/contact/v: copies of the bundled models (/tmp/r32/src/models)
with COMBINATIONS of contact/solver edits not tried in r31 (r32 contact probe; adapted from
probe_r31/contact/gen.py).  usage: python gen.py   (FORCE=1 rebuilds)"""
import os, re, shutil
from pathlib import Path
import numpy as np

M = Path("/tmp/r32/src/models")
V = Path("/tmp/r32/contact/v")
R = Path("/tmp/r32/contact")
OPT = '<option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>'
A, P = "aloha_transfer_cube", "panda_pick_place"
ABOX = 'condim="4" priority="1" friction="1 0.005 0.0001"\n            solref="0.01 1"/>'
PCUBE = 'condim="4" priority="2" friction="1 0.005 0.0001"\n            solref="0.01 1"/>'
APAD = ('<geom type="box" contype="1" conaffinity="1" rgba="0.85 0.85 0.85 1" condim="4"\n'
        '              solref="0.01 1" friction="1 0.005 0.0001"/>')
PPAD = ('<geom type="box" contype="1" conaffinity="1" condim="4" rgba="0.1 0.1 0.1 1"\n'
        '                friction="1.13 0.005 0.0001" solref="0.01 1"/>')
AMASS = ("range = [0.05, 10.0]     # [kg]", "range = [0.05, 1.5]     # [kg]")
ENDW = "</worldbody>"


def retime(src, dst, fps):
    """resample a 50 fps demo trajectory to `fps` (linear interpolation of the actions)."""
    z = dict(np.load(src, allow_pickle=True))
    a = z["actions"]; f0 = float(z.get("fps", 50.0))
    t0 = np.arange(len(a)) / f0
    t1 = np.arange(int(round(t0[-1] * fps)) + 1) / fps
    z["actions"] = np.stack([np.interp(t1, t0, a[:, j]) for j in range(a.shape[1])], 1)
    z["fps"] = np.array(float(fps))
    z.pop("time", None)
    np.savez(dst, **z)


def mk(name, base, edits=(), toml_edits=(), toml_append="", traj_fps=None):
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
    if traj_fps:
        retime(R / ("aloha_s0.npz" if base == A else "panda_s0.npz"), out / "traj.npz", traj_fps)


def opt(s="", **kw):
    o = OPT
    for k, v in kw.items():
        if f'{k}="' in o:
            o = re.sub(f'{k}="[^"]*"', f'{k}="{v}"', o)
        else:
            o = o.replace("/>", f' {k}="{v}"/>')
    if s:
        o = o.replace("/>", ">" + s + "</option>")
    return [("scene.xml", OPT, o)]


def _rep(s, pairs):
    for o, n in zip(pairs[::2], pairs[1::2]):
        assert o in s, o
        s = s.replace(o, n)
    return s


FLAG = lambda *f: "<flag " + " ".join(f) + "/>"

for base, pre, BOX, PAD, padfile, obj, pads in (
        (A, "a", ABOX, APAD, "vx300s.xml", "box", ["left/left_pad", "left/right_pad", "right/left_pad", "right/right_pad"]),
        (P, "p", PCUBE, PPAD, "panda.xml", "cube", ["left_pad", "right_pad"])):
    box = lambda *pairs: [("scene.xml", BOX, _rep(BOX, pairs))]
    pad = lambda *pairs: [(padfile, PAD, _rep(PAD, pairs))]
    def contact(xml):
        return [("scene.xml", ENDW, ENDW + "\n  <contact>\n" + xml + "\n  </contact>")]
    mk(f"{pre}_base", base)
    # integrator x timestep (trajectory at its 50 fps; 0.5/1/2/5 ms are 40/20/10/4 steps per frame)
    for integ in ("Euler", "implicit", "implicitfast", "RK4"):
        for dt, tag in ((0.0005, "05"), (0.001, "1"), (0.002, "2"), (0.005, "5")):
            if integ == "implicitfast" and dt == 0.002:
                continue
            mk(f"{pre}_{integ}_dt{tag}", base, opt(integrator=integ, timestep=dt))
    # re-timed trajectories: control rate = physics rate / 2 and = physics rate
    mk(f"{pre}_dt5_f100", base, opt(timestep=0.005), traj_fps=100)
    mk(f"{pre}_dt5_f200", base, opt(timestep=0.005), traj_fps=200)
    mk(f"{pre}_dt1_f250", base, opt(timestep=0.001), traj_fps=250)
    mk(f"{pre}_Euler_dt5_f200", base, opt(integrator="Euler", timestep=0.005), traj_fps=200)
    # condim with torsional / rolling friction
    mk(f"{pre}_obj_c1", base, box('condim="4"', 'condim="1"'))
    mk(f"{pre}_obj_c4_tors", base, box("1 0.005 0.0001", "1 0.1 0.0001"))
    mk(f"{pre}_obj_c6_roll", base, box('condim="4"', 'condim="6"', "1 0.005 0.0001", "1 0.05 0.05"))
    mk(f"{pre}_obj_c6_pyr_noslip", base, box('condim="4"', 'condim="6"', "1 0.005 0.0001", "1 0.05 0.001")
       + opt(cone="pyramidal", noslip_iterations=10))
    # priority and friction mixing between pads and object
    noprio = 'priority="1"' if base == A else 'priority="2"'
    mk(f"{pre}_noprio_padlo", base, box(noprio, 'priority="0"') + pad('friction="1' + ('.13 ' if base == P else ' '), 'friction="0.3 '))
    mk(f"{pre}_noprio_padhi", base, box(noprio, 'priority="0"') + pad('friction="1' + ('.13 ' if base == P else ' '), 'friction="2.0 '))
    mk(f"{pre}_padprio", base, pad('condim="4"', 'condim="4" priority="5"'))
    mk(f"{pre}_noprio_solmix", base, box(noprio, 'priority="0" solmix="10"')
       + pad('solref="0.01 1"', 'solref="0.05 1" solimp="0.5 0.9 0.005" solmix="0.1"'))
    mk(f"{pre}_noprio_c1pad", base, box(noprio, 'priority="0"') + pad('condim="4"', 'condim="1"'))
    # explicit <pair> overrides object-pad
    pr = "\n".join(f'    <pair geom1="{obj}" geom2="{g}" condim="4" friction="0.6 0.6 0.005 0.0001 0.0001" solref="0.01 1"/>' for g in pads)
    mk(f"{pre}_pair06", base, contact(pr))
    pr = "\n".join(f'    <pair geom1="{obj}" geom2="{g}" condim="{1 if k == 0 else 4}" friction="1 1 0.005 0.0001 0.0001"/>' for k, g in enumerate(pads))
    mk(f"{pre}_pair_c1one", base, contact(pr))
    pr = "\n".join(f'    <pair geom1="{obj}" geom2="{g}" condim="4" friction="1.5 0.5 0.005 0.0001 0.0001"/>' for g in pads)
    mk(f"{pre}_pair_aniso", base, contact(pr))
    pr = "\n".join(f'    <pair geom1="{obj}" geom2="{g}" condim="4" friction="1 1 0.005 0.0001 0.0001" solref="0.04 1" solimp="0.5 0.9 0.005" margin="0.002" gap="0.002"/>' for g in pads)
    mk(f"{pre}_pair_soft_mg", base, contact(pr))
    # margin / gap
    mk(f"{pre}_pad_mg2", base, pad('solref="0.01 1"', 'solref="0.01 1" margin="0.002" gap="0.002"'))
    mk(f"{pre}_obj_margin1", base, box('solref="0.01 1"', 'solref="0.01 1" margin="0.001"'))
    # soft + elliptic + noslip
    mk(f"{pre}_soft_noslip10", base, box('solref="0.01 1"', 'solref="0.04 1" solimp="0.5 0.9 0.005"') + opt(noslip_iterations=10))
    mk(f"{pre}_soft_ell1_noslip10", base, box('solref="0.01 1"', 'solref="0.04 1" solimp="0.5 0.9 0.005"') + opt(noslip_iterations=10, impratio=1))
    mk(f"{pre}_ell100_noslip10", base, opt(noslip_iterations=10, impratio=100))
    mk(f"{pre}_pyr1_noslip10", base, opt(cone="pyramidal", impratio=1, noslip_iterations=10))
    # contact override flag (o_solref/o_solimp/o_friction)
    mk(f"{pre}_override_soft", base, opt(FLAG('override="enable"'), o_solref="0.04 1", o_solimp="0.5 0.9 0.005 0.5 2"))
    mk(f"{pre}_override_fric", base, opt(FLAG('override="enable"'), o_friction="0.6 0.6 0.005 0.0001 0.0001"))
    mk(f"{pre}_override_margin", base, opt(FLAG('override="enable"'), o_margin="0.003"))
    # disabled flags
    mk(f"{pre}_nowarm", base, opt(FLAG('warmstart="disable"')))
    mk(f"{pre}_nofilter", base, opt(FLAG('filterparent="disable"')))
    mk(f"{pre}_nofrloss", base, opt(FLAG('frictionloss="disable"')))
    mk(f"{pre}_nowarm_PGS_it20", base, opt(FLAG('warmstart="disable"'), solver="PGS", iterations=20))
    # solvers x iterations, ls_iterations
    for s in ("CG", "Newton", "PGS"):
        mk(f"{pre}_{s}_it5", base, opt(solver=s, iterations=5))
        mk(f"{pre}_{s}_it1000", base, opt(solver=s, iterations=1000, tolerance="1e-12"))
    mk(f"{pre}_ls1", base, opt(ls_iterations=1))
    mk(f"{pre}_ls50_tol1e-12", base, opt(ls_iterations=50, tolerance="1e-12"))
    mk(f"{pre}_CG_ls2", base, opt(solver="CG", ls_iterations=2))
    # mesh-convex object (same cube as a mesh)
    verts = " ".join(f"{x} {y} {z}" for x in (-.02, .02) for y in (-.02, .02) for z in (-.02, .02))
    meshasset = f'<asset><mesh name="cubemesh" vertex="{verts}"/></asset>\n  <worldbody>'
    mk(f"{pre}_obj_mesh", base, box() + [("scene.xml", f'<geom name="{obj}" type="box" size="0.02 0.02 0.02"',
                                          f'<geom name="{obj}" type="mesh" mesh="cubemesh"'),
                                         ("scene.xml", "<worldbody>", meshasset)])
print("variants in", V, len(list(V.iterdir())))
