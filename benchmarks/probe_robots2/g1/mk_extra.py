"""From traj.npz: traj_3ax.npz (no yaw channel, for scene_3ax.xml) and traj_hold.npz (stops
after the carry and holds 1 s, for the pick_hold scenario)."""
import numpy as np
a = np.load('traj.npz')['actions']
np.savez('traj_3ax.npz', actions=np.delete(a, 3, axis=1), fps=50.0)
i = int(round((1.0 + 0.8 + 0.4 + 0.2 + 0.8 + 1.5) * 50))
np.savez('traj_hold.npz', actions=np.concatenate([a[:i + 1], np.repeat(a[i:i + 1], 50, 0)]), fps=50.0)
