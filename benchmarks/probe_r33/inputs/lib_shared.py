"""Library write_report (shared folder): a folder with the user's trajectory and the user's
own picture named like a critmoment figure (signals.png), no marker. Is the user's file kept?"""
import os, shutil, hashlib
from common import SCRATCH, log
import critmoment as cm
from critmoment.report import write_report
R = "lib_shared.txt"
traj = cm.load_trajectory(os.path.join(SCRATCH, "traj.npz"))
rep = cm.analyze(traj, cm.load_scenario(), options=cm.AnalyzeOptions(n_samples=8, seed=0))
for figs in ("none", "summary"):
    d = os.path.join(SCRATCH, f"shared_{figs}"); shutil.rmtree(d, ignore_errors=True); os.makedirs(d)
    shutil.copy(os.path.join(SCRATCH, "traj.npz"), d)
    for name in ("signals.png", "moment_12.png", "notes.txt"):
        open(os.path.join(d, name), "wb").write(b"USER'S OWN FILE " + name.encode())
    before = sorted(os.listdir(d))
    write_report(rep, d, figures=figs)
    after = sorted(os.listdir(d))
    kept = {n: (open(os.path.join(d, n), "rb").read(15) == b"USER'S OWN FILE") if os.path.exists(os.path.join(d, n)) else "DELETED"
            for n in ("signals.png", "moment_12.png", "notes.txt", "traj.npz")}
    log(R, f"figures={figs}: before={before} after={after} user files intact: {kept}")
