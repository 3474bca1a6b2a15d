"""probe_r38: a still 2 s trajectory for the single TIAGo (arm at keyframe 'home', gripper open) to check that the
hand-written scenario (scenarios/tiago1/pp_manual.toml) runs: `cm.sh rollout still.npz --scenario pp_manual.toml`.
usage (in /tmp/r38/robots/probe/tiago1): tiago1_still.py"""
import mujoco, numpy as np, critmoment
assert critmoment.__file__.startswith("/tmp/r38/robots/src")
from critmoment.trajectory import Trajectory, save_trajectory
m = mujoco.MjModel.from_xml_path("scene_tiago1.xml"); d = mujoco.MjData(m); mujoco.mj_resetDataKeyframe(m, d, 0)
arm = [d.qpos[m.joint(f"arm_{i}_joint").qposadr[0]] for i in range(1, 8)]
row = np.array(arm + [1.0]); acts = np.repeat(row[None], 100, 0)
cj = m.joint("cube_joint").qposadr[0]
t = Trajectory(actions=acts, fps=50.0, start=row.copy(), qpos0=d.qpos.copy(), object_pose=d.qpos[cj:cj + 7].copy(),
               meta={"generator": "probe_r38 tiago1 still"}, source="tiago1_still")
save_trajectory(t, "still.npz"); print("wrote still.npz", acts.shape)
