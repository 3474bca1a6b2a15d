"""Replays critmoment's contact-model probe (new code) window by window and says whether the
object is still touching the gripper's pads at the end of each window and where it is in
world z. usage: PYTHONPATH=/tmp/r29b/src python probe_windows.py SCENARIO TRAJ"""
import sys, math, warnings
import numpy as np, mujoco
import critmoment as cm
from critmoment import contactmodel as cmod
from critmoment.recording import at_scenario_rate, rollout
from critmoment.trajectory import load_trajectory
warnings.simplefilter("ignore")
twin = cm.Twin(sys.argv[1]); traj = at_scenario_rate(load_trajectory(sys.argv[2]), twin)
rec = rollout(traj, twin=twin)
calls = []
orig = cmod.measure_creep
def spy(model, data, **kw):
    r = orig(model, data, **kw)
    ob = model.body(kw["object_body"]).id
    pads = set()
    for g in range(model.ngeom):
        pass
    touching = []
    for i in range(data.ncon):
        c = data.contact[i]
        b1, b2 = model.geom_bodyid[c.geom1], model.geom_bodyid[c.geom2]
        if ob in (b1, b2):
            other = b2 if b1 == ob else b1
            touching.append(model.body(other).name)
    calls.append((r, float(data.xpos[ob][2]), sorted(set(touching))))
    return r
cmod.measure_creep = spy
rep = cmod.check_contact_model(twin, rec, warn=False)
for i, (r, z, t) in enumerate(calls):
    print(f"window {i}: rate {r*1e3:.3f} mm/s, object z {z:.4f} m, touching {t}")
print("probe mass", rep.probe_mass, "rate", rep.creep_rate, "soft", rep.soft, "carry", rep.carry_time)
