"""Builds every case of this probe under /tmp/r26/truth (scenario copies and trajectories).

    . /tmp/r26/venv/bin/activate && python make_cases.py

Cases (scenario folder, trajectory):
  aloha15            bundled ALOHA, [uncertainty.mass] range = [0.05, 1.5]    aloha_s0.npz, aloha_s7.npz
  panda_pick_place   bundled Panda (by name)                                    panda_s0.npz
  panda_gear20       Panda, every servo gear 20, kp/400, kv/400, forcerange/20,
                     ctrlrange*20, channel scales*20, [limits]/20                panda_s0.npz
  panda_offset       Panda arm servos as <general> with biasprm0 = 0.3*kp (target
                     = ctrl + 0.3 rad), ctrlrange shifted, channel offsets -0.3  panda_s0.npz
  panda_offset_gear20  both at once (gear 20 and the 0.3 rad offset), started from
                     the trajectory's `start` (qpos0 removed)                   panda_s0_noq.npz
  panda_hold         Panda, [task] kind = "pick_hold"                           panda_hold.npz
                     (panda_s0's first 310 rows, cube over the goal at 0.14 m,
                     then the last row held 1 s)
  aloha15_pyr        aloha15 with cone="pyramidal" impratio="1" (tests/scenarios.py soft_copy edit)
  panda_pyr          bundled Panda with cone="pyramidal" impratio="1"
"""
import os
import re
import shutil
import subprocess

import numpy as np

OUT = os.environ.get("TRUTH_OUT", "/tmp/r26/truth")
SRC = "/tmp/r26/src/models"


def demo(args, out):
    if not os.path.exists(out):
        subprocess.run(["critmoment", "demo", *args, "--out", out], check=True)


def copy(name, src):
    dst = f"{OUT}/{name}"
    if os.path.exists(dst):
        shutil.rmtree(dst)
    shutil.copytree(src, dst)
    return dst


def geared_offset(name, g, c):
    """Panda copy: arm servos geared g:1 (kp/g², kv/g², forcerange/g) with a target offset c
    [rad] (<general>, biasprm0 = kp·g·c); fingers geared too when g != 1 and c == 0."""
    dst = copy(name, f"{SRC}/panda_pick_place")
    x = open(f"{dst}/panda.xml").read()

    def rep(mt):
        s = mt.group(0)
        nm = re.search(r'name="([^"]+)"', s).group(1)
        kp = float(re.search(r'kp="([^"]+)"', s).group(1)) / g / g
        kv = float(re.search(r'kv="([^"]+)"', s).group(1)) / g / g
        fr = [float(v) / g for v in re.search(r'forcerange="([^"]+)"', s).group(1).split()]
        cr = [float(v) for v in re.search(r'ctrlrange="([^"]+)"', s).group(1).split()]
        if c == 0:
            s = re.sub(r'kp="[^"]+"', f'kp="{kp!r}"', s)
            s = re.sub(r'kv="[^"]+"', f'kv="{kv!r}"', s)
            s = re.sub(r'forcerange="[^"]+"', f'forcerange="{fr[0]!r} {fr[1]!r}"', s)
            s = re.sub(r'ctrlrange="[^"]+"', f'ctrlrange="{cr[0] * g!r} {cr[1] * g!r}"', s)
            return s.replace("<position ", f'<position gear="{g}" ')
        if not nm.startswith("joint"):
            return s
        joint = re.search(r'joint="([^"]+)"', s).group(1)
        return (f'<general name="{nm}" joint="{joint}" gear="{g}" gaintype="fixed" biastype="affine" '
                f'gainprm="{kp!r}" biasprm="{kp * g * c!r} {-kp!r} {-kv!r}" forcelimited="true" '
                f'forcerange="{fr[0]!r} {fr[1]!r}" ctrllimited="true" '
                f'ctrlrange="{g * (cr[0] - c)!r} {g * (cr[1] - c)!r}"/>')

    x = re.sub(r"<position [^>]*/>", rep, x)
    open(f"{dst}/panda.xml", "w").write(x)
    t = open(f"{dst}/scenario.toml").read()
    for j in range(1, 8):
        extra = f"scales = [{float(g)}]\n" + (f"offsets = [{-g * c!r}]\n" if c else "")
        t = t.replace(f'actuators = ["joint{j}"]\n', f'actuators = ["joint{j}"]\n{extra}')
    if c == 0:
        t = t.replace("scales = [0.04, 0.04]", f"scales = [{0.04 * g!r}, {0.04 * g!r}]")
    if g != 1:
        head, rest = t.split("[limits]")
        body, tail = rest.split("# The uncertainty box")
        pat = r"(\w+) = ([0-9.]+)" if c == 0 else r"(joint\d) = ([0-9.]+)"
        body = re.sub(pat, lambda mt: f"{mt.group(1)} = {float(mt.group(2)) / g!r}", body)
        t = head + "[limits]" + body + "# The uncertainty box" + tail
    open(f"{dst}/scenario.toml", "w").write(t)


def pyramidal(name, src):
    dst = copy(name, src)
    x = open(f"{dst}/scene.xml").read()
    assert 'cone="elliptic" impratio="10"' in x
    open(f"{dst}/scene.xml", "w").write(x.replace('cone="elliptic" impratio="10"',
                                                  'cone="pyramidal" impratio="1"'))


def main():
    os.makedirs(OUT, exist_ok=True)
    os.chdir(OUT)
    demo(["--seed", "0"], "aloha_s0.npz")
    demo(["--seed", "7"], "aloha_s7.npz")
    demo(["--seed", "0", "--scenario", "panda_pick_place"], "panda_s0.npz")
    d = dict(np.load("panda_s0.npz", allow_pickle=True))
    d.pop("qpos0")
    np.savez("panda_s0_noq.npz", **d)
    d = dict(np.load("panda_s0.npz", allow_pickle=True))
    a = d["actions"]
    d["actions"] = np.concatenate([a[:310], np.repeat(a[309:310], 50, axis=0)])
    np.savez("panda_hold.npz", **d)

    dst = copy("aloha15", f"{SRC}/aloha_transfer_cube")
    t = open(f"{dst}/scenario.toml").read()
    open(f"{dst}/scenario.toml", "w").write(t.replace("range = [0.05, 10.0]", "range = [0.05, 1.5]"))
    geared_offset("panda_gear20", 20, 0.0)
    geared_offset("panda_offset", 1, 0.3)
    geared_offset("panda_offset_gear20", 20, 0.3)
    dst = copy("panda_hold", f"{SRC}/panda_pick_place")
    t = open(f"{dst}/scenario.toml").read()
    t = re.sub(r"\[task\].*?\n\n", '[task]\nkind = "pick_hold"\ngripper = "hand"\nlift_height = 0.02\n\n',
               t, flags=re.S)
    open(f"{dst}/scenario.toml", "w").write(t)
    pyramidal("aloha15_pyr", f"{OUT}/aloha15")
    pyramidal("panda_pyr", f"{SRC}/panda_pick_place")


if __name__ == "__main__":
    main()
