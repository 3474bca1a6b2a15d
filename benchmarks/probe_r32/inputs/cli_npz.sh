#!/bin/bash
# CLI exit codes and stderr for npz variants not in r31's set (rollout --json; one line each)
cd /tmp/r32/inputs
CM=/work/main/benchmarks/probe_r32/inputs/cm.sh
/work/venv/bin/python - <<'PY'
import numpy as np
z = np.load("traj.npz"); d = {k: z[k] for k in z.files}; A = d["actions"]; T0 = np.arange(400) / 50
def w(name, **kw):
    e = {**d, **kw}; e = {k: v for k, v in e.items() if v is not None}; np.savez(f"c_{name}.npz", **e)
w("f16", actions=A.astype(np.float16))
w("int8", actions=np.round(A).astype(np.int8))
w("batch3d", actions=A[None])
w("last1", actions=A[..., None])
w("time5", time=T0 + 5)
w("time_f16", time=T0.astype(np.float16))
w("fps_f16", fps=np.float16(50))
w("fps_arr1", fps=np.array([50.0]))
w("start_f16", start=d["start"].astype(np.float16))
w("time_and_fps_1pct", time=T0, fps=np.float64(50.4))
w("time_desc", time=T0[::-1])
w("time_dup_end", time=np.r_[T0[:-1], T0[-2]])
w("actions_objarr_nopickle", actions=A.astype(object))
PY
for f in c_*.npz; do
  out=$($CM rollout "$f" --json 2>/tmp/r32/inputs/err.txt); rc=$?
  n=$(wc -l < /tmp/r32/inputs/err.txt)
  printf '%-28s rc=%s stderr_lines=%s %s | %s\n' "$f" "$rc" "$n" "$(head -c 260 /tmp/r32/inputs/err.txt | tr '\n' ' ')" "$(echo "$out" | head -c 100)"
done
