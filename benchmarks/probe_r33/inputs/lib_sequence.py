"""One process: ALOHA, Panda, ALOHA (modified copy uscn), ALOHA again; each compared with
the same audit in a fresh CLI process (report.json apart from timings)."""
import json, os
from common import SCRATCH, log, strip, diff
import critmoment as cm
R = "lib_sequence.txt"
def audit(traj, scn):
    t = cm.load_trajectory(os.path.join(SCRATCH, traj))
    s = cm.load_scenario(scn)
    r = cm.analyze(t, s, options=cm.AnalyzeOptions(n_samples=16, seed=0))
    return json.loads(json.dumps(cm.report.jsonable(r.to_json())))
seq = [("traj.npz", None, "cons_base"), ("panda.npz", "panda_pick_place", "ex_default_panda"),
       ("traj.npz", os.path.join(SCRATCH, "uscn"), None), ("traj.npz", None, "cons_base")]
docs = []
for traj, scn, ref in seq:
    d = audit(traj, scn); docs.append(d)
    msg = f"{traj} {scn}: {d['verdict']} p={d['p_success']}"
    if ref:
        r = json.load(open(os.path.join(SCRATCH, ref, "report.json")))
        dd = [x for x in diff(strip(r), strip(d)) if "/manifest/trajectory" not in x and "warnings" not in x]
        msg += f" | vs fresh CLI {ref}: {len(dd)} diffs {dd[:3]}"
    log(R, msg)
log(R, f"first vs last ALOHA: {diff(strip(docs[0]), strip(docs[3]))[:3]}")
