"""A scripted pick-and-place for HEXFELLOW's Archer Y6 (hex-driver-mujoco 0.1.1a5,
``mujoco_archer_y6/model/scene.xml`` as shipped: 6 torque motors, a parallel-linkage
gripper of six hinges coupled by five joint equalities on one torque motor, a free 4 cm
0.05 kg box (its free joint has frictionloss 0.01) dropped over a table, a target plate); the box starts at ``--box``, settled.

The arm is the scenario's twin (``critmoment.scenario.load_scenario(S).load_model()``: the
torque motors as init's ``[servos]``), so the joint targets carry the unloaded arm's inverse
dynamics (gravity, friction loss excluded) fed forward through those gains. DLS IK
(benchmarks/real_models/scripted.py) of a TCP ``--tcp`` metres out along grip_base_link's
x (the fingers' axis), fingers pointing down tilted ``--tilt`` toward +x (straight down is out of reach), spreading along world y; the real_models
500-step timeline at 50 Hz. Channels: joint_1..6
targets [rad], the gripper 0 closed (+8 N·m) .. 1 open (-8 N·m) — a torque, so ``--close``
sets the squeeze (0.5 is no torque).

Usage (the critmoment venv active, from this folder):
    python traj.py SCENARIO.toml OUT.npz [--close C] [--tcp X] [--steps N]
"""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

import mujoco
import numpy as np

REAL_MODELS = os.environ.get("CRITMOMENT_REAL_MODELS",
                             str(Path(__file__).absolute().parents[3] / "real_models"))
sys.path.insert(0, REAL_MODELS)
import scripted  # noqa: E402

from critmoment.scenario import load_scenario  # noqa: E402
from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402

JOINTS = tuple(f"joint_{i}" for i in range(1, 7))
HOME = np.zeros(6)
SEED = np.array([0.0, 0.21, 1.49, 0.94, 0.0, 0.0])


def main():
    p = argparse.ArgumentParser()
    p.add_argument("scenario")
    p.add_argument("out")
    p.add_argument("--close", type=float, default=0.0, help="gripper command when closed")
    p.add_argument("--tcp", type=float, default=0.165)
    p.add_argument("--tilt", type=float, default=0.5, help="fingers' tilt from vertical [rad]")
    p.add_argument("--transport", type=float, default=0.10)
    p.add_argument("--steps", type=int, default=500)
    p.add_argument("--goal", type=float, nargs=3, default=(0.45, 0.12, 0.32))
    p.add_argument("--box", type=float, nargs=2, default=(0.45, 0.0),
                   help="the box's start x y on the table (the trajectory's object_pose; the "
                        "shipped (0.5, 0) is beyond fingers-down reach)")
    a = p.parse_args()
    sc = load_scenario(a.scenario)
    model = sc.load_model()
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("home").id)
    qpos0 = data.qpos.copy()
    bj = model.jnt_qposadr[model.joint("red_box_joint").id]
    qpos0[bj:bj + 7] = [a.box[0], a.box[1], 0.32, 1, 0, 0, 0]
    box = qpos0[bj:bj + 7].copy()
    arm = scripted.Arm(model, JOINTS, "grip_base_link", ("red_box",), qpos0,
                       offset=np.array([a.tcp, 0.0, 0.0]))
    data.qpos[:] = qpos0
    mujoco.mj_kinematics(model, data)
    p0, r0 = arm.tcp(data)
    tilt = a.tilt  # fingers down, tilted toward +x (top-down is out of reach here)
    down = scripted._frame([np.sin(tilt), 0, -np.cos(tilt)], [0, 1, 0])
    goal = np.asarray(a.goal, float)
    grasp = box[:3]
    above = grasp + [0, 0, a.transport]
    place = goal + [0, 0, 0.002]
    over = place + [0, 0, a.transport]
    c, o = a.close, 1.0
    pts = [(0, p0, r0, o), (75, above, down, o), (125, grasp, down, o), (140, grasp, down, o),
           (165, grasp, down, c), (180, grasp, down, c), (230, above, down, c),
           (305, over, down, c), (355, place, down, c), (370, place, down, c),
           (395, place, down, o), (445, over, down, o), (500, over, down, o)]
    s = a.steps / 500.0
    pts = [(t * s, *r) for t, *r in pts]
    q, grip = scripted.joint_path(arm, data, pts, a.steps, start=HOME, seed=SEED)
    fps = 50.0
    actions = np.concatenate([arm.feed_forward(q, 1 / fps, qpos0), grip[:, None]], 1)
    start = np.concatenate([HOME, [1.0]])
    actions[0] = start
    t = Trajectory(actions=actions, fps=fps, start=start, qpos0=qpos0, object_pose=box,
                   meta={"generator": "probe_r25 archer traj"}, source="archer_pick_place")
    save_trajectory(t, a.out)
    print("wrote", a.out, actions.shape)


if __name__ == "__main__":
    main()
