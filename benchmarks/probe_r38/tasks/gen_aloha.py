"""ALOHA copies (box mass 0.05-1.5 kg) with one or two contact edits. usage: gen_aloha.py OUTDIR"""
import pathlib, shutil, sys, re
import critmoment
assert critmoment.__file__.startswith("/tmp/r38/tasks/src"), critmoment.__file__
OUT = pathlib.Path(sys.argv[1]); SRC = pathlib.Path(critmoment.__file__).parent.parent / "models/aloha_transfer_cube"
BOXA = 'contype="1" conaffinity="1" condim="4" priority="1" friction="1 0.005 0.0001"\n            solref="0.01 1"'
OPT = '<option timestep="0.002" integrator="implicitfast" cone="elliptic" impratio="10"/>'
cases = []
def var(name, box=None, opt=None):
    d = OUT / name; shutil.copytree(SRC, d, dirs_exist_ok=True)
    x = (d / "scene.xml").read_text(); assert BOXA in x and OPT in x
    if box: x = x.replace(BOXA, box)
    if opt: x = x.replace(OPT, opt)
    (d / "scene.xml").write_text(x)
    t = (d / "scenario.toml").read_text().replace("range = [0.05, 10.0]     # [kg]", "range = [0.05, 1.5]")
    (d / "scenario.toml").write_text(t); cases.append((f"A_{name}", name))
var("a_base")
var("a_negsolref", box=BOXA.replace('solref="0.01 1"', 'solref="-20000 -200"'))
var("a_c6roll", box=BOXA.replace('condim="4"', 'condim="6"').replace("1 0.005 0.0001", "1 0.05 0.01"))
var("a_jacsparse_noslip", opt=OPT.replace('/>', ' jacobian="sparse" noslip_iterations="5"/>'))
var("a_margin_gap", box=BOXA + ' margin="0.003" gap="0.003"')
(OUT / "cases_aloha.tsv").write_text("".join(f"{c}\t{s}\n" for c, s in cases))
