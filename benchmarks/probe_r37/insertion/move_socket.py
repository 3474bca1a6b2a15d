"""Copy a trajectory npz with the socket's start moved by (dx, dy) in qpos0 (the arms' motion unchanged):
the left arm then closes beside the socket. usage: move_socket.py IN.npz OUT.npz DX DY"""
import sys

import critmoment
assert critmoment.__file__.startswith("/tmp/r37/src"), critmoment.__file__
import mujoco
import numpy as np

src, dst, dx, dy = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
m = mujoco.MjModel.from_xml_path("/tmp/r37/insertion/gym_aloha/assets/bimanual_viperx_insertion.xml")
z = dict(np.load(src, allow_pickle=True))
a = m.jnt_qposadr[m.joint("blue_socket_joint").id]
z["qpos0"] = z["qpos0"].copy()
z["qpos0"][a:a + 2] += [dx, dy]
np.savez(dst, **z)
print("socket start", z["qpos0"][a:a + 3])
