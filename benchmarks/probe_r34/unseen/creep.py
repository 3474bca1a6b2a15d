"""What critmoment's contact-model check measures on a nominal run: the nominal creep
(contactmodel.check_contact_model) and the slip masks it is measured over.
usage: creep.py SCENARIO TRAJ"""
import sys
import warnings
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r34/src"), cm.__file__
from critmoment.trajectory import load_trajectory
from critmoment.recording import rollout
from critmoment.contactmodel import check_contact_model

twin = cm.Twin(sys.argv[1]); traj = load_trajectory(sys.argv[2])
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    rec = rollout(traj, twin=twin) if "twin" in rollout.__code__.co_varnames else rollout(traj, twin.scenario)
    rep = check_contact_model(twin, rec, warn=True)
print("nominal_creep [mm]:", None if rep.nominal_creep is None else round(rep.nominal_creep * 1e3, 2) if hasattr(rep, "nominal_creep") else "n/a")
print("findings:", [f.message[:160] for f in rep.findings])
print("warnings:", [str(x.message)[:200] for x in w])
sig = rec.signals
masks = twin.slip_masks(rec.controls, sig.contact_gripper, sig.contact_support)
c = masks.counted[:, 0]
idx = np.flatnonzero(c)
print("slip-counted steps:", len(idx), "first/last:", (idx[0], idx[-1]) if len(idx) else None, "of", len(c))
print("formed:", np.flatnonzero(np.asarray(masks.formed)[:, 0])[:1] if np.asarray(masks.formed).ndim == 2 else masks.formed)
from critmoment.groundtruth import hold_starts
held = np.asarray(sig.contact_gripper, bool) & ~np.asarray(sig.contact_support, bool)[:, None]
hs = hold_starts(held, masks.segments, masks.formed)
print("hold_starts at the first counted step:", hs[idx[0], 0] if len(idx) else None,
      "; at the last:", hs[idx[-1], 0] if len(idx) else None)
print("distinct hold starts over counted steps:", np.unique(hs[idx, 0])[:20] if len(idx) else None)
print("segments over counted steps:", np.unique(np.asarray(masks.segments)[idx, 0])[:20] if len(idx) else None)
