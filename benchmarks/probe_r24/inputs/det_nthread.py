"""Determinism across nthread: the same audit with nthread 1, 2 and 0 (default)."""
import json
import warnings

import critmoment as cm

warnings.simplefilter('ignore')
traj = cm.load_trajectory('base.npz')
tw = cm.Twin()
out = {}
for n in (1, 2, 0, 3):
    r = cm.analyze(traj, twin=tw, options=cm.AnalyzeOptions(n_samples=32, nthread=n, seed=0))
    d = r.to_json(timings=False)
    d.pop('timings', None)
    d.get('manifest', {}).get('options', {}).pop('nthread', None)
    out[n] = json.dumps(d, sort_keys=True)
    print(n, r.verdict, r.p_success, r.safe_region, flush=True)
print('all identical:', len(set(out.values())) == 1)
if len(set(out.values())) != 1:
    import difflib
    a, b = out[1].split(', '), out[2].split(', ')
    print([line for line in difflib.unified_diff(a, b, lineterm='', n=0)][:30])
