"""One sample's full rollout as critmoment runs it: brute_force classification (max slip, steps),
and the object's end position from a rollout of a scenario copy whose nominal is the sample.
usage: check_sample.py SCENARIO_DIR TRAJ name=value [name=value ...]"""
import pathlib, re, shutil, sys, tempfile
import numpy as np
import critmoment as cm
assert cm.__file__.startswith("/tmp/r32/src"), cm.__file__
from critmoment.groundtruth import brute_force
from critmoment.trajectory import load_trajectory

src = pathlib.Path(sys.argv[1]); traj = load_trajectory(sys.argv[2])
vals = dict(a.split("=") for a in sys.argv[3:]); vals = {k: float(v) for k, v in vals.items()}
twin = cm.Twin(str(src))
names = [p.name for p in twin.scenario.box.parameters]
bf = brute_force(traj, twin=twin, samples=np.array([[vals[n] for n in names]]), nthread=1); c = bf.classification
print("brute_force:", bf.outcome[0].value, "completed", bool(c.completed[0]), "first_fail", int(c.first_failure_step[0]),
      "slip_step", int(c.slip_step[0]), "drop_step", int(c.drop_step[0]), "motor_step", int(c.motor_step[0]),
      f"max_slip {1000*float(c.max_slip[0]):.2f} mm (tolerance {1000*c.criteria.slip_tolerance:.1f} mm)")
tmp = pathlib.Path(tempfile.mkdtemp()); d = tmp / src.name; shutil.copytree(src, d)
t = (d / "scenario.toml").read_text()
for n, v in vals.items():
    t, k = re.subn(rf"(\[uncertainty\.{n}\](?:(?!\n\[).)*?\nnominal = )[-0-9.e]+", rf"\g<1>{v!r}", t, flags=re.S)
    assert k == 1, (n, k)
(d / "scenario.toml").write_text(t)
tw2 = cm.Twin(str(d)); rec = cm.rollout(traj, twin=tw2)
pos = np.asarray(rec.signals.object_pos); goal = np.asarray(tw2.scenario.task.goal, float)
print("rollout with nominal = sample: completed", rec.completed, "end object_pos", np.round(pos[-1], 4),
      "goal", goal, f"goal distance {np.linalg.norm(pos[-1]-goal)*100:.2f} cm")
shutil.rmtree(tmp)
