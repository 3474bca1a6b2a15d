import shutil

import h5py
import numpy as np

d = dict(np.load('base.npz'))
A=d['actions']
start=d['start']
pose=d['object_pose']
def mk(name, attrs=None, **ds):
    with h5py.File(name,'w') as f:
        for k,v in ds.items():
            f.create_dataset(k, data=v)
        for k,v in (attrs or {}).items():
            f.attrs[k]=v
Q = np.repeat(start[None],400,0)
mk('act_ok.hdf5', action=A, **{'observations/qpos':Q}, attrs={'sim':True})
mk('act_pose.hdf5', action=A, **{'observations/qpos':Q, 'observations/env_state':np.repeat(pose[None],400,0)}, attrs={'sim':True})
mk('act_fps_str.hdf5', action=A, **{'observations/qpos':Q}, attrs={'fps':'fifty'})
mk('act_fps_30.hdf5', action=A, **{'observations/qpos':Q}, attrs={'fps':30.0})
mk('act_fps_both.hdf5', action=A, **{'observations/qpos':Q}, attrs={'fps':30.0, 'frame_rate':50.0})
mk('act_fps_arr.hdf5', action=A, **{'observations/qpos':Q}, attrs={'fps':np.array([50.,30.])})
mk('act_fps_neg.hdf5', action=A, **{'observations/qpos':Q}, attrs={'control_freq':-5})
mk('act_no_action.hdf5', **{'observations/qpos':Q})
mk('act_no_qpos.hdf5', action=A)
mk('act_qpos_short.hdf5', action=A, **{'observations/qpos':Q[:, :7]})
mk('act_qpos_deg.hdf5', action=A, **{'observations/qpos':np.degrees(Q)})
mk('act_action_f16.hdf5', action=A.astype(np.float16), **{'observations/qpos':Q})
mk('act_action_int.hdf5', action=(A*1000).astype(np.int32), **{'observations/qpos':Q})
mk('act_action_str.hdf5', action=np.array([b'x']*400), **{'observations/qpos':Q})
mk('act_empty.hdf5', action=np.zeros((0,14)), **{'observations/qpos':np.zeros((0,14))})
mk('act_envstate_bad.hdf5', action=A, **{'observations/qpos':Q, 'observations/env_state':np.zeros((400,3))})
mk('act_envstate_nan.hdf5', action=A, **{'observations/qpos':Q, 'observations/env_state':np.full((400,7),np.nan)})
mk('act_pose_attr.hdf5', action=A, **{'observations/qpos':Q}, attrs={'object_pose':pose})
mk('act_pose_attr_str.hdf5', action=A, **{'observations/qpos':Q}, attrs={'object_pose':'0 0 0'})
mk('act_action_group.hdf5', **{'action/x':A, 'observations/qpos':Q})
mk('act_nan.hdf5', action=np.where(np.arange(400)[:,None]==7, np.nan, A), **{'observations/qpos':Q})
mk('act_qpos_nan.hdf5', action=A, **{'observations/qpos':np.full_like(Q, np.nan)})
# an h5 that's really an npz
shutil.copy('base.npz', 'really_npz.hdf5')
open('garbage.h5','wb').write(b'\x89HDF\r\n\x1a\n'+b'\0'*100)
# external link / virtual dataset pointing elsewhere
with h5py.File('act_extlink.hdf5','w') as f:
    f['action'] = h5py.ExternalLink('act_ok.hdf5', '/action')
    f.create_dataset('observations/qpos', data=Q)
with h5py.File('act_extlink_missing.hdf5','w') as f:
    f['action'] = h5py.ExternalLink('/nonexistent.hdf5', '/action')
    f.create_dataset('observations/qpos', data=Q)
with h5py.File('act_softlink.hdf5','w') as f:
    f.create_dataset('observations/qpos', data=Q)
    f['action'] = h5py.SoftLink('/observations/qpos')
with h5py.File('act_compressed.hdf5','w') as f:
    f.create_dataset('action', data=A, compression='gzip', chunks=(10,14))
    f.create_dataset('observations/qpos', data=Q)
with h5py.File('act_lzf_scaleoffset.hdf5','w') as f:
    f.create_dataset('action', data=A, scaleoffset=2, chunks=(10,14))
    f.create_dataset('observations/qpos', data=Q)
with h5py.File('act_huge_declared.hdf5','w') as f:
    f.create_dataset('action', shape=(10**9,14), dtype='f8', chunks=(1000,14))
    f.create_dataset('observations/qpos', data=Q)
with h5py.File('act_resizable.hdf5','w') as f:
    ds=f.create_dataset('action', data=A, maxshape=(None,14), chunks=(10,14))
    f.create_dataset('observations/qpos', data=Q)
