#!/bin/bash
# usage: run_case.sh NAME SCENARIO TRAJ   (runs validate --samples 32 --json, then truth.py --brute)
# outputs in /tmp/r26/truth/: val_NAME.json, res_NAME.json, res_NAME.txt
set -e
. /tmp/r26/venv/bin/activate
cd /tmp/r26/truth
name=$1; scen=$2; traj=$3
nice -n 10 critmoment validate "$traj" --scenario "$scen" --samples 32 --json > val_$name.json 2> val_$name.err || echo "validate rc $?"
python -c "import json; d=json.load(open('val_$name.json')); print('validate', d['confusion'], d['outcomes'], 'agreement', d['agreement'], 'nominal_completed', d['nominal_completed'])"
nice -n 10 python /work/main/benchmarks/probe_r26/truth/truth.py --scenario "$scen" "$traj" --validate-json val_$name.json --brute --out res_$name.json > res_$name.txt 2>&1
head -1 res_$name.txt; grep -v "^      bf" res_$name.txt | grep "DIFFERS\|LABEL" || true; tail -3 res_$name.txt
