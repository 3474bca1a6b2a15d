import json
import os

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq

d = dict(np.load('base.npz'))
A=d['actions']
start=d['start']
n=len(A)
F32 = pa.float32()
def tbl(actions, ep=0, ts=None, fi=None, state=None, typ=F32):
    cols = {"action": pa.array([r.tolist() for r in actions], pa.list_(typ))}
    cols["episode_index"]=pa.array([ep]*len(actions) if np.isscalar(ep) else list(ep), pa.int64())
    if fi is not False:
        cols["frame_index"]=pa.array(list(range(len(actions))) if fi is None else fi, pa.int64())
    if ts is not False:
        cols["timestamp"]=pa.array((np.arange(len(actions))/50.0 if ts is None else ts).astype(np.float32), pa.float32())
    if state is not None:
        cols["observation.state"]=pa.array([r.tolist() for r in state], pa.list_(pa.float32()))
    return pa.table(cols)
pq.write_table(tbl(A, state=np.repeat(start[None],n,0)), 'lr_ok.parquet')
pq.write_table(tbl(A, ts=np.arange(n)/50.0*1000), 'lr_ts_ms.parquet')
pq.write_table(tbl(A, ts=1.7e9+np.arange(n)/50.0), 'lr_ts_epoch32.parquet')
pq.write_table(tbl(A, ts=(np.arange(n)/50.0)[::-1].copy()), 'lr_ts_reversed.parquet')
# rows shuffled (should be reordered by frame_index?)
perm=np.random.default_rng(0).permutation(n)
t=tbl(A).take(pa.array(perm))
pq.write_table(t,'lr_shuffled.parquet')
# two episodes
pq.write_table(pa.concat_tables([tbl(A,ep=0),tbl(A,ep=1)]),'lr_two_eps.parquet')
# ragged action lists
pq.write_table(pa.table({"action": pa.array([r.tolist() for r in A[:-1]]+[A[-1][:5].tolist()], pa.list_(pa.float64())), "episode_index": pa.array([0]*n, pa.int64())}), 'lr_ragged.parquet')
# null in action
rows=[r.tolist() for r in A]
rows[10]=None
pq.write_table(pa.table({"action": pa.array(rows, pa.list_(pa.float64())), "episode_index": pa.array([0]*n, pa.int64())}), 'lr_null_row.parquet')
rows=[r.tolist() for r in A]
rows[10][3]=None
pq.write_table(pa.table({"action": pa.array(rows, pa.list_(pa.float64())), "episode_index": pa.array([0]*n, pa.int64())}), 'lr_null_elem.parquet')
# no episode_index
pq.write_table(pa.table({"action": pa.array([r.tolist() for r in A], pa.list_(pa.float64()))}), 'lr_no_epidx.parquet')
# actions as separate columns
pq.write_table(pa.table({f"action_{i}": pa.array(A[:,i]) for i in range(14)}), 'lr_split_cols.parquet')
# fixed_size_list
pq.write_table(pa.table({"action": pa.FixedSizeListArray.from_arrays(pa.array(A.ravel()), 14), "episode_index": pa.array([0]*n, pa.int64())}), 'lr_fixedsize.parquet')
# frame_index duplicated
fi=list(range(n))
fi[5]=4
pq.write_table(tbl(A, fi=fi), 'lr_fi_dup.parquet')
# dataset dir
root='lr_ds'
os.makedirs(root+'/meta', exist_ok=True)
os.makedirs(root+'/data/chunk-000', exist_ok=True)
json.dump({"fps":50}, open(root+'/meta/info.json','w'))
pq.write_table(tbl(A,ep=0), root+'/data/chunk-000/episode_000000.parquet')
pq.write_table(tbl(A,ep=1), root+'/data/chunk-000/episode_000001.parquet')
root='lr_ds_badfps'
os.makedirs(root+'/meta', exist_ok=True)
os.makedirs(root+'/data/chunk-000', exist_ok=True)
json.dump({"fps":"fifty"}, open(root+'/meta/info.json','w'))
pq.write_table(tbl(A,ep=0), root+'/data/chunk-000/episode_000000.parquet')
root='lr_ds_badjson'
os.makedirs(root+'/meta', exist_ok=True)
os.makedirs(root+'/data', exist_ok=True)
open(root+'/meta/info.json','w').write('{fps:')
pq.write_table(tbl(A,ep=0), root+'/data/episode_000000.parquet')
root='lr_ds_nodata'
os.makedirs(root+'/meta', exist_ok=True)
json.dump({"fps":50}, open(root+'/meta/info.json','w'))
root='lr_ds_fps_mismatch'
os.makedirs(root+'/meta', exist_ok=True)
os.makedirs(root+'/data', exist_ok=True)
json.dump({"fps":30}, open(root+'/meta/info.json','w'))
pq.write_table(tbl(A,ep=0), root+'/data/episode_000000.parquet')
open('garbage.parquet','wb').write(b'PAR1'+b'\0'*50+b'PAR1')
