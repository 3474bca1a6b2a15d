"""ALOHA hand-over variants (seed 0) of round 30: wrist rotation / tilt while carrying,
re-timings, a mid-air pause, an overshoot (demos._waypoints patched), and action-space edits
(ACT-like chunks with and without temporal ensembling, correlated noise).
usage: gen_aloha.py OUTDIR"""
import pathlib, sys
import numpy as np
from scipy.spatial.transform import Rotation
import critmoment
assert critmoment.__file__.startswith("/tmp/r30/src"), critmoment.__file__
from critmoment import demos
from chunks import chunked, ensembled, ar_noise

OUT = pathlib.Path(sys.argv[1]); OUT.mkdir(parents=True, exist_ok=True)
orig = demos._waypoints


def save(name, tr, actions=None):
    a = tr.actions if actions is None else actions
    np.savez(OUT / f"{name}.npz", actions=a, fps=tr.fps, start=tr.start, object_pose=tr.object_pose)
    print("wrote", name, a.shape)


def shifted(pts, after, d):
    return [(s + d if s > after else s, *rest) for s, *rest in pts]


def patch(fr, fl):
    def wp(box, opt, sr, sl):
        r, l = orig(box, opt, sr, sl)
        return fr(r, box, opt), fl(l, box, opt)
    demos._waypoints = wp


def gen(name, n_steps=400, **kw):
    tr = demos.scripted_transfer(0, options=demos.DemoOptions(n_steps=n_steps, **kw))
    demos._waypoints = orig
    save(name, tr)
    return tr


nom = gen("A_nominal")
# wrist turned while carrying: at the lifted point (step 195) insert 100 steps: turn (30), hold (40), turn back (30)
def turned(rot, D=100):
    def fr(r, box, opt):
        r = shifted(r, 195, D)
        lifted = [p for p in r if p[0] == 195][0]
        R = lifted[2]
        ins = [(225, lifted[1], R * rot, 0.0), (265, lifted[1], R * rot, 0.0), (295, lifted[1], R, 0.0)]
        out = []
        for p in r:
            out.append(p)
            if p[0] == 195:
                out.extend(ins)
        return out
    return fr, (lambda l, box, opt: shifted(l, 195, D))
patch(*turned(Rotation.from_euler("x", 90, degrees=True))); gen("A_rot90", 500)
patch(*turned(Rotation.from_euler("x", 45, degrees=True))); gen("A_rot45", 500)
patch(*turned(Rotation.from_euler("y", -45, degrees=True))); gen("A_tilt45", 500)
# re-timings
gen("A_fast05", time_scale=0.5)
gen("A_slow2", time_scale=2.0)
# lift + carry + wait (170..260) at half duration: 195->182, 220->195, 260->215; later -45
def carryfast(pts, box, opt):
    m = {195: 182, 220: 195, 260: 215}
    return [(m.get(s, s - 45 if s > 260 else s), *rest) for s, *rest in pts]
def carryfast_l(pts, box, opt):
    m = {220: 175, 260: 215}
    return [(m.get(s, s - 45 if s > 260 else s), *rest) for s, *rest in pts]
patch(carryfast, carryfast_l); gen("A_carryfast", 355)
# 3 s pause mid-air at the lifted point (insert 150 steps after 195)
patch(lambda r, b, o: shifted(r, 195, 150), lambda l, b, o: shifted(l, 195, 150)); gen("A_pause3", 550)
# overshoot: carry 30 % past the meeting point, then back (insert 40 steps after 220)
def over(r, box, opt):
    r = shifted(r, 220, 40)
    lifted = [p for p in r if p[0] == 195][0][1]
    meet = np.asarray(opt.meet, float)
    o = meet + 0.3 * (meet - lifted)
    out = []
    for p in r:
        if p[0] == 260:   # was 220: arrive at the overshoot point at 220, come back by 260
            out.append((220, o, p[2], 0.0))
        out.append(p)
    return out
patch(over, lambda l, b, o: shifted(l, 220, 40)); gen("A_overshoot", 440)
# action-space edits of the nominal
arm = [0, 1, 2, 3, 4, 5, 7, 8, 9, 10, 11, 12]
grip = [6, 13]
save("A_chunk100", nom, chunked(nom.actions, 100, arm, grip, sigma=0.015, shift=3, seed=1))
save("A_chunk50", nom, chunked(nom.actions, 50, arm, grip, sigma=0.03, shift=3, seed=2))
save("A_chunk100_te", nom, ensembled(nom.actions, 100, arm, grip, sigma=0.015, shift=3, seed=1))
save("A_noise_ar", nom, ar_noise(nom.actions, arm, sigma=0.01, rho=0.9, seed=3))
save("A_noise_w20", nom, ar_noise(nom.actions, arm, sigma=0.02, rho=0.0, seed=4))
# joint-space wrist motions while carrying (IK variants above change the arm's branch): insert
# 100 steps at the lifted point (195): 30 up, 40 hold, 30 back
from chunks import insert_bump
save("A_jrot90", nom, insert_bump(nom.actions, 195, 100, 12, np.pi / 2, 30))   # right wrist_rotate
save("A_jtilt45", nom, insert_bump(nom.actions, 195, 100, 11, np.pi / 4, 30))  # right wrist_angle (pitch)
save("A_jtiltm45", nom, insert_bump(nom.actions, 195, 100, 11, -np.pi / 4, 30))
save("A_jroll60", nom, insert_bump(nom.actions, 195, 100, 10, np.pi / 3, 30))  # right forearm_roll
