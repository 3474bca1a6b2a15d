"""Per-variant Panda trajectories planned on the variant's own model, object at height z.
usage: python mktraj.py NAME Z [seed]"""
import sys

import mujoco

import critmoment.panda_demo as pd
from critmoment.trajectory import save_trajectory

name, z = sys.argv[1], float(sys.argv[2])
seed = int(sys.argv[3]) if len(sys.argv) > 3 else 0
orig = pd.sample_cube_pose
def pose(s):
    p = orig(s)
    p[2] = z
    return p
pd.sample_cube_pose = pose
m = mujoco.MjModel.from_xml_path(f"v/{name}/scene.xml")
t = pd.make_pick_place(seed, model=m)
save_trajectory(t, f"v/{name}/traj.npz")
print(name, t.object_pose)
