"""Keyframe adoption sweep: every compilable MJCF with keyframes under the given roots,
critmoment.modelinfo.keyframe_problems(model, 0) (new code). Prints one JSON line per model
with keyframes. usage: PYTHONPATH=/tmp/r29b/src python kf_sweep.py ROOT... > out.jsonl"""
import json, os, sys, signal
import mujoco
import critmoment
from critmoment.modelinfo import keyframe_problems
print("# critmoment", critmoment.__file__, file=sys.stderr)

def handler(*a):
    raise TimeoutError()
signal.signal(signal.SIGALRM, handler)
seen = set()
for root in sys.argv[1:]:
    for d, _, files in os.walk(root):
        for f in sorted(files):
            if not f.endswith(".xml"):
                continue
            p = os.path.join(d, f)
            try:
                txt = open(p, errors="ignore").read()
            except OSError:
                continue
            if "<key" not in txt and "<include" not in txt:
                continue
            signal.alarm(20)
            try:
                m = mujoco.MjModel.from_xml_path(p)
            except BaseException as e:
                signal.alarm(0)
                continue
            signal.alarm(0)
            if m.nkey == 0:
                continue
            sig = (m.nq, m.nbody, m.ngeom, float(m.key_qpos[0].sum()))
            dup = sig in seen
            seen.add(sig)
            try:
                probs = keyframe_problems(m, 0)
            except Exception as e:
                probs = [f"ERROR {type(e).__name__}: {e}"]
            print(json.dumps({"xml": p, "nkey": int(m.nkey), "key0": m.key(0).name,
                              "neq": int(m.neq), "nmocap": int(m.nmocap), "dup": dup,
                              "problems": probs}), flush=True)
