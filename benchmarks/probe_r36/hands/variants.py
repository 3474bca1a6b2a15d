"""Scenario and trajectory variants for the tendon checks (probe_r36), written next to ph*.toml in the scene dir:
  ph_ell_fl.toml      ph_ell_narrow.toml + a force_limit parameter on the tendon actuator rh_A_MFJ0 (0.2-1.0)
  ph_ell_limkey.toml  [limits] keyed by the tendon's name (rh_FFJ0); ph_ell_limbad.toml the same with an unknown key
  ph_tendonch.toml    ph.toml with rh_A_FFJ0 (tendon) taken out of the gripper channel into its own joint-space
                      channel, range_policy = "error"; nom_tendon_ok.npz (that channel 0 -> 2.0), nom_tendon_over.npz
                      (0 -> 3.5, above the actuator's ctrlrange 0..3.1415), nom_joint_over.npz (RFJ3 joint channel
                      0 -> 3.5, above its range 1.5708) for comparison.
usage (in the scene dir): variants.py"""
import re
import numpy as np
import critmoment
assert critmoment.__file__.startswith('/tmp/r36/src'), critmoment.__file__
from critmoment.trajectory import load_trajectory, save_trajectory, Trajectory
s = open('ph_ell_narrow.toml').read()
add = ('\n[uncertainty.tendon_force]   # probe_r36: the middle finger\'s distal tendon actuator\'s force limit\n'
       'kind = "force_limit"\nactuator = "rh_A_MFJ0"\nrange = [0.2, 1.0]\nnominal = 1.0\n')
i = s.index('[cost]'); open('ph_ell_fl.toml', 'w').write(s[:i] + add + '\n' + s[i:])
open('ph_ell_limkey.toml', 'w').write(s.replace('[limits]\n', '[limits]\nrh_FFJ0 = 0.8   # probe_r36: keyed by the tendon name\n', 1))
open('ph_ell_limbad.toml', 'w').write(s.replace('[limits]\n', '[limits]\nrh_NOPE0 = 0.8\n', 1))
s = open('ph.toml').read()
acts = ["rh_A_THJ4", "rh_A_THJ2", "rh_A_THJ1", "rh_A_FFJ4", "rh_A_FFJ3", "rh_A_FFJ0", "rh_A_MFJ3", "rh_A_MFJ0", "rh_A_RFJ4", "rh_A_RFJ0", "rh_A_LFJ4", "rh_A_LFJ3", "rh_A_LFJ0"]
closed = [1.2, 0.3, 0.8, 0.0, 1.1, 2.0, 1.1, 2.0, 0.0, 2.0, 0.0, 1.1, 2.0]; opn = [0.0, 0.0, 0.0, 0.05, 0.0, 0.0, 0.0, 0.0, 0.05, 0.0, 0.05, 0.0, 0.0]
k = acts.index("rh_A_FFJ0"); a2 = acts[:k] + acts[k + 1:]; c2 = closed[:k] + closed[k + 1:]; o2 = opn[:k] + opn[k + 1:]
s = s.replace('actuators = ' + str(acts).replace("'", '"'), 'actuators = ' + str(a2).replace("'", '"'), 1)
s = re.sub(r'(?m)^closed = .*$', 'closed = ' + str(c2), s, count=1); s = re.sub(r'(?m)^open = .*$', 'open = ' + str(o2), s, count=1)
s = s.replace('[task]', '[[actions.channel]]\nactuators = ["rh_A_FFJ0"]   # probe_r36: the index finger tendon as a joint-space channel\n\n[task]', 1)
s = s.replace('range_policy = "warn"', 'range_policy = "error"', 1)
open('ph_tendonch.toml', 'w').write(s)
tr = load_trajectory('nom.npz'); g = tr.actions[:, 4]
def save(act, name):
    save_trajectory(Trajectory(actions=act, fps=tr.fps, start=act[0], object_pose=tr.object_pose,
                               meta={"generator": "probe_r36 variants"}, source="variants"), name)
for name, top in (("ok", 2.0), ("over", 3.5)):
    save(np.hstack([tr.actions, ((1 - g) * top)[:, None]]), f'nom_tendon_{name}.npz')
act = np.hstack([tr.actions, ((1 - g) * 2.0)[:, None]]); act[:, 7] = (1 - g) * 3.5
save(act, 'nom_joint_over.npz')
print("wrote ph_ell_fl.toml ph_ell_limkey.toml ph_ell_limbad.toml ph_tendonch.toml nom_tendon_ok.npz nom_tendon_over.npz nom_joint_over.npz")
