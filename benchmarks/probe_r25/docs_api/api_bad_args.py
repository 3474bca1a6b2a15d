"""Bad arguments to the public API: each must raise a CritmomentError subclass with a clear message.

    python api_bad_args.py SCRATCH
"""
import os
import sys
import warnings
from pathlib import Path

import numpy as np

import critmoment as cm
from critmoment import demos, report

warnings.simplefilter("ignore")
d = Path(sys.argv[1] if len(sys.argv) > 1 else "/tmp/r25/docs_api/b_bad")
d.mkdir(parents=True, exist_ok=True)
traj = demos.scripted_transfer(seed=0)
small = cm.AnalyzeOptions(n_samples=8, max_moments=1, search=False, map_resolution=0)


def t(label, fn):
    try:
        r = fn()
        print(f"OK   {label}: returned {type(r).__name__}")
    except cm.CritmomentError as e:
        print(f"CMER {label}: {type(e).__name__}: {str(e)[:200]}")
    except Exception as e:  # noqa: BLE001
        print(f"**** {label}: {type(e).__module__}.{type(e).__name__}: {str(e)[:200]}")


t("analyze(None)", lambda: cm.analyze(None))
t("analyze('traj.npz' str)", lambda: cm.analyze("nope.npz"))
t("analyze(traj, scenario=123)", lambda: cm.analyze(traj, 123, options=small))
t("analyze(traj, scenario=None, twin='x')", lambda: cm.analyze(traj, twin="x", options=small))
t("analyze(seed=0.0)", lambda: cm.analyze(traj, seed=0.0, options=small))
t("analyze(seed='7')", lambda: cm.analyze(traj, seed="7", options=small))
t("analyze(seed=np.int64(3))", lambda: cm.analyze(traj, seed=np.int64(3), options=small))
t("analyze(seed=True)", lambda: cm.analyze(traj, seed=True, options=small))
t("analyze(progress='yes')", lambda: cm.analyze(traj, options=small, progress="yes"))
t("AnalyzeOptions(n_samples=-5)", lambda: cm.AnalyzeOptions(n_samples=-5))
t("AnalyzeOptions(n_samples=None)", lambda: cm.analyze(traj, options=cm.AnalyzeOptions(n_samples=None)))
t("AnalyzeOptions(seed=1.5)", lambda: cm.analyze(traj, options=cm.AnalyzeOptions(seed=1.5, n_samples=8)))
t("AnalyzeOptions(verify=-1)", lambda: cm.analyze(traj, options=cm.AnalyzeOptions(verify=-1, n_samples=8)))
t("AnalyzeOptions(min_success=2)", lambda: cm.AnalyzeOptions(min_success=2))
t("AnalyzeOptions(confidence=1.5)", lambda: cm.AnalyzeOptions(confidence=1.5))
t("AnalyzeOptions(max_moments=0)", lambda: cm.AnalyzeOptions(max_moments=0))
t("validate(n_samples=None)", lambda: cm.validate(traj, n_samples=None))
t("validate(n_samples='16')", lambda: cm.validate(traj, n_samples="16"))
t("validate(seed=2.5)", lambda: cm.validate(traj, n_samples=4, seed=2.5))
t("validate(traj=None)", lambda: cm.validate(None, n_samples=4))
t("Trajectory(actions 1-D)", lambda: cm.Trajectory(actions=np.zeros(14), fps=50))
t("Trajectory(fps=-50)", lambda: cm.Trajectory(actions=np.zeros((10, 14)), fps=-50))
t("Trajectory(actions NaN)", lambda: cm.Trajectory(actions=np.full((10, 14), np.nan), fps=50))
t("Trajectory(object_pose 3 values)", lambda: cm.Trajectory(actions=np.zeros((10, 14)), fps=50, object_pose=np.zeros(3)))
t("analyze(traj with 8 channels on ALOHA)", lambda: cm.analyze(cm.Trajectory(actions=np.zeros((400, 8)), fps=50), options=small))
rep = cm.analyze(traj, seed=0, options=small)
(d / "afile").write_text("x")
t("write_report(rep, file path)", lambda: report.write_report(rep, d / "afile"))
t("write_report(rep, under a file)", lambda: report.write_report(rep, d / "afile" / "x"))
t("write_report(rep, None)", lambda: report.write_report(rep, None))
t("write_report(rep, 5)", lambda: report.write_report(rep, 5))
t("write_report('notareport', dir)", lambda: report.write_report("x", d / "r1"))
t("write_report(rep, '/proc/x')", lambda: report.write_report(rep, "/proc/x"))
t("write_report(rep, 'a'*300)", lambda: report.write_report(rep, d / ("a" * 300)))
t("passes(min_success='0.5')", lambda: rep.passes("0.5"))
t("passes(min_success=2)", lambda: rep.passes(2))
t("to_json(timings='no')", lambda: rep.to_json(timings="no"))
t("save_trajectory(traj, dir)", lambda: cm.save_trajectory(traj, d))
t("save_trajectory(traj, 'x.txt')", lambda: cm.save_trajectory(traj, d / "x.txt"))
t("load_scenario('/nonexistent.toml')", lambda: cm.load_scenario("/nonexistent.toml"))
print("cwd files:", sorted(os.listdir(d)))
