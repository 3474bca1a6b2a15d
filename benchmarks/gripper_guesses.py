"""``critmoment inspect``/``init``'s gripper guesses on robosuite's grippers, each on its
Panda arm: which actuators make a gripper, which are wrists or finger joints.

Not run in CI: it reads robosuite's wheel (``pip download robosuite --no-deps``, never
installed; see ``benchmarks/real_models/scenes.py``) from ``$CRITMOMENT_REAL_MODELS``. Each
gripper is attached to the Panda's hand as robosuite does (the arm's torque motors made
position servos, a table and a free 4 cm cube added); the script prints the guessed
grippers and init's notes, and whether ``init --task pick_place`` writes a scenario that
loads. See docs/real_models.md (twentieth round).

Usage::

    python benchmarks/gripper_guesses.py
"""

from __future__ import annotations

import sys
import warnings
import zipfile
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent / "real_models"))
import scenes  # noqa: E402

from critmoment.exceptions import CritmomentError  # noqa: E402
from critmoment.modelinfo import init_scenario, inspect_model  # noqa: E402

GRIPPERS = ("panda_gripper", "rethink_gripper", "robotiq_gripper_85", "robotiq_gripper_140",
            "jaco_three_finger_gripper", "robotiq_gripper_s", "bd_gripper",
            "inspire_right_hand", "fourier_right_hand", "wiping_gripper")


def _assets() -> Path:
    """robosuite's whole ``models/assets`` folder, unzipped from its wheel once."""
    scenes.fetch("robosuite")  # downloads the wheel when it is not cached
    out = scenes.CACHE / "robosuite_all"
    marker = out / ".unzipped"
    if not marker.is_file():
        wheel = sorted((scenes.CACHE / "wheels").glob("robosuite-*.whl"))[-1]
        with zipfile.ZipFile(wheel) as z:
            z.extractall(out, members=[n for n in z.namelist()
                                       if n.startswith("robosuite/models/assets/")])
        marker.write_text(wheel.name)
    return out / "robosuite" / "models" / "assets"


def compose(assets: Path, gripper: str) -> Path:
    """The Panda with ``gripper`` on its hand, a table and a free cube."""
    arm_path = assets / "robots" / "panda" / "robot.xml"
    grip_path = assets / "grippers" / f"{gripper}.xml"
    arm = mujoco.MjSpec.from_file(str(arm_path))
    scenes._absolute_assets(arm, arm_path.parent)
    grip = mujoco.MjSpec.from_string(scenes._dedup_meshes(grip_path.read_text()))
    grip.compiler.degree = False  # robosuite merges it under the robot's radians
    scenes._absolute_assets(grip, grip_path.parent)
    arm.body("right_hand").add_frame().attach_body(grip.worldbody.first_body(), "gripper0_", "")
    for motor in list(arm.actuators):
        if motor.target.startswith("joint"):
            limit = float(max(abs(motor.ctrlrange[0]), abs(motor.ctrlrange[1])))
            joint = arm.joint(motor.target)
            arm.delete(motor)
            servo = arm.add_actuator(name=f"{joint.name}_servo", target=joint.name,
                                     trntype=mujoco.mjtTrn.mjTRN_JOINT)
            servo.set_to_position(kp=300.0, kv=10.0)
            servo.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
            servo.ctrlrange = joint.range
            servo.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
            servo.forcerange = np.array([-limit, limit])
    arm.body("base").pos = np.array([-0.56, 0.0, 0.8])
    world = arm.worldbody
    table = world.add_body(name="table", pos=[0, 0, 0.4])
    table.add_geom(name="table_collision", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.4, 0.4, 0.4])
    cube = world.add_body(name="cube", pos=[0, 0, 0.82])
    cube.add_freejoint(name="cube_joint")
    cube.add_geom(name="cube", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.02] * 3, mass=0.1,
                  condim=4)
    world.add_site(name="goal", pos=[0, 0.2, 0.82], size=[0.01] * 3)
    arm.option.timestep = 0.002
    return scenes._write(arm, f"panda_{gripper}")


def main() -> None:
    assets = _assets()
    for gripper in GRIPPERS:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            path = compose(assets, gripper)
            info = inspect_model(path)
            print(f"{gripper}:")
            for g in info.grippers:
                print(f"  gripper on body {g.body!r}: actuators {', '.join(g.actuators)}")
            for note in info.notes:
                if "unnamed" not in note and "soft friction" not in note:
                    print(f"  note: {note}")
            try:
                init_scenario(path, object_body="cube", task="pick_place", goal_site="goal",
                              out=path.with_suffix(".toml"), overwrite=True)
                print("  init: the scenario loads")
            except CritmomentError as exc:
                print(f"  init: {type(exc).__name__}: {exc}")


if __name__ == "__main__":
    main()
