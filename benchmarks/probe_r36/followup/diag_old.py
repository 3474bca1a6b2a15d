"""OLD code (805c813) counterpart of diag.py: why a sample's verdict changed (NEW code): the nominal's formed step with and without its
readings (Twin.grasp_formed / slip_masks), and each sample's max grip slip [mm] under the four
combinations of anchor (touch: new / held: old) x formed (fingers still: new / command only).
usage: diag.py SCENARIO TRAJ VAL.json IDX [IDX ...]"""
import json, sys
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r36/src"), cm.__file__
from critmoment.trajectory import load_trajectory
from critmoment import groundtruth as gt
from critmoment.recording import prepare_controls, initial_state, batched_rollouts

scen, trajp, valp = sys.argv[1:4]; idx = [int(i) for i in sys.argv[4:]]
twin = cm.Twin(scen); traj = load_trajectory(trajp)
val = json.load(open(valp)); names = twin.scenario.box.names
S = np.array([[val['per_sample'][i]['values'][n] for n in names] for i in idx])
probe = gt._probe_of(twin); controls = prepare_controls(twin, traj); s0 = initial_state(twin, traj)
dt = float(twin.model.opt.timestep)
allv = np.vstack([twin.scenario.box.nominal[None], S])
sd = None
for first, out, _ in batched_rollouts(twin, s0, controls, allv, model=probe.model, chunk=64, nthread=1):
    sd = out['sensordata']
fr = gt._Frames.read(twin, probe, sd, twin.sample_limits(allv)); ref = fr.row(0)
m_new = twin.slip_masks(controls, ref.contact_gripper, ref.contact_support)
m_cmd = twin.slip_masks(controls, ref.contact_gripper, ref.contact_support)
def first(mask):
    return [int(np.argmax(mask[:, g])) if mask[:, g].any() else -1 for g in range(mask.shape[1])]
touch0 = [int(np.argmax(ref.contact_gripper[:, g])) for g in range(ref.contact_gripper.shape[1])]
lift0 = [int(np.argmax(ref.held[:, g])) if ref.held[:, g].any() else -1 for g in range(ref.held.shape[1])]
print(f"dt {dt}; nominal first touch {touch0}, first held (off support) {lift0}")
print(f"OLD CODE nominal formed step {first(m_new.formed)}")
c = gt._classify_frames(fr, ref, controls, probe, dt, gt.OutcomeCriteria(), np.zeros(len(allv), bool),
                        np.full(len(allv), -1, np.int64), m_new)
for i in range(1, len(allv)):
    f = fr.row(i)
    res = {}
    for mk, m in (('old', m_new),):
        for an, kw in (('held', {}),):
            s = gt.grip_slip(f.position[None], ref.position, f.held[None], ref.held, counted=m.counted,
                             projectors=probe.projectors, segments=m.segments, formed=m.formed, **kw)[0]
            res[f"{an}/{mk}"] = f"{1e3*float(s.max()):.2f}@{int(s.argmax())}"
    ft = [int(np.argmax(f.contact_gripper[:, g])) for g in range(f.contact_gripper.shape[1])]
    fh = [int(np.argmax(f.held[:, g])) if f.held[:, g].any() else -1 for g in range(f.held.shape[1])]
    print(f"sample {idx[i-1]} {dict(zip(names, np.round(allv[i], 4)))}: first touch {ft} held {fh}; "
          f"outcome(OLD) {c.outcome[i]} step {c.first_failure_step[i]}; max slip mm@step anchor/formed: {res}")
