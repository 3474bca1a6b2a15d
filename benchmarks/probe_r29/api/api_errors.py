"""Failures a Python service meets: is each a CritmomentError whose message says what was
expected and what came?  (Wrong-type argument probes of r25/r28 are not repeated.)

    cd /tmp/r29/api && PYTHONPATH=/tmp/r29/src python api_errors.py
"""
import io
import sys
import warnings

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from common import check_src, demo_traj  # noqa: E402

import critmoment as cm  # noqa: E402
from critmoment import report as rpt  # noqa: E402

check_src()
tp = demo_traj()
pp = demo_traj(name="panda.npz", scenario="panda_pick_place")
traj = cm.load_trajectory(tp)
panda = cm.load_trajectory(pp)
OPTS = cm.AnalyzeOptions(n_samples=8, nthread=1, search=False)
twin = cm.Twin(cm.load_scenario())


def case(label, fn):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        try:
            r = fn()
            res = f"returned {type(r).__name__}" + (f" {r.verdict.value}" if hasattr(r, "verdict") else "")
        except cm.CritmomentError as exc:
            res = f"CritmomentError/{type(exc).__name__}: {str(exc)[:260]}"
        except Exception as exc:  # noqa: BLE001
            res = f"NOT CritmomentError: {type(exc).__module__}.{type(exc).__name__}: {str(exc)[:260]}"
    ws = [f"{x.category.__name__}: {str(x.message)[:160]}" for x in w]
    print(f"- {label}\n    {res}" + "".join(f"\n    warning {s}" for s in ws))


case("analyze('traj.npz') (a path, not a Trajectory)", lambda: cm.analyze(str(tp), options=OPTS))
case("rollout(Path) (a path)", lambda: cm.rollout(tp))
case("validate('traj.npz')", lambda: cm.validate(str(tp), n_samples=8))
case("load_trajectory(io.BytesIO(bytes of traj.npz)) (an upload)",
     lambda: cm.load_trajectory(io.BytesIO(tp.read_bytes())))
case("load_trajectory(bytes)", lambda: cm.load_trajectory(tp.read_bytes()))
case("analyze(panda traj, aloha scenario)", lambda: cm.analyze(panda, "aloha_transfer_cube", options=OPTS))
case("analyze(aloha traj, 'panda_pick_place')", lambda: cm.analyze(traj, "panda_pick_place", options=OPTS))
case("analyze(traj, twin=aloha twin, scenario='panda_pick_place')",
     lambda: cm.analyze(traj, "panda_pick_place", twin=twin, options=OPTS))
case("analyze(traj, 'Aloha_Transfer_Cube') (case)", lambda: cm.analyze(traj, "Aloha_Transfer_Cube", options=OPTS))
case("validate(samples of 3 columns, box has 2)",
     lambda: cm.validate(traj, twin=twin, samples=np.zeros((4, 3))))
case("validate(samples with NaN)", lambda: cm.validate(traj, twin=twin, samples=np.array([[np.nan, 1.0]] * 2)))
case("validate(samples outside the box: mass 50 kg)",
     lambda: cm.validate(traj, twin=twin, samples=np.array([[50.0, 1.0], [0.05, 1.0]]), nthread=1))
case("validate(n_samples=1)", lambda: cm.validate(traj, twin=twin, n_samples=1, nthread=1))
case("validate(seed=None)", lambda: cm.validate(traj, twin=twin, n_samples=8, seed=None, nthread=1))
# a joint step of 1.5 rad in one control step: the twin cannot follow
A = np.array(traj.actions)
A[200:, 1] += 1.2
jump = cm.Trajectory(actions=A, fps=traj.fps, start=traj.start, object_pose=traj.object_pose)
case("analyze(a 1.2 rad shoulder step the servo cannot follow)", lambda: cm.analyze(jump, options=OPTS))
case("analyze(fps=1000 > physics rate)",
     lambda: cm.analyze(cm.Trajectory(actions=A, fps=1000.0, start=traj.start,
                                      object_pose=traj.object_pose), options=OPTS))
case("Trajectory(actions=list of lists, fps='50')",
     lambda: cm.Trajectory(actions=np.asarray(traj.actions).tolist(), fps="50"))
case("analyze(options=OPTS, progress=lambda m: 1/0) (a progress callback that fails)",
     lambda: cm.analyze(traj, options=OPTS, progress=lambda m: 1 / 0))
r = cm.analyze(traj, options=OPTS)
case("report.passes(np.float64(0.05))", lambda: print("   ", r.passes(np.float64(0.05))))
case("write_report(r, out, figures='None')", lambda: rpt.write_report(r, "/tmp/r29/api/err_w1", figures="None"))
case("write_report(r, out, figures=None)", lambda: rpt.write_report(r, "/tmp/r29/api/err_w2", figures=None))
case("write_report(r, '/dev/null')", lambda: rpt.write_report(r, "/dev/null"))
case("write_report(r, '')", lambda: rpt.write_report(r, ""))
