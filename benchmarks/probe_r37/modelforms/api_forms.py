"""Model objects handed to the Python API where a path is expected (no documented string/MjSpec entry).

Run: PYTHONPATH=/tmp/r37/src /work/venv/bin/python api_forms.py
"""
import traceback
from pathlib import Path

import mujoco

import common  # noqa: F401
from critmoment import CritmomentError, inspect_model, init_scenario, load_scenario
from critmoment.twin import Twin

scene = "/tmp/r37/modelforms/base/scene.xml"
xml = Path(scene).read_text()
spec = mujoco.MjSpec.from_file(scene)
model = spec.compile()
sc = load_scenario("/tmp/r37/modelforms/base/init.toml")


def t(name, fn):
    try:
        r = fn()
        print(f"{name}: OK {type(r).__name__}")
    except CritmomentError as e:
        print(f"{name}: CritmomentError {type(e).__name__}: {str(e)[:220]}")
    except Exception as e:  # noqa: BLE001
        print(f"{name}: OTHER {type(e).__name__}: {str(e)[:220]}")
        traceback.print_exc(limit=2)


t("inspect_model(MjSpec)", lambda: inspect_model(spec))
t("inspect_model(MjModel)", lambda: inspect_model(model))
t("inspect_model(xml string)", lambda: inspect_model(xml))
t("inspect_model(bytes path)", lambda: inspect_model(scene.encode()))
t("init_scenario(MjSpec)", lambda: init_scenario(spec, object_body="cube", task="pick_hold"))
t("Scenario.replace(mjcf=MjSpec)", lambda: Twin(sc.replace(mjcf=spec)))
t("Scenario.replace(mjcf=xml string)", lambda: Twin(sc.replace(mjcf=xml)))
t("Scenario.replace(mjcf=relative str)", lambda: Twin(sc.replace(mjcf="scene.xml")))
t("Twin(MjModel)", lambda: Twin(model))
