#!/bin/bash
# ACT light-cube box (mass 0.025-0.5 kg, mu 0.2-1.0, nominal as init's), 64 samples: validate, then own truth + brute force
cd /tmp/r28/truth_real
P="env PYTHONPATH=/tmp/r28/src nice -n 5 /work/venv/bin/python /work/main/benchmarks/probe_r28/truth_real"
for c in "act_light_shipped act/scenario_shipped_light.toml act/traj_shipped.npz" "act_light_ell10 act/scenario_elliptic10_light.toml act/traj_elliptic10.npz"; do
  set -- $c
  $P/run_validate.py $2 $3 val_$1.json --samples 64 > val_$1.log 2>&1
  $P/truth.py --scenario $2 $3 --validate-json val_$1.json --compare-cm --brute --out res_$1.json > res_$1.txt 2>&1
  echo "$1 done $(date +%T)"
done
