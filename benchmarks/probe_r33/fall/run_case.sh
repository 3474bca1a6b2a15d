#!/bin/bash
# usage: run_case.sh SCEN.toml TRAJ.npz TAG [SAMPLES]  (run from /tmp/r33/fall)
# validate (verify on), validate --no-verify (library, nthread=1), independent truth on the samples
S=$1; T=$2; TAG=$3; N=${4:-32}; P=/work/main/benchmarks/probe_r33/fall
Q=${Q:-/tmp/r33/fall/scripts}   # the patched scripts, rebuilt there by make_scripts.sh (S=... of it)
export PYTHONPATH=/tmp/r33/src
PY="taskset -c 1 /work/venv/bin/python"
$PY $Q/run_validate.py $S $T val_$TAG.json --samples $N > log_val_$TAG.txt 2>&1
$PY $Q/run_validate.py $S $T valnv_$TAG.json --samples $N --no-verify > log_valnv_$TAG.txt 2>&1
IDX=$(/work/venv/bin/python $P/pick_idx.py val_$TAG.json valnv_$TAG.json ${K:-4})
$PY $Q/truth.py --scenario $S $T --validate-json val_$TAG.json --out tr_$TAG.json --only $IDX > log_tr_$TAG.txt 2>&1
echo "$TAG done: $(tail -1 log_val_$TAG.txt | cut -c1-200) | NV: $(tail -1 log_valnv_$TAG.txt | cut -c1-120) | truth: $(tail -1 log_tr_$TAG.txt)"
