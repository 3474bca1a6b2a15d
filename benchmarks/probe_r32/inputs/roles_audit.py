"""F1 reproduction: a HandoverTask built in code whose grippers tuple is not in the scenario's
order is accepted and evaluated against the wrong contact columns."""
from common import *
from critmoment import task as TK
from critmoment.analysis import AnalyzeOptions
traj = cm.load_trajectory(TRAJ); sc = cm.load_scenario()
safe = sc.replace(box=sc.box.with_range("mass", 0.05, 0.2).with_range("friction", 0.5, 1.5))
g = sc.gripper_names
O = AnalyzeOptions(n_samples=32, nthread=1)
for label, task in (("as asked, scenario order: left picks, right receives", TK.HandoverTask(grippers=g, picker="left", receiver="right")),
                    ("same roles, task grippers reversed", TK.HandoverTask(grippers=g[::-1], picker="left", receiver="right"))):
    r = cm.analyze(traj, safe.replace(task=task), options=O)
    print(f"{label}: task says {r.scenario.task.describe()!r}\n   verdict {r.verdict.value}, P={r.p_success}, passes={r.passes()}, json task={r.to_json()['manifest'].get('task') if 'manifest' in r.to_json() else None}")
