#!/bin/bash
# batch_ana.sh: analyze + region check, old vs new. cases: name|scenario(with @V for old/new, @D for r30/r30b)|traj
F=/work/main/benchmarks/probe_r30/followup; cd /tmp/r30/followup/ana
G=/tmp/r30/tasks/gen; H=/tmp/r29c/gen; SAT=/tmp/r30/followup/sat
while IFS='|' read name scen traj; do
  [ -z "$name" ] && continue
  for v in old:r30 new:r30b; do n=${v%%:*}; d=${v##*:}
    sc=${scen//@V/$n}; sc=${sc//@D/$d}
    [ -s ${name}_$n.json ] && continue
    PYTHONPATH=/tmp/$d/src timeout 580 /work/venv/bin/python $F/ana_region.py $sc $traj ${name}_$n.json > ${name}_$n.log 2>&1 || echo "FAIL $name $n"
  done
  /work/venv/bin/python $F/cmpana.py ${name}_old.json ${name}_new.json
done <<CASES
aloha0|/tmp/@D/src/models/aloha_transfer_cube|/tmp/r28/params/aloha0.npz
aloha3|/tmp/@D/src/models/aloha_transfer_cube|aloha3.npz
aloha7|/tmp/@D/src/models/aloha_transfer_cube|aloha7.npz
aloha_jit5|/tmp/@D/src/models/aloha_transfer_cube|aloha_jit5.npz
panda0|/tmp/@D/src/models/panda_pick_place|/tmp/r28/params/panda0.npz
panda3|/tmp/@D/src/models/panda_pick_place|panda3.npz
panda7|/tmp/@D/src/models/panda_pick_place|panda7.npz
P_tiltcarry40|/tmp/@D/src/models/panda_pick_place|$G/P_tiltcarry40.npz
A_chunk50b|$G/aloha_m15|$G/A_chunk50b.npz
A_chunk100|$G/aloha_m15|$G/A_chunk100.npz
A_chunk25|$G/aloha_m15|$G/A_chunk25.npz
P_regrasp_off|/tmp/@D/src/models/panda_pick_place|$H/P_regrasp_off.npz
aloha_mfg3|aloha_mass_fric_grip_@V.toml|/tmp/r28/params/aloha0.npz
panda_mfg3|panda_mass_fric_grip_@V.toml|/tmp/r28/params/panda0.npz
panda_mfcg4|panda_mass_fric_com_grip_@V.toml|/tmp/r28/params/panda0.npz
aloha_mass_shoulder|$SAT/aloha_mass_shoulder_@V.toml|/tmp/r28/params/aloha0.npz
panda_mass_shoulder|$SAT/panda_mass_shoulder_@V.toml|/tmp/r28/params/panda0.npz
P_creep|/tmp/@D/src/models/panda_pick_place|/tmp/r30/followup/grip/P_creep.npz
CASES
