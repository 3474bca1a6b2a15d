"""Two analyses in two Python threads at once vs the same two sequentially.

    python api_threads.py
"""
import json
import threading

import critmoment as cm
from critmoment import demos

opts = cm.AnalyzeOptions(n_samples=32, seed=0)
trajs = [demos.scripted_transfer(seed=0), demos.scripted_transfer(seed=3)]


def doc(t):
    return json.dumps(cm.analyze(t, options=opts).to_json(timings=False), sort_keys=True)


seq = [doc(t) for t in trajs]
par = [None, None]
errs = []


def work(i):
    try:
        par[i] = doc(trajs[i])
    except Exception as e:  # noqa: BLE001
        errs.append(f"{type(e).__module__}.{type(e).__name__}: {e}")


th = [threading.Thread(target=work, args=(i,)) for i in range(2)]
for t in th:
    t.start()
for t in th:
    t.join()
print("errors:", errs)
for i in range(2):
    same = par[i] == seq[i]
    print(f"traj {i}: threaded == sequential: {same}")
    if not same and par[i]:
        a, b = json.loads(seq[i]), json.loads(par[i])
        print("  differing keys:", [k for k in a if a[k] != b.get(k)])
