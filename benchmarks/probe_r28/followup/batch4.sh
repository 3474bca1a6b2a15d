#!/bin/bash
# narrow force-limit bands around the real thresholds (rated and unrated), validate 64, seeds 0 and 1
P=/work/main/benchmarks/probe_r28/followup; PY=/work/venv/bin/python; export PYTHONPATH=/tmp/r28b/src
cd /tmp/r28b/w
for s in aloha_elbow_band aloha_mass_elbow_band; do for v in "" _nolim; do for t in aloha0 aloha0_faster; do for sd in 0 1; do
  $PY $P/runval.py $P/scen/$s$v.toml $t.npz val4_$s$v.$t.s$sd.json 64 $sd 2>&1 | tail -1; done; done; done; done
for s in panda_j4_band panda_j6_band panda_mass_j6_band; do for v in "" _nolim; do for t in panda0 panda0_faster; do for sd in 0 1; do
  $PY $P/runval.py $P/scen/$s$v.toml $t.npz val4_$s$v.$t.s$sd.json 64 $sd 2>&1 | tail -1; done; done; done; done
