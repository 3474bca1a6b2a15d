"""Edit the gripper channel of a demo trajectory: python edit_grip.py IN.npz OUT.npz CH MODE A B [AMP] [SEED]
MODE: partial (set to AMP over actions [A,B)), noise (add |U(0,AMP)| over [A,B), clip 0..1),
      regrip (AMP over [A,B), back to the original after), squeeze (original - AMP over [A,B): past closed)"""
import sys, json, numpy as np
inp, out, ch, mode, a, b = sys.argv[1:7]
ch, a, b = int(ch), int(a), int(b)
amp = float(sys.argv[7]) if len(sys.argv) > 7 else 0.3
seed = int(sys.argv[8]) if len(sys.argv) > 8 else 0
d = dict(np.load(inp, allow_pickle=True))
act = d["actions"].copy()
if mode in ("partial", "regrip"):
    act[a:b, ch] = amp
elif mode == "noise":
    r = np.random.default_rng(seed).uniform(0, amp, b - a)
    act[a:b, ch] = np.clip(act[a:b, ch] + r, 0, 1)
elif mode == "noise2":  # symmetric noise around the command, clipped
    r = np.random.default_rng(seed).uniform(-amp, amp, b - a)
    act[a:b, ch] = np.clip(act[a:b, ch] + r, 0, 1)
elif mode == "squeeze":
    act[a:b, ch] = act[a:b, ch] - amp
else:
    raise SystemExit(mode)
d["actions"] = act
meta = json.loads(str(d["meta"])); meta["probe_edit"] = sys.argv[3:]; meta["generator"] = "probe_r28b.edit_grip"
d["meta"] = np.array(json.dumps(meta))
np.savez(out, **d)
print(out, np.round(act[::10, ch], 2))
