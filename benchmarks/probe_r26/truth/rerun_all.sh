#!/bin/bash
# Re-runs truth.py on every case of the README (validate JSONs already in /tmp/r26/truth).
. /tmp/r26/venv/bin/activate
cd /tmp/r26/truth
T=/work/main/benchmarks/probe_r26/truth/truth.py
run() { name=$1; scen=$2; traj=$3; shift 3
  nice -n 10 python $T --scenario $scen $traj --validate-json val_$name.json --brute --out res_$name.json > res_$name.txt 2>&1
  nice -n 10 python $T --scenario $scen $traj --validate-json val_$name.json --controls zoh --out res_${name}_zoh.json > res_${name}_zoh.txt 2>&1
  echo "== $name"; tail -3 res_$name.txt; echo "-- zoh"; tail -3 res_${name}_zoh.txt; }
run aloha15_s0 aloha15 aloha_s0.npz
run aloha15_s7 aloha15 aloha_s7.npz
run panda_s0 panda_pick_place panda_s0.npz
run panda_gear20 panda_gear20 panda_s0.npz
run panda_offset panda_offset panda_s0.npz
run panda_offg20_noq panda_offset_gear20 panda_s0_noq.npz
run panda_hold panda_hold panda_hold.npz
run aloha15_pyr_s0 aloha15_pyr aloha_s0.npz
run aloha15_pyr_s7 aloha15_pyr aloha_s7.npz
run panda_pyr panda_pyr panda_s0.npz
