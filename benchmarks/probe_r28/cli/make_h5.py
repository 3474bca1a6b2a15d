import os
import shutil

import h5py
import numpy as np

D = "/tmp/r28/cli/in"
z = np.load("/tmp/r28/cli/readme/traj.npz"); A = z["actions"]; S = z["start"]; P = z["object_pose"]
Q = np.vstack([S, A[:-1]])
def mk(name, action=A, qpos=Q, env=P, attrs=None, compress=None, extra=None, skip=()):
    p = os.path.join(D, name)
    with h5py.File(p, "w") as f:
        if "action" not in skip and action is not None: f.create_dataset("action", data=action, compression=compress)
        if "qpos" not in skip and qpos is not None: f.create_dataset("observations/qpos", data=qpos, compression=compress)
        if "env" not in skip and env is not None:
            f.create_dataset("observations/env_state", data=np.tile(env, (len(A), 1)))
        for k, v in (attrs or {}).items(): f.attrs[k] = v
        if extra: extra(f)
mk("act_ok.hdf5", attrs={"sim": True})
mk("act_ok.h5")
mk("act_noqpos.hdf5", skip=("qpos",))
mk("act_noenv.hdf5", skip=("env",))
mk("act_noaction.hdf5", skip=("action",))
mk("act_int.hdf5", action=np.round(A).astype(np.int32))
mk("act_u8.hdf5", action=(A * 10).astype(np.uint8))
mk("act_bool.hdf5", action=A > 0)
mk("act_wide.hdf5", action=np.hstack([A, A[:, :2]]))
mk("act_qpos_wide.hdf5", qpos=np.hstack([Q, Q[:, :2]]))
mk("act_gzip.hdf5", compress="gzip")
mk("act_lzf.hdf5", compress="lzf")
mk("act_extra.hdf5", extra=lambda f: (f.create_dataset("observations/images/top", data=np.zeros((400, 4, 4, 3), np.uint8)), f.create_dataset("foo", data="bar")))
mk("act_fps25.hdf5", attrs={"fps": 25})
mk("act_fps_str.hdf5", attrs={"fps": "50"})
mk("act_fps_bytes.hdf5", attrs={"fps": b"50"})
mk("act_fps_arr.hdf5", attrs={"fps": np.array([50.0, 50.0])})
mk("act_fps_conflict.hdf5", attrs={"fps": 50, "frame_rate": 30})
mk("act_fps0.hdf5", attrs={"fps": 0})
mk("act_fps_nan.hdf5", attrs={"control_freq": np.nan})
mk("act_attr_scn.hdf5", attrs={"scenario": "panda_pick_place"})
mk("act_attr_objs.hdf5", attrs={"strs": np.array([b"a", b"b"]), "big": np.arange(1000), "uni": "héllo"})
mk("act_env_bad.hdf5", env=np.zeros(7))
mk("act_env_str.hdf5", skip=("env",), attrs={"object_pose": "0 0 0"})
mk("act_env_attr.hdf5", skip=("env",), attrs={"object_pose": P})
mk("act_empty.hdf5", action=np.zeros((0, 14)), qpos=np.zeros((0, 14)), skip=("env",))
mk("act_scalar.hdf5", action=np.float64(1.0), skip=("env",))
mk("act_compound.hdf5", action=np.zeros(400, dtype=[("a", "f8"), ("b", "f8")]), skip=("env",))
mk("act_str.hdf5", action=np.array(["x"] * 400, dtype="S1"), skip=("env",))
mk("act_group.hdf5", skip=("action",), extra=lambda f: f.create_group("action"))
mk("act_softlink.hdf5", skip=("action",), extra=lambda f: f.__setitem__("action", h5py.SoftLink("/nowhere")))
mk("act_extlink.hdf5", skip=("action",), extra=lambda f: f.__setitem__("action", h5py.ExternalLink("/nonexistent.h5", "/action")))
mk("act_goodlink.hdf5", skip=("action",), extra=lambda f: (f.create_dataset("real_action", data=A), f.__setitem__("action", h5py.SoftLink("/real_action"))))
mk("act_emptyds.hdf5", skip=("action", "env"), extra=lambda f: f.create_dataset("action", shape=None, dtype="f8"))
mk("act_nan.hdf5", action=np.where(np.arange(A.size).reshape(A.shape) == 50, np.nan, A))
mk("act_f16.hdf5", action=A.astype(np.float16))
mk("act_qpos_nan.hdf5", qpos=np.where(np.arange(Q.size).reshape(Q.shape) == 3, np.nan, Q))
b = open(os.path.join(D, "act_ok.hdf5"), "rb").read()
open(os.path.join(D, "act_trunc.hdf5"), "wb").write(b[: len(b) // 2])
open(os.path.join(D, "act_text.hdf5"), "w").write("not hdf5")
shutil.copy("/tmp/r28/cli/readme/traj.npz", os.path.join(D, "npz_as.hdf5"))
print("ok")
