"""Sample #37 of the peg1_sockmissed validation (mass 0.0856 kg, friction 0.278): critmoment's own
rollout at those values (scenario peg_s37.toml: the nominal set to them) vs the plain-MuJoCo truth;
the peg's height and the right gripper's contact at the end, and critmoment's controls vs truth.py's."""
import sys

import critmoment as cm
assert cm.__file__.startswith("/tmp/r37/src"), cm.__file__
import mujoco
import numpy as np
from critmoment.recording import prepare_controls
from critmoment.trajectory import load_trajectory

sys.path.insert(0, "/work/main/benchmarks/probe_r37/insertion")
import truth as T  # noqa: E402

traj_path = sys.argv[1] if len(sys.argv) > 1 else "peg1_sockmissed.npz"
twin = cm.Twin("peg_s37.toml")
traj = load_trajectory(traj_path)
u_cm = prepare_controls(twin, traj)
tr = T.Truth(traj_path, "peg")
print("controls: cm", u_cm.shape, "truth", tr.ctrl.shape, "max |diff|", np.abs(u_cm[:len(tr.ctrl)] - tr.ctrl[:len(u_cm)]).max())
rec = cm.rollout(traj, twin=twin) if "twin" in cm.rollout.__code__.co_varnames else cm.rollout(traj, twin.scenario)
s = rec.summary()
print("cm rollout:", {k: s.get(k) for k in ("completed", "max_stage", "final_stage", "shortfalls")})
m = twin.model
q = twin.qpos(rec.states[[-1]])[0]
a = m.jnt_qposadr[m.joint("red_peg_joint").id]
print("cm final peg pos", q[a:a + 3])
print("cm model: peg friction", m.geom_friction[m.geom("red_peg").id], "prio", m.geom_priority[m.geom("red_peg").id], "mass", m.body_mass[m.body("peg").id])
r = tr.run(0.08561041417997331, 0.27807294772937896)
print("truth:", {k: r[k] for k in ("success", "right_holds_end", "peg_table_end", "peg_z_end")})
print("truth model: peg friction", tr.m.geom_friction[tr.peg], "prio", tr.m.geom_priority[tr.peg], "mass", tr.m.body_mass[tr.m.body("peg").id])
