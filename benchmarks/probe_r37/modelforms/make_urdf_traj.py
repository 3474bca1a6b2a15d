"""Scripted pick-and-place for the URDF gantry (/tmp/r37/modelforms/urdf): channels ax, ay, az, gripper."""
import numpy as np

import common  # noqa: F401

keys = [  # t [s], x, y, z, grip (1 open)
    (0.0, 0.0, 0.0, -0.2, 1), (1.0, 0.0, -0.15, -0.25, 1), (2.0, 0.0, -0.15, -0.375, 1),
    (2.6, 0.0, -0.15, -0.375, 0), (3.6, 0.0, -0.15, -0.25, 0), (5.1, 0.0, 0.15, -0.25, 0),
    (6.1, 0.0, 0.15, -0.372, 0), (6.6, 0.0, 0.15, -0.372, 1), (7.6, 0.0, 0.15, -0.2, 1), (8.5, 0.0, 0.15, -0.2, 1)]
fps = 50.0
t = np.arange(0, 8.5 + 1e-9, 1 / fps)
k = np.array(keys)
acts = np.stack([np.interp(t, k[:, 0], k[:, i]) for i in range(1, 5)], axis=1)
np.savez("/tmp/r37/modelforms/urdf/gantry.npz", actions=acts, fps=fps,
         object_pose=np.array([0.5, -0.15, 0.02, 1, 0, 0, 0.0]))
print(acts.shape)
