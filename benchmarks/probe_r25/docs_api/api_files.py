"""Scenario/model files changed on disk between two calls in one process: does the second call
see the change (no stale cache)?

    python api_files.py WORKDIR
"""
import json
import shutil
import sys
from pathlib import Path

import critmoment.models

import critmoment as cm
from critmoment import demos

work = Path(sys.argv[1] if len(sys.argv) > 1 else "/tmp/r25/docs_api/b_files")
shutil.rmtree(work, ignore_errors=True)
src = Path(critmoment.models.__file__).parent / "aloha_transfer_cube"
shutil.copytree(src, work / "sc")
toml = work / "sc" / "scenario.toml"
scene = work / "sc" / "scene.xml"
traj = demos.scripted_transfer(seed=0)
opts = cm.AnalyzeOptions(n_samples=32, seed=0)


def audit(label):
    r = cm.analyze(traj, str(toml), options=opts)
    d = r.to_json(timings=False)
    print(f"{label}: {r.verdict.value} P={r.p_success:.4f} box={ {k: v['range'] for k, v in d['uncertainty'].items()} } "
          f"scenario_sha={d['manifest']['scenario_sha256'][:10]} model_sha={d['manifest']['model_sha256'][:10]}")
    return d


a = audit("original")
text = toml.read_text()
i = text.index("[uncertainty.mass]")
j = text.index("range", i)
k = text.index("\n", j)
print("mass line was:", text[j:k])
toml.write_text(text[:j] + "range = [0.05, 0.2]" + text[k:])
b = audit("mass range 0.05-0.2 (same path)")
print("second call sees the TOML change:", a["uncertainty"] != b["uncertainty"])
# change the model: a heavier nominal cube (the MJCF body mass) and a lower friction on its geom
xml = scene.read_text()
print("scene mentions box:", xml.count('name="box"'))
toml.write_text(text)
c = audit("TOML restored")
print("restored == original:", json.dumps(c, sort_keys=True) == json.dumps(a, sort_keys=True))
xml2 = xml.replace('<option ', '<option gravity="0 0 -20" ', 1) if '<option ' in xml else xml
scene.write_text(xml2)
print("scene edited (gravity doubled):", xml2 != xml)
e = audit("scene gravity -20 (same path)")
print("second call sees the MJCF change:", e["manifest"]["model_sha256"] != a["manifest"]["model_sha256"],
      "P changed:", e["p_success"] != a["p_success"])
scene.write_text(xml)
f = audit("scene restored")
print("restored == original:", json.dumps(f, sort_keys=True) == json.dumps(a, sort_keys=True))
# a Twin built before a change keeps its compiled model (expected); does the report say which?
twin = cm.Twin(cm.load_scenario(str(toml)))
toml.write_text(text[:j] + "range = [0.05, 0.2]" + text[k:])
r = cm.analyze(traj, twin=twin, options=opts)
print("twin built before the TOML edit:", r.verdict.value, r.p_success,
      "manifest scenario_sha256 == original file's:", r.to_json()["manifest"]["scenario_sha256"] == a["manifest"]["scenario_sha256"])
