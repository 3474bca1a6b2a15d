#!/bin/bash
# batch_rollout.sh: critmoment rollout, old vs new, every scenario x trajectory in each earlier probe's robot folder
F=/work/main/benchmarks/probe_r30/followup; S=/tmp/r30/followup/ro; mkdir -p $S
for dir in /tmp/r29/robots/ur5e /tmp/r29/robots/xarm /tmp/r29/robots/vs050 /tmp/r30/robots/orca /tmp/r30/robots/z1 /tmp/r30/robots/gen3; do
  for sc in $dir/scenario*.toml; do for tr in $dir/*.npz; do
    k=$(basename $dir)_$(basename $sc .toml)_$(basename $tr .npz)
    for v in old new; do
      (cd $dir && timeout 300 $F/cm_$v.sh rollout --scenario $sc $tr --out $S/$k.$v > $S/$k.$v.log 2>&1; echo $? > $S/$k.$v.rc)
    done
    echo "$k old=$(cat $S/$k.old.rc) new=$(cat $S/$k.new.rc)"
  done; done
done
