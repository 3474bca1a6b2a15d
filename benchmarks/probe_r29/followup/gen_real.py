"""Scenario (critmoment init, code on PYTHONPATH) + scripted nominal trajectory for every
real_models.py quick case, into $CRITMOMENT_REAL_MODELS/runs/<case>/ (set it to a scratch copy).
Also runs init with the OLD code (/tmp/r29b/cm_old.sh) and saves both outputs for diffing."""
import subprocess, sys, os
from pathlib import Path
sys.path.insert(0, "/tmp/r29b/src/benchmarks")
import real_models as rm
from critmoment.trajectory import save_trajectory
for case in rm.cases(True) + [rm.Case("act_interbotix", "act", "shipped", rm.scenes.act_interbotix_limits(), "")]:
    work = rm.scenes.CACHE / "runs" / case.name
    work.mkdir(parents=True, exist_ok=True)
    task = "handover" if case.robot == "act" else "pick_place"
    extra = [] if case.robot == "act" else ["--goal-site", "goal"]
    for v in ("old", "new"):
        p = subprocess.run([f"/tmp/r29b/cm_{v}.sh", "init", str(case.mjcf), "--object",
                            "box" if case.robot == "act" else "cube", "--task", task, *extra,
                            "--out", str(work / f"scenario_{v}.toml"), "--force"],
                           capture_output=True, text=True)
        (work / f"init_{v}.txt").write_text(p.stdout + p.stderr + f"\nrc={p.returncode}\n")
    scen = work / "scenario_new.toml"
    save_trajectory(rm.trajectory_for(case, scen, 0), work / "nominal_new.npz")
    print(case.name, scen, flush=True)
