"""Library write_report (and save_trajectory) to awkward paths."""
import os, subprocess, pickle
from common import *
from critmoment.analysis import AnalyzeOptions
from critmoment.report import write_report
traj = cm.load_trajectory(TRAJ); sc = cm.load_scenario()
safe = sc.replace(box=sc.box.with_range("mass", 0.05, 0.2).with_range("friction", 0.5, 1.5))
R = cm.analyze(traj, safe, options=AnalyzeOptions(n_samples=8, nthread=1, search=False))
B = "/tmp/r32/inputs/out"; subprocess.run(["rm", "-rf", B]); os.makedirs(B)
open(f"{B}/afile", "w").write("x")
def ls(p):
    try: return sorted(os.listdir(p))
    except Exception as e: return repr(e)
t("out = existing file", lambda: write_report(R, f"{B}/afile", figures="none")); print("   file intact:", open(f"{B}/afile").read() == "x")
t("out under a file", lambda: write_report(R, f"{B}/afile/sub", figures="none"))
t("out = '' ", lambda: write_report(R, "", figures="none"))
t("out = None", lambda: write_report(R, None, figures="none"))
t("out = bytes", lambda: write_report(R, f"{B}/b".encode(), figures="none"))
t("out = 5", lambda: write_report(R, 5, figures="none"))
t("out unicode 'résumé ✓ 报告'", lambda: write_report(R, f"{B}/résumé ✓ 报告", figures="none")); print("  ", ls(B))
t("out 255-byte name", lambda: write_report(R, f"{B}/" + "a" * 255, figures="none"))
t("out 256-byte name", lambda: write_report(R, f"{B}/" + "a" * 256, figures="none"))
t("out 4000-char path", lambda: write_report(R, f"{B}/" + "/".join(["d" * 200] * 20), figures="none"))
deep = f"{B}/" + "/".join(["d" * 200] * 25)
t("out 5000-char path (> PATH_MAX)", lambda: write_report(R, deep, figures="none"))
t("out with NUL", lambda: write_report(R, f"{B}/a\0b", figures="none"))
t("out with newline", lambda: write_report(R, f"{B}/a\nb", figures="none")); print("  ", ls(B))
t("out trailing slash new", lambda: write_report(R, f"{B}/slash/", figures="none"))
os.makedirs(f"{B}/mixed"); open(f"{B}/mixed/traj.npz", "wb").write(open(TRAJ, "rb").read()); open(f"{B}/mixed/notes.txt", "w").write("keep")
t("out folder with user files (docs: kept)", lambda: write_report(R, f"{B}/mixed", figures="none")); print("  ", ls(f"{B}/mixed"))
t("  again with figures summary", lambda: write_report(R, f"{B}/mixed", figures="summary")); print("  ", ls(f"{B}/mixed"))
t("  again with figures none (earlier pngs gone?)", lambda: write_report(R, f"{B}/mixed", figures="none")); print("  ", ls(f"{B}/mixed"))
t("figures 'NONE'", lambda: write_report(R, f"{B}/f1", figures="NONE"))
t("figures 3", lambda: write_report(R, f"{B}/f2", figures=3))
# read-only fs
os.makedirs("/tmp/r32/inputs/ro", exist_ok=True)
rc = subprocess.run("mount -t tmpfs -o size=2m tmpfs /tmp/r32/inputs/ro && mkdir /tmp/r32/inputs/ro/prev && mount -o remount,ro /tmp/r32/inputs/ro", shell=True).returncode
print("ro mount rc", rc)
t("out in read-only fs (new)", lambda: write_report(R, "/tmp/r32/inputs/ro/new", figures="none"))
t("out in read-only fs (existing empty dir)", lambda: write_report(R, "/tmp/r32/inputs/ro/prev", figures="none"))
subprocess.run("umount /tmp/r32/inputs/ro", shell=True)
rc = subprocess.run("mount -t tmpfs -o size=300k tmpfs /tmp/r32/inputs/ro", shell=True).returncode
t("out on 300 kB fs, figures all", lambda: write_report(R, "/tmp/r32/inputs/ro/full", figures="all")); print("  ", ls("/tmp/r32/inputs/ro"))
subprocess.run("umount /tmp/r32/inputs/ro", shell=True)
# save_trajectory
from critmoment import save_trajectory
t("save_trajectory to existing dir", lambda: save_trajectory(traj, B))
t("save_trajectory to .txt suffix", lambda: save_trajectory(traj, f"{B}/t.txt"))
t("save_trajectory over an existing foreign npz", lambda: save_trajectory(traj, f"{B}/mixed/traj.npz"))
t("save_trajectory unicode", lambda: save_trajectory(traj, f"{B}/ü✓.npz"))
t("save+load float32-built traj round trip", lambda: cm.load_trajectory(save_trajectory(cm.Trajectory(traj.actions.astype(np.float32), fps=50.0, start=traj.start, object_pose=traj.object_pose), f"{B}/f32.npz") or f"{B}/f32.npz").content_sha256() == cm.Trajectory(traj.actions.astype(np.float32), fps=50.0, start=traj.start, object_pose=traj.object_pose).content_sha256())
t("pickle AuditReport", lambda: len(pickle.dumps(R)))
t("pickle Trajectory round trip", lambda: pickle.loads(pickle.dumps(traj)) == traj)
t("report to_json(timings=1)", lambda: R.to_json(timings=1))
t("report passes(1.5)", lambda: R.passes(1.5))
