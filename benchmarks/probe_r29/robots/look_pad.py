"""Where does a held object move: in the gripper base frame vs in each pad's frame (plain MuJoCo,
truth.Setup's rollout of one parameter point, recomputing positions from its qpos history).
usage: look_pad.py SCENARIO TRAJ MASS FRICTION BASE_BODY PAD_BODY [PAD_BODY...]"""
import sys
import numpy as np
import mujoco
sys.path.insert(0, __file__.rsplit("/", 1)[0])
import truth

scen, traj, mass, fr, base, *pads = sys.argv[1:]
s = truth.Setup(scen, traj)
r = s.rollout([float(mass), float(fr)])
m = s.model; d = mujoco.MjData(m)
obj = m.body(s.cfg["object"]["body"]).id
ids = [m.body(b).id for b in [base] + pads]
drv = [j for j in range(m.njnt) if "driver" in m.joint(j).name]
print("step  " + "  ".join(f"{b}-frame(mm)" for b in [base] + pads) + "  driver joints")
ref = None
n = len(r["qpos_s"])  # qpos every 50 steps
for i in list(range(30, n, 3)) + [n - 1]:
    t = 50 * i
    d.qpos[:] = r["qpos_s"][i]; mujoco.mj_kinematics(m, d)
    rows = []
    for b in ids:
        R = d.xmat[b].reshape(3, 3); rows.append(R.T @ (d.xpos[obj] - d.xpos[b]))
    rows = np.array(rows) * 1000
    if ref is None and t >= 1600: ref = rows.copy()
    rel = rows - (ref if ref is not None else rows)
    print(t, "  ".join(np.array2string(x, precision=1, suppress_small=True) for x in rel),
          np.round([d.qpos[m.jnt_qposadr[j]] for j in drv], 3))
