#!/bin/bash
# force_limit boxes on other actuators, rated and unrated, heavy masses, faster motion: validate 64
P=/work/main/benchmarks/probe_r28/followup; PY=/work/venv/bin/python; export PYTHONPATH=/tmp/r28b/src
cd /tmp/r28b/w
for s in aloha_elbow aloha_wrist aloha_mass_elbow aloha_mass10_shoulder aloha_left_shoulder; do
  for v in "" _nolim; do for t in aloha0 aloha0_faster; do
    timeout 600 $PY $P/runval.py $P/scen/$s$v.toml $t.npz val_$s$v.$t.json 64 2>&1 | tail -1
  done; done
done
for s in panda_j4 panda_j6 panda_mass10_j2 panda_mass_j4; do
  for v in "" _nolim; do for t in panda0 panda0_faster; do
    timeout 600 $PY $P/runval.py $P/scen/$s$v.toml $t.npz val_$s$v.$t.json 64 2>&1 | tail -1
  done; done
done
