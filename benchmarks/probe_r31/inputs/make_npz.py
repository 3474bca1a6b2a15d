"""Build odd .npz trajectory inputs under /tmp/r31/inputs/in from the demo (seed 0)."""
import json
import os
import shutil
import zipfile

import numpy as np

D = "/tmp/r31/inputs/in"; os.makedirs(D, exist_ok=True)
z = np.load("/tmp/r31/inputs/traj.npz"); A = z["actions"]; base = {k: z[k] for k in z.files}
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
b = open("/tmp/r31/inputs/traj.npz", "rb").read()
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
shutil.copy("/tmp/r31/inputs/traj.npz", os.path.join(D, "with space ü é.npz"))
shutil.copy("/tmp/r31/inputs/traj.npz", os.path.join(D, "-dash.npz"))
shutil.copy("/tmp/r31/inputs/traj.npz", os.path.join(D, "upper.NPZ"))
shutil.copy("/tmp/r31/inputs/traj.npz", os.path.join(D, "noext"))
os.makedirs(os.path.join(D, "dir.npz"), exist_ok=True)
for n in ("link.npz",):
    p = os.path.join(D, n)
    if os.path.lexists(p): os.remove(p)
os.symlink("/tmp/r31/inputs/traj.npz", os.path.join(D, "link.npz"))
if os.path.lexists(os.path.join(D, "dangling.npz")): os.remove(os.path.join(D, "dangling.npz"))
os.symlink("/nonexistent/x.npz", os.path.join(D, "dangling.npz"))
shutil.copy("/tmp/r31/inputs/traj.npz", os.path.join(D, "unreadable.npz")); os.chmod(os.path.join(D, "unreadable.npz"), 0)
# latin-1 bytes in filename
try:
    fn = os.path.join(D.encode(), b"lat\xe9.npz"); shutil.copy("/tmp/r31/inputs/traj.npz", fn)
except Exception as e: print("latin", e)
print("done", len(os.listdir(D)))
# --- r31 additions ---
q = None
save("u8_actions.npz", actions=(A * 10).astype(np.uint8))
save("i32_fps.npz", fps=np.int32(50))
save("f32_fps.npz", fps=np.float32(50))
save("fps_huge.npz", fps=np.float64(1e300))
save("fps_1e5.npz", fps=np.float64(1e5))
save("fps_subnormal.npz", fps=np.float64(5e-324))
save("fps_0d_obj_str.npz", fps=np.array(b"50"))
save("time_ms.npz", fps=None, time=np.arange(T) * 20.0)
save("time_drift.npz", fps=None, time=np.cumsum(np.r_[0, np.where(np.arange(T - 1) < T // 2, 0.0199, 0.0201)]))
save("time_f32_epoch.npz", fps=None, time=(1.7e9 + t).astype(np.float32))
save("time_int.npz", fps=None, time=np.arange(T) * 20)  # int ms
save("time_with_fps_agree.npz", time=t)
save("time_1pct.npz", time=t * 1.0099)  # fps 50 vs 49.5
save("time_int_idx.npz", fps=None, time=np.arange(T))  # sample indices
save("meta_nan.npz", meta=np.array('{"a": NaN}'))
save("meta_deep.npz", meta=np.array("[" * 100000 + "]" * 100000))
save("meta_bigint.npz", meta=np.array('{"a": ' + "9" * 5000 + '}'))
save("meta_empty.npz", meta=np.array(""))
save("meta_2d.npz", meta=np.array(["{}", "{}"]))
save("meta_fps.npz", fps=None, meta=np.array(json.dumps({"fps": 25})))
save("pose_nan.npz", object_pose=np.array([0.127, 0.454, 0.0125, np.nan, 0, 0, 0.0]))
save("pose_nonunit_1pct.npz", object_pose=np.array([0.127, 0.454, 0.0125, 1.009, 0, 0, 0.0]))
save("pose_nonunit_2pct.npz", object_pose=np.array([0.127, 0.454, 0.0125, 1.02, 0, 0, 0.0]))
save("pose_neg_quat.npz", object_pose=np.array([0.127, 0.454, 0.0125, -1, 0, 0, 0.0]))
save("pose_xyzw.npz", object_pose=np.array([0.127, 0.454, 0.0125, 0, 0, 0, 1.0]))  # scalar-last
save("pose_2d.npz", object_pose=np.array([[0.127, 0.454, 0.0125, 1, 0, 0, 0.0]]))
save("pose_int.npz", object_pose=np.array([0, 0, 0, 1, 0, 0, 0]))
save("pose_f32.npz", object_pose=base["object_pose"].astype(np.float32))
save("start_nan.npz", start=np.r_[base["start"][:-1], np.nan])
save("start_2d.npz", start=base["start"][None])
save("actions_2row_const.npz", actions=np.repeat(A[:1], 2, axis=0))
save("actions_T_ch.npz", actions=A.T.copy())  # transposed (14, 400)
save("actions_fortran.npz", actions=np.asfortranarray(A))
save("actions_bigendian.npz", actions=A.astype('>f8'))
save("actions_f128.npz", actions=A.astype(np.longdouble))
save("actions_tiny_denorm.npz", actions=A + 1e-310)
save("actions_big.npz", actions=A * 1e300)
save("actions_x1000.npz", actions=A * 57.2958)  # degrees
save("key_Actions.npz", actions=None, Actions=A)
save("key_object_pos.npz", object_pose=None, object_pos=base["object_pose"])
# unicode key / trailing slash member names
with zipfile.ZipFile(os.path.join(D, "member_noext.npz"), "w") as zf:
    import io
    for k, v in base.items():
        bio = io.BytesIO(); np.save(bio, v); zf.writestr(k, bio.getvalue())
# a zip with an actions.npy and a stray text file
shutil.copy("/tmp/r31/inputs/traj.npz", os.path.join(D, "stray.npz"))
with zipfile.ZipFile(os.path.join(D, "stray.npz"), "a") as zf: zf.writestr("README.txt", "hi")
# truncated at various points
for frac in (0.05, 0.5, 0.95, 0.999):
    open(os.path.join(D, f"trunc_{frac}.npz"), "wb").write(b[: int(len(b) * frac)])
# zip with appended junk
open(os.path.join(D, "junk_tail.npz"), "wb").write(b + b"junk" * 100)
# duplicate member
with zipfile.ZipFile(os.path.join(D, "dup.npz"), "w") as zf:
    import io
    for k, v in base.items():
        bio = io.BytesIO(); np.save(bio, v); zf.writestr(k + ".npy", bio.getvalue())
    bio = io.BytesIO(); np.save(bio, A * 0); zf.writestr("actions.npy", bio.getvalue())
# other formats with wrong suffix
np.savetxt(os.path.join(D, "as.csv"), A, delimiter=",")
shutil.copy(os.path.join(D, "as.csv"), os.path.join(D, "csv_as.npz"))
open(os.path.join(D, "as.json"), "w").write(json.dumps({"actions": A.tolist(), "fps": 50}))
shutil.copy(os.path.join(D, "as.json"), os.path.join(D, "json_as.npz"))
shutil.copy("/tmp/r31/inputs/traj.npz", os.path.join(D, "npz_as.h5"))
shutil.copy("/tmp/r31/inputs/traj.npz", os.path.join(D, "npz_as.hdf5"))
shutil.copy("/tmp/r31/inputs/traj.npz", os.path.join(D, "npz_as.parquet"))
open(os.path.join(D, "empty.h5"), "wb").write(b"")
open(os.path.join(D, "empty.parquet"), "wb").write(b"")
os.makedirs(os.path.join(D, "emptydir"), exist_ok=True)
shutil.copy("/tmp/r31/inputs/traj.npz", os.path.join(D, "ünï cødé 空白.npz"))
for n, tgt in (("rel_link.npz", "traj_copy.npz"), ("loop.npz", "loop.npz")):
    p = os.path.join(D, n)
    if os.path.lexists(p): os.remove(p)
    os.symlink(tgt, p)
shutil.copy("/tmp/r31/inputs/traj.npz", os.path.join(D, "traj_copy.npz"))
if not os.path.exists("/tmp/r31/inputs/fifo.npz"): os.mkfifo("/tmp/r31/inputs/fifo.npz")
print("done r31", len(os.listdir(D)))
