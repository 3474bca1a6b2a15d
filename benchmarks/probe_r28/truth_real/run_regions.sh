#!/bin/bash
# own truth (and critmoment's brute force) at the stated safe region's corners, mid-edges, centre and 4 inside points
cd /tmp/r28/truth_real
T="env PYTHONPATH=/tmp/r28/src nice -n 5 /work/venv/bin/python /work/main/benchmarks/probe_r28/truth_real/truth.py"
for c in "act_shipped act/scenario_shipped.toml act/traj_shipped.npz" "act_ell10 act/scenario_elliptic10.toml act/traj_elliptic10.npz" "wxai_shipped wxai/scenario_shipped_narrow.toml wxai/traj.npz" "wxai_ell10 wxai/scenario_elliptic10_narrow.toml wxai/traj.npz" "oa_shipped openarm/scenario_shipped_narrow.toml openarm/traj.npz" "oa_pyr1 openarm/scenario_pyramidal1_narrow.toml openarm/traj.npz"; do
  set -- $c
  while [ ! -s an_$1_analyze.json ] && ! grep -q "Error\|error" an_$1.log 2>/dev/null; do sleep 10; done
  if [ -s an_$1_points.json ]; then
    $T --scenario $2 $3 --points an_$1_points.json --brute --out reg_$1.json > reg_$1.txt 2>&1
    echo "$1 region done $(date +%T)"
  else echo "$1: no region"; fi
done
