"""A service's timeout: an exception raised in the main thread (SIGALRM handler) during
analyze. How long until analyze gives up, and is anything left running?

    PYTHONPATH=/tmp/r29/src python api_timeout.py [DELAY]
"""
import signal
import sys
import threading
import time

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from common import check_src, demo_traj  # noqa: E402

import critmoment as cm  # noqa: E402


class Timeout(Exception):
    pass


def alarm(*_):
    raise Timeout()


check_src()
traj = cm.load_trajectory(demo_traj())
signal.signal(signal.SIGALRM, alarm)
for delay in [float(x) for x in (sys.argv[1:] or ["2.5", "3.5", "5"])]:
    stages = []
    t0 = time.perf_counter()
    signal.setitimer(signal.ITIMER_REAL, delay)
    try:
        cm.analyze(traj, options=cm.AnalyzeOptions(n_samples=256),
                   progress=lambda m, stages=stages, t0=t0: stages.append(
                       (round(time.perf_counter() - t0, 2), m)))
        print(f"delay {delay}: finished before the alarm ({time.perf_counter() - t0:.1f} s)")
    except Timeout:
        late = time.perf_counter() - t0 - delay
        print(f"delay {delay}: Timeout reached the caller {late:.2f} s after the alarm; "
              f"threads alive after: {[t.name for t in threading.enumerate()]}; "
              f"stages after the alarm: {[s for s in stages if s[0] > delay]}")
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
