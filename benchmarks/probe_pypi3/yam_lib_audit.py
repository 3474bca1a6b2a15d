"""YAM through the library with a looser tracking check (lag tolerance 0.6 rad, delay 0.35 s,
about the servos' own (kv + damping)/kp = 0.32 s): the CLI refuses the motion (exit 2) because
the feed-forward in the targets is counted as lag. A probe of what the audit says otherwise.

Usage: python yam_lib_audit.py SCENARIO.toml TRAJ.npz SAMPLES
"""

import functools
import sys

import critmoment as cm
from critmoment import analysis, feasibility, validation
from critmoment.trajectory import load_trajectory

LOOSE = feasibility.FeasibilityOptions(lag_tolerance=0.6, delay=0.35)
loose = functools.partial(feasibility.preflight, options=LOOSE)
validation.preflight = loose
analysis.preflight = loose

scenario, path, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
sc = cm.load_scenario(scenario)
traj = load_trajectory(path)
rep = cm.analyze(traj, sc, seed=0)
print("ANALYZE", rep.verdict, "P(success)", round(rep.p_success, 3), "|", rep.safe_region_text)
for m in rep.moments[:8] if hasattr(rep, "moments") else []:
    print("  moment", m)
check = cm.validate(traj, twin=cm.Twin(sc), n_samples=n)
print("VALIDATE confusion", check.confusion, "false-safe rate", check.false_safe_rate,
      "agreement", getattr(check, "agreement", None))
print("outcomes", getattr(check, "outcomes", None))
