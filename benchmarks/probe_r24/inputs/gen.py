import json
import zipfile

import numpy as np

d = dict(np.load('base.npz'))
A = d['actions']
fps = d['fps']
start=d['start']
pose=d['object_pose']
meta=d['meta']
def save(name, **kw):
    np.savez(name, **kw)
save('f16.npz', actions=A.astype(np.float16), fps=fps, start=start, object_pose=pose, meta=meta)
save('f32.npz', actions=A.astype(np.float32), fps=fps, start=start, object_pose=pose, meta=meta)
save('int.npz', actions=np.round(A).astype(np.int64), fps=fps, start=start, object_pose=pose, meta=meta)
save('bool.npz', actions=(A>0.5), fps=fps, start=start, object_pose=pose, meta=meta)
save('cplx.npz', actions=A.astype(complex), fps=fps, start=start, object_pose=pose, meta=meta)
save('str.npz', actions=A.astype(str), fps=fps, start=start, object_pose=pose, meta=meta)
np.savez('objarr.npz', actions=np.array([list(r) for r in A], dtype=object), fps=fps)
save('norows.npz', actions=A[:0], fps=fps)
save('onerow.npz', actions=A[:1], fps=fps, start=start, object_pose=pose)
save('tworows.npz', actions=A[:2], fps=fps, start=start, object_pose=pose)
save('threerows.npz', actions=A[:3], fps=fps, start=start, object_pose=pose)
save('1d.npz', actions=A[0], fps=fps)
save('3d.npz', actions=A[None], fps=fps)
save('transposed.npz', actions=A.T.copy(), fps=fps, start=start, object_pose=pose)
save('missing_actions.npz', action=A, fps=fps)
save('extra_keys.npz', actions=A, fps=fps, start=start, object_pose=pose, foo=np.arange(3), observations=np.zeros((400,14)))
t = np.arange(400)/50.0
save('time_ms.npz', actions=A, time=t*1000, start=start, object_pose=pose)
save('time_epoch64.npz', actions=A, time=1.7e9+t, start=start, object_pose=pose)
save('time_epoch32.npz', actions=A, time=(1.7e9+t).astype(np.float32), start=start, object_pose=pose)
save('time_nonmono.npz', actions=A, time=t[::-1].copy(), start=start, object_pose=pose)
tt=t.copy()
tt[100]=tt[99]
save('time_dup.npz', actions=A, time=tt, start=start, object_pose=pose)
tt=t.copy()
tt[200:]+=0.5
save('time_gap.npz', actions=A, time=tt, start=start, object_pose=pose)
save('time_and_fps_disagree.npz', actions=A, time=t, fps=np.float64(30), start=start, object_pose=pose)
save('time_wronglen.npz', actions=A, time=t[:-1], start=start, object_pose=pose)
save('time_ns_int.npz', actions=A, time=(t*1e9).astype(np.int64), start=start, object_pose=pose)
save('deg.npz', actions=np.degrees(A), fps=fps, start=np.degrees(start), object_pose=pose)
save('deg_arms_only.npz', actions=np.where(np.arange(14)%7==6, A, np.degrees(A)), fps=fps, start=np.where(np.arange(14)%7==6, start, np.degrees(start)), object_pose=pose)
# degree actions but start in radians
save('deg_actions_rad_start.npz', actions=np.degrees(A), fps=fps, start=start, object_pose=pose)
g = np.arange(14)%7==6
def grip(fn):
    B=A.copy()
    B[:,g]=fn(A[:,g])
    S=start.copy()
    S[g]=fn(start[g])
    return B,S
B,S=grip(lambda x: 0.01844+x*(0.058-0.01844))
save('grip_metres.npz', actions=B, fps=fps, start=S, object_pose=pose)
B,S=grip(lambda x: np.round(x*4095))
save('grip_ticks.npz', actions=B, fps=fps, start=S, object_pose=pose)
B,S=grip(lambda x: x*100)
save('grip_percent.npz', actions=B, fps=fps, start=S, object_pose=pose)
B,S=grip(lambda x: 1-x)
save('grip_inverted.npz', actions=B, fps=fps, start=S, object_pose=pose)
# swap arms
save('swap_arms.npz', actions=np.concatenate([A[:,7:],A[:,:7]],1), fps=fps, start=np.concatenate([start[7:],start[:7]]), object_pose=pose)
# gripper first per arm
perm = [6,0,1,2,3,4,5,13,7,8,9,10,11,12]
save('grip_first.npz', actions=A[:,perm], fps=fps, start=start[perm], object_pose=pose)
save('panda_width.npz', actions=A[:,:8], fps=fps, object_pose=pose)
save('width16.npz', actions=np.concatenate([A,A[:,:2]],1), fps=fps, object_pose=pose)
B=A.copy()
B[50,3]=np.nan
save('nan.npz', actions=B, fps=fps, start=start, object_pose=pose)
B=A.copy()
B[50,3]=np.inf
save('inf.npz', actions=B, fps=fps, start=start, object_pose=pose)
save('fps_nan.npz', actions=A, fps=np.float64('nan'))
save('fps_zero.npz', actions=A, fps=np.float64(0))
save('fps_neg.npz', actions=A, fps=np.float64(-50))
save('fps_str.npz', actions=A, fps=np.array('50'))
save('fps_arr.npz', actions=A, fps=np.array([50.,50.]))
save('fps_int.npz', actions=A, fps=np.int64(50), start=start, object_pose=pose)
save('fps_bool.npz', actions=A, fps=np.True_, start=start, object_pose=pose)
save('fps_1000.npz', actions=A, fps=np.float64(1000), start=start, object_pose=pose)
save('fps_500.npz', actions=A, fps=np.float64(500), start=start, object_pose=pose)
save('fps_1e-300.npz', actions=A, fps=np.float64(1e-300))
save('pose_bad.npz', actions=A, fps=fps, object_pose=np.array([0,0.5,0.02,0,0,0,0.]))
save('pose_len3.npz', actions=A, fps=fps, object_pose=np.array([0,0.5,0.02]))
save('pose_underground.npz', actions=A, fps=fps, start=start, object_pose=np.array([0.127,0.454,-0.5,1,0,0,0.]))
save('pose_mm.npz', actions=A, fps=fps, start=start, object_pose=np.array([127,454,20,1,0,0,0.]))
save('pose_xyzw.npz', actions=A, fps=fps, start=start, object_pose=np.concatenate([pose[:3], pose[4:], pose[3:4]]))
save('start_wronglen.npz', actions=A, fps=fps, start=start[:7], object_pose=pose)
save('qpos0_wronglen.npz', actions=A, fps=fps, qpos0=np.zeros(5), object_pose=pose)
save('meta_notjson.npz', actions=A, fps=fps, start=start, object_pose=pose, meta=np.array('{not json'))
save('meta_list.npz', actions=A, fps=fps, start=start, object_pose=pose, meta=np.array('[1,2]'))
save('meta_scen_unknown.npz', actions=A, fps=fps, start=start, object_pose=pose, meta=np.array('{"scenario":"nonexistent_scen"}'))
save('meta_scen_path.npz', actions=A, fps=fps, start=start, object_pose=pose, meta=np.array('{"scenario":"/etc/passwd"}'))
save('meta_scen_int.npz', actions=A, fps=fps, start=start, object_pose=pose, meta=np.array('{"scenario":5}'))
save('meta_bytes.npz', actions=A, fps=fps, start=start, object_pose=pose, meta=np.array(b'{"a":1}'))
np.savez('pickle.npz', actions=np.array([A], dtype=object), fps=fps)
with zipfile.ZipFile('zip_other.npz','w') as z:
    z.writestr('hello.txt','hi')
    z.writestr('data.csv','1,2,3')
open('text.npz','w').write('not a zip')
open('empty.npz','w').close()
np.save('plain.npy', A)
np.savetxt('plain.csv', A, delimiter=',')
json.dump({'actions':A.tolist(),'fps':50}, open('plain.json','w'))
# long: 10^5 rows
save('long.npz', actions=np.repeat(A, 250, axis=0), fps=fps, start=start, object_pose=pose)
save('long_limit.npz', actions=np.repeat(A, 80, axis=0)[:25001], fps=fps, start=start, object_pose=pose)
# compressed
np.savez_compressed('compressed.npz', actions=A, fps=fps, start=start, object_pose=pose, meta=meta)
# big-endian
save('bigendian.npz', actions=A.astype('>f8'), fps=fps, start=start.astype('>f8'), object_pose=pose.astype('>f8'), meta=meta)
# fortran order / noncontiguous
save('fortran.npz', actions=np.asfortranarray(A), fps=fps, start=start, object_pose=pose, meta=meta)
# structured array
sa = np.zeros(400, dtype=[('a','f8',(14,))])
sa['a']=A
save('structured.npz', actions=sa, fps=fps)
# masked? datetime time
save('time_datetime.npz', actions=A, time=(np.datetime64('2026-01-01')+ (t*1e6).astype('timedelta64[us]')), start=start, object_pose=pose)
save('time_2d.npz', actions=A, time=t[:,None], start=start, object_pose=pose)
save('time_one.npz', actions=A[:1], time=np.array([0.0]), start=start, object_pose=pose)
save('time_two.npz', actions=A[:2], time=np.array([0.0, 0.02]), start=start, object_pose=pose)
save('time_offset.npz', actions=A, time=t+5, start=start, object_pose=pose)
save('time_jitter.npz', actions=A, time=t+np.random.default_rng(0).normal(0,0.0005,400), start=start, object_pose=pose)
save('actions_scalar.npz', actions=np.float64(1), fps=fps)
save('qvel_only.npz', actions=A, fps=fps, qvel0=np.zeros(30), start=start, object_pose=pose)
