"""Wrong argument types to the public API: expect CritmomentError subclasses (or TypeError) with clear messages."""
import os
import traceback
import warnings

import numpy as np

import critmoment as cm
from critmoment import analysis, demos, report
from critmoment.exceptions import CritmomentError

warnings.simplefilter("ignore")
sc = cm.load_scenario(); tw = cm.Twin(sc)
traj = cm.load_trajectory("/tmp/r28/cli/readme/traj.npz")
def t(label, f):
    try:
        r = f(); print(f"OK    {label}: returned {type(r).__name__}")
    except CritmomentError as e: print(f"CMERR {label}: {type(e).__name__}: {str(e)[:160]}")
    except TypeError as e: print(f"TYPE  {label}: {str(e)[:160]}")
    except BaseException as e:
        tb = traceback.extract_tb(e.__traceback__)[-1]
        print(f"!!!   {label}: {type(e).__name__}: {str(e)[:160]} @ {os.path.basename(tb.filename)}:{tb.lineno}")
t("load_scenario(5)", lambda: cm.load_scenario(5))
t("load_scenario('nope')", lambda: cm.load_scenario("nope"))
t("load_scenario(None)", lambda: cm.load_scenario(None))
t("load_scenario(b'aloha_transfer_cube')", lambda: cm.load_scenario(b"aloha_transfer_cube"))
t("load_scenario('/tmp')", lambda: cm.load_scenario("/tmp"))
t("Twin(None)", lambda: cm.Twin(None))
t("Twin('aloha_transfer_cube')", lambda: cm.Twin("aloha_transfer_cube"))
t("load_trajectory(5)", lambda: cm.load_trajectory(5))
t("load_trajectory(None)", lambda: cm.load_trajectory(None))
t("load_trajectory(path, fps='x')", lambda: cm.load_trajectory("/tmp/r28/cli/readme/traj.npz", fps="x"))
t("load_trajectory(path, fps=-1)", lambda: cm.load_trajectory("/tmp/r28/cli/readme/traj.npz", fps=-1))
t("load_trajectory(path, fps=25)", lambda: cm.load_trajectory("/tmp/r28/cli/readme/traj.npz", fps=25))
t("load_trajectory(path, episode='a')", lambda: cm.load_trajectory("/tmp/r28/cli/in/pq/multi.parquet", episode="a"))
t("load_trajectory(path, episode=1.5)", lambda: cm.load_trajectory("/tmp/r28/cli/in/pq/multi.parquet", episode=1.5))
t("load_trajectory(path, episode=True)", lambda: cm.load_trajectory("/tmp/r28/cli/in/pq/multi.parquet", episode=True))
t("load_trajectory(path, episode=np.int64(1))", lambda: cm.load_trajectory("/tmp/r28/cli/in/pq/multi.parquet", episode=np.int64(1)))
t("load_trajectory(path, episode=-1)", lambda: cm.load_trajectory("/tmp/r28/cli/in/pq/multi.parquet", episode=-1))
A = traj.actions
t("Trajectory(actions=list)", lambda: cm.Trajectory(actions=A.tolist(), fps=50))
t("Trajectory(actions=str)", lambda: cm.Trajectory(actions="abc", fps=50))
t("Trajectory(actions=None)", lambda: cm.Trajectory(actions=None, fps=50))
t("Trajectory(fps=None)", lambda: cm.Trajectory(actions=A, fps=None))
t("Trajectory(fps='50')", lambda: cm.Trajectory(actions=A, fps="50"))
t("Trajectory(fps=np.float32(50))", lambda: cm.Trajectory(actions=A, fps=np.float32(50)))
t("Trajectory(fps=True)", lambda: cm.Trajectory(actions=A, fps=True))
t("Trajectory(meta='x')", lambda: cm.Trajectory(actions=A, fps=50, meta="x"))
t("Trajectory(meta={'a': object()})", lambda: cm.Trajectory(actions=A, fps=50, meta={"a": object()}))
t("Trajectory(meta={'a': nan})", lambda: cm.Trajectory(actions=A, fps=50, meta={"a": float('nan')}))
t("Trajectory(start=[1,2])", lambda: cm.Trajectory(actions=A, fps=50, start=[1, 2]))
t("Trajectory(object_pose='x')", lambda: cm.Trajectory(actions=A, fps=50, object_pose="x"))
t("rollout(None, sc)", lambda: cm.rollout(None, sc))
t("rollout(A, sc) raw array", lambda: cm.rollout(A, sc))
t("rollout('/tmp/r28/cli/readme/traj.npz', sc) path", lambda: cm.rollout("/tmp/r28/cli/readme/traj.npz", sc))
t("rollout(traj, 'aloha_transfer_cube')", lambda: cm.rollout(traj, "aloha_transfer_cube"))
t("rollout(traj, 5)", lambda: cm.rollout(traj, 5))
t("analyze(traj, sc, seed=-1)", lambda: cm.analyze(traj, sc, seed=-1))
t("analyze(traj, sc, seed='a')", lambda: cm.analyze(traj, sc, seed="a"))
t("analyze(traj, sc, seed=1.5)", lambda: cm.analyze(traj, sc, seed=1.5))
t("analyze(traj, sc, seed=2**40)", lambda: cm.analyze(traj, sc, seed=2**40))
t("analyze(traj, sc, n_samples=0)", lambda: cm.analyze(traj, sc, n_samples=0))
t("analyze(traj, sc, bogus=1)", lambda: cm.analyze(traj, sc, bogus=1))
t("analyze(traj, 5)", lambda: cm.analyze(traj, 5))
t("analyze(traj) no scenario", lambda: cm.analyze(traj).verdict)
t("AnalyzeOptions(nthread=-1)", lambda: analysis.AnalyzeOptions(nthread=-1))
t("AnalyzeOptions(nthread='2')", lambda: analysis.AnalyzeOptions(nthread="2"))
t("AnalyzeOptions(n_samples=7)", lambda: analysis.AnalyzeOptions(n_samples=7))
t("AnalyzeOptions(verify_fraction=nan)", lambda: analysis.AnalyzeOptions(verify_fraction=float('nan')))
t("validate(traj, twin=tw, n_samples=0)", lambda: cm.validate(traj, twin=tw, n_samples=0))
t("validate(traj, twin=tw, n_samples='8')", lambda: cm.validate(traj, twin=tw, n_samples="8"))
t("validate(traj, twin=sc)", lambda: cm.validate(traj, twin=sc, n_samples=8))
t("box.with_range('mass', 1, 0.5)", lambda: sc.box.with_range("mass", 1.0, 0.5))
t("box.with_range('mass', 'a', 1)", lambda: sc.box.with_range("mass", "a", 1.0))
t("box.with_range('nope', 0.1, 1)", lambda: sc.box.with_range("nope", 0.1, 1.0))
t("box.with_range('mass', 0.1, nan)", lambda: sc.box.with_range("mass", 0.1, float('nan')))
t("box.with_range('mass', 1, 2) (nominal 0.05 outside)", lambda: sc.box.with_range("mass", 1.0, 2.0))
t("sc.replace(box=5)", lambda: sc.replace(box=5))
t("sc.replace(bogus=5)", lambda: sc.replace(bogus=5))
t("write_report(None, 'x')", lambda: report.write_report(None, "/tmp/r28/cli/api/x"))
t("save_trajectory(traj, '/tmp/r28/cli/api/t.txt')", lambda: cm.save_trajectory(traj, "/tmp/r28/cli/api/t.txt"))
t("save_trajectory(traj, '/tmp/r28/cli/api')", lambda: cm.save_trajectory(traj, "/tmp/r28/cli/api"))
t("save_trajectory(A, path)", lambda: cm.save_trajectory(A, "/tmp/r28/cli/api/t2.npz"))
t("demos.scripted_transfer(seed=-1)", lambda: demos.scripted_transfer(seed=-1))
t("demos.scripted_transfer(seed='a')", lambda: demos.scripted_transfer(seed="a"))
t("budget.limits(max_steps=0)", lambda: cm.budget.limits(max_steps=0).__enter__())
t("budget.limits(max_steps=-5)", lambda: cm.budget.limits(max_steps=-5).__enter__())
t("budget.limits(max_steps='a')", lambda: cm.budget.limits(max_steps='a').__enter__())
def small_limit():
    with cm.budget.limits(max_steps=100):
        return cm.rollout(traj, sc)
t("rollout under max_steps=100", small_limit)
