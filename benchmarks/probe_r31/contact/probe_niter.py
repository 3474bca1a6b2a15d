"""The contact-model probe's solver iterations: python probe_niter.py VARIANT TRAJ"""
import sys, numpy as np, mujoco, critmoment as cm
assert cm.__file__.startswith("/tmp/r31/src")
from critmoment import contactmodel as ccm
from critmoment.trajectory import load_trajectory
twin = cm.Twin(cm.load_scenario(f"/tmp/r31/contact/v/{sys.argv[1]}")); traj = load_trajectory(sys.argv[2])
rec = cm.rollout(traj, twin=twin) if "twin" in cm.rollout.__code__.co_varnames else cm.rollout(traj, twin.scenario)
orig = ccm.measure_creep
def traced(model, data, **kw):
    object_body, steps = kw['object_body'], kw['steps']
    nit = []
    step0 = mujoco.mj_step
    def st(m, d):
        step0(m, d); nit.append(int(d.solver_niter[0]))
    mujoco.mj_step = st
    try:
        r = orig(model, data, **kw)
    finally:
        mujoco.mj_step = step0
    print(f"measure_creep: rate {r*1e3:.3g} mm/s, steps {steps}, solver_niter capped at {model.opt.iterations} in {sum(n >= model.opt.iterations for n in nit)} of {len(nit)} steps, object mass {model.body_mass[model.body(object_body).id]:.3g}")
    return r
ccm.measure_creep = traced
r = ccm.check_contact_model(twin, rec)
print(r.summary())
