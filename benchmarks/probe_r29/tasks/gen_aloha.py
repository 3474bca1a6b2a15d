"""ALOHA hand-over variants (seed 0): demos.scripted_transfer with patched waypoint timing.
usage: gen_aloha.py OUTDIR"""
import pathlib, sys
import numpy as np
from critmoment import demos
from critmoment.trajectory import save_trajectory

OUT = pathlib.Path(sys.argv[1]); OUT.mkdir(parents=True, exist_ok=True)
orig = demos._waypoints


def variant(right_fn, left_fn):
    def wp(box, opt, sr, sl):
        r, l = orig(box, opt, sr, sl)
        return right_fn(r), left_fn(l)
    return wp


def save(name, tr):
    np.savez(OUT / f"{name}.npz", actions=tr.actions, fps=tr.fps, start=tr.start, object_pose=tr.object_pose)
    print("wrote", name, tr.actions.shape)


def shift(pts, mapping):
    """mapping: old step -> new step (others unchanged)"""
    return [(mapping.get(s, s), *rest) for s, *rest in pts]


save("A_nominal", demos.scripted_transfer(0))
# 1. both hold longer: receiver closed by 300, picker opens at 400 (not 340); everything later +60
late_r = lambda r: shift(r, {340: 400, 370: 430, 400: 460})
late_l = lambda l: shift(l, {340: 400, 370: 430, 400: 460})
demos._waypoints = variant(late_r, late_l)
save("A_both_long", demos.scripted_transfer(0, options=demos.DemoOptions(n_steps=460)))
# 2. receiver closes late: it arrives at 260 but closes 340->370; picker opens 370->400
rc_r = lambda r: shift(r, {340: 400, 370: 430, 400: 460})
rc_l = lambda l: [p for p in shift(l, {300: 370, 340: 400, 370: 430, 400: 460})]
demos._waypoints = variant(rc_r, rc_l)
# receiver stays open until 340 then closes by 370: insert an open waypoint at 340
def rc_l2(l):
    l = rc_l(l)
    out = []
    for p in l:
        if p[0] == 370:
            out.append((340, p[1], p[2], 1.0))
        out.append(p)
    return out
demos._waypoints = variant(rc_r, rc_l2)
save("A_recv_late", demos.scripted_transfer(0, options=demos.DemoOptions(n_steps=460)))
# 3. picker lets go early: picker opens 260->280 while the receiver is still open; receiver closes 280->320
def early_r(r):
    out = []
    for s, pos, rot, g in r:
        if s == 300: g = 1.0          # fully open by 300 (open from 260)
        if s == 340: g = 1.0
        out.append((s, pos, rot, g))
    return out
def early_l(l):
    return [(320, p[1], p[2], p[3]) if p[0] == 300 else p for p in l]
demos._waypoints = variant(early_r, early_l)
save("A_drop_into", demos.scripted_transfer(0))
# 3b picker lets go mid-close of the receiver (half-closed): picker open 290->310
def early_r2(r):
    out = []
    for s, pos, rot, g in r:
        if s == 300:
            out.append((290, pos, rot, 0.0)); out.append((310, pos, rot, 1.0)); continue
        if s == 340: g = 1.0
        out.append((s, pos, rot, g))
    return out
demos._waypoints = variant(early_r2, lambda l: l)
save("A_release_midclose", demos.scripted_transfer(0))
demos._waypoints = orig
# 4. hand-over lower / higher
save("A_meet_low", demos.scripted_transfer(0, options=demos.DemoOptions(meet=(0.0, 0.5, 0.15))))
