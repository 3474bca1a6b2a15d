#!/bin/bash
# the six validate runs, one after another (nthread 1), outputs in /tmp/r28/truth_real/val_*.json
cd /tmp/r28/truth_real
P="env PYTHONPATH=/tmp/r28/src nice -n 5 /work/venv/bin/python /work/main/benchmarks/probe_r28/truth_real/run_validate.py"
N=${N:-32}
$P wxai/scenario_shipped_narrow.toml wxai/traj.npz val_wxai_shipped.json --samples $N
$P wxai/scenario_elliptic10_narrow.toml wxai/traj.npz val_wxai_ell10.json --samples $N
$P act/scenario_shipped.toml act/traj_shipped.npz val_act_shipped.json --samples $N
$P act/scenario_elliptic10.toml act/traj_elliptic10.npz val_act_ell10.json --samples $N
$P openarm/scenario_shipped_narrow.toml openarm/traj.npz val_oa_shipped.json --samples $N
$P openarm/scenario_pyramidal1_narrow.toml openarm/traj.npz val_oa_pyr1.json --samples $N
