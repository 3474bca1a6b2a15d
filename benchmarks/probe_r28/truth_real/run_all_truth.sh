#!/bin/bash
# own ground truth on validate's samples, per case (waits for each val_*.json); outputs res_*.json/txt
cd /tmp/r28/truth_real
T="env PYTHONPATH=/tmp/r28/src nice -n 5 /work/venv/bin/python /work/main/benchmarks/probe_r28/truth_real/truth.py"
run() { name=$1; scen=$2; traj=$3
  while [ ! -s val_$name.json ]; do sleep 10; done
  $T --scenario $scen $traj --validate-json val_$name.json --compare-cm --out res_$name.json > res_$name.txt 2>&1
  echo "$name done $(date +%T)"; }
run wxai_shipped wxai/scenario_shipped_narrow.toml wxai/traj.npz
run wxai_ell10 wxai/scenario_elliptic10_narrow.toml wxai/traj.npz
run act_shipped act/scenario_shipped.toml act/traj_shipped.npz
run act_ell10 act/scenario_elliptic10.toml act/traj_elliptic10.npz
run oa_shipped openarm/scenario_shipped_narrow.toml openarm/traj.npz
run oa_pyr1 openarm/scenario_pyramidal1_narrow.toml openarm/traj.npz
