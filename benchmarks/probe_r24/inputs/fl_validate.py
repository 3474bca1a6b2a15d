"""force_limit parameter: audit predictions vs brute force at low wrist limits (scen/fl_wrist_narrow.toml)."""
import warnings

import numpy as np

import critmoment as cm

warnings.simplefilter('ignore')
sc = cm.load_scenario('scen/fl_wrist_narrow.toml')
tw = cm.Twin(sc)
traj = cm.load_trajectory('base.npz')
S = np.array([[m, f, w] for m in (0.05, 0.175, 0.3) for f in (0.8, 1.5) for w in (0.3, 0.5, 1.0)])
v = cm.validate(traj, twin=tw, samples=S)
print(v.confusion, 'false_safe_rate', v.false_safe_rate)
j = v.to_json() if hasattr(v, 'to_json') else {}
for p in j.get('per_sample', []):
    print({k: p[k] for k in p if k in ('values','outcome','predicted_safe','real','predicted','safe','source')})
