"""ALOHA demo seed 0 policy-like variants on aloha_m15 (bundled scenario, mass 0.05-1.5 kg). usage: gen_aloha.py OUTDIR -> cases_aloha.tsv"""
import pathlib, shutil, sys
import numpy as np
import critmoment
assert critmoment.__file__.startswith("/tmp/r32/src"), critmoment.__file__
from critmoment import demos
OUT = pathlib.Path(sys.argv[1]); rng = np.random.default_rng(320)
src = pathlib.Path(critmoment.__file__).parent.parent / "models" / "aloha_transfer_cube"
d = OUT / "aloha_m15"
if not d.exists():
    shutil.copytree(src, d)
    (d / "scenario.toml").write_text((d / "scenario.toml").read_text().replace("range = [0.05, 10.0]", "range = [0.05, 1.5]"))
ARM = [*range(0, 6), *range(7, 13)]   # aloha14: 6 left joints, left grip(6), 6 right joints, right grip(13)
rows = []
def save(nm, tr, actions=None, fps=None):
    kw = dict(qpos0=tr.qpos0) if tr.qpos0 is not None else {}
    a = tr.actions if actions is None else actions
    np.savez(OUT / f"{nm}.npz", actions=a, fps=fps or tr.fps, start=tr.start, object_pose=tr.object_pose, **kw)
    rows.append(f"{nm}\taloha_m15\n"); print(nm, a.shape, fps or tr.fps)
tr = demos.scripted_transfer(0); A = tr.actions
save("A_nominal", tr)
a = A.copy()
for k in range(0, len(a), 50): a[k:k + 50, ARM] += rng.normal(0, 0.01, len(ARM))
save("A_chunk50_step", tr, a)
a = A.copy()
for k in range(0, len(a), 50):
    dd = rng.normal(0, 0.03, len(ARM)); L = min(50, len(a) - k); a[k:k + L, ARM] += np.outer(np.arange(L) / 50, dd)
save("A_chunk50_saw", tr, a)
a = A.copy(); a[:, ARM] += rng.normal(0, 0.005, (len(a), len(ARM))); a[:, [6, 13]] = np.clip(a[:, [6, 13]] + rng.normal(0, 0.03, (len(a), 2)), 0, 1)
save("A_noise", tr, a)
# where do the grippers move? print the right (picker) and left gripper command changes
g_r, g_l = A[:, 13], A[:, 6]
print("right grip changes at", np.flatnonzero(np.abs(np.diff(g_r)) > 1e-6)[[0, -1]], "left at", np.flatnonzero(np.abs(np.diff(g_l)) > 1e-6)[[0, -1]])
k = 220   # mid-carry (the picker closes 130-170, opens 300-340): pause 1 s
save("A_pause_carry", tr, np.concatenate([A[:k], np.repeat(A[k:k + 1], 50, 0), A[k:]]))
save("A_fast15", demos.scripted_transfer(0, options=demos.DemoOptions(time_scale=0.67)))
save("A_jitter02", demos.scripted_transfer(0, options=demos.DemoOptions(jitter=0.02)))
save("A_carry_open03", demos.scripted_transfer(0, options=demos.DemoOptions(carry_opening=0.3)))
t0 = np.arange(len(A)) / 50.0
for f in (25.0, 100.0):
    n = int(len(A) * f / 50); t1 = np.arange(n) / f
    save(f"A_fps{int(f)}", tr, np.stack([np.interp(t1, t0, A[:, j]) for j in range(A.shape[1])], 1), f)
# receiver closes late: left gripper command delayed by 15 steps (the picker opens on schedule)
a = A.copy(); a[15:, 6] = A[:-15, 6]; a[:15, 6] = A[0, 6]
save("A_late_receiver", tr, a)
(OUT / "cases_aloha.tsv").write_text("".join(rows))
