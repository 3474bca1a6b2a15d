#!/bin/bash
# usage: run_case.sh CASEDIR [SAMPLES]   (run from /tmp/r33/clutter): validate (verify), validate (no verify), truth.py on all samples
D=$1; N=${2:-32}; P=/work/main/benchmarks/probe_r33/clutter
export PYTHONPATH=/tmp/r33/src2
Q=${Q:-/tmp/r33/clutter/scripts}   # truth.py, run_validate.py: rebuilt there by make_scripts.sh
PY="taskset -c 1 /work/venv/bin/python"
$PY $Q/run_validate.py $D/scenario.toml $D/traj.npz $D/val.json --samples $N > $D/log_val.txt 2>&1
$PY $Q/run_validate.py $D/scenario.toml $D/traj.npz $D/valnv.json --samples $N --no-verify > $D/log_valnv.txt 2>&1
$PY $Q/truth.py --scenario $D/scenario.toml $D/traj.npz --validate-json $D/val.json --out $D/tr.json > $D/log_tr.txt 2>&1
echo "$D: $(tail -1 $D/log_val.txt | cut -c1-220) | NV: $(tail -1 $D/log_valnv.txt | cut -c1-120)"
