#!/bin/bash
# F2: on a free-floating base standing on position-servo legs, the analytic motor bound
# (critmoment.dynamics: Pinocchio RNEA with a free-flyer root) sees no ground reaction, so it puts
# the leg servos' load at ~0.1 N m where they carry 3.75 N m (nominal) and saturate at 5 N m for
# heavy cubes; the report says "no motor saturates" and assumptions_hold = true.
set -e
P=$(cd "$(dirname "$0")" && pwd); W=${1:-/tmp/r34/floating/legged}; mkdir -p "$W"; cd "$W"
export PYTHONPATH=/tmp/r34/src; PY="taskset -c 0 /work/venv/bin/python"
$PY $P/make_robot.py legged legged.xml --hip-force 5 --grip-kp 1500
$PY $P/traj.py legged.xml legged.npz --slow 1.5 --grasp-dz 0.012
$P/cm.sh init legged.xml --object cube --task pick_place --goal 0.55 0.35 0.32 --out legged.toml --force 2>/dev/null
$P/boxify.sh legged.toml legged_T.toml 0.05 3.0 0.6 1.2
$P/cm.sh rollout legged.npz --scenario legged_T.toml 2>&1 | sed -n 2p        # simulation: min FOS motor 1.33 (h0)
$PY $P/run_analyze.py legged_T.toml legged.npz an.json | grep -i "analytic motor\|motor overload"
$PY - <<'PYEOF'
import json
r = json.load(open("an.json"))
print("load_bound:", json.dumps(r["load_bound"]))
a = r["moments"][0]["analytic"]
print("moment", r["moments"][0]["step"], "simulated min FOS motor", round(r["moments"][0]["min_fos_motor"], 3), "at", r["moments"][0]["limiting_actuator"],
      "| analytic: h0 worst torque", round(a["worst_torque"]["h0"], 3), "N m, critical_mass h0", a["critical_mass"]["h0"],
      ", min_fos_motor", round(a["min_fos_motor"], 2), ", assumptions_hold", a["assumptions_hold"])
PYEOF
