#!/bin/bash
cd /work/main/benchmarks/probe_r28/params
for b in aloha_mass_com aloha_grip_lim aloha_grip_lim_narrow aloha_shoulder_lim aloha_shoulder_narrow aloha_mass_shoulder aloha_com_wide panda_grip_lim_narrow panda_shoulder_lim panda_shoulder_narrow panda_mass_shoulder panda_mass_fric_grip panda_mass_fric_com_grip panda_com_wide aloha_mass_fric_com_grip; do
  tw=${b%%_*}
  PYTHONPATH=/tmp/r28/src /work/venv/bin/python runana.py scen/$b.toml /tmp/r28/params/${tw}0.npz /tmp/r28/params/ana_$b 2>&1 | grep -v "^$"
done
