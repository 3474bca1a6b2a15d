"""Scenario copies with other uncertainty boxes (com_offset, force_limit), made from built variants.
usage: python boxes.py"""
import shutil
from pathlib import Path

V = Path("/tmp/r29/physics/v")


def cp(src, dst, drop=(), append=""):
    out = V / dst
    if out.exists():
        shutil.rmtree(out)
    shutil.copytree(V / src, out, ignore=shutil.ignore_patterns("*.json", "*.err", "*.log", "report*"))
    p = out / "scenario.toml"
    t = p.read_text()
    for sec in drop:  # remove a whole [uncertainty.X] table
        i = t.index(f"[uncertainty.{sec}]")
        j = t.find("\n[", i + 1)
        t = t[:i] + (t[j + 1:] if j >= 0 else "")
    p.write_text(t + append)


GRIP = '\n[uncertainty.grip]\nkind = "force_limit"\nactuator = "finger_left"\nrange = [4.0, 35.0]\nnominal = 35.0\n'
GRIP2 = '\n[uncertainty.grip2]\nkind = "force_limit"\nactuator = "finger_right"\nrange = [4.0, 35.0]\nnominal = 35.0\n'
COM_A = '\n[uncertainty.com]\nkind = "com_offset"\nbody = "box"\nrange = [-0.015, 0.015]\nnominal = 0.0\n'
COM_P = '\n[uncertainty.com]\nkind = "com_offset"\nbody = "cube"\nrange = [-0.015, 0.015]\nnominal = 0.0\n'
cp("p_fingers", "p_fingers_grip", drop=("friction",), append=GRIP + GRIP2)
cp("p_base", "p_base_grip", drop=("friction",), append=GRIP + GRIP2)
cp("a_soft05", "a_soft05_com", drop=("friction",), append=COM_A)
cp("p_tilt_x", "p_tilt_x_com", drop=("friction",), append=COM_P)
cp("a_fingers", "a_fingers_shoulder", drop=("friction",),
   append='\n[uncertainty.shoulder]\nkind = "force_limit"\nactuator = "right/shoulder"\nrange = [3.0, 20.0]\nnominal = 20.0\n')
print("ok")
