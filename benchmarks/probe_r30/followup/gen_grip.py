"""gen_grip.py OUTDIR: Panda nominal (r30 tasks P_nominal.npz) with gripper commands that end their closing late
(within 1 s of the first touch) while the lift has begun. Touch ~ action 154, lift starts ~ action 180 (50 fps).
 P_creep:     closed at 0.05 at action 166, then creeping linearly to 0 at action 200 (a policy that keeps tightening)
 P_dip:       closed at 0.02, one action at 0.0 at action 200 (a single low jitter sample)
 P_slowclose: the 1->0 closing ramp stretched over actions 141..200 (lift starts at 180 while still closing)
 P_jitter:    closed value 0.03 + uniform(-0.03, 0.03) i.i.d. per action after 166 (clipped at 0)
 P_reopen:    mid-carry (actions 260..275) the gripper re-opens to 0.3 and closes again (partial re-opening)"""
import sys, numpy as np
src = "/tmp/r30/tasks/gen/P_nominal.npz"; d = dict(np.load(src, allow_pickle=True)); out = sys.argv[1]
a0 = d["actions"]; g0 = a0[:, 7].copy()
def save(name, g):
    a = a0.copy(); a[:, 7] = g; dd = dict(d); dd["actions"] = a; np.savez(f"{out}/{name}.npz", **dd)
closed = (np.arange(len(g0)) >= 166) & (g0 < 1e-9)
g = np.maximum(g0, 0.05 * (np.arange(len(g0)) < 300)); g[closed] = 0.05; r = np.arange(166, 201); g[r] = 0.05 * (200 - r) / 34; g[201:][closed[201:]] = 0.0; save("P_creep", g)
g = np.maximum(g0, 0.02 * (np.arange(len(g0)) < 300)); g[closed] = 0.02; g[200] = 0.0; save("P_dip", g)
g = g0.copy(); ramp = g0[141:167]; x = np.linspace(0, 1, 60); g[141:201] = np.interp(x, np.linspace(0, 1, len(ramp)), ramp); save("P_slowclose", g)
rng = np.random.default_rng(0); g = np.maximum(g0, 0.03 * (np.arange(len(g0)) < 300)); g[closed] = np.clip(0.03 + rng.uniform(-0.03, 0.03, closed.sum()), 0, 1); save("P_jitter", g)
g = g0.copy(); g[260:268] = np.linspace(0, 0.3, 8); g[268:276] = np.linspace(0.3, 0, 8); save("P_reopen", g)
