#!/bin/bash
# validate 32 samples on the scenarios init wrote for a few cases (run after run_cases.py)
C=/work/main/benchmarks/probe_r37/modelforms/cm.sh
R=/tmp/r37/modelforms/runs
DEFAULT=("base:/tmp/r37/modelforms/panda.npz" "attach:/tmp/r37/modelforms/panda.npz" "urdf:/tmp/r37/modelforms/urdf/gantry.npz" "replicate_c1:/tmp/r37/modelforms/panda_noq.npz" "twomesh:/tmp/r37/modelforms/panda_noq.npz")
[ $# -gt 0 ] && DEFAULT=("$@")   # cases given: only those
for spec in "${DEFAULT[@]}"; do
  c=${spec%%:*}; t=${spec#*:}
  [ -f $R/$c/scenario.toml ] || continue
  $C validate $t --scenario $R/$c/scenario.toml --samples 32 --json > $R/$c/validation.json 2> $R/$c/validation.err; rc=$?
  /work/venv/bin/python -c "
import json
try:
    v=json.load(open('$R/$c/validation.json')); print('$c', 'rc=$rc', v['confusion'], 'agreement', v['agreement'], 'vacuous', v['vacuous'], v['outcomes'])
except Exception as e: print('$c', 'rc=$rc', open('$R/$c/validation.err').read()[-300:])"
done
