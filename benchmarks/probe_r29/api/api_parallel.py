"""analyze from several threads (one shared Twin / Scenario) and from worker processes
(fork, spawn, forkserver), against the sequential report.

    PYTHONPATH=/tmp/r29/src python api_parallel.py
"""
import concurrent.futures as cf
import multiprocessing as mp
import sys
import time

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from common import check_src, demo_traj, diff  # noqa: E402

import critmoment as cm  # noqa: E402

N = 16


def job(path, seed, nthread=1):
    import critmoment as cm
    t = cm.load_trajectory(path)
    r = cm.analyze(t, "aloha_transfer_cube", options=cm.AnalyzeOptions(n_samples=N, nthread=nthread,
                                                                        seed=seed))
    return r.to_json(timings=False)


def job_twin(twin, traj, seed):
    r = cm.analyze(traj, twin=twin, options=cm.AnalyzeOptions(n_samples=N, nthread=1, seed=seed))
    return r.to_json(timings=False)


def job_error(path):
    import critmoment as cm
    return cm.analyze(cm.load_trajectory(path), "no_such_scenario")


if __name__ == "__main__":
    check_src()
    tp = demo_traj()
    tp3 = demo_traj(seed=3, name="traj3.npz")
    traj, traj3 = cm.load_trajectory(tp), cm.load_trajectory(tp3)
    seq = {0: job(tp, 0), 3: job(tp3, 0)}
    twin = cm.Twin(cm.load_scenario())

    t = time.perf_counter()
    with cf.ThreadPoolExecutor(2) as ex:
        a = ex.submit(job_twin, twin, traj, 0)
        b = ex.submit(job_twin, twin, traj3, 0)
        ra, rb = a.result(), b.result()
    print(f"threads, one shared Twin, traj0 & traj3 at once ({time.perf_counter() - t:.1f} s):",
          "traj0 diff", diff(seq[0], ra)[:5], "traj3 diff", diff(seq[3], rb)[:5])

    with cf.ThreadPoolExecutor(2) as ex:
        futs = [ex.submit(job_twin, twin, traj, 0) for _ in range(2)]
        rs = [f.result() for f in futs]
    print("threads, one shared Twin, same traj twice at once:", [diff(seq[0], r)[:5] for r in rs])

    for method in ("fork", "spawn", "forkserver"):
        t = time.perf_counter()
        try:
            with cf.ProcessPoolExecutor(2, mp_context=mp.get_context(method)) as ex:
                fa, fb = ex.submit(job, tp, 0), ex.submit(job, tp3, 0)
                ra, rb = fa.result(), fb.result()
            print(f"processes ({method}, {time.perf_counter() - t:.1f} s): traj0 diff",
                  diff(seq[0], ra)[:5], "traj3 diff", diff(seq[3], rb)[:5])
        except Exception as exc:  # noqa: BLE001
            print(f"processes ({method}): FAILS {type(exc).__name__}: {exc}")

    # a Twin sent to a worker process (pickled) and an error coming back
    with cf.ProcessPoolExecutor(1, mp_context=mp.get_context("spawn")) as ex:
        r = ex.submit(job_twin, twin, traj, 0).result()
        print("spawn worker with a pickled Twin: diff", diff(seq[0], r)[:5])
        try:
            ex.submit(job_error, tp).result()
        except cm.CritmomentError as exc:
            print("error from a worker: CritmomentError subclass", type(exc).__name__, str(exc)[:150])
        except Exception as exc:  # noqa: BLE001
            print("error from a worker: NOT a CritmomentError", type(exc).__name__, str(exc)[:150])
