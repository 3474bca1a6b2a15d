"""Build odd .npz trajectory inputs under /tmp/r28/cli/in from the demo (seed 0)."""
import json
import os
import shutil
import zipfile

import numpy as np

D = "/tmp/r28/cli/in"; os.makedirs(D, exist_ok=True)
z = np.load("/tmp/r28/cli/readme/traj.npz"); A = z["actions"]; base = {k: z[k] for k in z.files}
def save(name, **kw):
    d = dict(base)
    for k, v in kw.items():
        if v is None: d.pop(k, None)
        else: d[k] = v
    np.savez(os.path.join(D, name), **d)
save("int_actions.npz", actions=np.round(A).astype(np.int64))
save("f32.npz", actions=A.astype(np.float32), start=base["start"].astype(np.float32))
save("f16.npz", actions=A.astype(np.float16))
save("bool_actions.npz", actions=A > 0)
save("complex_actions.npz", actions=A.astype(np.complex128))
save("oned.npz", actions=A[:, 0])
save("wide.npz", actions=np.hstack([A, A[:, :1]]))
save("narrow.npz", actions=A[:, :13])
save("T1.npz", actions=A[:1])
save("T2.npz", actions=A[:2])
save("T3.npz", actions=A[:3])
save("T0.npz", actions=A[:0])
save("3d.npz", actions=A[None])
save("obj_actions.npz", actions=A.astype(object))
save("str_actions.npz", actions=A.astype(str))
save("nan_actions.npz", actions=np.where(np.arange(A.size).reshape(A.shape) == 100, np.nan, A))
save("inf_actions.npz", actions=np.where(np.arange(A.size).reshape(A.shape) == 100, np.inf, A))
save("no_actions.npz", actions=None, action=A)
save("extra_key.npz", foo=np.arange(3))
save("fps0.npz", fps=np.float64(0))
save("fpsneg.npz", fps=np.float64(-50))
save("fps1e6.npz", fps=np.float64(1e6))
save("fps_nan.npz", fps=np.float64(np.nan))
save("fps_str.npz", fps=np.array("50"))
save("fps_arr.npz", fps=np.array([50.0, 50.0]))
save("fps_int.npz", fps=np.int64(50))
save("fps_bool.npz", fps=np.bool_(True))
save("fps_500.npz", fps=np.float64(500))
save("fps_501.npz", fps=np.float64(501))
save("fps_tiny.npz", fps=np.float64(0.01))
save("fps_49.npz", fps=np.float64(49.0))  # scenario says 50: >1% differ -> warning
T = len(A); t = np.arange(T) / 50.0
save("time_ok.npz", fps=None, time=t)
save("time_ok_disagree.npz", time=t * 2)   # fps 50 + time says 25
save("time_dec.npz", fps=None, time=t[::-1].copy())
save("time_nonuni.npz", fps=None, time=t ** 1.1)
save("time_dup.npz", fps=None, time=np.r_[t[:10], t[9:-1]])
save("time_short.npz", fps=None, time=t[:-1])
save("time_2d.npz", fps=None, time=t[:, None])
save("time_nan.npz", fps=None, time=np.r_[t[:-1], np.nan])
save("time_offset.npz", fps=None, time=t + 1e9)  # epoch-ish timestamps
save("time_jitter.npz", fps=None, time=t + np.random.default_rng(0).uniform(-1e-4, 1e-4, T))
save("meta_bad.npz", meta=np.array("{not json"))
save("meta_list.npz", meta=np.array("[1,2]"))
save("meta_bytes.npz", meta=np.array(b'{"a":1}'))
save("meta_none.npz", meta=None)
save("meta_scn_unknown.npz", meta=np.array(json.dumps({"scenario": "nope_scenario"})))
save("meta_scn_path.npz", meta=np.array(json.dumps({"scenario": "/etc/passwd"})))
save("meta_scn_panda.npz", meta=np.array(json.dumps({"scenario": "panda_pick_place"})))
save("meta_scn_int.npz", meta=np.array(json.dumps({"scenario": 5})))
save("start_wrong.npz", start=base["start"][:5])
save("start_far.npz", start=base["start"] + 50)
save("no_start.npz", start=None)
save("pose_bad.npz", object_pose=np.array([0, 0, 0, 0, 0, 0, 0.0]))
save("pose_short.npz", object_pose=np.array([0, 0.5, 0.02]))
save("pose_nonunit.npz", object_pose=np.array([0.127, 0.454, 0.0125, 2, 0, 0, 0.0]))
save("pose_inside_table.npz", object_pose=np.array([0.127, 0.454, -0.5, 1, 0, 0, 0.0]))
save("pose_far.npz", object_pose=np.array([100, 100, 100, 1, 0, 0, 0.0]))
save("no_pose.npz", object_pose=None)
save("qpos0_wrong.npz", qpos0=np.zeros(3))
save("qvel0_alone.npz", qvel0=np.zeros(3))
save("out_of_range.npz", actions=np.where(np.arange(A.size).reshape(A.shape) == 100, 7.0, A))
save("big_T.npz", actions=np.tile(A, (30, 1)))  # 240 s
# pickled object array
np.savez(os.path.join(D, "pickled.npz"), actions=np.array([A, 1], dtype=object), fps=50.0)
# truncated / corrupted zip
b = open("/tmp/r28/cli/readme/traj.npz", "rb").read()
open(os.path.join(D, "truncated.npz"), "wb").write(b[: len(b) // 2])
bb = bytearray(b); bb[200:260] = b"\xff" * 60
open(os.path.join(D, "corrupt.npz"), "wb").write(bytes(bb))
open(os.path.join(D, "empty.npz"), "wb").write(b"")
open(os.path.join(D, "text.npz"), "w").write("hello\n")
np.save(os.path.join(D, "plain.npy"), A)
shutil.copy(os.path.join(D, "plain.npy"), os.path.join(D, "npy_as.npz"))
# npz with compressed
np.savez_compressed(os.path.join(D, "compressed.npz"), **base)
# npz with a nested dir entry
with zipfile.ZipFile(os.path.join(D, "zipdir.npz"), "w") as zf:
    for k, v in base.items():
        import io; bio = io.BytesIO(); np.save(bio, v); zf.writestr("sub/" + k + ".npy", bio.getvalue())
# names
shutil.copy("/tmp/r28/cli/readme/traj.npz", os.path.join(D, "with space ü é.npz"))
shutil.copy("/tmp/r28/cli/readme/traj.npz", os.path.join(D, "-dash.npz"))
shutil.copy("/tmp/r28/cli/readme/traj.npz", os.path.join(D, "upper.NPZ"))
shutil.copy("/tmp/r28/cli/readme/traj.npz", os.path.join(D, "noext"))
os.makedirs(os.path.join(D, "dir.npz"), exist_ok=True)
for n in ("link.npz",):
    p = os.path.join(D, n)
    if os.path.lexists(p): os.remove(p)
os.symlink("/tmp/r28/cli/readme/traj.npz", os.path.join(D, "link.npz"))
if os.path.lexists(os.path.join(D, "dangling.npz")): os.remove(os.path.join(D, "dangling.npz"))
os.symlink("/nonexistent/x.npz", os.path.join(D, "dangling.npz"))
shutil.copy("/tmp/r28/cli/readme/traj.npz", os.path.join(D, "unreadable.npz")); os.chmod(os.path.join(D, "unreadable.npz"), 0)
# latin-1 bytes in filename
try:
    fn = os.path.join(D.encode(), b"lat\xe9.npz"); shutil.copy("/tmp/r28/cli/readme/traj.npz", fn)
except Exception as e: print("latin", e)
print("done", len(os.listdir(D)))
