"""Per-step CPU of a full own run on the demo (seed 0): the twin's model (what a chain steps)
against the ground truth's probe model (extra sensors, what a verification rollout steps),
same 9 points (the demo's verification points), nthread=1, recording sensordata."""
import sys, time
import numpy as np
sys.path.insert(0, "/tmp/r30/src")
import critmoment as cm
from critmoment import suite, groundtruth as gt
from critmoment.recording import prepare_controls, initial_state, simulate
import mujoco.batch
twin = cm.Twin(cm.load_scenario("aloha_transfer_cube"))
traj = suite.make("nominal", seed=0, scenario="aloha_transfer_cube")
pts = np.array([[1.0901523049455135, 1.4777014057151974], [0.35249112509191033, 0.42482039695605633],
                [0.5120130193419754, 0.6155654611065984], [0.7837147226557135, 1.2994439103640616],
                [0.5669243437703699, 0.7217213976196946], [0.8393472526688128, 1.4182976268231868],
                [0.597766743041575, 0.8941555447876455], [0.4103843030519783, 0.48547396026551726],
                [0.682519537769258, 1.100801436509937]])
controls = prepare_controls(twin, traj); state0 = initial_state(twin, traj)
probe = gt._probe_of(twin)
print("nsensordata twin", twin.model.nsensordata, "probe", probe.model.nsensordata)
for rep in range(2):
    for name, model in (("twin", twin.model), ("probe", probe.model)):
        b = mujoco.batch.Batch(model, len(pts), nthread=1)
        c0 = time.process_time()
        out = simulate(twin, state0, controls, samples=pts, nthread=1, batch=b)
        c = time.process_time() - c0
        print(rep, name, f"{c:.3f} s CPU, {1e6 * c / (len(pts) * controls.shape[0]):.1f} us/step")
