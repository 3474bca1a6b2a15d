#!/bin/bash
# final truth runs (slide-axis closing axis) for the four slide-finger cases, with critmoment's brute force alongside
cd /tmp/r28/truth_real
T="env PYTHONPATH=/tmp/r28/src nice -n 5 /work/venv/bin/python /work/main/benchmarks/probe_r28/truth_real/truth.py"
for c in "act_shipped act/scenario_shipped.toml act/traj_shipped.npz" "act_ell10 act/scenario_elliptic10.toml act/traj_elliptic10.npz" "wxai_shipped wxai/scenario_shipped_narrow.toml wxai/traj.npz" "wxai_ell10 wxai/scenario_elliptic10_narrow.toml wxai/traj.npz"; do
  set -- $c
  $T --scenario $2 $3 --validate-json val_$1.json --compare-cm --brute --out res_$1.json > res_$1.txt 2>&1; echo "$1 done $(date +%T)"
done
