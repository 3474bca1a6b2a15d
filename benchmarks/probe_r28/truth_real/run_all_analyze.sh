#!/bin/bash
# critmoment analyze (library, nthread 1, seed 0) per case; outputs an_<case>_analyze.json, an_<case>_points.json
cd /tmp/r28/truth_real
A="env PYTHONPATH=/tmp/r28/src nice -n 5 /work/venv/bin/python /work/main/benchmarks/probe_r28/truth_real/run_analyze.py"
$A act/scenario_shipped.toml act/traj_shipped.npz an_act_shipped > an_act_shipped.log 2>&1
$A act/scenario_elliptic10.toml act/traj_elliptic10.npz an_act_ell10 > an_act_ell10.log 2>&1
$A wxai/scenario_shipped_narrow.toml wxai/traj.npz an_wxai_shipped > an_wxai_shipped.log 2>&1
$A wxai/scenario_elliptic10_narrow.toml wxai/traj.npz an_wxai_ell10 > an_wxai_ell10.log 2>&1
$A openarm/scenario_shipped_narrow.toml openarm/traj.npz an_oa_shipped > an_oa_shipped.log 2>&1
$A openarm/scenario_pyramidal1_narrow.toml openarm/traj.npz an_oa_pyr1 > an_oa_pyr1.log 2>&1
echo all done $(date +%T)
