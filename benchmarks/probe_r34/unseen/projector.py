"""The slip projector critmoment builds for a scenario's grippers, and what it drops.

usage: projector.py SCENARIO [SCENARIO ...]

critmoment measures slip in the gripper base's frame after projecting out the fingers' slide
(closing) axes: groundtruth._closing_projector (the ground truth's slip), sparse.grip_frames
(the sparse evaluation's slip and the contact-model creep check). Both keep the singular
directions of the stacked slide axes with s > 1e-9 * s.max(): two finger axes that are the
same line up to ~1e-8 (round-off of a shipped quat) count as two axes, and a second
direction of the base frame is dropped with the closing axis.
"""
import sys

import numpy as np

import critmoment as cm
assert cm.__file__.startswith("/tmp/r34/src"), cm.__file__
from critmoment.groundtruth import _closing_projector
from critmoment.sparse import grip_frames

for path in sys.argv[1:]:
    twin = cm.Twin(path)
    m = twin.model
    anchors, projs = grip_frames(m, twin.scenario)
    for g, gr in enumerate(twin.scenario.grippers):
        gt = _closing_projector(m, gr.geoms, int(anchors[g]))
        rank_kept = int(round(np.trace(gt)))
        print(f"{path}: gripper {gr.name!r}, base {m.body(int(anchors[g])).name!r}: "
              f"ground-truth projector keeps {rank_kept} of 3 directions "
              f"(diag {np.round(np.diag(gt), 3).tolist()}); sparse keeps "
              f"{int(round(np.trace(projs[g])))} (diag {np.round(np.diag(projs[g]), 3).tolist()})")

# the arithmetic alone: four pads on two fingers whose slide axes differ by 4.2e-6 rad
# (the PiPER's: link7/link8 quats 0.707108 / 0.707105 rounded to 6 digits)
axes = np.array([[0, -1, 4.2e-6], [0, -1, 4.2e-6], [0, -1, -4.2e-6], [0, -1, -4.2e-6]])
s = np.linalg.svd(axes.T, compute_uv=False)
print("singular values", s, "-> kept as axes:", int((s > 1e-9 * s.max()).sum()), "(1 expected)")
