"""A long-running service: RSS after each of N audits in one process (one Twin reused).

    PYTHONPATH=/tmp/r29/src python api_memory.py [N]
"""
import gc
import resource
import sys
import time

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from common import check_src, demo_traj  # noqa: E402

import critmoment as cm  # noqa: E402


def rss_mb():
    with open("/proc/self/status") as fh:
        for line in fh:
            if line.startswith("VmRSS"):
                return int(line.split()[1]) / 1024


check_src()
n = int(sys.argv[1]) if len(sys.argv) > 1 else 8
traj = cm.load_trajectory(demo_traj())
twin = cm.Twin(cm.load_scenario())
OPTS = cm.AnalyzeOptions(n_samples=16, nthread=1)
t = time.perf_counter()
cm.Twin(cm.load_scenario())
print(f"Twin(load_scenario()) {time.perf_counter() - t:.2f} s")
for i in range(n):
    t = time.perf_counter()
    r = cm.analyze(traj, twin=twin, options=OPTS)
    del r
    gc.collect()
    print(f"audit {i}: {time.perf_counter() - t:.1f} s, RSS {rss_mb():.0f} MB, "
          f"peak {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MB")
