"""The Shadow hand's fingers behind their closing command (plain MuJoCo, nominal run; probe_r36).
Replays TRAJ through SCENARIO's channels (as gen_shadow.py --check) and prints, at the given steps, the
gripper command, the largest |ctrl - actuator length| over the gripper channel's actuators (joint angle or
tendon length J1+J2), the gripper's summed joint speed, and the ball's height and speed.
usage: lag.py SCENE.xml TRAJ SCENARIO.toml STEP [STEP ...]"""
import sys, mujoco, numpy as np, tomllib
import critmoment; assert critmoment.__file__.startswith("/tmp/r36/src"), critmoment.__file__
from critmoment.trajectory import load_trajectory
scene, traj, toml, *at = sys.argv[1:]; at = {int(x) for x in at}
tr = load_trajectory(traj); ch = tomllib.load(open(toml, 'rb'))['actions']['channel']
m = mujoco.MjModel.from_xml_path(scene); d = mujoco.MjData(m)
qa = m.jnt_qposadr[m.joint("ball_joint").id]; d.qpos[qa:qa + 7] = tr.object_pose; mujoco.mj_forward(m, d)
gch = [c for c in ch if c.get("normalised")][0]; gids = [m.actuator(x).id for x in gch["actuators"]]
fj = [j for j in range(m.njnt) if m.joint(j).name.startswith("rh_") and "WR" not in m.joint(j).name]
steps = int(round(1 / tr.fps / m.opt.timestep)); k = 0
for a in tr.actions:
    for j, c in enumerate(ch):
        ids = [m.actuator(x).id for x in c["actuators"]]
        d.ctrl[ids] = (np.array(c["closed"]) + a[j] * (np.array(c["open"]) - np.array(c["closed"]))) if c.get("normalised") else a[j]
    for _ in range(steps):
        mujoco.mj_step(m, d); k += 1
        if k in at:
            lag = d.ctrl[gids] - d.actuator_length[gids]; i = int(np.abs(lag).argmax())
            sp = float(np.abs(d.qvel[[m.jnt_dofadr[j] for j in fj]]).sum())
            print(k, "grip command", round(float(a[[j for j, c in enumerate(ch) if c.get('normalised')][0]]), 4),
                  "max finger lag", round(float(abs(lag[i])), 3), gch["actuators"][i], "| finger joint speed sum [rad/s]", round(sp, 3),
                  "| ball z", round(float(d.qpos[qa + 2]), 4), "ball speed [mm/s]", round(float(np.linalg.norm(d.qvel[m.jnt_dofadr[m.joint('ball_joint').id]:][:3])) * 1e3, 1))
