#!/bin/bash
# Two runs: A --out rep (an earlier output), B --out rep/sub started while A runs and
# finishing first. Does A's swap delete B's finished report?   bash nested_out.sh [SCRATCH]
S=${1:-/tmp/r29/api}; W=$S/nested; rm -rf "$W"; mkdir -p "$W"; cd "$W"; cp ../traj.npz .
../cm.sh analyze traj.npz --samples 32 --figures none --out rep >/dev/null 2>&1
../cm.sh analyze traj.npz --samples 256 --figures summary --out rep >a.out 2>a.err & A=$!
sleep ${DELAY:-4}
../cm.sh analyze traj.npz --samples 8 --figures none --out rep/sub >b.out 2>b.err; echo "B rc=$? (finished at $(date +%T.%N)); B's report: $(ls rep/sub 2>&1 | tr '\n' ' ')"
wait $A; echo "A rc=$? (finished at $(date +%T.%N)) | $(grep -m1 error a.err)"
echo "after both: rep holds: $(ls -A rep | tr '\n' ' ')"; ls -A rep/sub >/dev/null 2>&1 && echo "B's report kept" || echo "B's report (rep/sub, exit code 1 = audit done) is GONE"
ls -A . | grep critmoment-tmp
