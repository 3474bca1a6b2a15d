#!/bin/bash
# validate each named variant (32 samples, seed 0 unless N/SEED set), sequentially
cd /tmp/r32/contact
for v in "$@"; do
  PYTHONPATH=/tmp/r32/src nice -n 5 timeout 900 /work/venv/bin/python /work/main/benchmarks/probe_r32/contact/runval.py $v ${N:-32} ${SEED:-0} 2>&1 | grep -v "^\s*$" | cut -c1-600
done
