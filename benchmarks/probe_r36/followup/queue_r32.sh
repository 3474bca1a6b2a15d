#!/bin/bash
# probe_r32 Jaco cases on the NEW code (validate nthread=1, 32 samples seed 0; truth where r32 ran it)
cd /tmp/r36f/followup/r32; R=/tmp/r36f/followup/res; PY="env PYTHONPATH=/tmp/r36f/src taskset -c 1 /work/venv/bin/python"
run() { tag=$1 scen=$2 traj=$3 tr=0
  $PY run_validate.py $scen $traj $R/val_r32_$tag.json --samples 32 --seed 0 2>&1 | tail -1
  [ "$tr" = 1 ] && $PY truth.py --scenario $scen $traj --validate-json $R/val_r32_$tag.json --out $R/tr_r32_$tag.json 2>&1 | tail -3; }
run scen_hold_narrow scen_hold_narrow.toml traj_hold.npz 1
run motor_dz_init scen_motor.toml traj_motor_s3_dz0.01.npz 1
run motor_init scen_motor.toml traj_motor_s3.npz 1
run scen_ell scen_ell.toml traj_motor_s3_dz0.01.npz 1
run motor_dz_narrow scen_motor_narrow.toml traj_motor_s3_dz0.01.npz 0
run motor_narrow scen_motor_narrow.toml traj_motor_s3.npz 0
run scen_ell_narrow scen_ell_narrow.toml traj_motor_s3_dz0.01.npz 0
run motor_heavy scen_motor_heavy.toml traj_motor_s3_dz0.01.npz 0
