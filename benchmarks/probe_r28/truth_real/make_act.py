"""ACT's gym-aloha transfer-cube scene (as shipped: pyramidal, impratio 1) and an elliptic
impratio-10 copy: init's scenario (unedited) and the real_models scripted trajectory (seed 0).
Outputs in /tmp/r28/truth_real/act/. Run with PYTHONPATH=/tmp/r28/src and
CRITMOMENT_REAL_MODELS=/tmp/r28/truth_real/rm (wheels downloaded there, never installed)."""
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, "/work/main/benchmarks")
sys.path.insert(0, "/work/main/benchmarks/real_models")
import real_models as rm  # noqa: E402
import scenes  # noqa: E402

from critmoment.trajectory import save_trajectory  # noqa: E402

W = Path("/tmp/r28/truth_real/act"); W.mkdir(parents=True, exist_ok=True)
act = scenes.act_scene()
ell = scenes.with_contact_model(act, "elliptic10", "act")
for name, mjcf in (("shipped", act), ("elliptic10", ell)):
    scen = W / f"scenario_{name}.toml"
    r = subprocess.run([sys.executable, "-c", "import sys; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())",
                        "init", str(mjcf), "--object", "box", "--task", "handover", "--out", str(scen), "--force"],
                       capture_output=True, text=True)
    print(name, r.returncode, r.stderr[-300:])
    case = rm.Case("act", "act", name, mjcf, "")
    save_trajectory(rm.trajectory_for(case, scen, 0), W / f"traj_{name}.npz")
print("ok")
